#include "app/viewer/view_panel.h"

#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app/viewer/heatmap_scale.h"

namespace app::viewer {

void draw_heatmap_legend(const ViewModeInfo& info, const renderer::HeatmapRange& range,
                         bool rendered, const std::string& method) {
  if (!rendered) {
    ImGui::TextWrapped("%s: nothing rendered yet.", info.unit);
    return;
  }
  if (range.max == 0.0 && range.min == 0.0) {
    ImGui::TextWrapped("%s: 0 in every rendered pixel; %s (%s).", info.unit, info.zero,
                       method.c_str());
    return;
  }
  if (range.max == range.min) {
    ImGui::TextWrapped("%s: %.4g in every rendered pixel (one colour).", info.unit, range.min);
    return;
  }
  const float width = ImGui::GetContentRegionAvail().x;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float bar_height = 14.0f;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const int steps = 64;
  for (int i = 0; i < steps; ++i) {
    const float t0 = static_cast<float>(i) / steps, t1 = static_cast<float>(i + 1) / steps;
    const glm::u8vec3 c = renderer::viridis(0.5f * (t0 + t1));
    draw->AddRectFilled(ImVec2(origin.x + t0 * width, origin.y),
                        ImVec2(origin.x + t1 * width, origin.y + bar_height),
                        IM_COL32(c.x, c.y, c.z, 255));
  }
  // Ticks at equal steps of the colour position, labelled with the values there; fewer ticks
  // when the panel is narrow, so the labels never overlap.
  const int ticks = width < 300.0f ? 3 : 5;
  for (int k = 0; k < ticks; ++k) {
    const double t = static_cast<double>(k) / (ticks - 1);
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", heatmap_value_at(t, range));
    const float x = origin.x + static_cast<float>(t) * width;
    draw->AddLine(ImVec2(x, origin.y + bar_height), ImVec2(x, origin.y + bar_height + 4.0f),
                  IM_COL32(220, 220, 220, 255));
    const float text_width = ImGui::CalcTextSize(text).x;
    const float tx = k == 0 ? x : (k == ticks - 1 ? x - text_width : x - 0.5f * text_width);
    draw->AddText(ImVec2(tx, origin.y + bar_height + 4.0f), IM_COL32(220, 220, 220, 255), text);
  }
  ImGui::Dummy(ImVec2(width, bar_height + 4.0f + ImGui::GetTextLineHeight()));
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  // The range leads its own line, so wrapping never splits a number.
  ImGui::TextWrapped("%s", info.unit);
  ImGui::TextWrapped("%.4g .. %.4g, log scale from the minimum; grey: not rendered yet", range.min,
                     range.max);
  ImGui::PopStyleColor();
}

void draw_view_section(ViewerState& state) {
  const std::vector<ViewModeInfo>& modes = view_mode_table();
  for (std::size_t i = 0; i < modes.size(); ++i) {
    if (i % 2 == 1) ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.5f);
    if (ImGui::RadioButton(modes[i].label, state.view == modes[i].mode))
      select_view(state, modes[i].mode);
    if (state.record_controls)
      record_item(&state.control_rects, std::string("view:") + modes[i].name);
  }
  const ViewModeInfo& info = view_mode_info(state.view);
  if (state.view == ViewMode::image) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped(
        "Dimmed: the previous render, until its tiles are redrawn. Outlined: tiles "
        "being traced now.");
    ImGui::PopStyleColor();
    return;
  }
  const bool rendered =
      state.view == ViewMode::error ? state.error.pixels_compared > 0 : state.image.tiles_seen > 0;
  draw_heatmap_legend(info, state.heatmap_range, rendered,
                      lev::method_info(state.status.method).name);
}

}  // namespace app::viewer
