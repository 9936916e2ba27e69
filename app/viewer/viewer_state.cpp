#include "app/viewer/viewer_state.h"

#include <algorithm>
#include <cmath>

#include "app/render_command.h"
#include "lev/methods.h"
#include "scenes/scene_models.h"

namespace app::viewer {

void mark_changed(ViewerState& state, const std::string& label) {
  state.request_dirty = true;
  if (!label.empty()) state.change_label = label;
}

void apply_display_defaults(ViewerState& state) {
  Settings& s = state.settings;
  const DisplaySettings defaults{};
  if (!state.exposure_chosen) {
    s.display.exposure_ev = defaults.exposure_ev;
    s.display.exposure_auto = defaults.exposure_auto;
  }
  if (!state.display_chosen) s.display.curve = defaults.curve;
  apply_scene_display_defaults(s, state.exposure_chosen, state.display_chosen);
}

void settings_changed(ViewerState& state, const Settings& before, const std::string& label) {
  Settings& s = state.settings;
  if (s.display.exposure_ev != before.display.exposure_ev ||
      s.display.exposure_auto != before.display.exposure_auto)
    state.exposure_chosen = true;
  if (s.display.curve != before.display.curve) state.display_chosen = true;
  if (s.scene.name != before.scene.name) {
    if (const scenes::SceneModel* model = scenes::find_scene_model(s.scene.name))
      s.scene.level = model->default_level;
    // The command line's camera (flags and glTF camera index) was for the first scene; another
    // file's cameras are its own (an index past them would refuse the file).
    s.scene.camera_flags = scenes::CameraFlags{};
    if (s.scene.camera == before.scene.camera) s.scene.camera = 0;
    apply_display_defaults(state);
  }
  const Restart restart = restart_needed(before, s);
  const bool new_scene = restart == Restart::scene;
  const bool new_size =
      s.image.width != before.image.width || s.image.height != before.image.height;
  if (new_size && s.resolution == before.resolution) s.resolution = "typed";
  const bool new_view = restart >= Restart::view || s.resolution != before.resolution;
  if (new_scene) {
    // Only the view of the scene on screen is worth giving back (a second open before the first
    // failed must not replace it with the preset it asked for).
    if (before.scene.name == state.status.scene) state.camera_before_scene_change = state.camera;
    state.camera.reset();
  }
  if (new_view && !view_info(state.view).needs_reference) state.want_reference = false;
  mark_changed(state, label);
}

std::array<int, 2> fit_render_size(int area_width, int area_height, int divisor) {
  double width = std::clamp(area_width / std::max(divisor, 1), 1, kMaxImageSide);
  double height = std::clamp(area_height / std::max(divisor, 1), 1, kMaxImageSide);
  const double most_pixels = static_cast<double>(kRenderMemoryBudgetBytes) /
                             static_cast<double>(kReferenceRenderBytesPerPixel);
  if (width * height > most_pixels) {
    const double scale = std::sqrt(most_pixels / (width * height));
    width = std::max(1.0, std::floor(width * scale));
    height = std::max(1.0, std::floor(height * scale));
  }
  return {static_cast<int>(width), static_cast<int>(height)};
}

void set_fit_size(ViewerState& state, int width, int height) {
  Settings before = state.settings;
  state.settings.image.width = width;
  state.settings.image.height = height;
  before.resolution = "typed";  // so that settings_changed keeps the fit resolution
  // The window, not the user, changed the view: a reference asked for is computed again at the
  // new size (the worker drops the old one).
  const bool want_reference = state.want_reference;
  settings_changed(state, before, "fit " + std::to_string(width) + "x" + std::to_string(height));
  state.want_reference = want_reference;
}

void select_view(ViewerState& state, ViewMode mode) {
  const bool missed_before = view_info(state.view).needs_missed;
  state.view = mode;
  const ViewInfo& info = view_info(mode);
  if (info.needs_reference && !state.want_reference) set_want_reference(state, true);
  if (info.needs_missed != missed_before) mark_changed(state, std::string("view ") + info.name);
}

void set_camera(ViewerState& state, const renderer::Camera& camera) {
  state.camera = camera;
  if (!view_info(state.view).needs_reference) state.want_reference = false;
  mark_changed(state, "");
}

void reset_camera(ViewerState& state) {
  state.camera.reset();
  if (!view_info(state.view).needs_reference) state.want_reference = false;
  mark_changed(state, "camera reset");
}

void set_want_reference(ViewerState& state, bool want) {
  state.want_reference = want;
  mark_changed(state, "");
}

void set_range_lock(ViewerState& state, bool locked) {
  if (!locked) {
    state.locked_ranges.erase(state.view);
  } else if (view_info(state.view).range_rule == RangeRule::data) {
    state.locked_ranges[state.view] = state.heatmap_range;
  }
}

std::optional<renderer::HeatmapRange> locked_range(const ViewerState& state) {
  return locked_range(state, state.view);
}

std::optional<renderer::HeatmapRange> locked_range(const ViewerState& state, ViewMode mode) {
  const auto it = state.locked_ranges.find(mode);
  if (it == state.locked_ranges.end()) return std::nullopt;
  return it->second;
}

void set_ab_rt(ViewerState& state, bool rt) {
  state.ab_rt = rt;
  if (rt && !state.want_reference) set_want_reference(state, true);
}

void set_swipe(ViewerState& state, std::optional<double> divider) {
  if (divider) divider = std::clamp(*divider, 0.0, 1.0);
  state.swipe = divider;
  if (divider && !state.want_reference) set_want_reference(state, true);
}

int rt_from_column(const ViewerState& state) {
  const int width = state.image.width;
  const bool reference = state.want_reference && state.reference.width == width &&
                         state.reference.height == state.image.height && width > 0;
  if (!reference) return width;
  if (state.swipe) return static_cast<int>(std::lround(*state.swipe * width));
  return state.ab_rt ? 0 : width;
}

bool scene_ready(const ViewerState& state) {
  return state.status.scene_serial > 0 && state.status.scene == state.settings.scene.name &&
         state.status.level == state.settings.scene.level;
}

renderer::Camera current_camera(const ViewerState& state) {
  return state.camera.value_or(state.status.preset_camera);
}

void set_inspect_pixel(ViewerState& state, const std::optional<std::array<int, 2>>& pixel) {
  if (state.inspect_pixel == pixel) return;
  state.inspect_pixel = pixel;
  state.inspect_row = -1;
  mark_changed(state, "");  // no new render: the worker starts its inspection task
}

RenderRequest make_request(const ViewerState& state) {
  RenderRequest r;
  r.settings = state.settings;
  // The Missed light view turns the estimate on for a method that estimates what it leaves out;
  // one that does not (ast, lightcuts, lev_cut) would read 0 where its pixels differ from rt's
  // (the view says so instead: view_panel.cpp).
  if (view_info(state.view).needs_missed &&
      lev::method_info(state.settings.method.method).missed_light_known) {
    r.settings.image.missed_draws = std::max(r.settings.image.missed_draws, kDefaultMissedDraws);
  }
  r.camera = state.camera;
  r.want_reference = state.want_reference;
  r.inspect_pixel = state.inspect_pixel;
  return r;
}

}  // namespace app::viewer
