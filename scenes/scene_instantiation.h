// From a scene description to a renderable scene (thesis 4.3, preprocessing). The lights become a
// lev::LightDescription that keeps the description's masters as masters, so the hierarchy grows
// with the number of distinct masters, not of lights (thesis 3.5.3); a union holding many bare
// lights gets the automatic hierarchy (lev::build_light_bvh). The geometry becomes Embree
// prototypes placed by single-level instances, because Embree 3 has one instance level: a master
// whose expanded geometry is small is baked whole into one prototype, a larger one is flattened
// into the placements of its parts. Built-in models and scene files take this same path, so a file
// exported from a model renders the same image and builds the same hierarchy.
#pragma once

#include "renderer/scene.h"
#include "scenes/render_space.h"
#include "scenes/scene_description.h"
#include "scenes/scene_validation.h"

namespace scenes {

// Validates, then builds the light hierarchy (its structure: each render fits the extent volumes
// for its own tolerance) and the geometry, in render space.
renderer::Scene instantiate_scene(const SceneDescription& scene);

}  // namespace scenes
