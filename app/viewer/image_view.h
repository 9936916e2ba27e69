// The picture area: the render's texture fitted to the window area, outlines of the tiles being
// traced, the mouse camera (left drag orbits, right or middle drag pans, the wheel zooms) and the
// hover tooltip with the pixel's colour, lights tested, nodes visited and error.
#pragma once

#include "app/viewer/gl_texture.h"
#include "app/viewer/viewer_state.h"

namespace app::viewer {

// Draws into the current Dear ImGui window, filling its content region.
void draw_image_view(ViewerState& state, const GlTexture& texture);

}  // namespace app::viewer
