#include "app/viewer/viewer_app.h"

#include <sys/stat.h>
#include <unistd.h>

#define GLFW_INCLUDE_NONE
#include <GL/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "app/interrupt.h"
#include "app/output_files.h"
#include "app/render_command.h"
#include "app/viewer/frame_log.h"
#include "app/viewer/frame_progress.h"
#include "app/viewer/gl_texture.h"
#include "app/viewer/image_view.h"
#include "app/viewer/inspector_panel.h"
#include "app/viewer/render_worker.h"
#include "app/viewer/scene_open_panel.h"
#include "app/viewer/scene_opening.h"
#include "app/viewer/scripted_changes.h"
#include "app/viewer/settings_panel.h"
#include "app/viewer/snapshot_panel.h"
#include "app/viewer/snapshot_writer.h"
#include "app/viewer/stats_panel.h"
#include "app/viewer/trade_plot.h"
#include "app/viewer/view_panel.h"
#include "app/viewer/viewer_state.h"
#include "scenes/scene_file.h"
#include "scenes/scene_inputs.h"

namespace app::viewer {
namespace {

constexpr double kFrameSeconds = 1.0 / 60.0;  // display rate the loop paces itself to
constexpr float kPanelWidth = 430.0f;
constexpr float kSideBySideWidth = 720.0f;  // narrower results show statistics and plot as tabs
constexpr float kRoomyHeight = 720.0f;      // lower windows pack the panel's rows closer
// A fit resolution follows a new window size once it has held this long, so dragging the border
// does not restart the render every frame.
constexpr double kResizeSettleSeconds = 0.3;

struct WindowSize {
  int width = 0;
  int height = 0;
};

WindowSize parse_window_flag(const std::string& text) {
  WindowSize size;
  if (!parse_window_size(text, size.width, size.height))
    throw UsageError("--window: must be WIDTHxHEIGHT from 320x240 to " +
                     std::to_string(kMaxImageSide) + "x" + std::to_string(kMaxImageSide) +
                     ", got '" + text + "'");
  return size;
}

// GLFW for the lifetime of the viewer. Without a display it throws NoDisplayError, whose one
// line names the headless route.
class GlfwLibrary {
 public:
  GlfwLibrary() {
    const char* display = std::getenv("DISPLAY");
    if (display == nullptr || display[0] == '\0') {
      throw NoDisplayError(
          "view: no display (DISPLAY is not set); use `levrt render` to render headless");
    }
    if (glfwInit() != GLFW_TRUE) {
      const char* description = nullptr;
      glfwGetError(&description);
      throw NoDisplayError(std::string("view: cannot open display '") + display + "' (" +
                           (description ? description : "glfwInit failed") +
                           "); use `levrt render` to render headless");
    }
  }
  ~GlfwLibrary() { glfwTerminate(); }
  GlfwLibrary(const GlfwLibrary&) = delete;
  GlfwLibrary& operator=(const GlfwLibrary&) = delete;
};

class Window {
 public:
  Window(int width, int height) {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    handle_ = glfwCreateWindow(width, height, "levrt", nullptr, nullptr);
    if (!handle_) {
      const char* description = nullptr;
      glfwGetError(&description);
      throw std::runtime_error(std::string("cannot create a GL 3.3 core window: ") +
                               (description ? description : "unknown GLFW error"));
    }
    glfwMakeContextCurrent(handle_);
    glfwSwapInterval(1);
    // ImGui's GLFW backend leaves the drop callback and the user pointer alone.
    glfwSetWindowUserPointer(handle_, this);
    glfwSetDropCallback(handle_, [](GLFWwindow* w, int count, const char** paths) {
      auto* self = static_cast<Window*>(glfwGetWindowUserPointer(w));
      for (int i = 0; i < count; ++i) self->dropped_.emplace_back(paths[i]);
    });
  }
  ~Window() { glfwDestroyWindow(handle_); }
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;
  GLFWwindow* get() const { return handle_; }
  // The paths dropped on the window since the last call (filled while events are polled).
  std::vector<std::string> take_dropped() { return std::exchange(dropped_, {}); }

 private:
  GLFWwindow* handle_ = nullptr;
  std::vector<std::string> dropped_;
};

class ImGuiSession {
 public:
  explicit ImGuiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0.0f;
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
  }
  ~ImGuiSession() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
};

// The texture on screen and what it was composed from.
enum class Await { nothing, idle, preview, resize };

// The fit resolution's size for the image area, and when the area last changed.
struct FitTracker {
  int width = 0, height = 0;  // the size the area asked for most recently
  Clock::time_point since;
  bool fitted_once = false;
  std::string resolution;  // of the last frame
};

// Follows the image area with the render size while the resolution is fit: at once while
// nothing has been shown yet (the first frames' layout settles while the scene builds) and for a
// change of the fit scale, after the area held still for kResizeSettleSeconds otherwise (and not
// while a mouse button is down, a drag in progress).
void follow_image_area(ViewerState& state, FitTracker& fit, Clock::time_point now) {
  const int divisor = fit_divisor(state.settings.resolution);
  const bool scale_changed = state.settings.resolution != fit.resolution;
  fit.resolution = state.settings.resolution;
  state.fit_pending = false;
  if (divisor == 0 || state.image_area_width <= 0 || state.image_area_height <= 0) return;
  const auto [width, height] =
      fit_render_size(state.image_area_width, state.image_area_height, divisor);
  if (width != fit.width || height != fit.height) {
    fit.width = width;
    fit.height = height;
    fit.since = now;
  }
  if (width == state.settings.image.width && height == state.settings.image.height) {
    fit.fitted_once = true;
    return;
  }
  const bool settled =
      seconds_between(fit.since, now) >= kResizeSettleSeconds && !ImGui::IsAnyMouseDown();
  if (!fit.fitted_once || state.image.generation == 0 || scale_changed || settled) {
    set_fit_size(state, width, height);
    fit.fitted_once = true;
  } else {
    state.fit_pending = true;
  }
}

// Whether an output goes to standard output: "-", or a name for the file or pipe it is
// (/dev/stdout, /proc/self/fd/1).
bool writes_standard_output(const std::string& path) {
  if (path == kStandardOutputName) return true;
  struct stat out {
  }, named{};
  return ::fstat(STDOUT_FILENO, &out) == 0 && ::stat(path.c_str(), &named) == 0 &&
         out.st_dev == named.st_dev && out.st_ino == named.st_ino;
}

void write_screenshot(GLFWwindow* window, const std::string& path) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window, &width, &height);
  app::write_png_rgb8(path, width, height, read_window_rgb8(width, height));
}

// The window's layout: the panel on the left; on the right the picture above the results
// (statistics next to the speed/accuracy plot, or as tabs when narrow). The results are as tall as
// the statistics' fixed rows (stats_panel.h: so no row is cut), within a third and three fifths of
// the window: the layout is a function of the window's size alone, so nothing the panels show
// (a row, a tab) moves the picture's border and, at a fit resolution, restarts the render.
struct Layout {
  ImVec2 panel_size, picture_pos, picture_size, results_pos, results_size;
};

Layout window_layout(const ImVec2& display) {
  Layout l;
  const float panel_width = std::min(kPanelWidth, display.x * 0.5f);
  const ImGuiStyle& style = ImGui::GetStyle();
  // The title bar, the padding, the table and the spacing after it.
  float content_height = ImGui::GetFrameHeight() + 2.0f * style.WindowPadding.y +
                         stats_section_height() + style.ItemSpacing.y;
  if (display.x - panel_width < kSideBySideWidth)  // the tab bar above the statistics
    content_height += ImGui::GetFrameHeight() + style.ItemSpacing.y;
  const float results_height = std::clamp(content_height, display.y / 3.0f, display.y * 0.6f);
  l.panel_size = ImVec2(panel_width, display.y);
  l.picture_pos = ImVec2(panel_width, 0.0f);
  l.picture_size = ImVec2(display.x - panel_width, display.y - results_height);
  l.results_pos = ImVec2(panel_width, display.y - results_height);
  l.results_size = ImVec2(display.x - panel_width, results_height);
  return l;
}

// The windows draw no background of their own: the clear colour is the style's window colour,
// which saves filling most of the window twice (the fill is what a software GL spends its time on).
constexpr ImGuiWindowFlags kFixedWindow = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                          ImGuiWindowFlags_NoCollapse |
                                          ImGuiWindowFlags_NoBackground;

void draw_panel(ViewerState& state, SnapshotWriter& snapshots, Clock::time_point now,
                const Layout& layout) {
  ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
  ImGui::SetNextWindowSize(layout.panel_size);
  // Below kRoomyHeight the rows pack closer, so the whole panel fits from 600 pixels up.
  const bool compact = layout.panel_size.y < kRoomyHeight;
  if (compact) ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(8.0f, 2.0f));
  ImGui::Begin("levrt", nullptr, kFixedWindow);
  // B flips the picture between the method's and rt's (not while a text field has the keys).
  if (!ImGui::GetIO().WantTextInput && ImGui::IsKeyPressed(GLFW_KEY_B, false))
    set_ab_rt(state, !state.ab_rt);
  draw_status_line(state, now);
  if (ImGui::CollapsingHeader("Scene and method", ImGuiTreeNodeFlags_DefaultOpen))
    draw_settings_section(state);
  if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) draw_view_section(state);
  if (ImGui::CollapsingHeader("rt reference", ImGuiTreeNodeFlags_DefaultOpen))
    draw_reference_section(state, now);
  if (ImGui::CollapsingHeader("Snapshot", ImGuiTreeNodeFlags_DefaultOpen)) {
    draw_snapshot_section(state, snapshots);
  }
  if (!state.messages.empty() &&
      ImGui::CollapsingHeader("Messages", ImGuiTreeNodeFlags_DefaultOpen))
    draw_messages_section(state);
  ImGui::End();
  if (compact) ImGui::PopStyleVar();
}

void draw_trade_section(const ViewerState& state) {
  ImGui::TextUnformatted("Pass-0 time vs average error against rt");
  draw_trade_plot(state.trade, state.status.generation);
}

void draw_results(const ViewerState& state, Clock::time_point now, const Layout& layout) {
  ImGui::SetNextWindowPos(layout.results_pos);
  ImGui::SetNextWindowSize(layout.results_size);
  ImGui::Begin("Statistics and the speed/accuracy trade", nullptr, kFixedWindow);
  if (layout.results_size.x < kSideBySideWidth) {
    if (ImGui::BeginTabBar("results")) {
      if (ImGui::BeginTabItem("Statistics")) {
        draw_stats_section(state, now);
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("Speed/accuracy")) {
        draw_trade_section(state);
        ImGui::EndTabItem();
      }
      ImGui::EndTabBar();
    }
  } else if (ImGui::BeginTable("results", 2,
                               ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchSame)) {
    ImGui::TableNextColumn();
    draw_stats_section(state, now);
    ImGui::TableNextColumn();
    draw_trade_section(state);
    ImGui::EndTable();
  }
  ImGui::End();
}

void draw_picture_window(ViewerState& state, const Picture& picture, const Layout& layout) {
  ImGui::SetNextWindowPos(layout.picture_pos);
  ImGui::SetNextWindowSize(layout.picture_size);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4.0f, 4.0f));
  ImGui::Begin("picture", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse |
                   ImGuiWindowFlags_NoBackground);
  draw_image_view(state, picture.texture);
  ImGui::End();
  ImGui::PopStyleVar();
  draw_inspector_window(state, layout.picture_pos, layout.picture_size);
}

}  // namespace

int run_viewer(const Settings& settings, const ViewerFlags& flags) {
  const WindowSize window_size = parse_window_flag(flags.window);
  const std::vector<ScriptedChange> script = parse_scripted_changes(flags.changes);
  check_script(script, settings, flags.frames);
  if (!flags.screenshot.empty() && flags.frames == 0)
    throw UsageError("--screenshot: needs --frames N");
  if (settings.resolution == "typed") check_memory_budget(settings, false);
  // The outputs' rule, before the window opens: no output is an input or another output.
  std::vector<std::string> inputs;
  std::vector<OutputPath> outputs;
  if (!flags.script.empty()) inputs.push_back(flags.script);
  if (!flags.screenshot.empty())
    outputs.push_back({"--screenshot", flags.screenshot, ".png", "PNG"});
  if (!flags.controls.empty()) outputs.push_back({"--controls", flags.controls, ".json", "JSON"});
  std::vector<std::string> scenes_read = {settings.scene.name};
  for (const ScriptedChange& c : script) {
    if (c.key == "screenshot") outputs.push_back({"--set screenshot", c.value, ".png", "PNG"});
    if (c.key == "scene" || c.key == "drop") scenes_read.push_back(c.value);
  }
  std::vector<std::string> all_inputs = inputs;
  if (!settings.scene.camera_flags.from_file.empty())
    all_inputs.push_back(settings.scene.camera_flags.from_file);
  for (const std::string& scene : scenes_read) {
    for (const std::string& file : scenes::scene_input_files(scene)) all_inputs.push_back(file);
  }
  check_output_paths(outputs, all_inputs);

  // Ctrl-C, SIGTERM and SIGHUP close the window like its close button (exit 130). A UI frame or
  // the worker's scene load may not notice at once (a loaded display, a large glTF's parse): the
  // watchdog ends the process kLoadGraceSeconds after the signal, once no snapshot or screenshot
  // is being written. It outlives the worker, whose destructor waits for the load.
  const InterruptScope interrupt_scope;
  const InterruptWatchdog shutdown_watchdog;
  GlfwLibrary glfw;
  Window window(window_size.width, window_size.height);
  ImGuiSession imgui(window.get());

  ViewerState state;
  state.settings = settings;
  state.mouse_input = flags.frames == 0 || flags.real_input;
  state.record_controls = !flags.controls.empty();
  state.print_messages = flags.frames > 0;
  state.exposure_chosen = flags.exposure_given;
  state.display_chosen = flags.display_given;
  state.other_inputs = inputs;
  state.other_outputs = outputs;
  const bool output_on_stdout =
      std::any_of(outputs.begin(), outputs.end(),
                  [](const OutputPath& o) { return writes_standard_output(o.path); });
  state.notes = output_on_stdout ? stderr : stdout;
  std::string controls_written;
  FrameLog log;
  log.enabled = flags.report_fps;
  Picture picture;
  ErrorClock error_clock;
  SnapshotWriter snapshots;
  int exit_code = 0;
  std::string bad_input_error;  // the first scene's
  std::string snapshot_error;   // the first scripted snapshot that failed
  // What the session wrote, named when a signal ends it (never "no output written" then).
  std::vector<std::string> written;
  std::string snapshot_noted;
  std::vector<std::string> snapshot_messages;  // each snapshot's "wrote ...", printed at the end
  const auto note_snapshot = [&] {
    const std::string m = snapshots.busy() || snapshots.failed() ? "" : snapshots.message();
    if (m != snapshot_noted && m.rfind("wrote ", 0) == 0) {
      written.push_back(m.substr(6));
      snapshot_messages.push_back(m);
    }
    if (!m.empty()) snapshot_noted = m;
  };
  {
    RenderWorker worker;
    std::uint64_t last_posted = 0;
    int script_frame = 0;
    Await awaiting = Await::nothing;
    int resize_width = 0, resize_height = 0;  // a scripted resize waits for the window to follow
    Clock::time_point previous_start = Clock::now();
    Clock::time_point next_frame = previous_start;
    bool first = true;
    FitTracker fit;
    std::optional<std::array<int, 2>> inspect_pixel_posted;  // for the inspection's latency
    // A scripted snapshot waits for the render (and the reference, if asked for) to complete.
    std::optional<std::string> pending_snapshot;

    while (!glfwWindowShouldClose(window.get()) && !InterruptScope::flag().load()) {
      for (Clock::time_point t = Clock::now(); t < next_frame; t = Clock::now()) {
        glfwWaitEventsTimeout(seconds_between(t, next_frame));
      }
      glfwPollEvents();
      const Clock::time_point now = Clock::now();
      next_frame = now + std::chrono::duration_cast<Clock::duration>(
                             std::chrono::duration<double>(kFrameSeconds));
      const double frame_ms = first ? 0.0 : 1000.0 * seconds_between(previous_start, now);
      previous_start = now;

      std::vector<std::string> screenshots;
      // No file is written before the first scene has loaded: a bad scene writes nothing. A frame
      // with a screenshot or snapshot holds until then (as the frame count does for an await).
      const bool first_load_pending =
          state.status.scene_serial == 0 && state.status.phase != WorkerPhase::failed;
      const bool frame_writes = std::any_of(script.begin(), script.end(), [&](const auto& c) {
        return c.frame == script_frame && (c.key == "screenshot" || c.key == "snapshot");
      });
      // Copy camera waits for the scene's camera, as a screenshot waits for its first load.
      const bool frame_copies = std::any_of(script.begin(), script.end(), [&](const auto& c) {
        return c.frame == script_frame && c.key == "copy";
      });
      const bool hold_frame =
          pending_snapshot || (first_load_pending && frame_writes) ||
          (frame_copies && !scene_ready(state) && state.status.phase != WorkerPhase::failed);
      if (awaiting == Await::nothing && !hold_frame) {
        for (const ScriptedChange& c : script) {
          if (c.frame != script_frame) continue;
          switch (apply_scripted_change(state, c)) {
            case ScriptAction::none:
              break;
            case ScriptAction::resize_window:
              parse_window_size(c.value, resize_width, resize_height);
              glfwSetWindowSize(window.get(), resize_width, resize_height);
              awaiting = Await::resize;
              break;
            case ScriptAction::snapshot:
              pending_snapshot = c.value;
              break;
            case ScriptAction::screenshot:
              screenshots.push_back(c.value);
              break;
            case ScriptAction::await_idle:
              awaiting = Await::idle;
              break;
            case ScriptAction::await_preview:
              awaiting = Await::preview;
              break;
          }
        }
      }

      take_worker_results(state, worker, log, now);
      if (const PublishedInspection* shown = current_inspection(state))
        record_inspection_shown(log, now, 1000.0 * shown->seconds);
      follow_scene_loads(state);
      open_dropped_files(state, window.take_dropped());
      // A first scene that cannot be read (or a size over the memory budget) is bad input.
      if (state.status.phase == WorkerPhase::failed && state.status.bad_input &&
          state.status.scene_serial == 0) {
        bad_input_error = state.status.error;
        break;
      }
      update_error(state, error_clock, now, false);
      add_trade_point_when_ready(state, error_clock, now);
      take_requested_snapshot(state, snapshots, now);  // Save snapshot, at a whole pass
      if (pending_snapshot && render_settled(state, last_posted)) {
        state.snapshot_folder = *pending_snapshot;
        pending_snapshot.reset();
        snapshots.wait();
        snapshots.start(make_snapshot_job(state, now));
        snapshots.wait();  // scripted: its outcome decides the exit code
        if (snapshots.failed() && snapshot_error.empty()) snapshot_error = snapshots.message();
      }
      note_snapshot();
      int window_width = 0, window_height = 0;
      glfwGetWindowSize(window.get(), &window_width, &window_height);
      if ((awaiting == Await::idle && render_settled(state, last_posted)) ||
          (awaiting == Await::preview && preview_settled(state, last_posted)) ||
          (awaiting == Await::resize && window_width == resize_width &&
           window_height == resize_height)) {
        awaiting = Await::nothing;
      }
      // A scripted session ends once its first scene has loaded (or failed), so its outputs and
      // exit code are of that scene.
      const bool last_frame = flags.frames > 0 && awaiting == Await::nothing && !hold_frame &&
                              !pending_snapshot && !first_load_pending &&
                              script_frame + 1 >= flags.frames;
      const bool screenshot_now = !screenshots.empty() || (last_frame && !flags.screenshot.empty());

      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      const Layout layout = window_layout(ImGui::GetIO().DisplaySize);
      state.control_rects.clear();
      draw_panel(state, snapshots, now, layout);
      draw_results(state, now, layout);
      // A screenshot shows the error of every tile received (the difference and mask views).
      if (screenshot_now) update_error(state, error_clock, now, true);
      compose_picture(state, picture, error_clock, now, screenshot_now);
      draw_picture_window(state, picture, layout);
      follow_image_area(state, fit, now);
      ImGui::Render();
      if (state.record_controls && !first_load_pending) {
        const std::string controls =
            controls_json(state.control_rects, state.settings, state.view,
                          ImGui::IsAnyItemActive() || ImGui::IsAnyMouseDown());
        if (controls != controls_written) {
          write_text_file(flags.controls, controls);
          if (controls_written.empty()) written.push_back(flags.controls);
        }
        controls_written = controls;
      }

      if (state.inspect_pixel != inspect_pixel_posted) {
        if (state.inspect_pixel)
          record_inspect_asked(log, (*state.inspect_pixel)[0], (*state.inspect_pixel)[1], now);
        inspect_pixel_posted = state.inspect_pixel;
      }
      if (state.request_dirty) {
        last_posted = worker.post(make_request(state));
        if (!state.change_label.empty()) record_post(log, state.change_label, last_posted, now);
        state.request_dirty = false;
        state.change_label.clear();
      }

      int fb_width = 0, fb_height = 0;
      glfwGetFramebufferSize(window.get(), &fb_width, &fb_height);
      glViewport(0, 0, fb_width, fb_height);
      const ImVec4 background = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
      glClearColor(background.x, background.y, background.z, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      for (const std::string& path : screenshots) {
        write_screenshot(window.get(), path);
        written.push_back(path);
      }
      if (last_frame && !flags.screenshot.empty()) write_screenshot(window.get(), flags.screenshot);
      glfwSwapBuffers(window.get());

      const bool busy = state.status.phase == WorkerPhase::loading ||
                        state.status.phase == WorkerPhase::preparing ||
                        state.status.phase == WorkerPhase::rendering;
      const double work_ms = 1000.0 * seconds_between(now, Clock::now());
      if (!first) {
        record_frame(log, frame_ms, work_ms, busy);
        state.ui_fps = state.ui_fps == 0.0 ? 1000.0 / frame_ms
                                           : 0.95 * state.ui_fps + 0.05 * 1000.0 / frame_ms;
      }
      first = false;
      if (awaiting == Await::nothing && !hold_frame) script_frame += 1;
      if (last_frame) break;
    }
    if (bad_input_error.empty() && state.status.phase == WorkerPhase::failed && flags.frames > 0) {
      std::fprintf(stderr, "levrt: view: the render failed: %s\n", state.status.error.c_str());
      exit_code = 1;
    }
  }
  snapshots.wait();
  note_snapshot();
  destroy_texture(picture.texture);
  if (InterruptScope::flag().load() && !written.empty()) {
    std::string files;
    for (const std::string& w : written) files += (files.empty() ? "" : ", ") + w;
    throw Interrupted("interrupted after writing " + files + "; nothing else written");
  }
  InterruptScope::throw_if_interrupted();
  if (!bad_input_error.empty()) throw UsageError(bad_input_error);
  if (!snapshot_error.empty()) throw std::runtime_error("view: " + snapshot_error);
  // Every snapshot of the session, not only the last.
  const std::string last = snapshots.message();
  if (!last.empty() && last.rfind("wrote ", 0) != 0) snapshot_messages.push_back(last);
  for (const std::string& m : flags.frames > 0 ? snapshot_messages : std::vector<std::string>{})
    std::fprintf(state.notes, "levrt view: %s\n", scenes::escape_control_characters(m).c_str());
  if (flags.report_fps) std::fputs(frame_report(log).c_str(), state.notes);
  if (!flags.screenshot.empty()) {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window.get(), &width, &height);
    std::fprintf(state.notes, "levrt view: wrote %s (%dx%d)\n",
                 scenes::escape_control_characters(flags.screenshot).c_str(), width, height);
  }
  return exit_code;
}

}  // namespace app::viewer
