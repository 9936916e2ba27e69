#include "lev/light_split.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace lev {
namespace {

constexpr int kBins = 12;
// The coordinates an item is binned by: its centre (0..2) and its spot axis (3..5).
constexpr int kDimensions = 6;
constexpr float kInf = std::numeric_limits<float>::infinity();

float coordinate(const SplitItem& item, int dimension) {
  if (dimension >= 3) return item.axis[dimension - 3];
  // An item without lights has no box; it sits at the origin so no coordinate is NaN.
  if (is_empty(item.positions)) return 0.0f;
  return 0.5f * (item.positions.lo[dimension] + item.positions.hi[dimension]);
}

// What a part of the items gathers: enough to price it. It has no default member values and starts
// as kEmptyPart, so that a split sets only the bins it uses (most sets in a tree are small).
struct Part {
  Bounds positions;
  glm::vec3 axis_lo, axis_hi;  // the box around the spot axes
  float axis_spread_rad;       // the widest spread of one item's own axes
  float emission_rad;
  bool shines_everywhere;
  double energy;
  std::uint32_t count;

  void add(const SplitItem& item) {
    if (!is_empty(item.positions)) positions = merge(positions, item.positions);
    if (item.axis == glm::vec3(0.0f)) {
      shines_everywhere = true;
    } else {
      axis_lo = glm::min(axis_lo, item.axis);
      axis_hi = glm::max(axis_hi, item.axis);
      axis_spread_rad = std::max(axis_spread_rad, item.axis_spread_rad);
      emission_rad = std::max(emission_rad, item.emission_rad);
    }
    energy += item.energy;
    ++count;
  }
  void add(const Part& p) {
    positions = merge(positions, p.positions);
    axis_lo = glm::min(axis_lo, p.axis_lo);
    axis_hi = glm::max(axis_hi, p.axis_hi);
    axis_spread_rad = std::max(axis_spread_rad, p.axis_spread_rad);
    emission_rad = std::max(emission_rad, p.emission_rad);
    shines_everywhere = shines_everywhere || p.shines_everywhere;
    energy += p.energy;
    count += p.count;
  }
};

constexpr Part kEmptyPart{Bounds{}, glm::vec3(kInf), glm::vec3(-kInf), 0.0f, 0.0f, false, 0.0, 0};

// The angle every unit vector of the box [lo, hi] lies within around the direction of its centre:
// the widest angle to a corner (the cone over a box is spanned by its corners), pi when the box
// holds the zero vector (the axes may point every way).
double axis_box_spread_rad(const glm::vec3& lo, const glm::vec3& hi) {
  const glm::dvec3 dlo(lo), dhi(hi);
  if (glm::all(glm::lessThanEqual(dlo, glm::dvec3(0.0))) &&
      glm::all(glm::greaterThanEqual(dhi, glm::dvec3(0.0))))
    return M_PI;
  const glm::dvec3 centre = glm::normalize(0.5 * (dlo + dhi));
  double min_cos = 1.0;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p((corner & 1) ? dhi.x : dlo.x, (corner & 2) ? dhi.y : dlo.y,
                       (corner & 4) ? dhi.z : dlo.z);
    min_cos = std::min(min_cos, glm::dot(p, centre) / glm::length(p));
  }
  return std::acos(std::clamp(min_cos, -1.0, 1.0));
}

// A part's cost: energy x surface area x orientation measure. Box extents below `min_extent` count
// as it, so that lights on a line or at one point still price their parts by energy and direction.
double cost(const Part& part, float min_extent) {
  const glm::dvec3 e(glm::max(part.positions.hi - part.positions.lo, glm::vec3(min_extent)));
  const double area = e.x * e.y + e.y * e.z + e.z * e.x;
  double measure = 4.0 * M_PI;  // a light shining everywhere
  if (!part.shines_everywhere) {
    const double spread =
        std::min(M_PI, axis_box_spread_rad(part.axis_lo, part.axis_hi) + part.axis_spread_rad);
    measure = orientation_measure(spread, part.emission_rad);
  }
  return part.energy * area * measure;
}

int bin_of(float value, float lo, float bins_per_unit, int bin_count) {
  const int bin = static_cast<int>((value - lo) * bins_per_unit);
  return std::clamp(bin, 0, bin_count - 1);
}

std::size_t split_at_median(std::vector<SplitItem>& items, std::size_t begin, std::size_t end,
                            int dimension) {
  // (coordinate, id) is a total order, so the parts are the same whatever nth_element does; the
  // stable partition then keeps the input order within each.
  const auto before = [&](const SplitItem& a, const SplitItem& b) {
    const float ca = coordinate(a, dimension), cb = coordinate(b, dimension);
    return ca < cb || (ca == cb && a.id < b.id);
  };
  const auto first = items.begin() + static_cast<std::ptrdiff_t>(begin);
  const auto last = items.begin() + static_cast<std::ptrdiff_t>(end);
  std::vector<SplitItem> scratch(first, last);
  const auto middle = scratch.begin() + static_cast<std::ptrdiff_t>(scratch.size() / 2);
  std::nth_element(scratch.begin(), middle, scratch.end(), before);
  const SplitItem pivot = *middle;
  const auto split =
      std::stable_partition(first, last, [&](const SplitItem& i) { return before(i, pivot); });
  return static_cast<std::size_t>(split - items.begin());
}

}  // namespace

double orientation_measure(double axis_spread_rad, double emission_rad) {
  const double theta_o = axis_spread_rad;
  const double theta_w = std::min(axis_spread_rad + emission_rad, M_PI);
  const double sin_o = std::sin(theta_o), cos_o = std::cos(theta_o);
  return 2.0 * M_PI * (1.0 - cos_o) +
         0.5 * M_PI *
             (2.0 * theta_w * sin_o - std::cos(theta_o - 2.0 * theta_w) - 2.0 * theta_o * sin_o +
              cos_o);
}

SplitItem split_item(const Bounds& positions, const LightAggregate& lights, std::uint32_t id) {
  SplitItem item;
  item.id = id;
  item.positions = positions;
  item.energy = static_cast<double>(lights.intensity.x) + static_cast<double>(lights.intensity.y) +
                static_cast<double>(lights.intensity.z);
  if (shines_everywhere(lights)) return item;
  item.axis = lights.axis;
  item.axis_spread_rad = static_cast<float>(
      std::acos(std::clamp(static_cast<double>(lights.cos_axis_spread), -1.0, 1.0)));
  item.emission_rad = static_cast<float>(
      std::acos(std::clamp(static_cast<double>(lights.cos_emission), -1.0, 1.0)));
  return item;
}

std::size_t split_items(std::vector<SplitItem>& items, std::size_t begin, std::size_t end,
                        int depth, SplitAt at) {
  const auto first = items.begin() + static_cast<std::ptrdiff_t>(begin);
  const auto last = items.begin() + static_cast<std::ptrdiff_t>(end);
  std::array<float, kDimensions> lo, hi;
  lo.fill(kInf);
  hi.fill(-kInf);
  const std::size_t count = end - begin;
  // Two items part one way only.
  if (count == 2) return begin + 1;
  Part whole = kEmptyPart;
  for (auto it = first; it != last; ++it) {
    for (int d = 0; d < kDimensions; ++d) {
      const float c = coordinate(*it, d);
      lo[d] = std::min(lo[d], c);
      hi[d] = std::max(hi[d], c);
    }
    whole.add(*it);
  }
  int widest_space = 0;
  for (int d = 1; d < 3; ++d)
    if (hi[d] - lo[d] > hi[widest_space] - lo[widest_space]) widest_space = d;
  const float widest_extent = hi[widest_space] - lo[widest_space];
  if (depth >= kMaxHeuristicSplitDepth || !(whole.energy > 0.0))
    return split_at_median(items, begin, end, widest_space);

  const glm::vec3 box_extent =
      is_empty(whole.positions) ? glm::vec3(0.0f) : whole.positions.hi - whole.positions.lo;
  const float largest_box_extent = std::max(std::max(box_extent.x, box_extent.y), box_extent.z);
  const float min_extent = largest_box_extent > 0.0f ? 1e-3f * largest_box_extent : 1.0f;

  // Fewer items than bins: as many bins as items, so that small sets (most of a tree's nodes)
  // cost little to price.
  const int bin_count = static_cast<int>(std::min<std::size_t>(kBins, count));
  std::array<float, kDimensions> bins_per_unit;
  Part bins[kDimensions][kBins];
  for (int d = 0; d < kDimensions; ++d) {
    const float extent = hi[d] - lo[d];
    // A dimension the items agree in (or an overflowing one) parts nothing.
    bins_per_unit[d] =
        extent > 0.0f && std::isfinite(extent) ? static_cast<float>(bin_count) / extent : 0.0f;
    std::fill(bins[d], bins[d] + bin_count, kEmptyPart);
  }
  for (auto it = first; it != last; ++it) {
    for (int d = 0; d < kDimensions; ++d) {
      if (bins_per_unit[d] > 0.0f)
        bins[d][bin_of(coordinate(*it, d), lo[d], bins_per_unit[d], bin_count)].add(*it);
    }
  }

  double best_cost = std::numeric_limits<double>::infinity();
  int best_dimension = -1, best_boundary = 0;
  for (int d = 0; d < kDimensions; ++d) {
    if (!(bins_per_unit[d] > 0.0f)) continue;
    // Thin slabs make poor clusters: a split across a short axis of space costs more
    // (Conty Estevez and Kulla's regularisation).
    const double thinness =
        d < 3 ? static_cast<double>(widest_extent) / static_cast<double>(hi[d] - lo[d]) : 1.0;
    // The parts right of each boundary, priced only where a boundary parts anything new: after a
    // non-empty bin with a non-empty bin to come.
    std::array<double, kBins> right_cost{};
    Part right = kEmptyPart;
    for (int b = bin_count - 1; b > 0; --b) {
      right.add(bins[d][b]);
      if (right.count > 0 && bins[d][b - 1].count > 0) right_cost[b] = cost(right, min_extent);
    }
    Part left = kEmptyPart;
    for (int b = 1; b < bin_count; ++b) {
      left.add(bins[d][b - 1]);
      if (bins[d][b - 1].count == 0 || left.count == whole.count) continue;
      const double c = (cost(left, min_extent) + right_cost[b]) * thinness;
      if (c < best_cost) {
        best_cost = c;
        best_dimension = d;
        best_boundary = b;
      }
    }
  }
  // Items that agree in position and axis: the middle of their order.
  if (best_dimension < 0) return begin + (end - begin) / 2;
  if (at == SplitAt::median)
    return split_at_median(items, begin, end, best_dimension >= 3 ? best_dimension : widest_space);
  const auto split = std::stable_partition(first, last, [&](const SplitItem& item) {
    return bin_of(coordinate(item, best_dimension), lo[best_dimension],
                  bins_per_unit[best_dimension], bin_count) < best_boundary;
  });
  return static_cast<std::size_t>(split - items.begin());
}

}  // namespace lev
