// The panel's controls, generated from app::setting_table(): a combo for every Choice, a number
// field for every IntRange, and for a logarithmic RealRange (the tolerance) a log slider over
// the table's slider span ([1e-6, 1]) plus a 0 button and a typed value. The model level is shown
// as the scene's light counts. A new setting in the table appears here without changes.
#pragma once

#include <string>

#include "app/viewer/viewer_state.h"

namespace app::viewer {

void draw_settings_section(ViewerState& state);

// The value a number field of the panel sets when the user asks for `asked` (typed, or a "+" or
// "-" step) where it held `held`: clamped to the table's range, and past a gap in it (the
// missed-light draws are 0, off, or at least renderer::kMinMissedDraws) to the side the user
// moved toward, so no step gives a value the render refuses.
// Why a value typed into a real setting's field is refused ("" when it is within the table's
// range): the panel logs it in the Messages pane (and scripted sessions print it) instead of
// dropping the value without a word.
std::string typed_value_refusal(const SettingSpec& spec, const RealRange& range, double typed);

// The tooltip of a logarithmic setting's 0 button, named for that setting (the tolerance's, the
// relative error's): what 0 means for it.
std::string zero_button_tooltip(const SettingSpec& spec);

int panel_int_value(const SettingSpec& spec, const IntRange& range, int held, int asked);

}  // namespace app::viewer
