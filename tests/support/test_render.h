// One way for the renderer tests to render a scene: a width x height image in tiles of 8, with
// one method at one tolerance on `threads` threads (0: all), after `passes` passes.
#pragma once

#include <gtest/gtest.h>

#include "renderer/ray_scene.h"
#include "renderer/render.h"

inline renderer::Framebuffer render_test_image(const renderer::Scene& scene,
                                               const renderer::RayScene& rays, lev::Method method,
                                               float tolerance, int threads, int passes,
                                               int width = 64, int height = 48) {
  renderer::RenderSettings rs;
  rs.width = width;
  rs.height = height;
  rs.method = method;
  rs.tolerance = tolerance;
  rs.threads = threads;
  rs.tile_size = 8;
  auto state = renderer::make_render_state(scene, rays, rs);
  for (int i = 0; i < passes; ++i) EXPECT_TRUE(renderer::render_pass(*state));
  return renderer::render_framebuffer(*state);
}
