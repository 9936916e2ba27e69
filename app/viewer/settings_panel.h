// The panel's controls, generated from app::setting_table(): a combo for every Choice, a number
// field for every IntRange, and for a logarithmic RealRange (the tolerance) a log slider over
// the table's slider span ([1e-6, 1]) plus a 0 button and a typed value. The model level is shown
// as the scene's light counts. A new setting in the table appears here without changes.
#pragma once

#include "app/viewer/viewer_state.h"

namespace app::viewer {

void draw_settings_section(ViewerState& state);

}  // namespace app::viewer
