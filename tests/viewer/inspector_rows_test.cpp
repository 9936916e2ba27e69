// The inspector's rows and overlays (app/viewer/inspector_rows.h): rows over every hit, largest
// contribution first and cut to the number asked, every light of an inspection among them when
// none is cut; a light's extent radius as LEV culls by it; and its outline projected where the
// camera sees it (a sphere's around the light's own projection), nothing behind the camera; NaN
// and infinite values ordered, NaN last.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "app/viewer/inspector_rows.h"
#include "lev/methods.h"
#include "renderer/ray_scene.h"
#include "scenes/scene_models.h"
#include "tests/support/odd_inspection.h"

namespace {

using app::viewer::extent_outline;
using app::viewer::extent_radius;
using app::viewer::inspector_rows;
using app::viewer::InspectorRow;

float brightest_abs(const glm::vec3& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

TEST(InspectorRows, LargestFirstOverEveryHitAndCutToTheCountAsked) {
  const renderer::Scene scene = scenes::find_scene_model("hall")->build(3);
  const renderer::RayScene rays(scene);
  renderer::RenderSettings rs;
  rs.width = 64;
  rs.height = 48;
  rs.method = lev::Method::lev;
  rs.tolerance = 0.05f;
  const auto selector = lev::make_selector(scene.lights, renderer::method_params(rs));
  const renderer::PixelInspection inspection =
      renderer::inspect_pixel(scene, rays, rs, *selector, 32, 30);
  std::size_t all = 0;
  const std::vector<InspectorRow> every = inspector_rows(inspection, 100000, &all);
  EXPECT_EQ(every.size(), all);
  EXPECT_EQ(all, inspection.totals.shaded + inspection.totals.culled_lights);
  for (std::size_t i = 1; i < every.size(); ++i)
    EXPECT_GE(brightest_abs(every[i - 1].to_pixel), brightest_abs(every[i].to_pixel));
  const std::vector<InspectorRow> top = inspector_rows(inspection, 5);
  ASSERT_EQ(top.size(), std::min<std::size_t>(5, all));
  for (std::size_t i = 0; i < top.size(); ++i)
    EXPECT_EQ(brightest_abs(top[i].to_pixel), brightest_abs(every[i].to_pixel));
}

TEST(InspectorRows, ExtentOutlineSurroundsTheLightWhereTheCameraSeesIt) {
  renderer::Camera camera;  // at (0, -10, 5) looking at the origin
  const lev::Light light = lev::make_point_light({0.0f, 0.0f, 0.0f}, glm::vec3(0.04f));
  EXPECT_FLOAT_EQ(extent_radius(light, 0.01f), 2.0f);
  EXPECT_TRUE(std::isinf(extent_radius(light, 0.0f)));
  glm::vec2 centre;
  float depth = 0.0f;
  ASSERT_TRUE(renderer::project_point(camera, 320, 240, light.position, centre, depth));
  EXPECT_NEAR(centre.x, 160.0f, 1e-3f);
  EXPECT_NEAR(centre.y, 120.0f, 1e-3f);
  const auto lines = extent_outline(camera, 320, 240, light, 0.01f);
  ASSERT_EQ(lines.size(), 1u);
  for (const glm::vec2& p : lines[0]) {
    const float r = glm::length(p - centre);
    EXPECT_GT(r, 10.0f);
    EXPECT_LT(r, 200.0f);
  }
  const lev::Light behind = lev::make_point_light({0.0f, -30.0f, 5.0f}, glm::vec3(0.04f));
  EXPECT_TRUE(extent_outline(camera, 320, 240, behind, 0.01f).empty());
  const lev::Light spot =
      lev::make_spot_light({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, -1.0f}, glm::vec3(0.04f), 0.5f, 1.0f);
  EXPECT_EQ(extent_outline(camera, 320, 240, spot, 0.01f).size(), 5u);  // rim and four lines
}

// NaN and infinite values (a broken light) are ordered, not undefined behaviour: largest first,
// NaN last, ties in record order; the cut keeps the head of that order.
TEST(InspectorRows, NanAndInfiniteContributionsAreOrderedNanLast) {
  const renderer::PixelInspection inspection = levrt_test::odd_inspection();
  const std::vector<std::size_t> expected = levrt_test::odd_expected_order();
  std::size_t all = 0;
  const std::vector<InspectorRow> every = inspector_rows(inspection, expected.size() + 5, &all);
  ASSERT_EQ(all, expected.size());
  ASSERT_EQ(every.size(), expected.size());
  for (std::size_t i = 0; i < every.size(); ++i)
    EXPECT_EQ(static_cast<std::size_t>(every[i].light.position.x), expected[i]) << "row " << i;
  const std::vector<InspectorRow> top = inspector_rows(inspection, 7);
  ASSERT_EQ(top.size(), 7u);
  for (std::size_t i = 0; i < top.size(); ++i)
    EXPECT_EQ(static_cast<std::size_t>(top[i].light.position.x), expected[i]) << "row " << i;
}

}  // namespace
