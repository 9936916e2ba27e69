#include "app/viewer/frame_log.h"

#include <algorithm>
#include <cstdio>

namespace app::viewer {

void record_frame(FrameLog& log, double frame_ms, double work_ms, bool tracer_busy) {
  if (!log.enabled) return;
  log.frame_ms.push_back(frame_ms);
  log.work_ms.push_back(work_ms);
  if (tracer_busy) log.busy_frame_ms.push_back(frame_ms);
}

void record_post(FrameLog& log, const std::string& label, std::uint64_t serial,
                 std::chrono::steady_clock::time_point when) {
  if (!log.enabled) return;
  for (LatencyRecord& r : log.latencies) r.superseded = true;
  log.latencies.push_back({label, serial, when, -1.0, -1.0, -1.0, false});
}

void record_first_tile(FrameLog& log, std::uint64_t generation,
                       std::chrono::steady_clock::time_point when) {
  for (LatencyRecord& r : log.latencies) {
    if (r.first_tile_ms >= 0.0 || r.serial > generation || r.superseded) continue;
    r.first_tile_ms = std::chrono::duration<double, std::milli>(when - r.posted).count();
  }
}

void record_preview(FrameLog& log, std::uint64_t generation, bool every_level,
                    std::chrono::steady_clock::time_point when) {
  for (LatencyRecord& r : log.latencies) {
    double& ms = every_level ? r.preview_ms : r.whole_frame_ms;
    if (ms >= 0.0 || r.serial > generation || r.superseded) continue;
    ms = std::chrono::duration<double, std::milli>(when - r.posted).count();
  }
}

void record_inspect_asked(FrameLog& log, int x, int y, std::chrono::steady_clock::time_point when) {
  if (!log.enabled) return;
  log.inspections.push_back({x, y, when, -1.0, 0.0});
}

void record_inspection_shown(FrameLog& log, std::chrono::steady_clock::time_point when,
                             double inspection_ms) {
  if (log.inspections.empty() || log.inspections.back().shown_ms >= 0.0) return;
  InspectionLatency& r = log.inspections.back();
  r.shown_ms = std::chrono::duration<double, std::milli>(when - r.asked).count();
  r.inspection_ms = inspection_ms;
}

FrameTimeSummary summarize_frames(const std::vector<double>& frame_ms) {
  FrameTimeSummary s;
  s.frames = frame_ms.size();
  if (frame_ms.empty()) return s;
  std::vector<double> sorted = frame_ms;
  std::sort(sorted.begin(), sorted.end());
  s.median_ms = sorted[sorted.size() / 2];
  s.p95_ms = sorted[std::min(sorted.size() - 1, sorted.size() * 95 / 100)];
  s.max_ms = sorted.back();
  return s;
}

namespace {

std::string summary_line(const char* what, const FrameTimeSummary& s) {
  char line[256];
  std::snprintf(
      line, sizeof line,
      "levrt view: %s: %zu frames, frame time median %.1f ms (%.1f fps), 95th percentile %.1f ms, "
      "max %.1f ms\n",
      what, s.frames, s.median_ms, s.median_ms > 0.0 ? 1000.0 / s.median_ms : 0.0, s.p95_ms,
      s.max_ms);
  return line;
}

}  // namespace

std::string frame_report(const FrameLog& log) {
  std::string report = summary_line("all frames", summarize_frames(log.frame_ms));
  report += summary_line("frames while tracing", summarize_frames(log.busy_frame_ms));
  const FrameTimeSummary work = summarize_frames(log.work_ms);
  char work_line[160];
  std::snprintf(work_line, sizeof work_line,
                "levrt view: UI work per frame: median %.1f ms, 95th percentile %.1f ms\n",
                work.median_ms, work.p95_ms);
  report += work_line;
  for (const LatencyRecord& r : log.latencies) {
    char line[256];
    if (r.first_tile_ms >= 0.0 && r.whole_frame_ms >= 0.0) {
      char all_levels[64] = "";
      if (r.preview_ms >= 0.0)
        std::snprintf(all_levels, sizeof all_levels, ", every preview level after %.1f ms",
                      r.preview_ms);
      std::snprintf(line, sizeof line,
                    "levrt view: %s: first tile on screen after %.1f ms, whole-frame preview "
                    "after %.1f ms%s\n",
                    r.label.c_str(), r.first_tile_ms, r.whole_frame_ms, all_levels);
    } else if (r.first_tile_ms >= 0.0) {
      std::snprintf(line, sizeof line, "levrt view: %s: first tile on screen after %.1f ms\n",
                    r.label.c_str(), r.first_tile_ms);
    } else {
      std::snprintf(line, sizeof line,
                    "levrt view: %s: no new tile (render unchanged or superseded)\n",
                    r.label.c_str());
    }
    report += line;
  }
  for (const InspectionLatency& r : log.inspections) {
    char line[192];
    if (r.shown_ms >= 0.0) {
      std::snprintf(line, sizeof line,
                    "levrt view: inspect %d,%d: list on screen after %.1f ms (the inspection "
                    "%.1f ms)\n",
                    r.x, r.y, r.shown_ms, r.inspection_ms);
    } else {
      std::snprintf(line, sizeof line,
                    "levrt view: inspect %d,%d: no list shown (cleared or superseded first)\n", r.x,
                    r.y);
    }
    report += line;
  }
  return report;
}

}  // namespace app::viewer
