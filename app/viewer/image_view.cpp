#include "app/viewer/image_view.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <imgui.h>

#include "app/viewer/camera_control.h"
#include "app/viewer/inspector_panel.h"

namespace app::viewer {
namespace {

constexpr float kOrbitRadiansPerPixel = 0.006f;
constexpr float kZoomPerWheelStep = 0.88f;
constexpr float kDividerGrabPixels = 8.0f;

void move_camera(ViewerState& state, const ImVec2& image_size) {
  if (!scene_ready(state) || !state.mouse_input) return;
  const ImGuiIO& io = ImGui::GetIO();
  renderer::Camera camera = current_camera(state);
  bool moved = false;
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f) &&
      (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
    camera = orbit_camera(camera, -io.MouseDelta.x * kOrbitRadiansPerPixel,
                          io.MouseDelta.y * kOrbitRadiansPerPixel);
    moved = true;
  }
  const bool panning = ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f) ||
                       ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0.0f);
  if (ImGui::IsItemActive() && panning && image_size.y > 0.0f &&
      (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
    camera = pan_camera(camera, -io.MouseDelta.x / image_size.y, io.MouseDelta.y / image_size.y);
    moved = true;
  }
  if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
    camera = zoom_camera(camera, std::pow(kZoomPerWheelStep, io.MouseWheel));
    moved = true;
  }
  if (moved) set_camera(state, camera);
}

void draw_hover(const ViewerState& state, int x, int y, const ImVec2& tooltip_at) {
  if (x < 0 || y < 0 || x >= state.image.width || y >= state.image.height) return;
  const auto i = static_cast<std::size_t>(y) * static_cast<std::size_t>(state.image.width) +
                 static_cast<std::size_t>(x);
  ImGui::SetNextWindowPos(tooltip_at);
  ImGui::BeginTooltip();
  ImGui::Text("pixel %d, %d", x, y);
  const std::uint32_t samples = state.image.samples[i];
  if (samples == 0) {
    ImGui::TextDisabled("not rendered yet");
    ImGui::EndTooltip();
    return;
  }
  const std::uint8_t* rgb = &state.image.rgb[3 * i];
  ImGui::ColorButton("##colour", ImVec4(rgb[0] / 255.0f, rgb[1] / 255.0f, rgb[2] / 255.0f, 1.0f),
                     ImGuiColorEditFlags_NoTooltip, ImVec2(14.0f, 14.0f));
  ImGui::SameLine();
  ImGui::Text("colour %d %d %d", rgb[0], rgb[1], rgb[2]);
  // One line per view of the table: its read-out, or (greyed) why it has none.
  const ViewPixels pixels = view_pixels(state.image, state.error, state.mask_threshold_pct);
  for (const ViewInfo& view : view_table()) {
    if (view.hover == nullptr) continue;
    const std::string line = view.hover(pixels, i);
    if (view.value(pixels, i)) {
      ImGui::TextUnformatted(line.c_str());
    } else {
      ImGui::TextDisabled("%s", line.c_str());
    }
  }
  ImGui::Text("samples        %u", samples);
  ImGui::EndTooltip();
}

// A/B: which side shows what, and the swipe's divider.
void draw_ab_marks(const ViewerState& state, ImDrawList* draw, const ImVec2& image_min,
                   const ImVec2& image_max, float scale) {
  const int rt_from = rt_from_column(state);
  if (view_info(state.view).colour_map != ColourMap::image || rt_from >= state.image.width) return;
  const float x = image_min.x + static_cast<float>(rt_from) * scale;
  const ImU32 white = IM_COL32(255, 255, 255, 230);
  if (state.swipe) {
    draw->AddLine(ImVec2(x, image_min.y), ImVec2(x, image_max.y), white, 2.0f);
    const float mid = 0.5f * (image_min.y + image_max.y);
    draw->AddTriangleFilled(ImVec2(x - 7.0f, mid), ImVec2(x - 1.0f, mid - 6.0f),
                            ImVec2(x - 1.0f, mid + 6.0f), white);
    draw->AddTriangleFilled(ImVec2(x + 7.0f, mid), ImVec2(x + 1.0f, mid - 6.0f),
                            ImVec2(x + 1.0f, mid + 6.0f), white);
    if (rt_from > 0) draw->AddText(ImVec2(image_min.x + 6.0f, image_min.y + 4.0f), white, "method");
  }
  const float text_width = ImGui::CalcTextSize("rt").x;
  draw->AddText(ImVec2(image_max.x - text_width - 6.0f, image_min.y + 4.0f), white, "rt");
}

}  // namespace

void draw_image_view(ViewerState& state, const GlTexture& texture) {
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("image", ImVec2(std::max(avail.x, 1.0f), std::max(avail.y, 1.0f)),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  const bool hovered = ImGui::IsItemHovered();
  record_item(state.record_controls ? &state.control_rects : nullptr, "image_area");
  const ImVec2 pixels_per_point = ImGui::GetIO().DisplayFramebufferScale;
  state.image_area_width =
      static_cast<int>(std::floor(std::max(avail.x, 1.0f) * pixels_per_point.x));
  state.image_area_height =
      static_cast<int>(std::floor(std::max(avail.y, 1.0f) * pixels_per_point.y));
  const int w = state.image.width, h = state.image.height;
  float scale = 1.0f;
  ImVec2 image_min = origin, image_max = origin;
  if (w > 0 && h > 0) {
    scale = std::min(avail.x / static_cast<float>(w), avail.y / static_cast<float>(h));
    // Whole multiples keep pixels square and sharp for hovering (and cost less to draw).
    if (scale >= 1.0f) scale = std::floor(scale);
    const ImVec2 size(scale * static_cast<float>(w), scale * static_cast<float>(h));
    image_min = ImVec2(origin.x + 0.5f * (avail.x - size.x), origin.y + 0.5f * (avail.y - size.y));
    image_max = ImVec2(image_min.x + size.x, image_min.y + size.y);
  }
  // A click (a press and release that did not drag) pins the inspector on that pixel.
  if (w > 0 && state.mouse_input && ImGui::IsItemDeactivated() &&
      ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
      ImGui::GetIO().MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] < 9.0f) {
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const int x = static_cast<int>(std::floor((mouse.x - image_min.x) / scale));
    const int y = static_cast<int>(std::floor((mouse.y - image_min.y) / scale));
    if (x >= 0 && y >= 0 && x < w && y < h) set_inspect_pixel(state, std::array<int, 2>{x, y});
  }
  // The swipe's divider: a press near it drags it instead of the camera.
  if (state.swipe && state.mouse_input && w > 0) {
    const float span = image_max.x - image_min.x;
    const float mouse_x = ImGui::GetIO().MousePos.x;
    const float divider_x = image_min.x + static_cast<float>(*state.swipe) * span;
    if (ImGui::IsItemActivated() && std::abs(mouse_x - divider_x) <= kDividerGrabPixels)
      state.swipe_dragging = true;
    if (!ImGui::IsItemActive()) state.swipe_dragging = false;
    if (state.swipe_dragging && span > 0.0f)
      state.swipe = std::clamp(static_cast<double>((mouse_x - image_min.x) / span), 0.0, 1.0);
  } else {
    state.swipe_dragging = false;
  }
  if (!state.swipe_dragging)
    move_camera(state, ImVec2(image_max.x - image_min.x, image_max.y - image_min.y));

  ImDrawList* draw = ImGui::GetWindowDrawList();
  if (texture.id != 0 && w > 0) {
    draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture.id)),
                   image_min, image_max);
    // Tiles being traced; the rects belong to the render in flight, which has the settings' size.
    if (state.status.width == w && state.status.height == h) {
      for (const TileRect& r : state.in_flight) {
        draw->AddRect(ImVec2(image_min.x + r.x0 * scale, image_min.y + r.y0 * scale),
                      ImVec2(image_min.x + r.x1 * scale, image_min.y + r.y1 * scale),
                      IM_COL32(255, 150, 40, 255), 0.0f, 0, 2.0f);
      }
    }
  }
  if (w > 0) draw_ab_marks(state, draw, image_min, image_max, scale);
  // Where the picture is, for tests that read the window's pixels.
  if (w > 0 && state.record_controls)
    record_rect(&state.control_rects, "image", image_min.x, image_min.y, image_max.x, image_max.y);
  if (w > 0) draw_inspector_overlay(state, draw, image_min, image_max, scale);
  const WorkerStatus& st = state.status;
  if (st.phase == WorkerPhase::loading || st.phase == WorkerPhase::preparing) {
    draw->AddText(ImVec2(origin.x + 12.0f, origin.y + 10.0f), IM_COL32(255, 255, 255, 255),
                  worker_phase_text(st.phase));
  }
  if (w > 0 && state.mouse_input && hovered) {
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    draw_hover(state, static_cast<int>(std::floor((mouse.x - image_min.x) / scale)),
               static_cast<int>(std::floor((mouse.y - image_min.y) / scale)),
               ImVec2(mouse.x + 16.0f, mouse.y + 8.0f));
  } else if (w > 0 && state.scripted_hover) {
    const TileRect& p = *state.scripted_hover;
    const ImVec2 at(image_min.x + (static_cast<float>(p.x0) + 0.5f) * scale,
                    image_min.y + (static_cast<float>(p.y0) + 0.5f) * scale);
    draw->AddCircle(at, 6.0f, IM_COL32(255, 255, 255, 255), 12, 2.0f);
    draw_hover(state, p.x0, p.y0, ImVec2(at.x + 16.0f, at.y + 8.0f));
  }
}

}  // namespace app::viewer
