#include "app/viewer/inspector_panel.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace app::viewer {
namespace {

// The window covers the top right of the picture: at most this wide, or this share of it.
constexpr float kWindowWidth = 380.0f;
constexpr float kWindowWidthShare = 0.36f;
constexpr float kWindowHeightShare = 0.6f;
constexpr int kMarkedRows = 10;
constexpr ImU32 kOutlineColour = IM_COL32(255, 230, 40, 255);
constexpr ImU32 kPinColour = IM_COL32(255, 255, 255, 255);

float brightest(const glm::vec3& v) {
  return std::max({v.x, v.y, v.z});
}

void text_rgb(const char* label, const glm::dvec3& v) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
    ImGui::Text("%-19s none (sampling)", label);
    return;
  }
  ImGui::Text("%-19s %.4f %.4f %.4f", label, v.x, v.y, v.z);
}

void draw_marks(const ViewerState& state, ImDrawList* draw, const ImVec2& image_min, float scale);

}  // namespace

const PublishedInspection* current_inspection(const ViewerState& state) {
  const PublishedInspection* view = state.status.inspection.get();
  if (!view || !state.inspect_pixel || view->generation != state.status.generation ||
      view->x != (*state.inspect_pixel)[0] || view->y != (*state.inspect_pixel)[1]) {
    return nullptr;
  }
  return view;
}

std::string inspector_wait_text(const ViewerState& state) {
  if (!state.inspect_pixel || current_inspection(state)) return "";
  const int x = (*state.inspect_pixel)[0], y = (*state.inspect_pixel)[1];
  const WorkerStatus& st = state.status;
  if (st.width > 0 && st.height > 0 && (x >= st.width || y >= st.height)) {
    return "outside the " + std::to_string(st.width) + "x" + std::to_string(st.height) +
           " image: click a pixel of it";
  }
  return "inspecting...";
}

void draw_inspector_window(ViewerState& state, const ImVec2& picture_pos,
                           const ImVec2& picture_size) {
  if (!state.inspect_pixel) return;
  const float width = std::min(kWindowWidth, picture_size.x * kWindowWidthShare);
  ImGui::SetNextWindowPos(ImVec2(picture_pos.x + picture_size.x - width, picture_pos.y));
  ImGui::SetNextWindowSize(ImVec2(width, picture_size.y * kWindowHeightShare));
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("Pixel inspector", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  record_item(state.record_controls ? &state.control_rects : nullptr, "inspector");
  ImGui::Text("pixel %d, %d", (*state.inspect_pixel)[0], (*state.inspect_pixel)[1]);
  ImGui::SameLine();
  if (ImGui::SmallButton("Clear")) set_inspect_pixel(state, std::nullopt);
  record_item(state.record_controls ? &state.control_rects : nullptr, "inspector:clear");
  const PublishedInspection* view = current_inspection(state);
  if (!state.inspect_pixel) {
    ImGui::End();
    return;
  }
  if (!view) {
    ImGui::TextDisabled("%s", inspector_wait_text(state).c_str());
    ImGui::End();
    return;
  }
  const renderer::InspectedTotals& t = view->totals;
  text_rgb("tested sum", t.tested);
  text_rgb("lost (shadows)", t.lost);
  text_rgb("bound (no shadows)", t.bound);
  ImGui::Text("%zu shaded, %zu culled, %zu in %zu clusters", t.shaded, t.culled_lights,
              t.clustered_lights, t.clusters);
  ImGui::TextDisabled("top %zu of %zu rows, %.0f ms; a row: its extent", view->rows.size(),
                      view->all_rows, view->seconds * 1000.0);
  if (ImGui::BeginTable("inspector_rows", 6,
                        ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg |
                            ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit)) {
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("#");
    ImGui::TableSetupColumn("hit");
    ImGui::TableSetupColumn("role");
    ImGui::TableSetupColumn("node");
    ImGui::TableSetupColumn("seen");
    ImGui::TableSetupColumn("to pixel", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < view->rows.size(); ++i) {
      const InspectorRow& row = view->rows[i];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      const std::string label = std::to_string(i + 1);
      if (ImGui::Selectable(label.c_str(), state.inspect_row == static_cast<int>(i),
                            ImGuiSelectableFlags_SpanAllColumns)) {
        state.inspect_row = state.inspect_row == static_cast<int>(i) ? -1 : static_cast<int>(i);
      }
      ImGui::TableNextColumn();
      ImGui::Text("%d", row.depth);
      ImGui::TableNextColumn();
      if (row.members > 0) {
        ImGui::Text("%s(%zu)", row.role.c_str(), row.members);
      } else {
        ImGui::TextUnformatted(row.role.c_str());
      }
      ImGui::TableNextColumn();
      if (row.node == lev::kOwnTest) {
        ImGui::TextUnformatted("-");
      } else {
        ImGui::Text("%u", row.node);
      }
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(row.seen ? "yes" : "no");
      ImGui::TableNextColumn();
      ImGui::Text("%.5f", brightest(row.to_pixel));
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

void draw_inspector_overlay(const ViewerState& state, ImDrawList* draw, const ImVec2& image_min,
                            const ImVec2& image_max, float scale) {
  if (!state.inspect_pixel) return;
  draw->PushClipRect(image_min, image_max, true);
  draw_marks(state, draw, image_min, scale);
  draw->PopClipRect();
}

namespace {

void draw_marks(const ViewerState& state, ImDrawList* draw, const ImVec2& image_min, float scale) {
  const auto on_screen = [&](const glm::vec2& image) {
    return ImVec2(image_min.x + image.x * scale, image_min.y + image.y * scale);
  };
  const float px = static_cast<float>((*state.inspect_pixel)[0]);
  const float py = static_cast<float>((*state.inspect_pixel)[1]);
  draw->AddRect(on_screen({px - 1.0f, py - 1.0f}), on_screen({px + 2.0f, py + 2.0f}), kPinColour,
                0.0f, 0, 2.0f);
  const PublishedInspection* view = current_inspection(state);
  if (!view) return;
  const int marked = std::min(kMarkedRows, static_cast<int>(view->rows.size()));
  for (int i = 0; i < marked; ++i) {
    glm::vec2 image;
    float depth = 0.0f;
    if (!renderer::project_point(view->camera, view->width, view->height,
                                 view->rows[static_cast<std::size_t>(i)].light.position, image,
                                 depth)) {
      continue;
    }
    const ImVec2 at = on_screen(image);
    const float size = i == state.inspect_row ? 9.0f : 6.0f;
    draw->AddCircle(at, size, kInspectorMarkerColour, 16, 2.0f);
    draw->AddLine(ImVec2(at.x - size, at.y), ImVec2(at.x + size, at.y), kInspectorMarkerColour,
                  2.0f);
    draw->AddLine(ImVec2(at.x, at.y - size), ImVec2(at.x, at.y + size), kInspectorMarkerColour,
                  2.0f);
  }
  if (state.inspect_row >= 0 && state.inspect_row < static_cast<int>(view->rows.size())) {
    const InspectorRow& row = view->rows[static_cast<std::size_t>(state.inspect_row)];
    for (const std::vector<glm::vec2>& line :
         extent_outline(view->camera, view->width, view->height, row.light, view->tolerance)) {
      std::vector<ImVec2> points;
      for (const glm::vec2& p : line) points.push_back(on_screen(p));
      draw->AddPolyline(points.data(), static_cast<int>(points.size()), kOutlineColour, 0, 2.0f);
    }
  }
}

}  // namespace

}  // namespace app::viewer
