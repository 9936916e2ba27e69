// Adding a method is its selector plus one row of the method table (lev/methods.h): this test
// binary adds a small one, `every2` (a shadow ray to every second light), through the seam of
// lev/method_rows.h, and checks that it renders through the render service and `levrt render`'s
// path, is offered by the method list the CLI and the viewer build their controls from, and runs
// in the bench's trade and control experiments. Its own binary, so the row never reaches the
// other tests' method lists.
#include <algorithm>
#include <cstddef>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/bench/bench.h"
#include "app/render_command.h"
#include "app/scene_loading.h"
#include "app/settings.h"
#include "lev/important_lights.h"
#include "lev/light_selector.h"
#include "lev/method_rows.h"
#include "lev/methods.h"
#include "renderer/render_service.h"
#include "tests/support/temp_dir.h"

namespace {

class EverySecondLightSelector final : public lev::LightSelector {
 public:
  explicit EverySecondLightSelector(const lev::LightHierarchy& hierarchy)
      : world_lights_(lev::flatten_lights(hierarchy)) {}
  glm::vec3 direct_radiance(lev::ShadingPoint& point, lev::SelectorScratch& scratch,
                            lev::SelectionCounters& counters,
                            glm::vec3* culled_irradiance_bound = nullptr) const override {
    if (culled_irradiance_bound) {
      // What the skipped lights could add, exactly.
      *culled_irradiance_bound = glm::vec3(0.0f);
      for (std::size_t i = 1; i < world_lights_.size(); i += 2)
        *culled_irradiance_bound += lev::irradiance(world_lights_[i], point.position());
    }
    std::size_t index = 0;
    return lev::sum_visible_lights(
        world_lights_, [&](const lev::Light&) { return index++ % 2 == 0; }, point, counters,
        scratch.cancel);
  }

 private:
  std::vector<lev::Light> world_lights_;
};

}  // namespace

// This binary's own row, through the link-time seam of lev/method_rows.h.
std::vector<lev::MethodInfo> lev::extra_method_rows() {
  return {{lev::Method::rt,
           "every2",
           "Every second light",
           "a shadow ray to every second light (a test's method)",
           lev::kScansEveryLight,
           {0.1},
           [](const lev::LightHierarchy& h,
              const lev::MethodParams&) -> std::unique_ptr<lev::LightSelector> {
             return std::make_unique<EverySecondLightSelector>(h);
           }}};
}

namespace {

const lev::Method kEverySecond = lev::parse_method("every2").value();

app::Settings small_settings() {
  app::Settings s;
  s.scene.level = 2;
  s.image.width = 40;
  s.image.height = 30;
  return s;
}

TEST(ExtraMethod, TheTableGivesItTheNextIdAndItsRow) {
  EXPECT_EQ(static_cast<std::size_t>(kEverySecond) + 1, lev::method_table().size());
  EXPECT_STREQ(lev::method_info(kEverySecond).name, "every2");
  EXPECT_EQ(lev::parse_method("every2"), kEverySecond);
  EXPECT_EQ(lev::reference_method(), lev::Method::rt);
}

TEST(ExtraMethod, TheCliAndTheViewerOfferIt) {
  const std::vector<std::string> options = app::method_options();
  EXPECT_NE(std::find(options.begin(), options.end(), "every2"), options.end());
  app::Settings s;
  const app::SettingSpec* spec = app::find_setting("method");
  ASSERT_NE(spec, nullptr);
  app::set_setting(s, *spec, "every2");
  EXPECT_EQ(s.method.method, kEverySecond);
  EXPECT_EQ(app::setting_text(s, *spec), "every2");
  EXPECT_EQ(app::render_settings_from(s).method, kEverySecond);
  const auto& choice = std::get<app::Choice>(spec->kind);
  ASSERT_NE(choice.option_summary, nullptr);
  EXPECT_STREQ(choice.option_summary("every2"), lev::method_info(kEverySecond).summary);
}

TEST(ExtraMethod, ItRendersThroughTheRenderService) {
  app::Settings s = small_settings();
  const std::unique_ptr<app::LoadedScene> loaded = app::load_scene(s.scene);
  s.method.method = kEverySecond;
  renderer::RenderResult every2;
  ASSERT_TRUE(renderer::render_passes(loaded->scene, *loaded->rays, app::render_settings_from(s), 1,
                                      every2));
  const renderer::RenderResult rt = app::render_image(*loaded, s, lev::Method::rt);
  // rt tests every light that can reach a point, every2 every second light of the scene.
  ASSERT_EQ(every2.totals.shading_points, rt.totals.shading_points);
  EXPECT_GT(every2.totals.lights_tested, 0u);
  EXPECT_LE(every2.totals.lights_tested,
            (loaded->scene.lights.light_count + 1) / 2 * every2.totals.shading_points);
  EXPECT_NE(every2.rendered_rgb, rt.rendered_rgb);
  // The command's path is the same service.
  const renderer::RenderResult again = app::render_image(*loaded, s, kEverySecond);
  EXPECT_EQ(again.rendered_rgb, every2.rendered_rgb);
  EXPECT_EQ(again.totals.lights_tested, every2.totals.lights_tested);
}

TEST(ExtraMethod, TheTradeAndControlExperimentsMeasureIt) {
  const levrt_test::TempDir dir("levrt_extra_method_");
  app::BenchFlags flags;
  flags.out = dir.path().string();
  flags.quick = true;
  flags.only = "trade,control";
  flags.only_given = true;
  ASSERT_EQ(app::run_bench(flags), 0);
  std::ifstream csv(dir.path() / "trade.csv");
  std::stringstream text;
  text << csv.rdbuf();
  EXPECT_NE(text.str().find(",every2,0.1,"), std::string::npos) << text.str();
  // control: its row (a method that ignores the tolerance shows none), its bound holding on
  // every pixel.
  std::ifstream control_csv(dir.path() / "control.csv");
  std::stringstream control;
  control << control_csv.rdbuf();
  const std::size_t row = control.str().find(",every2,-,");
  ASSERT_NE(row, std::string::npos) << control.str();
  const std::string line = control.str().substr(row, control.str().find('\n', row) - row);
  // Before the last two columns: pixels, bound_over_error.
  const std::string before_ratio = line.substr(0, line.rfind(','));
  const std::string held = before_ratio.substr(0, before_ratio.rfind(','));
  EXPECT_EQ(held.substr(held.rfind(',') + 1), "100") << line;
}

}  // namespace
