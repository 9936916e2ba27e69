// One way for the tests to render a scene: settings for a small image in tiles of 8 with one
// method, and a render of some passes with them, each pass expected to finish.
#pragma once

#include <gtest/gtest.h>

#include "renderer/ray_scene.h"
#include "renderer/render.h"

inline renderer::RenderSettings test_render_settings(lev::Method method, int width, int height) {
  renderer::RenderSettings rs;
  rs.width = width;
  rs.height = height;
  rs.method = method;
  rs.tile_size = 8;
  return rs;
}

inline renderer::Framebuffer render_test_image(const renderer::Scene& scene,
                                               const renderer::RayScene& rays,
                                               const renderer::RenderSettings& settings,
                                               int passes = 1) {
  auto state = renderer::make_render_state(scene, rays, settings);
  for (int i = 0; i < passes; ++i) EXPECT_TRUE(renderer::render_pass(*state));
  return renderer::render_framebuffer(*state);
}

// The method at one tolerance on `threads` threads (0: all), a width x height image.
inline renderer::Framebuffer render_test_image(const renderer::Scene& scene,
                                               const renderer::RayScene& rays, lev::Method method,
                                               float tolerance, int threads, int passes,
                                               int width = 64, int height = 48) {
  renderer::RenderSettings rs = test_render_settings(method, width, height);
  rs.tolerance = tolerance;
  rs.threads = threads;
  return render_test_image(scene, rays, rs, passes);
}
