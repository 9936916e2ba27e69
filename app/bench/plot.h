// Line charts for the benchmark report, drawn by levrt itself into PNGs: linear or logarithmic
// axes with labelled ticks, one anti-aliased polyline with markers per series, an optional
// dashed reference line per series, and a legend. Text comes from stb_easy_font's quads, so no
// font file or plotting tool is needed at run time.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace app::bench {

struct Series {
  std::string label;
  std::vector<double> x, y;      // same length; points that cannot be placed on an axis are skipped
  bool horizontal_line = false;  // draw y[0] as a dashed line across the plot (a reference level)
};

struct Chart {
  std::string title;
  std::string x_label;
  std::string y_label;
  bool log_x = false;
  bool log_y = false;
  std::vector<Series> series;
};

inline constexpr int kChartWidth = 960;
inline constexpr int kChartHeight = 600;

// 8-bit RGB, row-major, width * height * 3 bytes. A chart without plottable points still gets
// its frame, title and a "no data" note.
std::vector<std::uint8_t> render_chart(const Chart& chart, int width, int height);

// Renders at kChartWidth x kChartHeight and writes the PNG (atomically, via app/output_files).
void write_chart_png(const std::string& path, const Chart& chart);

}  // namespace app::bench
