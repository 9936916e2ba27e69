// The scene's group of the settings (scenes::SceneChoice): the scene, its level and the camera
// flags are always compared; the camera index only for a glTF file, the one scene that reads it.
#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "scenes/scene_choice.h"

namespace {

TEST(SceneChoice, ComparesTheSceneTheLevelAndTheCameraFlags) {
  const scenes::SceneChoice a;
  EXPECT_EQ(a, a);
  scenes::SceneChoice b = a;
  b.name = "maze";
  EXPECT_NE(a, b);
  b = a;
  b.level = a.level + 1;
  EXPECT_NE(a, b);
  b = a;
  b.camera_flags.vertical_fov_deg = 30.0f;
  EXPECT_NE(a, b);
  b = a;
  b.camera_flags.position = glm::vec3(1.0f, 2.0f, 3.0f);
  EXPECT_NE(a, b);
  b = a;
  b.camera_flags.from_file = "stats.json";
  EXPECT_NE(a, b);
}

TEST(SceneChoice, TheCameraIndexCountsForAGltfFileAlone) {
  scenes::SceneChoice a;
  scenes::SceneChoice b = a;
  b.camera = 2;
  EXPECT_FALSE(scenes::reads_camera_index(a));
  EXPECT_EQ(a, b);  // a built-in scene has one preset camera
  for (const char* file : {"room.gltf", "room.glb"}) {
    a.name = b.name = file;
    EXPECT_TRUE(scenes::reads_camera_index(a));
    EXPECT_NE(a, b) << file;
  }
  a.name = b.name = "room.json";
  EXPECT_EQ(a, b);  // a scene file has one camera too
}

}  // namespace
