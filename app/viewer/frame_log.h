// What --report-fps prints: the UI's frame times (all frames, and the frames during which the
// tracer was busy) and, for each change, how long until its first tile (preview or full), its
// whole frame at the coarsest preview step and its last preview level reached the screen; and for
// each pixel pinned in the inspector, how long until its list was on screen.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace app::viewer {

struct FrameTimeSummary {
  std::size_t frames = 0;
  double median_ms = 0.0;
  double p95_ms = 0.0;
  double max_ms = 0.0;
};

struct LatencyRecord {
  std::string label;
  std::uint64_t serial = 0;
  std::chrono::steady_clock::time_point posted;
  double first_tile_ms = -1.0;  // negative until a tile of this or a later render arrives
  // Negative until the coarsest preview level (the whole frame, coarsely) and then every level of
  // this or a later render is on screen.
  double whole_frame_ms = -1.0;
  double preview_ms = -1.0;
  // A later change was posted: what arrives from then on belongs to it (a change that started no
  // render, like the tolerance under rt, must not claim the next change's tiles).
  bool superseded = false;
};

// A pixel pinned in the inspector: when, and how long until its list was on screen (negative
// until then, and for ever if another pixel or Clear came first), and the inspection's own time.
struct InspectionLatency {
  int x = 0, y = 0;
  std::chrono::steady_clock::time_point asked;
  double shown_ms = -1.0;
  double inspection_ms = 0.0;
};

struct FrameLog {
  // Only --report-fps reads the log; when it is off nothing is recorded, so an interactive session
  // of hours does not grow it frame by frame.
  bool enabled = true;
  std::vector<double> frame_ms;  // from one frame's start to the next's
  std::vector<double>
      busy_frame_ms;            // the same, while the worker was loading, preparing or rendering
  std::vector<double> work_ms;  // the UI thread's own work per frame, pacing excluded
  std::vector<LatencyRecord> latencies;
  std::vector<InspectionLatency> inspections;
};

void record_frame(FrameLog& log, double frame_ms, double work_ms, bool tracer_busy);
void record_post(FrameLog& log, const std::string& label, std::uint64_t serial,
                 std::chrono::steady_clock::time_point when);
// A tile of render `generation` reached the screen at `when`.
void record_first_tile(FrameLog& log, std::uint64_t generation,
                       std::chrono::steady_clock::time_point when);

// The coarsest preview level (whole_frame) or every level of render `generation` was on screen at
// `when`.
void record_preview(FrameLog& log, std::uint64_t generation, bool every_level,
                    std::chrono::steady_clock::time_point when);

// The inspector was pinned on pixel (x, y) at `when`; its list reached the screen at `when`
// (the latest pixel pinned), the inspection having taken inspection_ms.
void record_inspect_asked(FrameLog& log, int x, int y, std::chrono::steady_clock::time_point when);
void record_inspection_shown(FrameLog& log, std::chrono::steady_clock::time_point when,
                             double inspection_ms);

FrameTimeSummary summarize_frames(const std::vector<double>& frame_ms);
// The report, one line per item.
std::string frame_report(const FrameLog& log);

}  // namespace app::viewer
