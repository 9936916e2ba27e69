// What every scene model shares: a scene file exported from it renders the same image, bit for
// bit, and builds the same light hierarchy; LEV at tolerance 0 is RT, bit for bit.
#include "scenes/scene_models.h"

#include <cstring>
#include <memory>

#include <gtest/gtest.h>

#include "lev/light_hierarchy.h"
#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "scenes/scene_file.h"
#include "scenes/scene_instantiation.h"
#include "tests/support/framebuffer_compare.h"
#include "tests/support/test_render.h"

namespace {

renderer::Framebuffer render_model(renderer::Scene& scene, lev::Method method, float tolerance) {
  const renderer::RayScene rays(scene);
  renderer::RenderSettings rs = test_render_settings(method, 48, 36);
  rs.tolerance = tolerance;
  return render_test_image(scene, rays, rs);
}

TEST(SceneModels, ExportedFileRendersTheSameImageAndHierarchy) {
  for (const scenes::SceneModel& model : scenes::scene_models()) {
    for (int level : {model.min_level, model.min_level + 1}) {
      const scenes::SceneDescription description = model.describe(level);
      const std::string text = scenes::scene_file_json(description);
      const scenes::SceneDescription read = scenes::parse_scene_json(text, "export.json");
      EXPECT_EQ(scenes::scene_file_json(read), text) << model.name << " " << level;
      renderer::Scene built = model.build(level);
      renderer::Scene loaded = scenes::instantiate_scene(read);
      EXPECT_EQ(loaded.name, built.name);
      EXPECT_EQ(loaded.level, level);
      EXPECT_EQ(loaded.lights.light_count, model.light_count(level));
      EXPECT_EQ(lev::hierarchy_bytes(loaded.lights), lev::hierarchy_bytes(built.lights))
          << model.name << " " << level;
      EXPECT_EQ(loaded.lights.nodes.size(), built.lights.nodes.size());
      EXPECT_EQ(loaded.geometry.instances.size(), built.geometry.instances.size());
      const renderer::Framebuffer a = render_model(built, lev::Method::lev, 0.01f);
      const renderer::Framebuffer b = render_model(loaded, lev::Method::lev, 0.01f);
      EXPECT_TRUE(bitwise_equal(a, b)) << model.name << " " << level;
      EXPECT_EQ(renderer::framebuffer_rgb8(a), renderer::framebuffer_rgb8(b))
          << model.name << " " << level;
    }
  }
}

TEST(SceneModels, LevAtToleranceZeroEqualsRtBitForBit) {
  for (const char* name : {"maze", "hall", "stage", "carpark", "street"}) {
    const scenes::SceneModel* model = scenes::find_scene_model(name);
    ASSERT_NE(model, nullptr);
    for (int level : {model->min_level, model->min_level + 1}) {
      renderer::Scene scene = model->build(level);
      const renderer::Framebuffer rt = render_model(scene, lev::Method::rt, 0.0f);
      const renderer::Framebuffer lev = render_model(scene, lev::Method::lev, 0.0f);
      EXPECT_TRUE(bitwise_equal(rt, lev)) << name << " " << level;
      EXPECT_EQ(renderer::framebuffer_rgb8(rt), renderer::framebuffer_rgb8(lev));
      EXPECT_EQ(rt.lights_tested, lev.lights_tested);
      EXPECT_EQ(rt.shadow_rays, lev.shadow_rays);
      const renderer::FramebufferTotals totals = renderer::sum_framebuffer(rt);
      EXPECT_GT(totals.shading_points, 0u);
      EXPECT_GT(totals.shadow_rays, 0u);
    }
  }
}

TEST(SceneModels, EveryModelDescribesAValidScene) {
  for (const scenes::SceneModel& model : scenes::scene_models()) {
    EXPECT_NO_THROW(scenes::validate_description(model.describe(model.default_level)))
        << model.name;
    EXPECT_EQ(model.describe(model.default_level).name, model.name);
  }
}

}  // namespace
