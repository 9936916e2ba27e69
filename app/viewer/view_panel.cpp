#include "app/viewer/view_panel.h"

#include <cmath>
#include <cstdio>
#include <string>

#include <imgui.h>

namespace app::viewer {

void draw_heatmap_legend(const ViewModeInfo& info, const renderer::HeatmapRange& range) {
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
  // Ticks at equal steps of t = log(1 + v) / log(1 + max): v = (1 + max)^t - 1.
  const double max = std::max(range.max, 0.0);
  const int ticks = 5;
  for (int k = 0; k < ticks; ++k) {
    const double t = static_cast<double>(k) / (ticks - 1);
    const double v = std::pow(1.0 + max, t) - 1.0;
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    const float x = origin.x + static_cast<float>(t) * width;
    draw->AddLine(ImVec2(x, origin.y + bar_height), ImVec2(x, origin.y + bar_height + 4.0f),
                  IM_COL32(220, 220, 220, 255));
    const float text_width = ImGui::CalcTextSize(text).x;
    const float tx = k == 0 ? x : (k == ticks - 1 ? x - text_width : x - 0.5f * text_width);
    draw->AddText(ImVec2(tx, origin.y + bar_height + 4.0f), IM_COL32(220, 220, 220, 255), text);
  }
  ImGui::Dummy(ImVec2(width, bar_height + 4.0f + ImGui::GetTextLineHeight()));
  ImGui::TextDisabled("%s; log(1 + value), viridis", info.unit);
  ImGui::TextDisabled("rendered pixels range %.3g .. %.3g; grey: not rendered yet", range.min,
                      range.max);
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
    ImGui::TextDisabled("dimmed: the previous render, until its tiles are redrawn");
    ImGui::TextDisabled("outlined: tiles being traced now");
    return;
  }
  draw_heatmap_legend(info, state.heatmap_range);
}

}  // namespace app::viewer
