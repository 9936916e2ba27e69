#include "app/viewer/snapshot_panel.h"

#include <cstdio>

#include <imgui.h>

#include "app/json_text.h"
#include "app/scene_loading.h"
#include "app/viewer/live_stats.h"

namespace app::viewer {

std::string snapshot_base_name(const std::string& scene, std::uint64_t light_count,
                               const lev::MethodChoice& choice) {
  const lev::MethodInfo& method = lev::method_info(choice.method);
  char text[96];
  std::snprintf(text, sizeof text, "_%llu_%s", static_cast<unsigned long long>(light_count),
                method.name);
  std::string base = "view_" + scene + text;
  if (method.uses_tolerance) {
    std::snprintf(text, sizeof text, "_%g", choice.tolerance);
    base += text;
  } else if (method.uses_relative_error) {
    std::snprintf(text, sizeof text, "_%g", choice.relative_error);
    base += text;
  }
  if (method.stochastic && choice.lights_per_point != 1) {
    std::snprintf(text, sizeof text, "_k%d", choice.lights_per_point);
    base += text;
  }
  for (char& c : base) {
    if (c == '/' || c == '\\' || c == ' ') c = '_';
  }
  return base;
}

SnapshotJob make_snapshot_job(const ViewerState& state, std::chrono::steady_clock::time_point now) {
  SnapshotJob job;
  const WorkerStatus& st = state.status;
  job.folder = state.snapshot_folder;
  job.base = snapshot_base_name(state.settings.scene.name, st.light_count, st.method_choice);
  job.width = state.image.width;
  job.height = state.image.height;
  RenderStats stats = snapshot_stats(collect_live_stats(state.image, st, state.error, now), st,
                                     state.settings, current_camera(state));
  renderer::HeatmapRange range;
  const renderer::Display display = display_from(state.settings);
  job.image_rgb = view_rgb8(state.image, state.error, ViewMode::image, range, display);
  // The range of every heatmap `levrt render` would write for these settings goes into the stats
  // (the same keys: app/view_table.h's rows with a flag, those needing the reference or the
  // missed-light estimate only with it); every view with a value somewhere becomes an EXR
  // channel; the heatmap file holds the view on screen (lights when the image is). A view whose
  // range is locked is drawn over the locked range, and its stats report it, as
  // `render --heatmap-range` does.
  job.exr_channels = rgb_channels(state.image.radiance);
  job.exr_channels.push_back(
      {"samples", std::vector<float>(state.image.samples.begin(), state.image.samples.end())});
  const ViewPixels pixels = view_pixels(state.image, state.error, state.mask_threshold_pct);
  for (const ViewInfo& view : view_table()) {
    if (view.value == nullptr) continue;
    const bool in_stats = *view.output_flag != '\0' && (!view.needs_reference || stats.error) &&
                          (!view.needs_missed || stats.missed);
    if (in_stats) {
      view_rgb8(state.image, state.error, view.mode, stats.heatmap_ranges[view.mode], display,
                state.mask_threshold_pct, locked_range(state, view.mode));
    }
    std::vector<float> values(pixels.count, 0.0f);
    bool any = false;
    for (std::size_t i = 0; i < pixels.count; ++i) {
      const std::optional<double> v = view.value(pixels, i);
      any = any || v.has_value();
      if (v) values[i] = static_cast<float>(*v);
    }
    if (any) job.exr_channels.push_back({view.channel, std::move(values)});
  }
  const ViewMode heat = state.view == ViewMode::image ? ViewMode::lights : state.view;
  job.heatmap_name = view_info(heat).name;
  job.heatmap_rgb = view_rgb8(state.image, state.error, heat, range, display,
                              state.mask_threshold_pct, locked_range(state, heat));
  // A scene named by a file name that is not UTF-8 (a glTF's stem in Latin-1) gets U+FFFD for
  // its invalid bytes instead of failing the snapshot.
  job.stats_json = json_text(render_stats_json(stats), 2);
  job.inputs = settings_input_files(state.settings.scene);
  job.inputs.insert(job.inputs.end(), state.other_inputs.begin(), state.other_inputs.end());
  job.other_outputs = state.other_outputs;
  return job;
}

bool image_holds_whole_passes(const ViewerState& state) {
  const WorkerStatus& st = state.status;
  const DisplayImage& image = state.image;
  return st.generation != 0 && image.generation == st.generation && st.tile_count > 0 &&
         image.tiles_done_in_pass == st.tile_count && image.pass + 1 == st.passes_done;
}

void request_snapshot(ViewerState& state) {
  state.snapshot_requested = true;
}

void take_requested_snapshot(ViewerState& state, SnapshotWriter& writer,
                             std::chrono::steady_clock::time_point now) {
  if (!state.snapshot_requested || writer.busy() || !image_holds_whole_passes(state)) return;
  state.snapshot_requested = false;
  writer.start(make_snapshot_job(state, now));
}

void draw_snapshot_section(ViewerState& state, const SnapshotWriter& writer) {
  char folder[512];
  std::snprintf(folder, sizeof folder, "%s", state.snapshot_folder.c_str());
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.62f);
  if (ImGui::InputText("folder", folder, sizeof folder)) state.snapshot_folder = folder;
  const bool ready = state.image.width > 0 && !writer.busy() && !state.snapshot_requested;
  if (!ready) ImGui::BeginDisabled();
  if (ImGui::Button("Save snapshot")) request_snapshot(state);
  if (!ready) ImGui::EndDisabled();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "image, current heatmap, stats JSON and the EXR of the radiance, of whole passes (taken "
        "when the pass in flight completes)");
  if (state.snapshot_requested) {
    ImGui::SameLine();
    ImGui::TextUnformatted("waiting for the pass in flight");
  } else if (writer.busy()) {
    ImGui::SameLine();
    ImGui::ProgressBar(writer.progress(), ImVec2(-1.0f, 0.0f), "writing");
  } else if (!writer.message().empty()) {
    ImGui::TextWrapped("%s", writer.message().c_str());
  }
}

}  // namespace app::viewer
