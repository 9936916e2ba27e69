// The viewer's background side. One worker thread owns the scene: it loads (rebuilds) it, sets
// the camera, makes the render jobs (renderer/render_service.h: each fits its own extent volumes
// for its tolerance) and runs their passes one after another, posting every finished tile to a
// DisplayBuffer from the tile-done callback. The UI thread only posts requests (the whole view it
// wants), reads a status snapshot and takes tiles; posting sets the cancel flag, so the pass in
// flight stops between tiles and the worker picks the request up at once. A render state whose
// settings did not change is kept, and its interrupted pass resumes. The `rt` reference of the same
// view renders on a second thread (ReferenceRender), as many passes as the method, the two taking
// turns pass by pass; it keeps rendering through method and tolerance changes (the scene is only
// read) and is dropped when the view (camera, size, depth, subsample) changes. Every new render
// state starts with preview passes (pixel steps 8, 4, 2: renderer::render_pass's preview_step)
// posted to a display buffer of their own, so preview samples never mix with the render's tiles.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "app/render_command.h"
#include "app/settings.h"
#include "app/viewer/display_buffer.h"
#include "app/viewer/inspector_rows.h"
#include "lev/methods.h"
#include "renderer/camera.h"

namespace app::viewer {

struct RenderRequest {
  Settings settings;
  std::optional<renderer::Camera> camera;  // empty: the scene's preset view
  bool want_reference = false;             // render the rt reference of this view
  // The pinned pixel to inspect (the inspector, inspector_rows.h), in the render's image pixels.
  std::optional<std::array<int, 2>> inspect_pixel;
  // The memory the render may plan for (the image, and the reference when wanted): a size over
  // it fails the request; a reference over it is not rendered, the image still is.
  std::uint64_t memory_budget_bytes = kRenderMemoryBudgetBytes;
};

enum class WorkerPhase { idle, loading, preparing, rendering, waiting_for_reference, failed };
const char* worker_phase_text(WorkerPhase phase);

enum class ReferencePhase { none, rendering, done, failed };

struct WorkerStatus {
  WorkerPhase phase = WorkerPhase::idle;
  std::string error;
  bool bad_input = false;            // the failure was the request's (a scene or size it refused)
  std::uint64_t request_serial = 0;  // the latest request the worker has fully applied

  // A scene that could not be loaded while another one stayed loaded: the whole message, the
  // scene as the request named it, and a serial that bumps with every such failure.
  std::string load_error;
  std::string load_error_scene;
  std::uint64_t load_error_serial = 0;
  std::string loading_scene;  // the scene being loaded now (empty when none is)

  // The loaded scene.
  std::uint64_t scene_serial = 0;  // bumps with every (re)load
  std::string scene;               // as the request named it (model name or file)
  std::string scene_name;          // as the scene calls itself
  int level = 0;                   // as the request named it (the settings' level)
  int scene_level = 0;             // as the scene states it (a scene file's own; 0 for glTF)
  int camera_index = 0;
  scenes::CameraFlags camera_flags;
  std::uint64_t light_count = 0;
  std::size_t directional_lights = 0;  // suns, outside the hierarchy
  renderer::Camera preset_camera;      // in render space
  glm::vec3 world_origin{0.0f};        // world = render space + this (scenes/render_space.h)
  double build_seconds = 0.0;          // model, hierarchy and Embree build
  std::size_t hierarchy_bytes = 0;
  // --exposure auto's choice for this scene (renderer/auto_exposure.h), made at its load when the
  // settings asked for auto; the renders cull at it while auto is on.
  double auto_exposure_ev = 0.0;

  // The render being shown; generation is the serial of the request that started it.
  std::uint64_t generation = 0;
  int width = 0;
  int height = 0;
  int tile_count = 0;
  lev::Method method = lev::Method::lev;
  double tolerance = 0.0;
  lev::MethodChoice method_choice;  // the render's method settings (tolerance among them)
  int missed_draws = 0;             // the missed-light estimate's draws per point (0: off)
  double setup_seconds = 0.0;       // making the render state: extent volumes and selector
  std::size_t method_bytes = 0;
  // The probe that chose between the method and rt's loop (renderer/rt_fallback.h), if made.
  std::optional<renderer::RtFallbackProbe> rt_fallback;
  int passes_done = 0;
  int passes_target = 0;
  double render_seconds = 0.0;  // inside render_pass, up to the last call's end
  bool pass_running = false;
  std::chrono::steady_clock::time_point pass_started;
  double last_pass_seconds = 0.0;
  double first_pass_seconds = -1.0;  // pass 0's time once it is complete
  int preview_levels = 0;            // preview passes this render starts with
  int preview_levels_done = 0;
  int preview_step = 0;            // pixel step of the preview level rendering now
  bool first_pass_shared = false;  // the reference rendered while pass 0 did

  // The rt reference of the same view.
  ReferencePhase reference = ReferencePhase::none;
  std::uint64_t reference_generation = 0;
  int reference_tile_count = 0;
  std::chrono::steady_clock::time_point reference_started;
  double reference_seconds = 0.0;
  // It renders as many passes as the method (the settings' passes), taking turns with it.
  int reference_passes_done = 0;
  int reference_passes_target = 0;
  double reference_first_pass_seconds = 0.0;  // its pass 0 (0: not done yet)

  // The inspection of the pinned pixel in the render shown (null: none asked for, the pixel is
  // outside the image, or it is still pending: computed on a thread of its own).
  std::shared_ptr<const PublishedInspection> inspection;
  bool inspection_pending = false;
};

// Render time so far, the running pass included.
double elapsed_render_seconds(const WorkerStatus& status,
                              std::chrono::steady_clock::time_point now);

// What a worker did between the quit and its thread's end: the tiles that finished (render,
// previews and the rt reference together). Only the tiles in flight at the quit may finish; a
// worker that went on rendering would report a pass's worth or more.
struct ShutdownReport {
  std::uint64_t tiles_finished_after_quit = 0;
};

struct WorkerShared;  // the mutex-guarded mailbox between the UI and the worker thread

class RenderWorker {
 public:
  RenderWorker();
  ~RenderWorker();  // shut_down(), unless called already
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

  // Replaces any request not taken yet and cancels the pass in flight; returns the request's
  // serial (the generation of the render it starts, if it starts one).
  std::uint64_t post(const RenderRequest& request);
  WorkerStatus status() const;
  TakenTiles take_tiles();
  TakenTiles take_preview_tiles();
  TakenTiles take_reference_tiles();
  // Tiles of the current render that a worker is tracing right now.
  std::vector<TileRect> tiles_in_flight() const;
  // Cancels everything and joins the worker's threads; after it only status() and the take_*
  // calls may be made. A second call reports nothing more.
  ShutdownReport shut_down();

 private:
  std::unique_ptr<WorkerShared> shared_;
  std::thread thread_;
};

}  // namespace app::viewer
