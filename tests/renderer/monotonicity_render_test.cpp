// Monotonicity: for each LEV method on a small hall, where every light adds a little
// and the culled rest matters most, the average and maximum pixel error against rt never grow as
// the method's setting tightens (its tolerance, or lev_cut's relative error), over a sequence of
// settings two decades wide: each tighter setting against every looser one.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/methods.h"
#include "renderer/pixel_error.h"
#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "scenes/hall.h"

namespace {

std::vector<std::uint8_t> render_rgb8(const renderer::Scene& scene, const renderer::RayScene& rays,
                                      lev::Method method, float setting) {
  renderer::RenderSettings rs;
  rs.width = 64;
  rs.height = 48;
  rs.method = method;
  rs.threads = 2;
  if (lev::swept_setting(lev::method_info(method)) == &lev::MethodParams::relative_error) {
    rs.relative_error = setting;
  } else {
    rs.tolerance = setting;
  }
  auto state = renderer::make_render_state(scene, rays, rs);
  EXPECT_TRUE(renderer::render_pass(*state));
  return renderer::framebuffer_rgb8(renderer::render_framebuffer(*state));
}

TEST(Monotonicity, ErrorNeverGrowsAsTheSettingTightens) {
  const renderer::Scene scene = scenes::build_hall(5);  // 1,024 spots
  const renderer::RayScene rays(scene);
  const std::vector<std::uint8_t> rt = render_rgb8(scene, rays, lev::Method::rt, 0.0f);
  const std::vector<float> loosest_first{0.1f, 0.03f, 0.01f, 0.003f, 0.001f};
  for (const lev::Method method :
       {lev::Method::lev, lev::Method::lev_est, lev::Method::lev_bounded, lev::Method::lev_cut}) {
    const char* name = lev::method_info(method).name;
    std::vector<renderer::PixelErrorStats> errors;
    for (const float setting : loosest_first) {
      errors.push_back(renderer::summarize_pixel_error(
          renderer::pixel_error_pct(render_rgb8(scene, rays, method, setting), rt)));
    }
    // The sequence is not trivial: the loosest setting errs, so there is something to shrink.
    EXPECT_GT(errors.front().max_pct, 0.0) << name;
    for (std::size_t t = 1; t < errors.size(); ++t) {
      for (std::size_t l = 0; l < t; ++l) {
        const std::string pair = std::string(name) + " " + std::to_string(loosest_first[t]) +
                                 " after " + std::to_string(loosest_first[l]);
        EXPECT_LE(errors[t].average_pct, errors[l].average_pct) << pair;
        EXPECT_LE(errors[t].max_pct, errors[l].max_pct) << pair;
      }
    }
  }
}

}  // namespace
