#include "app/viewer/trade_plot.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "lev/methods.h"

namespace app::viewer {

void follow_reference(TradePlot& plot, std::uint64_t reference_generation) {
  if (plot.reference_generation == reference_generation) return;
  plot.reference_generation = reference_generation;
  plot.points.clear();
}

void add_trade_point(TradePlot& plot, const TradePoint& point) {
  const auto same = [&](const TradePoint& p) {
    return p.method == point.method && p.tolerance == point.tolerance;
  };
  plot.points.erase(std::remove_if(plot.points.begin(), plot.points.end(), same),
                    plot.points.end());
  plot.points.push_back(point);
}

int trade_point_passes(const TradePlot& plot, std::uint64_t generation) {
  for (const TradePoint& p : plot.points) {
    if (p.generation == generation) return p.passes;
  }
  return 0;
}

namespace {

// One colour per row of lev::method_table(), so new methods get their own.
ImU32 method_colour(lev::Method method) {
  static const ImU32 kPalette[] = {IM_COL32(230, 230, 230, 255), IM_COL32(240, 160, 60, 255),
                                   IM_COL32(90, 200, 250, 255),  IM_COL32(200, 120, 220, 255),
                                   IM_COL32(120, 220, 120, 255), IM_COL32(250, 110, 110, 255)};
  return kPalette[static_cast<std::size_t>(method) % (sizeof kPalette / sizeof kPalette[0])];
}

}  // namespace

void draw_trade_plot(const TradePlot& plot, std::uint64_t current) {
  if (plot.points.empty()) {
    ImGui::TextDisabled("Compute the rt reference, then try tolerances:");
    ImGui::TextDisabled("each render adds a (pass-0 time, error) point, its error updated");
    ImGui::TextDisabled("over more passes as both renders go on.");
    return;
  }
  double max_time = 0.0, max_error = 0.0;
  for (const TradePoint& p : plot.points) {
    max_time = std::max(max_time, p.seconds);
    max_error = std::max(max_error, p.error_avg_pct);
  }
  max_time = max_time > 0.0 ? max_time * 1.1 : 1.0;
  max_error = max_error > 0.0 ? max_error * 1.1 : 1.0;

  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const ImVec2 size(avail.x,
                    std::max(90.0f, avail.y - 2.0f * ImGui::GetTextLineHeightWithSpacing()));
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("trade_plot", size);
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float left = 48.0f, bottom = 18.0f;
  const ImVec2 p0(origin.x + left, origin.y + 4.0f);
  const ImVec2 p1(origin.x + size.x - 6.0f, origin.y + size.y - bottom);
  draw->AddRectFilled(p0, p1, IM_COL32(25, 25, 30, 255));
  draw->AddRect(p0, p1, IM_COL32(110, 110, 120, 255));
  char text[64];
  std::snprintf(text, sizeof text, "%.3g%%", max_error);
  draw->AddText(ImVec2(origin.x, p0.y), IM_COL32(200, 200, 200, 255), text);
  draw->AddText(ImVec2(origin.x, p1.y - 12.0f), IM_COL32(200, 200, 200, 255), "0%");
  std::snprintf(text, sizeof text, "%.3g s", max_time);
  draw->AddText(ImVec2(p1.x - ImGui::CalcTextSize(text).x, p1.y + 2.0f),
                IM_COL32(200, 200, 200, 255), text);
  draw->AddText(ImVec2(p0.x, p1.y + 2.0f), IM_COL32(200, 200, 200, 255), "0 s   pass-0 time ->");

  const TradePoint* nearest = nullptr;
  float nearest_d2 = 64.0f;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  for (const TradePoint& p : plot.points) {
    const ImVec2 c(p0.x + static_cast<float>(p.seconds / max_time) * (p1.x - p0.x),
                   p1.y - static_cast<float>(p.error_avg_pct / max_error) * (p1.y - p0.y));
    const ImU32 colour = method_colour(p.method);
    const float radius = p.generation == current ? 5.0f : 3.5f;
    if (p.shared_cpu) {
      draw->AddCircle(c, radius, colour, 12, 1.5f);
    } else {
      draw->AddCircleFilled(c, radius, colour);
    }
    if (p.generation == current) draw->AddCircle(c, radius + 3.0f, IM_COL32(255, 255, 255, 200));
    const float dx = mouse.x - c.x, dy = mouse.y - c.y;
    if (hovered && dx * dx + dy * dy < nearest_d2) {
      nearest_d2 = dx * dx + dy * dy;
      nearest = &p;
    }
  }
  if (nearest) {
    ImGui::BeginTooltip();
    ImGui::Text("%s, tolerance %g", lev::method_info(nearest->method).name, nearest->tolerance);
    ImGui::Text("pass 0: %.3f s", nearest->seconds);
    ImGui::Text("error avg %.4f%%, max %.3f%% (over %d passes)", nearest->error_avg_pct,
                nearest->error_max_pct, nearest->passes);
    if (nearest->shared_cpu) ImGui::TextDisabled("measured while the reference rendered");
    ImGui::EndTooltip();
  }
  for (const lev::MethodInfo& m : lev::method_table()) {
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(method_colour(m.id)), "%s", m.name);
    ImGui::SameLine();
  }
  ImGui::TextDisabled("  y: avg pixel error; hollow: shared CPU");
}

}  // namespace app::viewer
