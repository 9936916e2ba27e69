// The viewer's pixel inspector on screen: a window over the top right of the picture listing the
// pinned pixel's top contributors and totals (inspector_rows.h; the worker makes them), and on
// the image, markers at those lights' projected positions, the pinned pixel, and the selected
// row's extent volume outline.
#pragma once

#include <imgui.h>

#include <string>

#include "app/viewer/viewer_state.h"

namespace app::viewer {

// The inspection of the pinned pixel in the render shown, or null (none pinned, or not ready).
const PublishedInspection* current_inspection(const ViewerState& state);

// What the window says while it has no list to show: "inspecting...", or, for a pinned pixel
// the render in flight does not have (a window or size change left it outside the image), that
// it is outside the image (no inspection comes for it). Empty when there is a list, or no pin.
std::string inspector_wait_text(const ViewerState& state);

// The window, when a pixel is pinned; picture_pos and picture_size: the picture area's.
void draw_inspector_window(ViewerState& state, const ImVec2& picture_pos,
                           const ImVec2& picture_size);

// The overlay, clipped to the image; its pixel (x, y) is drawn at image_min + (x, y) * scale.
void draw_inspector_overlay(const ViewerState& state, ImDrawList* draw, const ImVec2& image_min,
                            const ImVec2& image_max, float scale);

// The colour of the contributors' markers (the scripted viewer test looks for it).
inline constexpr ImU32 kInspectorMarkerColour = IM_COL32(255, 0, 255, 255);

}  // namespace app::viewer
