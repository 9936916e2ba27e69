// The camera (renderer/camera.h): project_point puts a point of a primary ray back on the pixel
// the ray went through, in front of the camera.
#include <gtest/gtest.h>

#include "renderer/camera.h"

namespace {

TEST(CameraProjection, ProjectPointInvertsThePrimaryRay) {
  renderer::Camera camera;
  camera.position = {3.0f, -7.0f, 4.0f};
  camera.target = {0.5f, 1.0f, 0.0f};
  for (const glm::vec2 pixel :
       {glm::vec2(10.5f, 20.5f), glm::vec2(300.0f, 5.0f), glm::vec2(160.0f, 239.0f)}) {
    const renderer::Ray ray = renderer::primary_ray(camera, 320, 240, pixel.x, pixel.y);
    glm::vec2 image;
    float depth = 0.0f;
    ASSERT_TRUE(
        renderer::project_point(camera, 320, 240, ray.origin + 7.0f * ray.direction, image, depth));
    EXPECT_NEAR(image.x, pixel.x, 1e-3f);
    EXPECT_NEAR(image.y, pixel.y, 1e-3f);
    EXPECT_GT(depth, 0.0f);
  }
}

}  // namespace
