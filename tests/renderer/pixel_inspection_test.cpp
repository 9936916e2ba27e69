// The pixel inspector (renderer/pixel_inspection.h, lev/inspect_record.h) against the render it
// explains: for every method of the table its lists hold every light of the scene once (tested,
// culled, or inside a cluster; a sampling method's draws come on top), it shades what the render's
// pass 0 shaded at that pixel (the per-pixel lights-tested counter and the radiance, bit for bit),
// and for lev, which is deterministic, the light it reports lost is rt's pixel minus lev's.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/methods.h"
#include "renderer/pixel_inspection.h"
#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "scenes/scene_models.h"
#include "tests/support/test_render.h"

namespace {

constexpr int kInspectWidth = 24;
constexpr int kInspectHeight = 18;

struct ScenePair {
  renderer::Scene scene;
  renderer::RayScene rays;
  explicit ScenePair(const char* model, int level)
      : scene(scenes::find_scene_model(model)->build(level)), rays(scene) {}
};

renderer::RenderSettings inspection_settings(lev::Method method, float tolerance) {
  renderer::RenderSettings rs = test_render_settings(method, kInspectWidth, kInspectHeight);
  rs.tolerance = tolerance;
  rs.compute_error_bound = true;  // as levrt render, and as the inspector asks
  rs.lights_per_point = 4;
  return rs;
}

renderer::PixelInspection inspect(const ScenePair& s, const renderer::RenderSettings& rs, int x,
                                  int y) {
  const auto selector = lev::make_selector(s.scene.lights, renderer::method_params(rs));
  return renderer::inspect_pixel(s.scene, s.rays, rs, *selector, x, y);
}

// The positions of every single light a hit's lists account for (sampled draws aside).
std::vector<glm::vec3> accounted_positions(const renderer::InspectedHit& hit) {
  std::vector<glm::vec3> positions;
  for (const lev::ShadedLight& s : hit.record.shaded) {
    if (s.role == lev::InspectRole::tested) positions.push_back(s.light.position);
    if (s.role == lev::InspectRole::cluster || s.role == lev::InspectRole::estimated) {
      for (const lev::InspectedLight& m : s.members) positions.push_back(m.light.position);
    }
  }
  for (const lev::InspectedLight& c : hit.record.culled) positions.push_back(c.light.position);
  return positions;
}

bool position_less(const glm::vec3& a, const glm::vec3& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

TEST(PixelInspection, EveryLightAppearsOnceAsTestedCulledOrClustered) {
  for (const auto& [model, level] : {std::pair{"building", 3}, std::pair{"hall", 3}}) {
    const ScenePair s(model, level);
    std::vector<glm::vec3> all;
    for (const lev::Light& l : lev::flatten_lights(s.scene.lights)) all.push_back(l.position);
    std::sort(all.begin(), all.end(), position_less);
    for (const lev::MethodInfo& method : lev::method_table()) {
      SCOPED_TRACE(std::string(model) + " " + method.name);
      int hits = 0;
      for (const auto& [x, y] : {std::pair{12, 9}, std::pair{3, 15}, std::pair{20, 4}}) {
        const renderer::PixelInspection inspection =
            inspect(s, inspection_settings(method.id, 0.05f), x, y);
        for (const renderer::InspectedHit& hit : inspection.hits) {
          ++hits;
          std::vector<glm::vec3> seen = accounted_positions(hit);
          ASSERT_EQ(seen.size(), all.size());
          std::sort(seen.begin(), seen.end(), position_less);
          for (std::size_t i = 0; i < all.size(); ++i) {
            EXPECT_NEAR(seen[i].x, all[i].x, 1e-3f);
            EXPECT_NEAR(seen[i].y, all[i].y, 1e-3f);
            EXPECT_NEAR(seen[i].z, all[i].z, 1e-3f);
          }
          const renderer::InspectedTotals t = renderer::hit_totals(hit);
          EXPECT_EQ(t.tested_lights + t.culled_lights + t.clustered_lights, all.size());
        }
      }
      EXPECT_GT(hits, 0);
    }
  }
}

TEST(PixelInspection, ShadesWhatTheRenderShadedAtThatPixel) {
  const ScenePair s("hall", 3);
  for (const lev::MethodInfo& method : lev::method_table()) {
    SCOPED_TRACE(method.name);
    const renderer::RenderSettings rs = inspection_settings(method.id, 0.05f);
    const renderer::Framebuffer fb = render_test_image(s.scene, s.rays, rs, 1);
    std::uint64_t tested_somewhere = 0;
    for (int y = 0; y < kInspectHeight; y += 4) {
      for (int x = 0; x < kInspectWidth; x += 3) {
        const std::size_t pixel = static_cast<std::size_t>(y) * kInspectWidth + x;
        const renderer::PixelInspection inspection = inspect(s, rs, x, y);
        EXPECT_EQ(inspection.totals.shaded, fb.lights_tested[pixel]) << x << "," << y;
        EXPECT_EQ(inspection.counters.selection.lights_tested, fb.lights_tested[pixel]);
        EXPECT_EQ(inspection.radiance, fb.radiance_sum[pixel]) << x << "," << y;
        tested_somewhere += fb.lights_tested[pixel];
      }
    }
    EXPECT_GT(tested_somewhere, 0u);
  }
}

TEST(PixelInspection, LevLostSumIsRtPixelMinusLevPixel) {
  for (const auto& [model, level] :
       {std::pair{"building", 3}, std::pair{"hall", 3}, std::pair{"maze", 1}}) {
    SCOPED_TRACE(model);
    const ScenePair s(model, level);
    const renderer::RenderSettings lev_settings = inspection_settings(lev::Method::lev, 0.1f);
    const renderer::Framebuffer lev_fb = render_test_image(s.scene, s.rays, lev_settings, 1);
    const renderer::Framebuffer rt_fb =
        render_test_image(s.scene, s.rays, inspection_settings(lev::Method::rt, 0.1f), 1);
    double lost_total = 0.0;
    for (int y = 0; y < kInspectHeight; y += 2) {
      for (int x = 0; x < kInspectWidth; x += 2) {
        const std::size_t pixel = static_cast<std::size_t>(y) * kInspectWidth + x;
        const renderer::PixelInspection inspection = inspect(s, lev_settings, x, y);
        const glm::dvec3 difference =
            glm::dvec3(rt_fb.radiance_sum[pixel]) - glm::dvec3(lev_fb.radiance_sum[pixel]);
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(inspection.totals.lost[c], difference[c],
                      1e-5 + 1e-5 * std::abs(rt_fb.radiance_sum[pixel][c]))
              << x << "," << y;
          // What lev lost is only ever light it did not add, and within its certified bound.
          EXPECT_GE(inspection.totals.lost[c], -1e-6);
          EXPECT_LE(inspection.totals.lost[c], inspection.totals.bound[c] + 1e-5);
        }
        lost_total += inspection.totals.lost.x;
      }
    }
    if (std::string(model) != "building") {  // the walls hide it there
      EXPECT_GT(lost_total, 0.0);
    }
  }
}

// The inspector's order is a strict total order over every value a row can hold, NaN and the
// infinities included (std::sort needs a strict weak order; NaN broke the old comparators).
TEST(PixelInspection, RanksAreATotalOrderWithNanLast) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> values = {nan, inf, -inf, 0.0, -0.0, 1.0, -2.0, 2.0};
  std::vector<renderer::ContributionRank> ranks;
  for (const double to_pixel : values) {
    for (const double unshadowed : values) {
      ranks.push_back(renderer::contribution_rank(
          glm::dvec3(to_pixel, 0.0, 0.0), glm::dvec3(0.0, unshadowed, 0.0), ranks.size() % 3));
    }
  }
  const auto before = renderer::ranks_before;
  for (const auto& a : ranks) {
    EXPECT_FALSE(before(a, a));
    for (const auto& b : ranks) {
      EXPECT_FALSE(before(a, b) && before(b, a));
      for (const auto& c : ranks) {
        if (before(a, b) && before(b, c)) {
          EXPECT_TRUE(before(a, c));
        }
        // Incomparability is transitive too.
        const bool ab = !before(a, b) && !before(b, a), bc = !before(b, c) && !before(c, b);
        if (ab && bc) {
          EXPECT_TRUE(!before(a, c) && !before(c, a));
        }
      }
    }
  }
  const auto rank = [](double to_pixel, std::size_t order) {
    return renderer::contribution_rank(glm::dvec3(to_pixel), glm::dvec3(0.0), order);
  };
  // Any NaN channel makes the row NaN, listed after every number; larger magnitudes first.
  EXPECT_TRUE(before(rank(0.0, 5),
                     renderer::contribution_rank(glm::dvec3(9.0, nan, 1.0), glm::dvec3(0.0), 0)));
  EXPECT_TRUE(before(rank(inf, 5), rank(1.0, 0)));
  EXPECT_TRUE(before(rank(-3.0, 5), rank(2.0, 0)));
  EXPECT_TRUE(before(rank(2.0, 0), rank(2.0, 1)));  // ties in record order
  EXPECT_TRUE(before(rank(nan, 0), rank(nan, 1)));
}

// A raised cancel flag stops the inspection before it records anything (the viewer's inspector
// raises it for a new pixel, Clear or quitting, and discards what comes back).
TEST(PixelInspection, ARaisedCancelStopsTheInspection) {
  const ScenePair s("hall", 3);
  const renderer::RenderSettings rs = inspection_settings(lev::Method::lev, 0.01f);
  const auto selector = lev::make_selector(s.scene.lights, renderer::method_params(rs));
  std::atomic<bool> cancel{false};
  const renderer::PixelInspection whole =
      renderer::inspect_pixel(s.scene, s.rays, rs, *selector, 12, 9, &cancel);
  EXPECT_FALSE(whole.hits.empty());
  cancel.store(true);
  const renderer::PixelInspection stopped =
      renderer::inspect_pixel(s.scene, s.rays, rs, *selector, 12, 9, &cancel);
  EXPECT_TRUE(stopped.hits.empty());
}

}  // namespace
