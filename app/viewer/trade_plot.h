// The speed/accuracy trade of one view: a (time, error) point for every method and tolerance the
// user has tried on the rt reference of this view. Time is pass 0's render time and error the
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
};

struct TradePlot {
  std::uint64_t reference_generation = 0;  // the view the points belong to
  std::vector<TradePoint> points;
};

// Forgets the points when the reference (the view) changed.
void follow_reference(TradePlot& plot, std::uint64_t reference_generation);

// Adds a point, replacing an earlier one with the same method and tolerance.
void add_trade_point(TradePlot& plot, const TradePoint& point);

// The passes of the point measured on `generation`; 0 when there is none.
int trade_point_passes(const TradePlot& plot, std::uint64_t generation);

// Draws the plot (Dear ImGui) in the current window; `current` is the shown render's generation.
void draw_trade_plot(const TradePlot& plot, std::uint64_t current);

}  // namespace app::viewer
