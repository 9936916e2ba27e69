#include "app/viewer/trade_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>

#include "lev/methods.h"

namespace app::viewer {

void follow_reference(TradePlot& plot, std::uint64_t reference_generation) {
  if (plot.reference_generation == reference_generation) return;
  plot.reference_generation = reference_generation;
  plot.points.clear();
}

namespace {

lev::MethodChoice used_choice(const TradePoint& p) {
  lev::MethodChoice c;
  c.method = p.method;
  c.tolerance = p.tolerance;
  c.relative_error = p.relative_error;
  c.lights_per_point = p.lights_per_point;
  c.rt_fallback = p.rt_fallback;
  return lev::used_settings(c);
}

}  // namespace

void add_trade_point(TradePlot& plot, const TradePoint& point) {
  // Two relative errors of lev_cut (or lights per point of lev_mc) are two points: keyed by the
  // tolerance alone, each replaced the one before.
  const lev::MethodChoice key = used_choice(point);
  const auto same = [&](const TradePoint& p) { return used_choice(p) == key; };
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

// Whether a label of `size` at (x, y) would cover one of `placed`.
bool overlaps(const std::vector<ImVec4>& placed, float x, float y, const ImVec2& size) {
  for (const ImVec4& r : placed) {
    if (x < r.z && x + size.x > r.x && y < r.w && y + size.y > r.y) return true;
  }
  return false;
}

// log10 position of v in [lo, hi] (both > 0), clamped to [0, 1].
double log_position(double v, double lo, double hi) {
  if (!(hi > lo)) return 0.5;
  const double t = std::log10(std::max(v, lo) / lo) / std::log10(hi / lo);
  return std::clamp(t, 0.0, 1.0);
}

// Bounds padded by a fifth of a decade each side, and a decade around a single value.
void pad_log_range(double& lo, double& hi) {
  if (!(hi > lo)) {
    lo /= std::sqrt(10.0);
    hi *= std::sqrt(10.0);
    return;
  }
  lo /= std::pow(10.0, 0.2);
  hi *= std::pow(10.0, 0.2);
}

}  // namespace

TradeAxes trade_axes(const std::vector<TradePoint>& points) {
  TradeAxes a;
  double min_positive_error = 0.0;
  bool any_time = false;
  for (const TradePoint& p : points) {
    if (p.seconds > 0.0) {
      a.min_seconds = any_time ? std::min(a.min_seconds, p.seconds) : p.seconds;
      a.max_seconds = any_time ? std::max(a.max_seconds, p.seconds) : p.seconds;
      any_time = true;
    }
    if (p.error_avg_pct > 0.0) {
      min_positive_error = min_positive_error > 0.0 ? std::min(min_positive_error, p.error_avg_pct)
                                                    : p.error_avg_pct;
      a.max_error_pct = std::max(a.max_error_pct, p.error_avg_pct);
    }
  }
  if (!any_time) a.min_seconds = a.max_seconds = 1.0;
  // The floor, for errors of 0: a decade below the smallest error above it (1e-3 % if none).
  a.min_error_pct = min_positive_error > 0.0 ? min_positive_error / 10.0 : 1e-3;
  if (a.max_error_pct <= a.min_error_pct) a.max_error_pct = a.min_error_pct * 10.0;
  pad_log_range(a.min_seconds, a.max_seconds);
  a.max_error_pct *= std::pow(10.0, 0.2);
  return a;
}

double trade_x(const TradeAxes& axes, double seconds) {
  return log_position(seconds, axes.min_seconds, axes.max_seconds);
}

double trade_y(const TradeAxes& axes, double error_pct) {
  return log_position(error_pct, axes.min_error_pct, axes.max_error_pct);
}

std::string trade_label(const TradePoint& point, double reference_pass0_seconds) {
  const lev::MethodInfo& method = lev::method_info(point.method);
  char text[64];
  if (method.uses_tolerance) {
    std::snprintf(text, sizeof text, "%g", point.tolerance);
  } else if (method.uses_relative_error) {
    std::snprintf(text, sizeof text, "%g", point.relative_error);
  } else {
    std::snprintf(text, sizeof text, "%s", method.name);
  }
  std::string label = text;
  if (method.stochastic && point.lights_per_point != 1) {
    std::snprintf(text, sizeof text, " k=%d", point.lights_per_point);
    label += text;
  }
  if (reference_pass0_seconds > 0.0 && point.seconds > 0.0) {
    std::snprintf(text, sizeof text, ", %.3gx", reference_pass0_seconds / point.seconds);
    label += text;
  }
  return label;
}

void draw_trade_plot(const TradePlot& plot, std::uint64_t current) {
  if (plot.points.empty()) {
    ImGui::TextDisabled("Compute the rt reference, then try tolerances:");
    ImGui::TextDisabled("each render adds a (pass-0 time, error) point, its error updated");
    ImGui::TextDisabled("over more passes as both renders go on.");
    return;
  }
  const TradeAxes axes = trade_axes(plot.points);

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
  const ImU32 grey = IM_COL32(200, 200, 200, 255);
  char text[64];
  std::snprintf(text, sizeof text, "%.2g%%", axes.max_error_pct);
  draw->AddText(ImVec2(origin.x, p0.y), grey, text);
  std::snprintf(text, sizeof text, "%.2g%%", axes.min_error_pct);
  draw->AddText(ImVec2(origin.x, p1.y - 12.0f), grey, text);
  std::snprintf(text, sizeof text, "%.3g s", axes.max_seconds);
  draw->AddText(ImVec2(p1.x - ImGui::CalcTextSize(text).x, p1.y + 2.0f), grey, text);
  std::snprintf(text, sizeof text, "%.3g s   pass-0 time (log) ->", axes.min_seconds);
  draw->AddText(ImVec2(p0.x, p1.y + 2.0f), grey, text);

  const TradePoint* nearest = nullptr;
  float nearest_d2 = 64.0f;
  std::vector<ImVec4> placed;  // the labels drawn: x0, y0, x1, y1
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  for (const TradePoint& p : plot.points) {
    const ImVec2 c(p0.x + static_cast<float>(trade_x(axes, p.seconds)) * (p1.x - p0.x),
                   p1.y - static_cast<float>(trade_y(axes, p.error_avg_pct)) * (p1.y - p0.y));
    const ImU32 colour = method_colour(p.method);
    const float radius = p.generation == current ? 5.0f : 3.5f;
    if (p.shared_cpu) {
      draw->AddCircle(c, radius, colour, 12, 1.5f);
    } else {
      draw->AddCircleFilled(c, radius, colour);
    }
    if (p.generation == current) draw->AddCircle(c, radius + 3.0f, IM_COL32(255, 255, 255, 200));
    const std::string label = trade_label(p, plot.reference_pass0_seconds);
    // Right of the point, or left of it near the right edge; moved up or down a line at a time
    // while it would cover a label already drawn (points close together, errors of 0).
    const ImVec2 label_size = ImGui::CalcTextSize(label.c_str());
    const float lx = c.x + 8.0f + label_size.x < p1.x ? c.x + 8.0f : c.x - 8.0f - label_size.x;
    float ly = c.y - 0.5f * label_size.y;
    for (int k = 1; k < 12 && overlaps(placed, lx, ly, label_size); ++k) {
      ly = c.y - 0.5f * label_size.y +
           static_cast<float>(k % 2 == 1 ? -(k + 1) / 2 : k / 2) * label_size.y;
    }
    placed.push_back(ImVec4(lx, ly, lx + label_size.x, ly + label_size.y));
    draw->AddText(ImVec2(lx, ly), IM_COL32(220, 220, 220, 220), label.c_str());
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
    if (plot.reference_pass0_seconds > 0.0 && nearest->seconds > 0.0)
      ImGui::Text("%.3gx faster than rt's pass 0 (%.3f s)",
                  plot.reference_pass0_seconds / nearest->seconds, plot.reference_pass0_seconds);
    ImGui::Text("error avg %.4f%%, max %.3f%% (over %d passes)", nearest->error_avg_pct,
                nearest->error_max_pct, nearest->passes);
    if (nearest->shared_cpu) ImGui::TextDisabled("measured while the reference rendered");
    ImGui::EndTooltip();
  }
  for (const lev::MethodInfo& m : lev::method_table()) {
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(method_colour(m.id)), "%s", m.name);
    ImGui::SameLine();
  }
  ImGui::TextDisabled(
      "  y: avg pixel error (log); labels: tolerance, speedup over rt; hollow: "
      "shared CPU");
}

}  // namespace app::viewer
