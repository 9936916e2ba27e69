#include "app/bench/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include <stb/stb_easy_font.h>

#include "app/output_files.h"

namespace app::bench {
namespace {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

// Tableau 10: distinct at a glance and readable on white.
constexpr Rgb kPalette[] = {{31, 119, 180},  {255, 127, 14}, {44, 160, 44},   {214, 39, 40},
                            {148, 103, 189}, {140, 86, 75},  {227, 119, 194}, {127, 127, 127},
                            {188, 189, 34},  {23, 190, 207}};
constexpr int kPaletteSize = static_cast<int>(sizeof(kPalette) / sizeof(kPalette[0]));
constexpr Rgb kBlack{0, 0, 0};
constexpr Rgb kGrid{225, 225, 225};
constexpr Rgb kMinorGrid{242, 242, 242};
constexpr Rgb kFrame{90, 90, 90};

enum class Shape { circle, square, diamond, triangle };
constexpr Shape kShapes[] = {Shape::circle, Shape::square, Shape::diamond, Shape::triangle};

enum class Align { left, centre, right };

// An RGB image plus a coverage mask, so that a polyline (or marker set) is blended once even
// where its anti-aliased segments overlap at the joints.
class Canvas {
 public:
  Canvas(int width, int height)
      : w_(width),
        h_(height),
        rgb_(static_cast<std::size_t>(width) * height * 3, 255),
        mask_(static_cast<std::size_t>(width) * height, 0.0f) {}

  int width() const { return w_; }
  int height() const { return h_; }
  std::vector<std::uint8_t> take_pixels() { return std::move(rgb_); }

  void fill_rect(int x0, int y0, int x1, int y1, Rgb c) {
    for (int y = std::max(0, y0); y < std::min(h_, y1); ++y) {
      for (int x = std::max(0, x0); x < std::min(w_, x1); ++x) put(x, y, c, 1.0f);
    }
  }

  // Adds an anti-aliased segment of the given width to the mask; dash > 0 draws dashes of that
  // length (and gaps of the same length), phase measured along the whole line.
  void mask_segment(float x0, float y0, float x1, float y1, float width, float dash = 0.0f) {
    const float hw = 0.5f * width;
    const float dx = x1 - x0, dy = y1 - y0;
    const float len2 = dx * dx + dy * dy;
    const float len = std::sqrt(len2);
    const int bx0 = static_cast<int>(std::floor(std::min(x0, x1) - hw - 1.0f));
    const int bx1 = static_cast<int>(std::ceil(std::max(x0, x1) + hw + 1.0f));
    const int by0 = static_cast<int>(std::floor(std::min(y0, y1) - hw - 1.0f));
    const int by1 = static_cast<int>(std::ceil(std::max(y0, y1) + hw + 1.0f));
    for (int y = std::max(0, by0); y <= std::min(h_ - 1, by1); ++y) {
      for (int x = std::max(0, bx0); x <= std::min(w_ - 1, bx1); ++x) {
        const float px = static_cast<float>(x) + 0.5f, py = static_cast<float>(y) + 0.5f;
        float t = len2 > 0.0f ? ((px - x0) * dx + (py - y0) * dy) / len2 : 0.0f;
        t = std::clamp(t, 0.0f, 1.0f);
        if (dash > 0.0f && std::fmod(t * len, 2.0f * dash) > dash) continue;
        const float ex = x0 + t * dx - px, ey = y0 + t * dy - py;
        cover(x, y, hw + 0.5f - std::sqrt(ex * ex + ey * ey));
      }
    }
  }

  void mask_marker(float cx, float cy, Shape shape, float r) {
    for (int y = static_cast<int>(cy - r - 2.0f); y <= static_cast<int>(cy + r + 2.0f); ++y) {
      for (int x = static_cast<int>(cx - r - 2.0f); x <= static_cast<int>(cx + r + 2.0f); ++x) {
        if (x < 0 || y < 0 || x >= w_ || y >= h_) continue;
        const float dx = static_cast<float>(x) + 0.5f - cx, dy = static_cast<float>(y) + 0.5f - cy;
        float d = 0.0f;  // signed distance to the shape's edge, negative inside
        switch (shape) {
          case Shape::circle:
            d = std::sqrt(dx * dx + dy * dy) - r;
            break;
          case Shape::square:
            d = std::max(std::abs(dx), std::abs(dy)) - 0.85f * r;
            break;
          case Shape::diamond:
            d = (std::abs(dx) + std::abs(dy) - 1.2f * r) * 0.7071f;
            break;
          case Shape::triangle: {
            // Upward triangle: the three edge half-planes.
            const float k = 0.8660f;
            d = std::max(
                {dy - 0.6f * r, -k * dx - 0.5f * dy - 0.6f * r, k * dx - 0.5f * dy - 0.6f * r});
            break;
          }
        }
        cover(x, y, 0.5f - d);
      }
    }
  }

  // Blends the mask in colour c and clears it.
  void flush_mask(Rgb c) {
    for (int y = mask_y0_; y <= mask_y1_; ++y) {
      for (int x = mask_x0_; x <= mask_x1_; ++x) {
        float& m = mask_[static_cast<std::size_t>(y) * w_ + x];
        if (m > 0.0f) put(x, y, c, m);
        m = 0.0f;
      }
    }
    mask_x0_ = w_;
    mask_y0_ = h_;
    mask_x1_ = mask_y1_ = -1;
  }

  void line(float x0, float y0, float x1, float y1, float width, Rgb c, float dash = 0.0f) {
    mask_segment(x0, y0, x1, y1, width, dash);
    flush_mask(c);
  }

  // stb_easy_font text at an integer scale; (x, y) is the top of the line, aligned as asked.
  // vertical: turned 90 degrees counter-clockwise, (x, y) then the centre of its left edge.
  void text(float x, float y, const std::string& s, int scale, Rgb c, Align align,
            bool vertical = false) {
    std::string buffer = s;
    const float w = static_cast<float>(text_width(s) * scale);
    float ox = x;
    if (align == Align::centre) ox -= 0.5f * w;
    if (align == Align::right) ox -= w;
    std::vector<char> vertices(buffer.size() * 1200 +
                               256);  // stb: about 270 bytes a glyph on average
    const int quads = stb_easy_font_print(0.0f, 0.0f, buffer.data(), nullptr, vertices.data(),
                                          static_cast<int>(vertices.size()));
    for (int q = 0; q < quads; ++q) {
      float corner[2][2];
      for (int v = 0; v < 2; ++v) {  // vertices 0 and 2 are opposite corners; 16 bytes each
        std::memcpy(corner[v], vertices.data() + (4 * q + 2 * v) * 16, 2 * sizeof(float));
      }
      const float qx0 = corner[0][0] * scale, qy0 = corner[0][1] * scale;
      const float qx1 = corner[1][0] * scale, qy1 = corner[1][1] * scale;
      if (!vertical) {
        fill_rect(static_cast<int>(std::lround(ox + qx0)), static_cast<int>(std::lround(y + qy0)),
                  static_cast<int>(std::lround(ox + qx1)), static_cast<int>(std::lround(y + qy1)),
                  c);
      } else {
        // Text runs upwards: its x becomes -y, its y becomes x.
        const float base_y = y + 0.5f * w;
        fill_rect(
            static_cast<int>(std::lround(x + qy0)), static_cast<int>(std::lround(base_y - qx1)),
            static_cast<int>(std::lround(x + qy1)), static_cast<int>(std::lround(base_y - qx0)), c);
      }
    }
  }

  static int text_width(const std::string& s) {
    std::string buffer = s;
    return stb_easy_font_width(buffer.data());
  }

 private:
  void put(int x, int y, Rgb c, float alpha) {
    std::uint8_t* p = &rgb_[(static_cast<std::size_t>(y) * w_ + x) * 3];
    const float a = std::clamp(alpha, 0.0f, 1.0f);
    p[0] = static_cast<std::uint8_t>(std::lround(a * c.r + (1.0f - a) * p[0]));
    p[1] = static_cast<std::uint8_t>(std::lround(a * c.g + (1.0f - a) * p[1]));
    p[2] = static_cast<std::uint8_t>(std::lround(a * c.b + (1.0f - a) * p[2]));
  }

  void cover(int x, int y, float coverage) {
    if (coverage <= 0.0f) return;
    float& m = mask_[static_cast<std::size_t>(y) * w_ + x];
    m = std::max(m, std::min(coverage, 1.0f));
    mask_x0_ = std::min(mask_x0_, x);
    mask_y0_ = std::min(mask_y0_, y);
    mask_x1_ = std::max(mask_x1_, x);
    mask_y1_ = std::max(mask_y1_, y);
  }

  int w_, h_;
  std::vector<std::uint8_t> rgb_;
  std::vector<float> mask_;
  int mask_x0_ = std::numeric_limits<int>::max(), mask_y0_ = std::numeric_limits<int>::max();
  int mask_x1_ = -1, mask_y1_ = -1;
};

// One axis: data range, scale and ticks.
struct Axis {
  bool log = false;
  double lo = 0.0, hi = 1.0;
  std::vector<double> ticks;        // labelled
  std::vector<double> minor_ticks;  // grid only
};

bool placeable(const Axis& axis, double v) {
  return std::isfinite(v) && (!axis.log || v > 0.0);
}

double unit(const Axis& a, double v) {
  if (a.log) return (std::log10(v) - std::log10(a.lo)) / (std::log10(a.hi) - std::log10(a.lo));
  return (v - a.lo) / (a.hi - a.lo);
}

double nice_step(double raw) {
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0}) {
    if (m * p >= raw) return m * p;
  }
  return 10.0 * p;
}

Axis make_axis(bool log, double lo, double hi) {
  Axis a;
  a.log = log;
  if (!(lo <= hi)) {  // no data
    lo = log ? 1.0 : 0.0;
    hi = log ? 10.0 : 1.0;
  }
  if (log) {
    // The range snaps outwards to 1, 2 or 5 times a power of ten, so the data fills the plot.
    auto snap_down = [](double v) {
      const double p = std::pow(10.0, std::floor(std::log10(v) + 1e-9));
      for (double m : {5.0, 2.0, 1.0}) {
        if (m * p <= v * (1.0 + 1e-9)) return m * p;
      }
      return p;
    };
    auto snap_up = [](double v) {
      const double p = std::pow(10.0, std::floor(std::log10(v) - 1e-9));
      for (double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * p >= v * (1.0 - 1e-9)) return m * p;
      }
      return 10.0 * p;
    };
    a.lo = snap_down(lo);
    a.hi = snap_up(hi);
    if (a.hi <= a.lo) {
      a.lo /= 10.0;
      a.hi *= 10.0;
    }
    const bool few_decades = a.hi / a.lo <= 1000.0;
    for (double d = std::floor(std::log10(a.lo)) - 1.0; d <= std::ceil(std::log10(a.hi)) + 1e-9;
         d += 1.0) {
      const double p = std::pow(10.0, d);
      for (int m = 1; m <= 9; ++m) {
        const double t = m * p;
        if (t < a.lo * (1.0 - 1e-9) || t > a.hi * (1.0 + 1e-9)) continue;
        if (m == 1 || (few_decades && (m == 2 || m == 5))) {
          a.ticks.push_back(t);
        } else {
          a.minor_ticks.push_back(t);
        }
      }
    }
    return a;
  }
  if (lo >= 0.0 && lo < 0.3 * hi) lo = 0.0;  // counts and times read best from zero
  if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) {
    const double pad = std::max(std::abs(hi) * 0.1, 1e-9);
    lo -= pad;
    hi += pad;
  }
  const double step = nice_step((hi - lo) / 6.0);
  a.lo = std::floor(lo / step + 1e-9) * step;
  a.hi = std::ceil(hi / step - 1e-9) * step;
  for (double t = a.lo; t <= a.hi + 0.5 * step; t += step)
    a.ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  return a;
}

std::string tick_label(double v) {
  char buffer[32];
  const double a = std::abs(v);
  if (a >= 1e6 && std::fmod(a, 1e5) == 0.0) {
    std::snprintf(buffer, sizeof buffer, "%gM", v / 1e6);
  } else if (a >= 1e3 && std::fmod(a, 100.0) == 0.0) {
    std::snprintf(buffer, sizeof buffer, "%gk", v / 1e3);
  } else {
    std::snprintf(buffer, sizeof buffer, "%g", v);
  }
  return buffer;
}

// `text` in lines no wider than max_width (stb_easy_font units), broken at spaces; a word wider
// than that stands on a line of its own.
std::vector<std::string> wrap_text(const std::string& text, int max_width) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && Canvas::text_width(longer) > max_width) {
      lines.push_back(line);
      line = word;
    } else {
      line = longer;
    }
    start = end + 1;
  }
  if (!line.empty() || lines.empty()) lines.push_back(line);
  return lines;
}

}  // namespace

std::vector<std::uint8_t> render_chart(const Chart& chart, int width, int height) {
  Canvas canvas(width, height);
  constexpr int kTextScale = 2;
  constexpr int kLineHeight = 10 * kTextScale;

  // Data ranges over every placeable point.
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
  double y_lo = x_lo, y_hi = -x_lo;
  Axis probe_x, probe_y;
  probe_x.log = chart.log_x;
  probe_y.log = chart.log_y;
  bool any_point = false;
  for (const Series& s : chart.series) {
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!placeable(probe_y, s.y[i])) continue;
      y_lo = std::min(y_lo, s.y[i]);
      y_hi = std::max(y_hi, s.y[i]);
      if (s.horizontal_line) continue;  // spans whatever x range the others have
      if (!placeable(probe_x, s.x[i])) continue;
      x_lo = std::min(x_lo, s.x[i]);
      x_hi = std::max(x_hi, s.x[i]);
      any_point = true;
    }
  }
  const Axis ax = make_axis(chart.log_x, x_lo, x_hi);
  const Axis ay = make_axis(chart.log_y, y_lo, y_hi);

  // Layout: legend on the right, outside the plot.
  int legend_width = 0;
  for (const Series& s : chart.series)
    legend_width = std::max(legend_width, Canvas::text_width(s.label) * kTextScale);
  legend_width += 60;
  // Room on the left for the widest y tick label and the turned axis label beside it.
  int y_label_width = 0;
  for (double t : ay.ticks)
    y_label_width = std::max(y_label_width, Canvas::text_width(tick_label(t)) * kTextScale);
  const int left = 56 + y_label_width, top = 56;
  const int right = std::min(width / 2, legend_width + 24);
  const int px0 = left, px1 = width - right;
  // The x label, centred under the plot, in as many lines as fit inside the image there (a
  // targets chart's scene key runs long); each extra line takes room from the plot.
  constexpr int kLabelLineStep = kLineHeight + 4;
  const float label_centre = 0.5f * static_cast<float>(px0 + px1);
  const int label_room = std::min(px0 + px1, 2 * width - px0 - px1) - 20;  // 2 x the nearer edge
  const std::vector<std::string> x_label_lines =
      wrap_text(chart.x_label + (ax.log ? " (log scale)" : ""), label_room / kTextScale);
  const int extra_label_lines = static_cast<int>(x_label_lines.size()) - 1;
  const int bottom = 72 + extra_label_lines * kLabelLineStep;
  const int py0 = top, py1 = height - bottom;
  auto to_px = [&](double x) { return static_cast<float>(px0 + unit(ax, x) * (px1 - px0)); };
  auto to_py = [&](double y) { return static_cast<float>(py1 - unit(ay, y) * (py1 - py0)); };

  // Grid, ticks and their labels.
  for (double t : ax.minor_ticks) canvas.line(to_px(t), py0, to_px(t), py1, 1.0f, kMinorGrid);
  for (double t : ay.minor_ticks) canvas.line(px0, to_py(t), px1, to_py(t), 1.0f, kMinorGrid);
  for (double t : ax.ticks) {
    canvas.line(to_px(t), py0, to_px(t), py1, 1.0f, kGrid);
    canvas.line(to_px(t), py1, to_px(t), py1 + 6, 1.5f, kFrame);
    canvas.text(to_px(t), py1 + 10, tick_label(t), kTextScale, kBlack, Align::centre);
  }
  for (double t : ay.ticks) {
    canvas.line(px0, to_py(t), px1, to_py(t), 1.0f, kGrid);
    canvas.line(px0 - 6, to_py(t), px0, to_py(t), 1.5f, kFrame);
    canvas.text(px0 - 10, to_py(t) - 0.35f * kLineHeight, tick_label(t), kTextScale, kBlack,
                Align::right);
  }
  canvas.line(px0, py0, px1, py0, 1.5f, kFrame);
  canvas.line(px0, py1, px1, py1, 1.5f, kFrame);
  canvas.line(px0, py0, px0, py1, 1.5f, kFrame);
  canvas.line(px1, py0, px1, py1, 1.5f, kFrame);

  // Series: polyline, then markers, each blended once.
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const Series& s = chart.series[k];
    const Rgb colour = kPalette[k % kPaletteSize];
    const Shape shape = kShapes[k % 4];
    if (s.horizontal_line) {
      if (!s.y.empty() && placeable(ay, s.y[0]))
        canvas.line(px0, to_py(s.y[0]), px1, to_py(s.y[0]), 2.0f, colour, 8.0f);
      continue;
    }
    std::vector<std::pair<float, float>> points;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (placeable(ax, s.x[i]) && placeable(ay, s.y[i]))
        points.emplace_back(to_px(s.x[i]), to_py(s.y[i]));
    }
    for (std::size_t i = 1; i < points.size(); ++i) {
      canvas.mask_segment(points[i - 1].first, points[i - 1].second, points[i].first,
                          points[i].second, 2.5f);
    }
    canvas.flush_mask(colour);
    for (const auto& [x, y] : points) canvas.mask_marker(x, y, shape, 5.0f);
    canvas.flush_mask(colour);
  }
  if (!any_point) {
    canvas.text(0.5f * (px0 + px1), 0.5f * (py0 + py1), "no data", kTextScale, kFrame,
                Align::centre);
  }

  // Legend.
  const int lx = px1 + 20;
  int ly = py0;
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const Series& s = chart.series[k];
    const Rgb colour = kPalette[k % kPaletteSize];
    const float cy = static_cast<float>(ly) + 0.4f * kLineHeight;
    canvas.line(lx, cy, lx + 32, cy, 2.5f, colour, s.horizontal_line ? 6.0f : 0.0f);
    if (!s.horizontal_line) {
      canvas.mask_marker(lx + 16, cy, kShapes[k % 4], 5.0f);
      canvas.flush_mask(colour);
    }
    canvas.text(lx + 40, ly, s.label, kTextScale, kBlack, Align::left);
    ly += kLineHeight + 8;
  }

  // Title and axis labels.
  canvas.text(0.5f * (px0 + px1), 16, chart.title, kTextScale, kBlack, Align::centre);
  for (std::size_t i = 0; i < x_label_lines.size(); ++i) {
    const int below = extra_label_lines - static_cast<int>(i);
    canvas.text(label_centre, static_cast<float>(height - 34 - below * kLabelLineStep),
                x_label_lines[i], kTextScale, kBlack, Align::centre);
  }
  canvas.text(14, 0.5f * (py0 + py1), chart.y_label + (ay.log ? " (log scale)" : ""), kTextScale,
              kBlack, Align::centre, true);
  return canvas.take_pixels();
}

void write_chart_png(const std::string& path, const Chart& chart) {
  app::write_png_rgb8(path, kChartWidth, kChartHeight,
                      render_chart(chart, kChartWidth, kChartHeight));
}

}  // namespace app::bench
