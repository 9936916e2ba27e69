// The automatic hierarchy for a structure without boxes to cull with: a flat list of lights (a
// scene file without structure, an import), or a union of many subtrees (instances of a lamp
// placed thousands of times, bare lights and affine subtrees side by side). A 4-wide bounding
// volume hierarchy over the items' lights, each inner node an extent volume over
// a union; the items themselves are its leaves, so an instance stays an instance and its master
// stays shared. Built once; like any hierarchy, each render fits its extent volumes.
#pragma once

#include <vector>

#include "lev/bounds.h"
#include "lev/light.h"
#include "lev/light_bounds.h"
#include "lev/light_description.h"

namespace lev {

// What the split weighs of a subtree's lights, in the frame it is entered with: the box around
// their positions, exact (a light's box is its position, bit for bit, however it was placed, so
// that instanced lights and the same lights written bare split alike), and their aggregate
// (intensity and spot cones).
struct SubtreeLights {
  Bounds positions;
  LightAggregate aggregate;
};

// One leaf of the hierarchy: a subtree that holds lights, and its lights in the frame of the union
// it stands in.
struct BvhItem {
  LightDescriptionNode node;
  SubtreeLights lights;
};

// Splits each set in two at the median along an axis of the spot axes where position and
// orientation together price that cheapest, else along the widest axis of the item centres
// (light_split.h), and each half in two again, so spots aimed different ways part early and the
// tree stays balanced; an item alone is returned as it is. The order of the items is kept inside a
// leaf.
LightDescriptionNode build_bvh(std::vector<BvhItem> items);
// build_bvh over one light node per light.
LightDescriptionNode build_light_bvh(const std::vector<Light>& lights);

// A subtree's lights in the frame it is entered with; an instance's are its master's,
// master_lights[master] (empty for a master without lights).
SubtreeLights subtree_lights(const LightDescriptionNode& node,
                             const std::vector<SubtreeLights>& master_lights);

}  // namespace lev
