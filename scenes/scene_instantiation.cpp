#include "scenes/scene_instantiation.h"

#include <optional>

#include "lev/light_hierarchy.h"
#include "scenes/geometry_baking.h"
#include "scenes/light_description_conversion.h"

namespace scenes {

renderer::Scene instantiate_scene(const SceneDescription& description) {
  const SceneAnalysis analysis = analyze_description(description);
  renderer::Scene scene;
  scene.name = description.name;
  scene.level = description.level;
  scene.world_origin = render_space_origin(description.camera);
  scene.camera = description.camera;
  scene.camera.position -= scene.world_origin;
  scene.camera.target -= scene.world_origin;
  scene.ambient = description.ambient;
  scene.background = description.background;
  scene.directional_lights = description.directional_lights;
  scene.textures = description.textures;
  for (const NamedMaterial& m : description.materials) scene.materials.push_back(m.material);
  // Only the root is copied and moved; masters are placed by the nodes above their instances.
  std::optional<SceneNode> moved_root;
  if (scene.world_origin != glm::vec3(0.0f)) {
    moved_root = description.root;
    move_subtree(*moved_root, -scene.world_origin);
  }
  const SceneNode& root = moved_root ? *moved_root : description.root;
  scene.light_description = convert_lights(description, root, analysis);
  scene.geometry = bake_geometry(description, root, analysis);
  scene.lights = lev::build_hierarchy(scene.light_description);
  return scene;
}

}  // namespace scenes
