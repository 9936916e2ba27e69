// Where a light hierarchy built top down splits a set of lights (or of subtrees holding lights)
// in two: the lightcuts tree (light_cut_tree.h) and the automatic hierarchy (light_bvh.h) share
// it. Splitting by position alone puts spots aimed different ways into one cluster, whose cone of
// axes then bounds nothing; so the split weighs where the lights shine as well as where they are,
// after the surface-area-orientation heuristic of Conty Estevez and Kulla 2018 ("Importance
// sampling of many lights with adaptive tree splitting"): a part costs
//
//   energy * surface area of its box of positions * M(theta_o, theta_e)
//
// where M is the solid-angle measure of the directions its lights can shine into (theta_o the
// spread of the spot axes, theta_e the widest cone about an axis; 4 pi for a point light). The
// items are binned by their centre along each axis of space and by their spot axis along each
// axis of direction (so spots at one place aimed opposite ways still part), and the cheapest
// boundary of the twelve bins of the six is taken. Deterministic: it depends on the items and
// their order only, and keeps that order within each part.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "lev/bounds.h"
#include "lev/light_bounds.h"

namespace lev {

// What the split knows of one item.
struct SplitItem {
  Bounds positions;           // around its light positions
  glm::vec3 axis{0.0f};       // the unit axis of its spots' cone; zero if a light shines everywhere
  float axis_spread_rad = 0;  // the angle its spot axes lie within around `axis`
  float emission_rad = 0;     // the widest a light shines from its own axis
  double energy = 0.0;        // summed channels of the intensity
  std::uint32_t id = 0;       // the caller's name for the item (its index in the caller's list)
};

// The item `id` for lights at `positions` with the aggregate `lights` (in the frame the split works
// in). The box is taken apart from the aggregate, whose box is padded: a light's exact position
// keeps lights placed by different transforms to the same point in the same bins.
SplitItem split_item(const Bounds& positions, const LightAggregate& lights, std::uint32_t id);

// Below this depth the heuristic splits; from it on, the median of the widest axis of the item
// centres, so that no input can make a tree deeper than this plus log2 of its size.
inline constexpr int kMaxHeuristicSplitDepth = 40;

// Where a set splits once its cheapest dimension is known: at the cheapest boundary of that
// dimension's bins (parts of any sizes: the lightcuts tree), or at the median of the items (halves:
// the automatic hierarchy, whose walk tests each level's extent volumes, so that a lopsided tree
// costs it more tests) along that dimension when it is an axis of direction, else along the
// widest axis of space (measured: the cheapest axis of space made LEV's walk on the car park
// visit 4-10 % more nodes than the widest).
enum class SplitAt : std::uint8_t { cheapest_boundary, median };

// Reorders items[begin, end) (at least two) into two non-empty parts and returns where the second
// begins: as `at` says, or the median of the widest axis of the centres at `depth`
// kMaxHeuristicSplitDepth and beyond (and for items that agree in position and axis, the middle).
// The items themselves move, not indices to them, so that a million are read in sequence.
std::size_t split_items(std::vector<SplitItem>& items, std::size_t begin, std::size_t end,
                        int depth, SplitAt at);

// The heuristic's measure of the directions a part shines into (Conty Estevez and Kulla 2018,
// eq. 1): axes within axis_spread_rad of one axis, each shining up to emission_rad from it.
double orientation_measure(double axis_spread_rad, double emission_rad);

}  // namespace lev
