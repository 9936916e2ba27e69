// The camera (renderer/camera.h): project_point puts a point of a primary ray back on the pixel
// the ray went through, in front of the camera; an orthographic camera's rays are parallel and
// start on its plane, spread over its half height.
#include <initializer_list>

#include <gtest/gtest.h>

#include "renderer/camera.h"

namespace {

// Each pixel's primary ray, followed `distance` along, projects back onto that pixel.
void expect_rays_project_back(const renderer::Camera& camera, int width, int height,
                              std::initializer_list<glm::vec2> pixels, float distance) {
  for (const glm::vec2 pixel : pixels) {
    const renderer::Ray ray = renderer::primary_ray(camera, width, height, pixel.x, pixel.y);
    glm::vec2 image;
    float depth = 0.0f;
    ASSERT_TRUE(renderer::project_point(camera, width, height,
                                        ray.origin + distance * ray.direction, image, depth));
    EXPECT_NEAR(image.x, pixel.x, 1e-3f);
    EXPECT_NEAR(image.y, pixel.y, 1e-3f);
    EXPECT_GT(depth, 0.0f);
  }
}

TEST(CameraProjection, ProjectPointInvertsThePrimaryRay) {
  renderer::Camera camera;
  camera.position = {3.0f, -7.0f, 4.0f};
  camera.target = {0.5f, 1.0f, 0.0f};
  expect_rays_project_back(
      camera, 320, 240,
      {glm::vec2(10.5f, 20.5f), glm::vec2(300.0f, 5.0f), glm::vec2(160.0f, 239.0f)}, 7.0f);
}

TEST(CameraProjection, OrthographicRaysAreParallelAndSpanTheHalfHeight) {
  renderer::Camera camera;
  camera.position = {1.0f, 2.0f, 3.0f};
  camera.target = {1.0f, 2.0f, -5.0f};
  camera.up = {0.0f, 1.0f, 0.0f};
  camera.orthographic_half_height = 2.5f;
  const renderer::Ray top = renderer::primary_ray(camera, 200, 100, 100.0f, 0.0f);
  const renderer::Ray right = renderer::primary_ray(camera, 200, 100, 200.0f, 50.0f);
  EXPECT_EQ(top.direction, glm::vec3(0.0f, 0.0f, -1.0f));
  EXPECT_EQ(right.direction, glm::vec3(0.0f, 0.0f, -1.0f));
  EXPECT_NEAR(top.origin.y, 2.0f + 2.5f, 1e-5f);
  EXPECT_NEAR(top.origin.z, 3.0f, 1e-6f);
  EXPECT_NEAR(right.origin.x, 1.0f + 5.0f, 1e-5f);  // the image's 2:1 aspect
  expect_rays_project_back(camera, 200, 100, {glm::vec2(10.5f, 20.5f), glm::vec2(170.0f, 95.0f)},
                           9.0f);
  glm::vec2 image;
  float depth = 0.0f;
  ASSERT_TRUE(renderer::project_point(camera, 200, 100, {1.0f, 2.0f, -6.0f}, image, depth));
  EXPECT_NEAR(depth, 9.0f, 1e-4f);
  EXPECT_NEAR(image.x, 100.0f, 1e-3f);  // the axis, at any depth, is the image's centre
  EXPECT_NEAR(image.y, 50.0f, 1e-3f);
}

}  // namespace
