#include "app/viewer/stats_panel.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <optional>
#include <string>

#include <imgui.h>

#include "app/viewer/live_stats.h"
#include "lev/methods.h"

namespace app::viewer {
namespace {

void row(const char* name, const char* format, ...) IM_FMTARGS(2);

void row(const char* name, const char* format, ...) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextUnformatted(name);
  ImGui::TableSetColumnIndex(1);
  va_list args;
  va_start(args, format);
  ImGui::TextV(format, args);
  va_end(args);
}

std::string bytes_text(std::size_t bytes) {
  char text[32];
  if (bytes < 10 * 1024) {
    std::snprintf(text, sizeof text, "%zu B", bytes);
  } else if (bytes < 10 * 1024 * 1024) {
    std::snprintf(text, sizeof text, "%.1f KB", static_cast<double>(bytes) / 1024.0);
  } else {
    std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  }
  return text;
}

}  // namespace

float stats_section_height() {
  const float row_height = ImGui::GetTextLineHeight() + 2.0f * ImGui::GetStyle().CellPadding.y;
  return static_cast<float>(kStatsRows) * row_height;
}

void draw_status_line(const ViewerState& state, std::chrono::steady_clock::time_point now) {
  const WorkerStatus& st = state.status;
  // Errors are shown whole, wrapped to the panel (a glTF error names the file and the field).
  if (st.phase == WorkerPhase::failed) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.4f, 0.4f, 1.0f));
    ImGui::TextWrapped("error: %s", st.error.c_str());
    ImGui::PopStyleColor();
    return;
  }
  if (!st.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.3f, 1.0f));
    ImGui::TextWrapped("%s", st.error.c_str());
    ImGui::PopStyleColor();
  }
  if (st.phase == WorkerPhase::loading && !st.loading_scene.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("loading %s", st.loading_scene.c_str());
    ImGui::PopStyleColor();
  }
  if (st.phase == WorkerPhase::loading || st.phase == WorkerPhase::preparing) {
    const float t =
        static_cast<float>(std::chrono::duration<double>(now.time_since_epoch()).count());
    ImGui::ProgressBar(-1.0f * t, ImVec2(-1.0f, 0.0f), worker_phase_text(st.phase));
    return;
  }
  const bool current = state.image.generation == st.generation && st.tile_count > 0;
  const int done =
      current && state.image.pass == st.passes_done ? state.image.tiles_done_in_pass : 0;
  char text[128];
  if (st.passes_done >= st.passes_target) {
    std::snprintf(text, sizeof text, "done: %d passes", st.passes_done);
    ImGui::ProgressBar(1.0f, ImVec2(-1.0f, 0.0f), text);
  } else if (st.preview_levels_done < st.preview_levels) {
    std::snprintf(text, sizeof text, "preview %d of %d: one sample per %dx%d pixels",
                  st.preview_levels_done + 1, st.preview_levels, st.preview_step, st.preview_step);
    ImGui::ProgressBar(
        static_cast<float>(st.preview_levels_done) / static_cast<float>(st.preview_levels),
        ImVec2(-1.0f, 0.0f), text);
  } else {
    const float fraction =
        st.tile_count > 0 ? static_cast<float>(done) / static_cast<float>(st.tile_count) : 0.0f;
    std::snprintf(text, sizeof text, "pass %d of %d: %d/%d tiles%s", st.passes_done + 1,
                  st.passes_target, done, st.tile_count,
                  st.phase == WorkerPhase::waiting_for_reference ? " (paused for rt)" : "");
    ImGui::ProgressBar(fraction, ImVec2(-1.0f, 0.0f), text);
  }
}

void draw_stats_section(const ViewerState& state, std::chrono::steady_clock::time_point now) {
  const WorkerStatus& st = state.status;
  const LiveStats s = collect_live_stats(state.image, st, state.error, now);
  if (!ImGui::BeginTable("stats", 2, ImGuiTableFlags_RowBg)) return;
  // The names keep their full width; the values take the rest.
  ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed);
  ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
  row("scene", "%s, %llu lights", st.scene_name.c_str(),
      static_cast<unsigned long long>(st.light_count));
  const lev::MethodInfo& method = lev::method_info(st.method);
  row("method", "%s", method_text(st.method_choice).c_str());
  if (st.rt_fallback) {
    // Work per probe point in shadow rays; short enough for the table's column.
    row("rt fallback", "%s (%.0f vs rt %.0f rays/pt)",
        st.rt_fallback->use_rt ? "rt's loop" : "own walk", st.rt_fallback->method_cost_rays,
        st.rt_fallback->rt_cost_rays);
  }
  row(st.passes_done > 0 ? "time per pass" : "pass 1 so far", "%.3f s", s.pass_seconds);
  row("render time", "%.2f s (%d passes)", s.render_seconds, st.passes_done);
  row("Mrays/s", "%.2f (primary + shadow)", s.mrays_per_second);
  row("shading points", "%llu", static_cast<unsigned long long>(s.shading_points));
  row("shadow rays", "%llu", static_cast<unsigned long long>(s.shadow_rays));
  row("lights tested/point", "%.2f avg, %u max", s.lights_tested_avg, s.lights_tested_max);
  row("nodes visited/point", "%s",
      nodes_visited_text(s.nodes_visited_avg, s.shading_points, method.name,
                         st.rt_fallback && st.rt_fallback->use_rt)
          .c_str());
  row("hierarchy", "%s", bytes_text(st.hierarchy_bytes).c_str());
  if (st.method_bytes > 0)
    row("method memory", "%s", bytes_text(st.method_bytes).c_str());
  else
    row("method memory", "none besides the hierarchy");
  row("build / set-up", "%.3f s / %.4f s", st.build_seconds, st.setup_seconds);
  if (s.error_bound) {
    row("error bound", "%.4f%% avg, %.3f%% max", s.error_bound->average_pct,
        s.error_bound->max_pct);
  } else {
    row("error bound", "once pixels are rendered");
  }
  if (s.error_avg_pct) {
    row("pixel error", "%.4f%% avg, %.3f%% max (%d passes)", *s.error_avg_pct, *s.error_max_pct,
        s.error_passes);
  } else {
    row("pixel error", "needs the rt reference");
  }
  if (s.noise_avg_pct) {
    row("noise", "%.4f%% avg std error (%d passes)", *s.noise_avg_pct, st.passes_done);
  } else {
    row("noise", "from the second pass on");
  }
  // Always a row, so choosing the view does not change the layout (and with it the fit size).
  if (s.missed) {
    row("missed light", "%.4f%% avg (+- %.4f%%), %.3f%% max", s.missed->average_pct,
        s.missed->std_error_avg_pct, s.missed->max_pct);
  } else if (!lev::method_info(st.method).missed_light_known) {
    row("missed light", "not estimated by %s", lev::method_info(st.method).name);
  } else {
    row("missed light", "with the Missed light view");
  }
  row("UI", "%.0f fps", state.ui_fps);
  ImGui::EndTable();
}

namespace {

// A/B against rt: which picture the image view shows (B flips it), and the swipe split.
void draw_ab_controls(ViewerState& state) {
  ControlRects* rects = state.record_controls ? &state.control_rects : nullptr;
  ImGui::TextUnformatted("show");
  ImGui::SameLine();
  if (ImGui::RadioButton("method", !state.ab_rt)) set_ab_rt(state, false);
  record_item(rects, "ab:method");
  ImGui::SameLine();
  if (ImGui::RadioButton("rt (key B)", state.ab_rt)) set_ab_rt(state, true);
  record_item(rects, "ab:rt");
  ImGui::SameLine();
  bool swipe = state.swipe.has_value();
  if (ImGui::Checkbox("swipe", &swipe))
    set_swipe(state, swipe ? std::optional<double>(0.5) : std::nullopt);
  record_item(rects, "swipe");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("method left, rt right of a divider; drag the divider on the image");
}

}  // namespace

void draw_reference_section(ViewerState& state, std::chrono::steady_clock::time_point now) {
  const WorkerStatus& st = state.status;
  const bool live = st.reference != ReferencePhase::none && state.want_reference;
  if (!live) {
    if (ImGui::Button("Compute rt reference")) set_want_reference(state, true);
    ImGui::SameLine();
    ImGui::TextDisabled("same view, every light: slow");
    return;
  }
  if (st.reference == ReferencePhase::rendering) {
    // Passes done, and the tiles of the pass in flight.
    const DisplayImage& ref = state.reference;
    const bool shown = ref.generation == st.reference_generation;
    const int tiles = shown && ref.pass == st.reference_passes_done ? ref.tiles_done_in_pass : 0;
    const int passes = std::max(st.reference_passes_target, 1);
    const float fraction =
        st.reference_tile_count > 0
            ? (static_cast<float>(st.reference_passes_done) +
               static_cast<float>(tiles) / static_cast<float>(st.reference_tile_count)) /
                  static_cast<float>(passes)
            : 0.0f;
    const double seconds = std::chrono::duration<double>(now - st.reference_started).count();
    char text[96];
    std::snprintf(text, sizeof text, "rt: pass %d/%d, %d/%d tiles, %.1f s",
                  std::min(st.reference_passes_done + 1, passes), passes, tiles,
                  st.reference_tile_count, seconds);
    ImGui::ProgressBar(fraction, ImVec2(ImGui::GetContentRegionAvail().x - 70.0f, 0.0f), text);
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) set_want_reference(state, false);
  } else if (st.reference == ReferencePhase::done) {
    ImGui::Text("rt reference done: %d passes, %.2f s", st.reference_passes_done,
                st.reference_seconds);
    ImGui::SameLine();
    if (ImGui::SmallButton("Drop")) set_want_reference(state, false);
  } else {
    ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "rt reference failed");
  }
  draw_ab_controls(state);
  if (state.error.pixels_compared > 0) {
    const std::size_t total = state.error.pct.size();
    ImGui::Text("error avg %.4f%%, max %.3f%% over %.0f%% of pixels", state.error.average_pct,
                state.error.max_pct,
                total > 0 ? 100.0 * static_cast<double>(state.error.pixels_compared) /
                                static_cast<double>(total)
                          : 0.0);
  }
}

}  // namespace app::viewer
