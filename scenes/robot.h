// A robot riding a unicycle (the figure every thesis scene places under its lights): wheel,
// seat post, body, arms and head, built from cylinders, boxes and a sphere. Scenes define it once
// as a master and instance it.
#pragma once

#include <cstdint>

#include "scenes/scene_description.h"

namespace scenes {

struct RobotMaterials {
  std::uint32_t body = 0;
  std::uint32_t head = 0;
  std::uint32_t metal = 0;
  std::uint32_t tyre = 0;
};

// One robot standing on z = 0, about 2.7 units tall, facing +y, arms held out along x.
SceneNode robot_node(const RobotMaterials& materials);

}  // namespace scenes
