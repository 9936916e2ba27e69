// The light tree of Lightcuts (Walter et al. 2005, sec. 4): a binary tree over every light of the
// scene in world space (instances expanded), each node a cluster with its aggregate (summed
// intensity, box of positions, cone of spot axes: light_bounds.h) and a representative light.
// The representative of a cluster is one of its two children's, picked with probability
// proportional to the children's intensities (so each light represents the cluster with
// probability proportional to its own intensity, as the paper asks), from a hash of the node's
// index: fixed when the tree is built, the same for every thread and every render.
//
// The tree is built top down: a set of lights mixing point lights and spots is first split by
// kind (the paper keeps one tree per kind, as a spot cone says nothing in a cluster with a point
// light), then where position and orientation together price the two parts cheapest
// (light_split.h), so that spots aimed different ways part early and a cluster's cone bounds
// something. A flat array: a node's children are two nodes with larger indices; a leaf is one
// light.
#pragma once

#include <cstdint>
#include <vector>

#include "lev/light.h"
#include "lev/light_bounds.h"
#include "lev/light_hierarchy.h"

namespace lev {

struct CutTreeNode {
  LightAggregate aggregate;            // the cluster's lights, in world space
  std::uint32_t representative = 0;    // index into LightCutTree::lights
  std::uint32_t children[2] = {0, 0};  // both 0 for a leaf (the root, index 0, is nobody's child)
  bool is_leaf() const { return children[0] == 0; }
};

struct LightCutTree {
  // Every light in world space, in flatten_lights' order (the order `rt` sums them in): a leaf's
  // representative is its light.
  std::vector<Light> lights;
  std::vector<CutTreeNode> nodes;  // the root first; empty when the scene has no light
};

// A uniform number in [0, 1) from a node's index (splitmix64's finaliser): a representative's
// draw, fixed per node (here, and for lev_cut's clusters in important_lights.cpp).
double node_uniform(std::uint32_t node);
// The weight a representative is drawn by: the summed channels of the intensity (all three
// channels count, so a dim red light still represents a red cluster).
double draw_weight(const glm::vec3& intensity);

// The tree over the hierarchy's lights (flatten_lights).
LightCutTree build_light_cut_tree(const LightHierarchy& hierarchy);
// The tree over lights given in world space (for tests).
LightCutTree build_light_cut_tree(std::vector<Light> world_lights);

// The representative light of a node as the cut shades it: the representative itself for a
// leaf, else a copy carrying the cluster's summed intensity (Walter et al. 2005, eq. 2).
Light cluster_light(const LightCutTree& tree, std::uint32_t node);

}  // namespace lev
