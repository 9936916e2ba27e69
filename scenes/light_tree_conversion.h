// The light part of a scene description as a lev::LightTree: masters stay masters (the
// hierarchy grows with the distinct masters, not with the lights, thesis 3.5.3), a transform right
// above a light is folded into it, and a union of many bare lights gets the automatic hierarchy
// (lev::build_light_bvh).
#pragma once

#include "lev/light_tree.h"
#include "scenes/scene_description.h"
#include "scenes/scene_validation.h"

namespace scenes {

// root: the description's root, or its stand-in moved to render space (render_space.h).
lev::LightTree convert_lights(const SceneDescription& scene, const SceneNode& root,
                              const SceneAnalysis& analysis);

}  // namespace scenes
