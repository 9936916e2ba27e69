// The inspector's task (app/viewer/inspection_task.h): it publishes what a render's pass 0 shows
// at the pixel (the rows of renderer::inspect_pixel for the render's settings), a stop() returns
// only once nothing of the stopped inspection can be published any more, a start() replaces the
// inspection in flight: only the latest pixel's is published after it, and inspecting with a
// render's own selector leaves that render's images as they would have been (AST, which learns
// between passes, gets a selector of its own).
#include "app/viewer/inspection_task.h"

#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include <gtest/gtest.h>

#include "lev/methods.h"
#include "renderer/framebuffer.h"
#include "renderer/pixel_inspection.h"
#include "renderer/render.h"
#include "scenes/scene_models.h"

namespace {

using app::viewer::InspectionTask;
using app::viewer::PublishedInspection;

struct Published {
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<std::shared_ptr<const PublishedInspection>> views;

  void add(std::shared_ptr<const PublishedInspection> view) {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      views.push_back(std::move(view));
    }
    changed.notify_all();
  }
  std::size_t count() {
    const std::lock_guard<std::mutex> lock(mutex);
    return views.size();
  }
  std::vector<std::shared_ptr<const PublishedInspection>> all() {
    const std::lock_guard<std::mutex> lock(mutex);
    return views;
  }
  std::shared_ptr<const PublishedInspection> wait_for_generation(std::uint64_t generation) {
    std::unique_lock<std::mutex> lock(mutex);
    changed.wait(lock, [&] { return !views.empty() && views.back()->generation == generation; });
    return views.back();
  }
  std::shared_ptr<const PublishedInspection> wait_for(std::size_t count) {
    std::unique_lock<std::mutex> lock(mutex);
    changed.wait(lock, [&] { return views.size() >= count; });
    return views[count - 1];
  }
};

struct HallScene {
  renderer::Scene scene = scenes::find_scene_model("hall")->build(3);
  renderer::RayScene rays{scene};
  renderer::RenderSettings settings;
  std::unique_ptr<lev::LightSelector> selector;  // the render's, as the worker passes it
  HallScene() {
    settings.width = 64;
    settings.height = 48;
    settings.method = lev::Method::lev;
    settings.tolerance = 0.05f;
    settings.compute_error_bound = true;
    selector = lev::make_selector(scene.lights, renderer::method_params(settings));
  }
};

TEST(InspectionTask, PublishesThePixelsRowsAsTheRenderSeesThem) {
  const HallScene hall;
  Published published;
  InspectionTask task([&](auto view) { published.add(std::move(view)); });
  task.start(hall.scene, hall.rays, hall.settings, *hall.selector, 32, 30, 7);
  const auto view = published.wait_for(1);
  EXPECT_EQ(view->x, 32);
  EXPECT_EQ(view->y, 30);
  EXPECT_EQ(view->generation, 7u);
  EXPECT_EQ(view->width, 64);
  const auto selector =
      lev::make_selector(hall.scene.lights, renderer::method_params(hall.settings));
  const renderer::PixelInspection direct =
      renderer::inspect_pixel(hall.scene, hall.rays, hall.settings, *selector, 32, 30);
  std::size_t all = 0;
  const auto rows = app::viewer::inspector_rows(direct, app::viewer::kInspectorRows, &all);
  EXPECT_EQ(view->all_rows, all);
  ASSERT_EQ(view->rows.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(view->rows[i].light.position, rows[i].light.position);
    EXPECT_EQ(view->rows[i].to_pixel, rows[i].to_pixel);
  }
  EXPECT_EQ(view->totals.tested, direct.totals.tested);
  task.stop();
  EXPECT_FALSE(task.busy());
}

TEST(InspectionTask, StopAndANewStartLeaveOnlyTheLatestPixelToBePublished) {
  const HallScene hall;
  Published published;
  InspectionTask task([&](auto view) { published.add(std::move(view)); });
  for (int round = 0; round < 20; ++round) {
    task.start(hall.scene, hall.rays, hall.settings, *hall.selector, round, round, 1);
    task.stop();
  }
  // Whatever finished before its stop() was published then; nothing comes after.
  const std::size_t before = published.count();
  task.start(hall.scene, hall.rays, hall.settings, *hall.selector, 3, 40, 2);
  // The second replaces the one in flight.
  task.start(hall.scene, hall.rays, hall.settings, *hall.selector, 50, 20, 3);
  const auto latest = published.wait_for_generation(3);
  EXPECT_EQ(latest->x, 50);
  EXPECT_EQ(latest->y, 20);
  task.stop();
  // Between: at most the first of the two, had it finished before the second start.
  const std::vector<std::shared_ptr<const PublishedInspection>> views = published.all();
  ASSERT_GE(views.size(), before + 1);
  ASSERT_LE(views.size(), before + 2);
  EXPECT_EQ(views.back(), latest);
  if (views.size() == before + 2) {
    EXPECT_EQ(views[before]->generation, 2u);
  }
}

// The viewer inspects with the render's own selector while the render goes on. AST's statistics
// of a pass are folded in at its end, so shadow tests counted by an inspection after pass 1 would
// change pass 3: its images must equal those of a render nobody inspected.
TEST(InspectionTask, InspectingWithTheRendersSelectorLeavesItsImagesUnchanged) {
  for (const lev::Method method : {lev::Method::ast, lev::Method::lev_cut}) {
    HallScene hall;
    hall.settings.method = method;
    const auto inspected = renderer::make_render_state(hall.scene, hall.rays, hall.settings);
    const auto untouched = renderer::make_render_state(hall.scene, hall.rays, hall.settings);
    ASSERT_TRUE(renderer::render_pass(*inspected));
    ASSERT_TRUE(renderer::render_pass(*untouched));
    Published published;
    InspectionTask task([&](auto view) { published.add(std::move(view)); });
    std::size_t tested = 0;  // shadow tests the inspections made: what AST would learn from
    for (int k = 0; k < 4; ++k) {
      task.start(hall.scene, hall.rays, hall.settings, renderer::render_selector(*inspected),
                 8 + 12 * k, 6 + 10 * k, 1 + k);
      tested += published.wait_for(static_cast<std::size_t>(k + 1))->totals.tested_lights;
    }
    task.stop();
    EXPECT_GT(tested, 0u) << lev::method_info(method).name;
    for (int pass = 0; pass < 2; ++pass) {
      ASSERT_TRUE(renderer::render_pass(*inspected));
      ASSERT_TRUE(renderer::render_pass(*untouched));
    }
    EXPECT_EQ(renderer::framebuffer_rgb8(renderer::render_framebuffer(*inspected)),
              renderer::framebuffer_rgb8(renderer::render_framebuffer(*untouched)))
        << lev::method_info(method).name;
  }
}

}  // namespace
