// The pinned pixel's inspection (renderer/pixel_inspection.h) on a thread of its own, so that a
// click never stalls the render worker or the UI, however many lights the scene has. The render
// worker starts it with its render's scene and settings; a new pixel, Clear, a new render or
// quitting cancels it (the trace, the selector's walk and the inspector's shadow rays read the
// flag every few thousand lights) and waits for it, and a cancelled inspection publishes nothing.
// The thread lives as long as the task: made on the UI thread (RenderWorker's constructor), it
// keeps the normal priority while the tracer's threads run at a lower one, so the inspection gets
// a core at once instead of queueing behind the render's tiles.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "app/viewer/inspector_rows.h"
#include "lev/light_selector.h"
#include "renderer/ray_scene.h"
#include "renderer/render.h"

namespace app::viewer {

class InspectionTask {
 public:
  // Called on the task's thread with each inspection that ran to its end.
  using Done = std::function<void(std::shared_ptr<const PublishedInspection>)>;

  explicit InspectionTask(Done on_done);
  ~InspectionTask();  // cancels and joins
  InspectionTask(const InspectionTask&) = delete;
  InspectionTask& operator=(const InspectionTask&) = delete;

  // Cancels the inspection in flight (stop()), then inspects pixel (x, y) of render `generation`
  // (settings: its own) with the render's own selector, or, when that one learns between passes
  // (AST: shadow tests made here would count in the render's statistics), a fresh one made as
  // the render's. The scene, rays and selector must stay alive and unchanged until the next
  // stop() or start().
  void start(const renderer::Scene& scene, const renderer::RayScene& rays,
             const renderer::RenderSettings& settings, const lev::LightSelector& render_selector,
             int x, int y, std::uint64_t generation);
  // Cancels the inspection in flight, if any, and returns once it has stopped: the scene is then
  // free to change.
  void stop();
  // An inspection is queued or running.
  bool busy() const;

 private:
  struct Job {
    const renderer::Scene* scene = nullptr;
    const renderer::RayScene* rays = nullptr;
    const lev::LightSelector* render_selector = nullptr;
    renderer::RenderSettings settings;
    int x = 0, y = 0;
    std::uint64_t generation = 0;
  };
  void run();
  void inspect(const Job& job);

  Done on_done_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<Job> queued_;
  bool running_ = false;
  bool quit_ = false;
  std::atomic<bool> cancel_{false};
  std::thread thread_;
};

}  // namespace app::viewer
