// What the experiments of `levrt bench` share: text helpers, the scaling plan that scaling and
// work both read, and write_section, the one layout every experiment's output takes (its table
// as NAME.csv, its charts as PNGs, its part of results.md). An experiment declares its renders
// as MeasureRequests that BenchRun::measure_together runs in turns, fills a Table and Charts from
// the measurements, and hands them to write_section.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/bench/experiments.h"
#include "app/bench/plot.h"
#include "app/bench/runner.h"
#include "app/bench/table.h"
#include "lev/methods.h"

namespace app::bench {

std::string scene_label(const std::string& scene);
std::string tolerance_text(double t);
// "met", "missed", or "n/a" when the figure is not comparable with the target.
std::string status(bool comparable, bool met);
// The level of `scene` among `levels` whose light count is nearest `lights` (in ratio).
int nearest_level(const BenchRun& run, const std::string& scene, const std::vector<int>& levels,
                  std::uint64_t lights);

// A (scene, light count) render that every method's errors are taken against rt on (control,
// converge): the level nearest the wanted count, and rt's pixel stride, which every render of
// the scene takes so that errors compare the same pixels. Empty when the build lacks the scene.
struct ReferencedScene {
  int level = 0;
  std::uint64_t lights = 0;
  int stride = 1;
};
std::optional<ReferencedScene> referenced_scene(BenchRun& run, const std::string& scene,
                                                std::uint64_t wanted_lights);

// The tolerances a method is swept over (trade, control): its row's bench_tolerances, none for
// the reference, the default alone for a method that ignores the tolerance and names none; a quick
// run takes the first, middle and last.
std::vector<double> swept_tolerances(const BenchRun& run, const lev::MethodInfo& method);

// The columns of a table with one row per (scene, light count, method, tolerance) render: its
// time, speedup over rt and pixel errors, then `rest` (trade, control).
std::vector<Column> per_method_columns(std::vector<Column> rest);
// Where an error sits on a log axis: errors of exactly 0 cannot, so they are drawn at 1e-4 %.
inline constexpr double kErrorFloorPct = 1e-4;
double error_on_log_axis(double error_pct);

// The columns of a table with one row per (scene, light count, tolerance) render, then `rest`.
std::vector<Column> per_tolerance_columns(std::vector<Column> rest);

struct NamedChart {
  std::string file;  // PNG file name in the output folder
  Chart chart;
};

// How an experiment's part of results.md reads: "## heading", the quick-run note, the intro, the
// scenes this build lacks, `before_table`, the table and the plots.
struct SectionText {
  std::string heading;
  std::string intro;
  std::string before_table;
};

// Writes NAME.csv (while planning, only notes its name: BenchRun::plan_output): a table of its own
// besides the section's.
void write_table(BenchRun& run, const std::string& out_dir, const std::string& name,
                 const Table& table);

// Writes NAME.csv and the charts (while planning, only notes their names) and returns the section.
Section write_section(BenchRun& run, const std::string& out_dir, const std::string& name,
                      const SectionText& text, const Table& table,
                      const std::vector<NamedChart>& charts,
                      std::vector<HeadlineRow> headline = {});

// scaling (thesis Tables 4, 5) and work (Tables 12-15, from the same runs).
struct ScalingPlan {
  std::string scene;
  std::vector<int> levels;
};
std::vector<ScalingPlan> scaling_plan(const BenchRun& run);
MeasureRequest scaling_request(BenchRun& run, const std::string& scene, int level,
                               double tolerance);
const Measurement& scaling_measure(BenchRun& run, const std::string& scene, int level,
                                   double tolerance);

// The experiments, one file each (experiment_NAME.cpp).
Section run_speed(BenchRun& run, const std::string& out_dir);
Section run_memory(BenchRun& run, const std::string& out_dir);
Section run_scaling(BenchRun& run, const std::string& out_dir);
Section run_fraction(BenchRun& run, const std::string& out_dir);
Section run_error(BenchRun& run, const std::string& out_dir);
Section run_work(BenchRun& run, const std::string& out_dir);
Section run_trade(BenchRun& run, const std::string& out_dir);
Section run_limit(BenchRun& run, const std::string& out_dir);
Section run_control(BenchRun& run, const std::string& out_dir);
Section run_converge(BenchRun& run, const std::string& out_dir);
Section run_targets(BenchRun& run, const std::string& out_dir);
// The pass counts converge snapshots: 1, 2, 3, 4, 6, 8, 12, ... up to `last`.
std::vector<int> snapshot_pass_counts(int last);

}  // namespace app::bench
