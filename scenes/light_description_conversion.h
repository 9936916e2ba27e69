// The light part of a scene description as a lev::LightDescription: masters stay masters (the
// hierarchy grows with the distinct masters, not with the lights, thesis 3.5.3), and within each
// master and the root the lights and placed instances, whatever unions and transforms they came
// in, get the automatic hierarchy (lev::build_bvh) once they are more than a few: a lamp placed
// 16,000 times costs a walk of a few dozen nodes, like the same lights written bare.
#pragma once

#include "lev/light_description.h"
#include "scenes/scene_description.h"
#include "scenes/scene_validation.h"

namespace scenes {

// root: the description's root, or its stand-in moved to render space (render_space.h).
lev::LightDescription convert_lights(const SceneDescription& scene, const SceneNode& root,
                                     const SceneAnalysis& analysis);

}  // namespace scenes
