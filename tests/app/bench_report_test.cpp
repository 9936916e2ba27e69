// The benchmark report's building blocks: tables (CSV quoting, markdown alignment, number
// formats) and line charts (every case draws a full image, series in their own colours).
#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "app/bench/plot.h"
#include "app/bench/table.h"

namespace {

using app::bench::Chart;
using app::bench::Series;

TEST(BenchTable, CsvKeepsFullPrecisionAndQuotes) {
  app::bench::Table t;
  t.columns = {{"scene", "scene"}, {"lights", "lights"}, {"seconds", "time (s)"}};
  t.rows.push_back({app::bench::text_cell("a, \"b\""), app::bench::count_cell(16384),
                    app::bench::number_cell(0.123456789, 2)});
  t.rows.push_back({app::bench::text_cell("c"), app::bench::count_cell(1),
                    app::bench::number_cell(std::numeric_limits<double>::quiet_NaN(), 2)});
  EXPECT_EQ(app::bench::table_csv(t),
            "scene,lights,seconds\n\"a, \"\"b\"\"\",16384,0.123457\nc,1,\n");
  const std::string md = app::bench::table_markdown(t);
  EXPECT_NE(md.find("| scene | lights | time (s) |\n|---|---:|---:|\n"), std::string::npos) << md;
  EXPECT_NE(md.find("| 16,384 | 0.12 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| n/a |"), std::string::npos) << md;
}

TEST(BenchTable, Formats) {
  EXPECT_EQ(app::bench::format_count(1048576), "1,048,576");
  EXPECT_EQ(app::bench::format_count(64), "64");
  EXPECT_EQ(app::bench::format_ratio(131.9), "132x");
  EXPECT_EQ(app::bench::format_ratio(43.16), "43.2x");
  EXPECT_EQ(app::bench::format_ratio(2.134), "2.13x");
  EXPECT_EQ(app::bench::format_bytes(6452), "6.3 KB");
  EXPECT_EQ(app::bench::format_bytes(100), "100 B");
}

int coloured_pixels(const std::vector<std::uint8_t>& rgb) {
  int n = 0;
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
    const int r = rgb[i], g = rgb[i + 1], b = rgb[i + 2];
    if (std::max({r, g, b}) - std::min({r, g, b}) > 60)
      ++n;  // saturated: a series, not text or grid
  }
  return n;
}

TEST(BenchChart, DrawsLogAndLinearChartsAndTheEmptyCase) {
  Chart log_chart;
  log_chart.title = "time";
  log_chart.x_label = "lights";
  log_chart.y_label = "seconds";
  log_chart.log_x = log_chart.log_y = true;
  log_chart.series.push_back({"rt", {64, 256, 1024}, {1.0, 4.0, 16.0}});
  log_chart.series.push_back({"lev", {64, 256, 1024}, {0.5, 0.6, 0.7}});
  log_chart.series.push_back({"reference", {0.0}, {2.0}, true});
  // Points a log axis cannot place are skipped, not drawn at infinity.
  log_chart.series.push_back({"skipped", {0.0, -1.0, std::nan("")}, {1.0, 1.0, 1.0}});
  const std::vector<std::uint8_t> a = app::bench::render_chart(log_chart, 640, 400);
  ASSERT_EQ(a.size(), 640u * 400u * 3u);
  EXPECT_GT(coloured_pixels(a), 500);

  Chart linear = log_chart;
  linear.log_x = linear.log_y = false;
  EXPECT_GT(coloured_pixels(app::bench::render_chart(linear, 640, 400)), 500);

  Chart empty;
  empty.title = "nothing";
  const std::vector<std::uint8_t> e = app::bench::render_chart(empty, 320, 200);
  ASSERT_EQ(e.size(), 320u * 200u * 3u);
  EXPECT_EQ(coloured_pixels(e), 0);
  EXPECT_TRUE(std::any_of(e.begin(), e.end(), [](std::uint8_t v) { return v < 128; }))
      << "frame and text";
}

// A long x label (the targets chart's scene key) is broken into lines that stay inside the
// image: no text at its left and right edges, and the words all drawn (the label band is dark
// in several rows of text). One line, centred under the plot, ran off both edges.
TEST(BenchChart, ALongXLabelIsWrappedInsideTheImage) {
  Chart chart;
  chart.title = "speedup";
  chart.y_label = "speedup";
  chart.x_label = "scene: ";
  for (int i = 1; i <= 12; ++i)
    chart.x_label += std::to_string(i) + " a scene name " + std::to_string(1000 * i) + ", ";
  chart.series.push_back({"a method with a long name", {1, 2, 3}, {1.0, 4.0, 16.0}});
  const int width = 960, height = 600;
  const std::vector<std::uint8_t> rgb = app::bench::render_chart(chart, width, height);
  const auto dark = [&](int x, int y) {
    const std::uint8_t* p = &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
    return std::max({p[0], p[1], p[2]}) < 100;
  };
  int rows_with_text = 0;
  for (int y = height - 140; y < height; ++y) {
    for (int x : {0, 1, 2, 3, width - 4, width - 3, width - 2, width - 1})
      ASSERT_FALSE(dark(x, y)) << "text at the edge, x " << x << " y " << y;
    bool any = false;
    for (int x = 0; x < width && !any; ++x) any = dark(x, y);
    rows_with_text += any ? 1 : 0;
  }
  EXPECT_GT(rows_with_text, 40);  // several lines of 2x text, not one
}

}  // namespace
