// The worker's state machine (render_worker.h). Over 600 lines on purpose: one class, Worker,
// owns the scene, the render jobs, the reference and the inspection, and every member reads and
// changes that state under the same rules (the shared lock, the cancel flag, the serials);
// split over files, those rules would have to be read in several places to change one.
#include "app/viewer/render_worker.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <utility>

#include "app/render_command.h"
#include "app/scene_loading.h"
#include "app/viewer/inspection_task.h"
#include "app/viewer/reference_render.h"
#include "lev/light_hierarchy.h"
#include "lev/methods.h"
#include "renderer/auto_exposure.h"
#include "renderer/render.h"
#include "renderer/render_service.h"

namespace app::viewer {

using Clock = std::chrono::steady_clock;

struct WorkerShared {
  std::mutex mutex;  // guards everything below but the atomics and the display buffers
  std::condition_variable wake;
  std::optional<RenderRequest> pending;
  std::uint64_t pending_serial = 0;
  std::uint64_t last_serial = 0;
  bool quit = false;
  WorkerStatus status;
  std::atomic<bool> cancel{false};    // the main render's pass in flight
  std::atomic<bool> quitting{false};  // the scene load in flight (only quitting stops a load)

  DisplayBuffer tiles;
  DisplayBuffer preview_tiles;
  DisplayBuffer reference_tiles;

  // The main render state, for the UI's in-flight markers. The worker swaps the pointer under
  // slot_mutex and never destroys a state that is still published.
  mutable std::mutex slot_mutex;
  const renderer::RenderState* slot = nullptr;

  // The pinned pixel's inspection, on its own thread (made here, on the UI thread: it keeps the
  // normal priority); it publishes into `status`. Last, so it stops before the rest goes.
  InspectionTask inspector{[this](std::shared_ptr<const PublishedInspection> view) {
    const std::lock_guard<std::mutex> lock(mutex);
    status.inspection = std::move(view);
    status.inspection_pending = false;
  }};
};

namespace {

// Preview pixel steps, coarsest first: 8, 4, 2, and coarser levels in front while the coarsest
// would have more samples than the default frame (320x240) has at step 8, so that the first whole
// frame costs about the same at any window size. Steps at or below the subsample stride add
// nothing and are left out.
constexpr int kFinestPreviewStep = 2;
constexpr int kCoarsePreviewStep = 8;
constexpr int kMaxPreviewStep = 128;
constexpr long long kCoarsestPreviewSamples = (renderer::kDefaultImageWidth / kCoarsePreviewStep) *
                                              (renderer::kDefaultImageHeight / kCoarsePreviewStep);

std::vector<int> preview_steps_for(int width, int height, int pixel_stride) {
  const auto samples_at = [&](int step) {
    return static_cast<long long>((width + step - 1) / step) * ((height + step - 1) / step);
  };
  int coarsest = kCoarsePreviewStep;
  while (coarsest < kMaxPreviewStep && samples_at(coarsest) > kCoarsestPreviewSamples)
    coarsest *= 2;
  std::vector<int> steps;
  for (int step = coarsest; step >= kFinestPreviewStep; step /= 2) {
    if (step > pixel_stride) steps.push_back(step);
  }
  return steps;
}

bool same_camera(const renderer::Camera& a, const renderer::Camera& b) {
  return a.position == b.position && a.target == b.target && a.up == b.up &&
         a.vertical_fov_deg == b.vertical_fov_deg &&
         a.orthographic_half_height == b.orthographic_half_height;
}

// Everything the worker thread owns. Members are torn down explicitly (reference, then main
// state, then scene) because the states refer to the scene.
struct Worker {
  WorkerShared& shared;
  std::unique_ptr<LoadedScene> loaded;
  double auto_exposure_ev = 0.0;  // the loaded scene's (renderer/auto_exposure.h)
  renderer::Camera preset;
  // The settings last applied: their scene choice is the loaded scene's, the rest those of the
  // view and the main render shown (what a request's settings are compared with).
  Settings applied;
  // The camera of the view shown (with applied's image settings, what the reference is of).
  std::optional<renderer::Camera> view;
  std::unique_ptr<renderer::RenderJob> main;
  renderer::RenderSettings main_settings;
  std::uint64_t generation = 0;
  std::uint64_t last_serial = 0;  // the latest request applied; every generation is <= it
  int passes_target = 1;
  std::vector<int> preview_steps;  // of the main state
  std::size_t preview_levels_done = 0;
  double seconds_at_last_pass = 0.0;
  ReferenceRender reference;
  // The pixel and render of the inspection published (status.inspection).
  std::optional<std::array<int, 2>> inspected_pixel;
  std::uint64_t inspected_generation = 0;

  explicit Worker(WorkerShared& s)
      : shared(s),
        reference(s.reference_tiles, [this](int passes, double seconds, const std::string& error) {
          reference_pass_done(passes, seconds, error);
        }) {}
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;

  template <typename F>
  void update_status(F&& change) {
    const std::lock_guard<std::mutex> lock(shared.mutex);
    change(shared.status);
  }

  // Runs on the reference thread, after each of its passes.
  void reference_pass_done(int passes, double seconds, const std::string& error) {
    {
      const std::lock_guard<std::mutex> lock(shared.mutex);
      WorkerStatus& st = shared.status;
      st.reference_passes_done = passes;
      st.reference_seconds = seconds;
      if (passes == 1) st.reference_first_pass_seconds = seconds;
      if (!error.empty()) {
        st.reference = ReferencePhase::failed;
        st.error = "rt reference: " + error;
      } else if (passes >= reference.target()) {
        st.reference = ReferencePhase::done;
      }
    }
    shared.wake.notify_all();
  }

  void publish_main(std::unique_ptr<renderer::RenderJob> job) {
    shared.inspector.stop();  // it may read the old render's selector
    {
      const std::lock_guard<std::mutex> lock(shared.slot_mutex);
      shared.slot = &job->state();
    }
    main = std::move(job);
  }

  void drop_main(std::uint64_t floor) {
    shared.inspector.stop();  // it may read this render's selector
    {
      const std::lock_guard<std::mutex> lock(shared.slot_mutex);
      shared.slot = nullptr;
    }
    main.reset();
    shared.tiles.raise_floor(floor);
    shared.preview_tiles.raise_floor(floor);
  }

  void drop_reference(std::uint64_t floor) {
    reference.discard();
    shared.reference_tiles.raise_floor(floor);
    update_status([](WorkerStatus& s) {
      s.reference = ReferencePhase::none;
      s.reference_generation = 0;
      s.reference_tile_count = 0;
      s.reference_passes_done = 0;
      s.reference_first_pass_seconds = 0.0;
    });
  }

  // Cancels the inspection in flight and waits for it, so that the scene may change; the next
  // inspect() starts afresh.
  void stop_inspection() {
    shared.inspector.stop();
    inspected_pixel.reset();
    inspected_generation = 0;
    update_status([](WorkerStatus& st) {
      st.inspection.reset();
      st.inspection_pending = false;
    });
  }

  void tear_down(std::uint64_t floor) {
    stop_inspection();
    drop_reference(floor);
    drop_main(floor);
    loaded.reset();
    view.reset();
  }

  int passes_done() const { return main ? renderer::render_passes_done(main->state()) : 0; }
  bool wants_preview() const { return main && preview_levels_done < preview_steps.size(); }

  // With the reference on, the two renders take turns pass by pass, the reference first: the
  // method's refinement pass k waits for the reference's pass k, so the error compares the means
  // over the same passes as soon as a tile arrives, and neither shares the other's cores (pass 0
  // alone runs beside the reference's, as it always has: the trade plot marks it).
  bool wants_pass() const {
    if (wants_preview()) return true;
    if (!main || passes_done() >= passes_target) return false;
    if (passes_done() == 0 || !reference.has_state() || reference.failed()) return true;
    return !reference.running() &&
           (reference.complete() || reference.passes_done() > passes_done());
  }

  // The reference's next pass is due while it is not ahead of the method's next pass.
  bool reference_due() const {
    return reference.has_state() && !reference.running() && !reference.failed() &&
           !reference.complete() && (!main || reference.passes_done() <= passes_done());
  }

  WorkerPhase resting_phase() const {
    if (wants_pass()) return WorkerPhase::rendering;
    if (main && passes_done() < passes_target) return WorkerPhase::waiting_for_reference;
    return WorkerPhase::idle;
  }

  // The new scene is built before the old one is let go, so a file that cannot be read leaves
  // the old scene, its render and its reference as they were (at the cost of both scenes in
  // memory while the new one loads). Throws what load_scene throws.
  void load(const Settings& s, std::uint64_t serial) {
    update_status([&](WorkerStatus& st) {
      st.phase = WorkerPhase::loading;
      st.loading_scene = s.scene.name;
    });
    std::unique_ptr<LoadedScene> fresh;
    try {
      fresh = load_scene(s.scene, &shared.quitting);
    } catch (...) {
      update_status([](WorkerStatus& st) { st.loading_scene.clear(); });
      throw;
    }
    tear_down(serial);
    loaded = std::move(fresh);
    applied.scene = s.scene;
    preset = loaded->scene.camera;
    auto_exposure_ev = renderer::auto_exposure_ev(
        loaded->scene, *loaded->rays, render_settings_from(s), s.display.curve, &shared.quitting);
    update_status([&](WorkerStatus& st) {
      st.loading_scene.clear();
      st.scene = s.scene.name;
      st.level = s.scene.level;
      st.scene_level = loaded->scene.level;
      st.camera_index = s.scene.camera;
      st.camera_flags = s.scene.camera_flags;
      st.generation = 0;
      st.scene_serial += 1;
      st.scene_name = loaded->scene.name;
      st.light_count = loaded->scene.lights.light_count;
      st.directional_lights = loaded->scene.directional_lights.size();
      st.preset_camera = preset;
      st.world_origin = loaded->scene.world_origin;
      st.build_seconds = loaded->build_seconds;
      st.hierarchy_bytes = lev::hierarchy_bytes(loaded->scene.lights);
      st.auto_exposure_ev = auto_exposure_ev;
    });
  }

  // Loads the scene a request names. When another scene is loaded already and this one cannot
  // be read (any failure but a cancelled load), the old scene stays: the failure is reported as
  // a load error (the UI logs it and returns its settings to the loaded scene), and the request
  // is applied to the old scene. Returns the settings to apply.
  Settings load_or_keep(const Settings& requested, std::uint64_t serial) {
    try {
      load(requested, serial);
      return requested;
    } catch (const LoadCancelled&) {
      throw;
    } catch (const std::exception& e) {
      if (!loaded) throw;
      const std::string message = e.what();
      update_status([&](WorkerStatus& st) {
        st.load_error = message;
        st.load_error_scene = requested.scene.name;
        st.load_error_serial += 1;
      });
    }
    Settings kept = requested;
    kept.scene = applied.scene;
    return kept;
  }

  void apply(const RenderRequest& request, std::uint64_t serial) {
    last_serial = serial;
    update_status([](WorkerStatus& st) {
      st.error.clear();
      st.bad_input = false;
    });
    // A size over the budget is refused before the scene is built or a framebuffer allocated. The
    // rt reference (a second framebuffer) may not fit where the image alone does: the image then
    // renders without it, and the status says why (it used to fail the render until the
    // reference was turned off).
    if (const std::string refusal =
            memory_budget_refusal(request.settings, false, request.memory_budget_bytes);
        !refusal.empty()) {
      throw UsageError(refusal);
    }
    const std::string reference_refusal =
        request.want_reference
            ? memory_budget_refusal(request.settings, true, request.memory_budget_bytes)
            : std::string();
    const bool want_reference = request.want_reference && reference_refusal.empty();
    // What restarts is derived from the groups of the settings that changed (app/settings.h):
    // a setting the scene or the method does not read (a built-in scene's camera index, rt's
    // tolerance) restarts nothing, and a method's setting keeps the reference.
    const Settings& r = request.settings;
    const bool scene_changed = !loaded || restart_needed(applied, r) == Restart::scene;
    Settings s = scene_changed ? load_or_keep(r, serial) : r;
    // An auto exposure is the EV chosen when the scene loaded: compared as that, turning auto on
    // or off at the EV it chose restarts nothing.
    if (s.display.exposure_auto) s.display.exposure_ev = auto_exposure_ev;
    // A request for a scene that could not be loaded asked for that scene's preset view; the
    // old scene keeps the view it had (and with it its render and reference).
    const bool kept_old_scene = scene_changed && s.scene.name != r.scene.name;
    const Restart restart = restart_needed(applied, s);
    renderer::Scene& sc = loaded->scene;
    renderer::RenderSettings rs = render_settings_from(s);
    rs.compute_error_bound = true;  // the "Error bound" view and the stats panel show it
    const renderer::Camera camera =
        kept_old_scene && view ? *view : request.camera.value_or(preset);
    const bool view_changed = !view || !same_camera(camera, *view) || restart >= Restart::view;
    // The missed-light estimate (on while its view is shown) costs shadow rays of its own. Fewer
    // passes than the render has done start it again, so the image is that of the passes asked
    // for (`levrt render --spp N`'s), not of the passes it happened to have.
    const bool fewer_passes = main && passes_done() > s.image.spp;
    const bool main_changed = !main || view_changed || restart >= Restart::render || fewer_passes;

    // Nothing may render on the scene while its camera moves: the reference is dropped when its
    // view is gone and the main state destroyed first. A new method or tolerance changes nothing
    // in the scene (each render state fits its own extent volumes), so the reference keeps going.
    if ((view_changed || !want_reference) && reference.has_state()) drop_reference(serial);
    if (main_changed) {
      stop_inspection();  // it reads the scene, whose camera may move now
      drop_main(serial);
    }
    if (!same_camera(camera, sc.camera)) sc.camera = camera;
    view = camera;
    applied = s;
    passes_target = s.image.spp;

    if (main_changed) {
      update_status([](WorkerStatus& st) { st.phase = WorkerPhase::preparing; });
      auto job = std::make_unique<renderer::RenderJob>(sc, *loaded->rays, rs);
      const double setup_seconds = job->setup_seconds();
      const int tiles = renderer::render_tile_count(job->state());
      const std::size_t method_bytes = renderer::render_selector(job->state()).bookkeeping_bytes();
      std::optional<renderer::RtFallbackProbe> rt_fallback;
      if (const renderer::RtFallbackProbe* probe = renderer::render_rt_fallback(job->state()))
        rt_fallback = *probe;
      publish_main(std::move(job));
      main_settings = rs;
      generation = serial;
      preview_steps = preview_steps_for(rs.width, rs.height, rs.pixel_stride);
      preview_levels_done = 0;
      seconds_at_last_pass = 0.0;
      update_status([&](WorkerStatus& st) {
        st.generation = serial;
        st.width = rs.width;
        st.height = rs.height;
        st.tile_count = tiles;
        st.method = s.method.method;
        st.tolerance = s.method.tolerance;
        st.method_choice = s.method;
        st.missed_draws = rs.missed_draws;
        st.setup_seconds = setup_seconds;
        st.hierarchy_bytes = lev::hierarchy_bytes(sc.lights);
        st.method_bytes = method_bytes;
        st.rt_fallback = rt_fallback;
        st.passes_done = 0;
        st.render_seconds = 0.0;
        st.pass_running = false;
        st.last_pass_seconds = 0.0;
        st.first_pass_seconds = -1.0;
        st.first_pass_shared = false;
        st.preview_levels = static_cast<int>(preview_steps.size());
        st.preview_levels_done = 0;
      });
    }
    update_status([&](WorkerStatus& st) { st.passes_target = s.image.spp; });

    reference.set_target(s.image.spp);
    if (!reference_refusal.empty()) {
      update_status([&](WorkerStatus& st) {
        st.reference = ReferencePhase::failed;
        st.error = "rt reference not rendered: " + reference_refusal;
      });
    }
    if (want_reference && !reference.complete()) {
      if (!reference.has_state()) {
        renderer::RenderSettings ref = rs;
        ref.method = lev::Method::rt;
        ref.missed_draws = 0;  // rt leaves nothing out
        shared.reference_tiles.raise_floor(serial);
        reference.begin(std::make_unique<renderer::RenderJob>(sc, *loaded->rays, ref), serial);
        update_status([&](WorkerStatus& st) {
          st.reference = ReferencePhase::rendering;
          st.reference_generation = serial;
          st.reference_tile_count = reference.tile_count();
          st.reference_started = Clock::now();
          st.reference_seconds = 0.0;
          st.reference_passes_done = 0;
          st.reference_first_pass_seconds = 0.0;
        });
      }
      if (reference_due()) reference.resume();
    }
    // A new number of passes makes a complete reference go on, or one ahead complete.
    if (reference.has_state() && !reference.failed()) {
      const ReferencePhase phase =
          reference.complete() ? ReferencePhase::done : ReferencePhase::rendering;
      update_status([&](WorkerStatus& st) { st.reference = phase; });
    }
    update_status([&](WorkerStatus& st) { st.reference_passes_target = s.image.spp; });
    inspect(request.inspect_pixel);
  }

  // The pinned pixel's inspection, started on the inspection task (a new pixel cancels the one in
  // flight) with the render's selector (InspectionTask::start), once per pixel and render; the
  // task publishes it when done.
  void inspect(const std::optional<std::array<int, 2>>& pixel) {
    if (pixel == inspected_pixel && generation == inspected_generation) return;
    shared.inspector.stop();
    inspected_pixel = pixel;
    inspected_generation = generation;
    const bool inside =
        pixel && main && (*pixel)[0] < main_settings.width && (*pixel)[1] < main_settings.height;
    update_status([&](WorkerStatus& st) {
      st.inspection.reset();
      st.inspection_pending = inside;
    });
    if (inside) {
      shared.inspector.start(loaded->scene, *loaded->rays, main_settings,
                             renderer::render_selector(main->state()), (*pixel)[0], (*pixel)[1],
                             generation);
    }
  }

  // One preview level over the whole frame; a cancelled level is rendered again from the start.
  void render_preview_level() {
    renderer::RenderState& state = main->state();
    const int step = preview_steps[preview_levels_done];
    update_status([&](WorkerStatus& st) {
      st.phase = WorkerPhase::rendering;
      st.preview_step = step;
    });
    const renderer::Framebuffer& preview = renderer::render_preview(state);
    const std::uint64_t gen = generation;
    const auto on_tile_done = [&](int tile) {
      TileRect r;
      renderer::render_tile_rect(state, tile, r.x0, r.y0, r.x1, r.y1);
      shared.preview_tiles.post(copy_preview_tile(preview, step, main_settings.width,
                                                  main_settings.height, gen, tile, r));
    };
    if (!main->pass(&shared.cancel, on_tile_done, step)) return;
    preview_levels_done += 1;
    update_status(
        [&](WorkerStatus& st) { st.preview_levels_done = static_cast<int>(preview_levels_done); });
  }

  void render_one_pass() {
    if (wants_preview()) {
      render_preview_level();
      return;
    }
    renderer::RenderState& state = main->state();
    const int pass = renderer::render_passes_done(state);
    const bool shared_cpu = pass == 0 && reference.running();
    update_status([&](WorkerStatus& st) {
      st.phase = WorkerPhase::rendering;
      st.pass_running = true;
      st.pass_started = Clock::now();
      if (shared_cpu) st.first_pass_shared = true;
    });
    const renderer::Framebuffer& framebuffer = renderer::render_framebuffer(state);
    const std::uint64_t gen = generation;
    const auto on_tile_done = [&](int tile) {
      TileRect r;
      renderer::render_tile_rect(state, tile, r.x0, r.y0, r.x1, r.y1);
      shared.tiles.post(copy_tile(framebuffer, gen, tile, pass, r));
    };
    const bool complete = main->pass(&shared.cancel, on_tile_done);
    const double seconds = renderer::render_seconds(state);
    const std::size_t method_bytes = renderer::render_selector(state).bookkeeping_bytes();
    double pass_seconds = 0.0;
    if (complete) {
      pass_seconds = seconds - seconds_at_last_pass;
      seconds_at_last_pass = seconds;
    }
    update_status([&](WorkerStatus& st) {
      st.pass_running = false;
      st.render_seconds = seconds;
      st.passes_done = renderer::render_passes_done(state);
      st.method_bytes = method_bytes;
      if (complete) {
        st.last_pass_seconds = pass_seconds;
        if (pass == 0) st.first_pass_seconds = seconds;
      }
    });
  }

  void fail(const std::string& message, bool bad_input, std::uint64_t serial) {
    stop_inspection();
    drop_reference(serial);
    drop_main(serial);
    view.reset();
    update_status([&](WorkerStatus& st) {
      st.phase = WorkerPhase::failed;
      st.error = message;
      st.bad_input = bad_input;
      st.generation = 0;
    });
  }
};

// Linux nice values are per thread and inherited by the threads a thread creates, so the tile
// workers that oneTBB and Embree start from this thread (and the reference thread) inherit it
// too. The UI thread and the GL driver's threads keep the normal priority: they get a core the
// moment they need one, and the tracer still gets every cycle they leave.
void lower_this_thread_priority() {
  constexpr int kTracerNice = 10;
  const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
  const int current = ::getpriority(PRIO_PROCESS, tid);
  if (current < kTracerNice) ::setpriority(PRIO_PROCESS, tid, kTracerNice);
}

void run_worker(WorkerShared& shared) {
  lower_this_thread_priority();
  Worker w(shared);
  for (;;) {
    // Outside the lock: resuming joins the reference's previous thread, which takes the lock
    // to report its pass.
    if (w.reference_due()) w.reference.resume();
    std::optional<RenderRequest> request;
    std::uint64_t serial = 0;
    {
      std::unique_lock<std::mutex> lock(shared.mutex);
      shared.wake.wait(lock, [&] {
        return shared.quit || shared.pending || w.wants_pass() || w.reference_due();
      });
      if (shared.quit) break;
      if (shared.pending) {
        request = std::move(shared.pending);
        shared.pending.reset();
        serial = shared.pending_serial;
        shared.cancel.store(false);
      }
    }
    if (!request && !w.wants_pass()) continue;  // the reference's turn
    try {
      if (request) {
        w.apply(*request, serial);
      } else {
        w.render_one_pass();
      }
      // The serial and the phase change together, so "request taken and idle" means done.
      w.update_status([&](WorkerStatus& st) {
        st.phase = w.resting_phase();
        if (request) st.request_serial = serial;
      });
    } catch (const std::exception& e) {
      // UsageError and std::invalid_argument are the input's fault (as levrt's exit code 2 says).
      const bool bad_input = dynamic_cast<const UsageError*>(&e) != nullptr ||
                             dynamic_cast<const std::invalid_argument*>(&e) != nullptr;
      w.fail(e.what(), bad_input, w.last_serial + 1);
      if (request) w.update_status([&](WorkerStatus& st) { st.request_serial = serial; });
    }
  }
  w.tear_down(w.last_serial + 1);
}

}  // namespace

const char* worker_phase_text(WorkerPhase phase) {
  switch (phase) {
    case WorkerPhase::idle:
      return "idle";
    case WorkerPhase::loading:
      return "building the scene";
    case WorkerPhase::preparing:
      return "fitting the extent volumes";
    case WorkerPhase::rendering:
      return "rendering";
    case WorkerPhase::waiting_for_reference:
      return "refinement paused while the rt reference renders";
    case WorkerPhase::failed:
      return "failed";
  }
  return "";
}

double elapsed_render_seconds(const WorkerStatus& status, Clock::time_point now) {
  double seconds = status.render_seconds;
  if (status.pass_running)
    seconds += std::chrono::duration<double>(now - status.pass_started).count();
  return seconds;
}

RenderWorker::RenderWorker() : shared_(std::make_unique<WorkerShared>()) {
  thread_ = std::thread([shared = shared_.get()] { run_worker(*shared); });
}

RenderWorker::~RenderWorker() {
  shut_down();
}

ShutdownReport RenderWorker::shut_down() {
  ShutdownReport report;
  if (!thread_.joinable()) return report;
  const auto tiles_posted = [&] {
    return shared_->tiles.posted() + shared_->preview_tiles.posted() +
           shared_->reference_tiles.posted();
  };
  {
    const std::lock_guard<std::mutex> lock(shared_->mutex);
    shared_->quit = true;
    shared_->cancel.store(true);
    shared_->quitting.store(true);
  }
  const std::uint64_t posted_at_quit = tiles_posted();
  shared_->wake.notify_all();
  thread_.join();
  report.tiles_finished_after_quit = tiles_posted() - posted_at_quit;
  return report;
}

std::uint64_t RenderWorker::post(const RenderRequest& request) {
  std::uint64_t serial = 0;
  {
    const std::lock_guard<std::mutex> lock(shared_->mutex);
    serial = ++shared_->last_serial;
    shared_->pending = request;
    shared_->pending_serial = serial;
    shared_->cancel.store(true);
  }
  shared_->wake.notify_all();
  return serial;
}

WorkerStatus RenderWorker::status() const {
  const std::lock_guard<std::mutex> lock(shared_->mutex);
  return shared_->status;
}

TakenTiles RenderWorker::take_tiles() {
  return shared_->tiles.take_all();
}

TakenTiles RenderWorker::take_preview_tiles() {
  return shared_->preview_tiles.take_all();
}

TakenTiles RenderWorker::take_reference_tiles() {
  return shared_->reference_tiles.take_all();
}

std::vector<TileRect> RenderWorker::tiles_in_flight() const {
  std::vector<TileRect> rects;
  const std::lock_guard<std::mutex> lock(shared_->slot_mutex);
  if (!shared_->slot) return rects;
  const renderer::RenderState& state = *shared_->slot;
  const int count = renderer::render_tile_count(state);
  for (int tile = 0; tile < count; ++tile) {
    if (renderer::render_tile_status(state, tile) != renderer::TileStatus::rendering) continue;
    TileRect r;
    renderer::render_tile_rect(state, tile, r.x0, r.y0, r.x1, r.y1);
    rects.push_back(r);
  }
  return rects;
}

}  // namespace app::viewer
