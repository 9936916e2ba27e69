// The geometry of a scene description as Embree prototypes placed by single-level instances
// (Embree 3 has one instance level): a master whose expanded geometry is small
// (kBakeTriangleBudget) is baked whole into one prototype, a larger one is flattened into the
// placements of its parts. One mesh per material in each prototype; spheres apart.
#pragma once

#include "renderer/scene.h"
#include "scenes/scene_description.h"
#include "scenes/scene_validation.h"

namespace scenes {

// root: the description's root, or its stand-in moved to render space (render_space.h).
renderer::Geometry bake_geometry(const SceneDescription& scene, const SceneNode& root,
                                 const SceneAnalysis& analysis);

}  // namespace scenes
