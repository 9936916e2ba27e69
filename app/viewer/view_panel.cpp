#include "app/viewer/view_panel.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <imgui.h>

#include "app/viewer/heatmap_scale.h"
#include "lev/methods.h"

namespace app::viewer {
namespace {

constexpr float kBarHeight = 14.0f;

// A colour bar across the panel, `colour` at each position t in [0, 1], with a labelled tick at
// each (position, text) of `ticks`, and the space for both reserved.
void draw_colour_bar(glm::u8vec3 (*colour)(float t),
                     const std::vector<std::pair<float, std::string>>& ticks) {
  const float width = ImGui::GetContentRegionAvail().x;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const int steps = 64;
  for (int i = 0; i < steps; ++i) {
    const float t0 = static_cast<float>(i) / steps, t1 = static_cast<float>(i + 1) / steps;
    const glm::u8vec3 c = colour(0.5f * (t0 + t1));
    draw->AddRectFilled(ImVec2(origin.x + t0 * width, origin.y),
                        ImVec2(origin.x + t1 * width, origin.y + kBarHeight),
                        IM_COL32(c.x, c.y, c.z, 255));
  }
  for (std::size_t k = 0; k < ticks.size(); ++k) {
    const float x = origin.x + ticks[k].first * width;
    const char* text = ticks[k].second.c_str();
    draw->AddLine(ImVec2(x, origin.y + kBarHeight), ImVec2(x, origin.y + kBarHeight + 4.0f),
                  IM_COL32(220, 220, 220, 255));
    const float text_width = ImGui::CalcTextSize(text).x;
    const float tx = k == 0 ? x : (k + 1 == ticks.size() ? x - text_width : x - 0.5f * text_width);
    draw->AddText(ImVec2(tx, origin.y + kBarHeight + 4.0f), IM_COL32(220, 220, 220, 255), text);
  }
  ImGui::Dummy(ImVec2(width, kBarHeight + 4.0f + ImGui::GetTextLineHeight()));
}

glm::u8vec3 viridis_at(float t) {
  return renderer::viridis(t);
}

glm::u8vec3 diverging_at(float t) {
  return diverging_rgb8(2.0 * t - 1.0);
}

}  // namespace

void draw_heatmap_legend(const ViewInfo& info, const renderer::HeatmapRange& range, bool rendered,
                         const std::string& method) {
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
  // Ticks at equal steps of the colour position, labelled with the values there; fewer ticks
  // when the panel is narrow, so the labels never overlap.
  const int ticks = ImGui::GetContentRegionAvail().x < 300.0f ? 3 : 5;
  std::vector<std::pair<float, std::string>> labels;
  for (int k = 0; k < ticks; ++k) {
    const double t = static_cast<double>(k) / (ticks - 1);
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", heatmap_value_at(t, range));
    labels.emplace_back(static_cast<float>(t), text);
  }
  draw_colour_bar(viridis_at, labels);
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  // The range leads its own line, so wrapping never splits a number.
  ImGui::TextWrapped("%s", info.unit);
  ImGui::TextWrapped("%.4g .. %.4g, log scale from the minimum; grey: not rendered yet", range.min,
                     range.max);
  ImGui::PopStyleColor();
}

namespace {

// The diverging bar over the row's symmetric fixed range, ticks at -R, 0 and +R.
void draw_diverging_legend(const ViewInfo& info) {
  std::vector<std::pair<float, std::string>> labels;
  for (int k = 0; k < 3; ++k) {
    char text[32];
    std::snprintf(text, sizeof text, "%+.3g%%", (k - 1) * info.fixed_range);
    labels.emplace_back(0.5f * static_cast<float>(k), text);
  }
  draw_colour_bar(diverging_at, labels);
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("%s", info.unit);
  ImGui::TextWrapped(
      "fixed range %+.3g .. %+.3g%%, linear; beyond it the end colours; grey: not "
      "compared yet",
      -info.fixed_range, info.fixed_range);
  ImGui::PopStyleColor();
}

// The mask's threshold control and what share of the compared pixels it marks.
void draw_mask_legend(ViewerState& state, const ViewInfo& info) {
  float threshold = static_cast<float>(state.mask_threshold_pct);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
  if (ImGui::SliderFloat("threshold %", &threshold, 0.01f, 100.0f, "%.3g",
                         ImGuiSliderFlags_Logarithmic)) {
    state.mask_threshold_pct = threshold;
  }
  if (state.record_controls) record_item(&state.control_rects, "mask_threshold");
  std::size_t above = 0;
  for (std::size_t i = 0; i < state.error.pct.size(); ++i) {
    if (state.error.pct[i] > state.mask_threshold_pct) ++above;
  }
  const std::size_t compared = state.error.pixels_compared;
  if (compared == 0) {
    ImGui::TextWrapped("%s: nothing compared yet.", info.unit);
    return;
  }
  if (above == 0) {
    ImGui::TextWrapped("%s: %s (max error %.3g%%).", info.unit, info.zero, state.error.max_pct);
    return;
  }
  ImGui::TextWrapped("%s: %zu of %zu compared pixels (%.3g%%) above %.3g%%.", info.unit, above,
                     compared, 100.0 * static_cast<double>(above) / static_cast<double>(compared),
                     state.mask_threshold_pct);
}

}  // namespace

void draw_view_section(ViewerState& state) {
  const std::vector<ViewInfo>& views = view_table();
  for (std::size_t i = 0; i < views.size(); ++i) {
    if (i % 2 == 1) ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.5f);
    if (ImGui::RadioButton(views[i].label, state.view == views[i].mode))
      select_view(state, views[i].mode);
    if (state.record_controls)
      record_item(&state.control_rects, std::string("view:") + views[i].name);
  }
  const ViewInfo& info = view_info(state.view);
  const lev::MethodInfo& method = lev::method_info(state.settings.method.method);
  if (info.needs_missed && !method.missed_light_known) {
    ImGui::TextWrapped(
        "%s does not estimate the light it leaves out: the Error view compares it with rt.",
        method.name);
    return;
  }
  const bool rendered =
      info.needs_reference ? state.error.pixels_compared > 0 : state.image.tiles_seen > 0;
  switch (info.colour_map) {
    case ColourMap::image:
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
      ImGui::TextWrapped(
          "Dimmed: the previous render, until its tiles are redrawn. Outlined: tiles "
          "being traced now.");
      ImGui::PopStyleColor();
      return;
    case ColourMap::sequential: {
      // The lock keeps this range while renders change, so two compare on one scale.
      bool locked = locked_range(state).has_value();
      if (ImGui::Checkbox("lock range", &locked)) set_range_lock(state, locked);
      if (state.record_controls) record_item(&state.control_rects, "range_lock");
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("keep this heatmap's range for every render");
      if (locked) {
        ImGui::SameLine();
        ImGui::TextDisabled("%.4g .. %.4g (locked)", state.heatmap_range.min,
                            state.heatmap_range.max);
      }
      draw_heatmap_legend(info, state.heatmap_range, rendered,
                          lev::method_info(state.status.method).name);
      return;
    }
    case ColourMap::diverging:
      draw_diverging_legend(info);
      return;
    case ColourMap::mask:
      draw_mask_legend(state, info);
      return;
  }
}

}  // namespace app::viewer
