// The automatic hierarchy for a structure without boxes to cull with: a flat list of lights (a
// scene file without structure, an import), or a union of many subtrees (instances of a lamp
// placed thousands of times, bare lights and affine subtrees side by side). A 4-wide bounding
// volume hierarchy over the positions of the items' lights, each inner node an extent volume over
// a union; the items themselves are its leaves, so an instance stays an instance and its master
// stays shared. Built once; like any hierarchy, each render fits its extent volumes.
#pragma once

#include <vector>

#include "lev/bounds.h"
#include "lev/light.h"
#include "lev/light_description.h"

namespace lev {

// One leaf of the hierarchy: a subtree that holds lights, and the box around its light positions
// in the frame of the union it stands in.
struct BvhItem {
  LightDescriptionNode node;
  Bounds light_positions;
};

// Splits at the median of the items' box centres along the widest axis of those centres; an item
// alone is returned as it is. The order of the items is kept inside a leaf.
LightDescriptionNode build_bvh(std::vector<BvhItem> items);
// build_bvh over one light node per light (a light's box is its position).
LightDescriptionNode build_light_bvh(const std::vector<Light>& lights);

// The box around a subtree's light positions in the frame it is entered with; an instance's is its
// master's, master_light_positions[master] (empty for a master without lights).
Bounds light_positions(const LightDescriptionNode& node,
                       const std::vector<Bounds>& master_light_positions);

}  // namespace lev
