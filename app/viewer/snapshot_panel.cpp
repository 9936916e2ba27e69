#include "app/viewer/snapshot_panel.h"

#include <cstdio>

#include <imgui.h>

#include "app/viewer/live_stats.h"
#include "app/scene_loading.h"

namespace app::viewer {

SnapshotJob make_snapshot_job(const ViewerState& state, std::chrono::steady_clock::time_point now) {
  SnapshotJob job;
  const WorkerStatus& st = state.status;
  job.folder = state.snapshot_folder;
  char base[160];
  std::snprintf(base, sizeof base, "view_%s_%llu_%s_%g", state.settings.scene.c_str(),
                static_cast<unsigned long long>(st.light_count), lev::method_info(st.method).name,
                st.tolerance);
  job.base = base;
  for (char& c : job.base) {
    if (c == '/' || c == '\\' || c == ' ') c = '_';
  }
  job.width = state.image.width;
  job.height = state.image.height;
  RenderStats stats = snapshot_stats(collect_live_stats(state.image, st, state.error, now), st,
                                     state.settings, current_camera(state));
  renderer::HeatmapRange range;
  job.image_rgb = view_rgb8(state.image, state.error, ViewMode::image, range);
  // The ranges of both counters' heatmaps, as `levrt render` reports them; the file holds the
  // one on screen (lights when the image is).
  view_rgb8(state.image, state.error, ViewMode::lights, stats.heatmap_lights_range);
  view_rgb8(state.image, state.error, ViewMode::nodes, stats.heatmap_nodes_range);
  view_rgb8(state.image, state.error, ViewMode::bound, stats.heatmap_bound_range);
  view_rgb8(state.image, state.error, ViewMode::noise, stats.heatmap_noise_range);
  if (stats.error) view_rgb8(state.image, state.error, ViewMode::error, stats.heatmap_error_range);
  const ViewMode heat = state.view == ViewMode::image ? ViewMode::lights : state.view;
  job.heatmap_name = view_mode_info(heat).name;
  job.heatmap_rgb = view_rgb8(state.image, state.error, heat, range);
  job.stats_json = render_stats_json(stats).dump(2) + "\n";
  job.inputs = settings_input_files(state.settings);
  job.inputs.insert(job.inputs.end(), state.other_inputs.begin(), state.other_inputs.end());
  job.other_outputs = state.other_outputs;
  return job;
}

void draw_snapshot_section(ViewerState& state, SnapshotWriter& writer,
                           std::chrono::steady_clock::time_point now) {
  char folder[512];
  std::snprintf(folder, sizeof folder, "%s", state.snapshot_folder.c_str());
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.62f);
  if (ImGui::InputText("folder", folder, sizeof folder)) state.snapshot_folder = folder;
  const bool ready = state.image.width > 0 && !writer.busy();
  if (!ready) ImGui::BeginDisabled();
  if (ImGui::Button("Save snapshot")) writer.start(make_snapshot_job(state, now));
  if (!ready) ImGui::EndDisabled();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("image, current heatmap and stats JSON");
  if (writer.busy()) {
    ImGui::SameLine();
    ImGui::ProgressBar(writer.progress(), ImVec2(-1.0f, 0.0f), "writing");
  } else if (!writer.message().empty()) {
    ImGui::TextWrapped("%s", writer.message().c_str());
  }
}

}  // namespace app::viewer
