// The speed/accuracy trade of one view: a (time, error) point for every method and setting of it
// (tolerance, relative error, lights per point, rt fallback) the user has tried on the rt
// reference of this view. Time is pass 0's render time and error the
// average pixel error against the reference over the same passes, updated as both render more
// (the point records how many). Points measured while the reference was still rendering shared
// its cores and are drawn hollow.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lev/methods.h"

namespace app::viewer {

struct TradePoint {
  lev::Method method = lev::Method::lev;
  double tolerance = 0.0;
  double seconds = 0.0;
  double error_avg_pct = 0.0;
  double error_max_pct = 0.0;
  bool shared_cpu = false;
  int passes = 0;                // the error's: the means over this many passes of both
  std::uint64_t generation = 0;  // the render it was measured on
  // The method's other settings (those it does not read are ignored, lev::used_settings).
  double relative_error = lev::kDefaultRelativeError;
  int lights_per_point = 1;
  bool rt_fallback = true;
};

struct TradePlot {
  std::uint64_t reference_generation = 0;  // the view the points belong to
  std::vector<TradePoint> points;
  double reference_pass0_seconds = 0.0;  // rt's pass 0 (0: not known yet): the speedups' base
};

// Both axes are logarithmic, so small tolerances (fast, tiny errors) spread out instead of
// crowding a corner: a decade of time or error is the same length anywhere. An error of 0 (the
// image equals rt) sits on the floor, a decade below the smallest error above 0.
struct TradeAxes {
  double min_seconds = 0.0, max_seconds = 0.0;
  double min_error_pct = 0.0, max_error_pct = 0.0;  // the floor and the top
};
TradeAxes trade_axes(const std::vector<TradePoint>& points);
// A point's position in [0, 1] on each axis (0: left, bottom).
double trade_x(const TradeAxes& axes, double seconds);
double trade_y(const TradeAxes& axes, double error_pct);
// The label drawn beside a point: its tolerance, else its relative error, else its method's name
// (with the lights per point of a sampling method above 1: "0.01 k=4"), and its speedup over rt's
// pass 0 when that is known ("0.01, 12x").
std::string trade_label(const TradePoint& point, double reference_pass0_seconds);

// Forgets the points when the reference (the view) changed.
void follow_reference(TradePlot& plot, std::uint64_t reference_generation);

// Adds a point, replacing an earlier one with the same method and settings that it reads.
void add_trade_point(TradePlot& plot, const TradePoint& point);

// The passes of the point measured on `generation`; 0 when there is none.
int trade_point_passes(const TradePlot& plot, std::uint64_t generation);

// Draws the plot (Dear ImGui) in the current window; `current` is the shown render's generation.
void draw_trade_plot(const TradePlot& plot, std::uint64_t current);

}  // namespace app::viewer
