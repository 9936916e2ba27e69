// A robot riding a unicycle (the figure every thesis scene places under its lights): wheel,
// seat post, body, arms and head, built from cylinders, boxes and a sphere.
#pragma once

#include <cstdint>

#include "lev/transform.h"
#include "renderer/geometry.h"

namespace scenes {

struct RobotMaterials {
  std::uint32_t body = 0;
  std::uint32_t head = 0;
  std::uint32_t metal = 0;
  std::uint32_t tyre = 0;
};

// Adds one robot standing on z = 0, about 2.7 units tall, facing +y in its own frame, placed
// in the prototype by world_from_robot.
void add_robot(renderer::Prototype& prototype, const lev::Similarity& world_from_robot,
               const RobotMaterials& materials);

}  // namespace scenes
