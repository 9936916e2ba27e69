#include "app/viewer/inspection_task.h"

#include <chrono>
#include <utility>

#include "lev/methods.h"
#include "renderer/pixel_inspection.h"

namespace app::viewer {

InspectionTask::InspectionTask(Done on_done) : on_done_(std::move(on_done)) {
  thread_ = std::thread([this] { run(); });
}

InspectionTask::~InspectionTask() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    quit_ = true;
    queued_.reset();
    cancel_.store(true);
  }
  wake_.notify_all();
  thread_.join();
}

void InspectionTask::start(const renderer::Scene& scene, const renderer::RayScene& rays,
                           const renderer::RenderSettings& settings,
                           const lev::LightSelector& render_selector, int x, int y,
                           std::uint64_t generation) {
  stop();
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    queued_ = Job{&scene, &rays, &render_selector, settings, x, y, generation};
  }
  wake_.notify_all();
}

void InspectionTask::stop() {
  std::unique_lock<std::mutex> lock(mutex_);
  queued_.reset();
  if (!running_) return;
  cancel_.store(true);
  wake_.wait(lock, [this] { return !running_; });
  cancel_.store(false);
}

bool InspectionTask::busy() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return running_ || queued_.has_value();
}

void InspectionTask::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return quit_ || queued_.has_value(); });
    if (quit_) return;
    const Job job = *queued_;
    queued_.reset();
    running_ = true;
    lock.unlock();
    inspect(job);
    lock.lock();
    running_ = false;
    wake_.notify_all();
  }
}

void InspectionTask::inspect(const Job& job) {
  const auto start = std::chrono::steady_clock::now();
  // The render's selector is shared (its direct_radiance is const and thread-safe), so a click
  // costs no second build of a light tree or extent volumes (lightcuts on hall 16,384: most of
  // 265 ms).
  std::unique_ptr<lev::LightSelector> own;
  if (job.render_selector->learns_between_passes())
    own = lev::make_selector(job.scene->lights, renderer::method_params(job.settings));
  const lev::LightSelector& selector = own ? *own : *job.render_selector;
  const renderer::PixelInspection inspection = renderer::inspect_pixel(
      *job.scene, *job.rays, job.settings, selector, job.x, job.y, &cancel_);
  if (cancel_.load()) return;  // what a cancelled trace returns is not the pixel's
  auto view = std::make_shared<PublishedInspection>();
  view->generation = job.generation;
  view->x = job.x;
  view->y = job.y;
  view->camera = job.scene->camera;
  view->width = job.settings.width;
  view->height = job.settings.height;
  view->tolerance = job.settings.tolerance;
  view->totals = inspection.totals;
  view->rows = inspector_rows(inspection, kInspectorRows, &view->all_rows);
  view->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (cancel_.load()) return;
  on_done_(std::move(view));
}

}  // namespace app::viewer
