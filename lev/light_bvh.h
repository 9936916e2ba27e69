// The automatic hierarchy for a flat list of lights (a scene file without structure, an import):
// a 4-wide bounding volume hierarchy over light positions, each inner node an extent volume over
// a union. Built once; like any hierarchy, each render fits its extent volumes.
#pragma once

#include <vector>

#include "lev/light.h"
#include "lev/light_tree.h"

namespace lev {

LightTreeNode build_light_bvh(const std::vector<Light>& lights);

}  // namespace lev
