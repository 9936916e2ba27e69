#include "app/bench/experiment_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/output_files.h"
#include "scenes/scene_models.h"

namespace app::bench {

std::string scene_label(const std::string& scene) {
  const scenes::SceneModel* m = scenes::find_scene_model(scene);
  return m ? std::string(m->label) : scene;
}

std::string tolerance_text(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", t);
  return buffer;
}

std::string status(bool comparable, bool met) {
  return !comparable ? "n/a" : (met ? "met" : "missed");
}

std::optional<ReferencedScene> referenced_scene(BenchRun& run, const std::string& scene,
                                                std::uint64_t wanted_lights) {
  const std::vector<int> levels = run.levels(scene, 1, ~std::uint64_t{0});
  if (levels.empty()) return std::nullopt;
  ReferencedScene r;
  r.level = nearest_level(run, scene, levels, wanted_lights);
  r.lights = run.light_count(scene, r.level);
  r.stride = run.stride_for(scene, r.level, lev::reference_method(), 0.0);
  return r;
}

std::vector<double> swept_tolerances(const BenchRun& run, const lev::MethodInfo& method) {
  const std::vector<double>& all = method.bench_tolerances;
  if (method.is_reference) return {};
  // A method whose images do not depend on the tolerance and that names no sweep (light_tree)
  // is still measured, once.
  if (!method.uses_tolerance && all.empty()) return {lev::kDefaultTolerance};
  if (!run.config().quick || all.size() <= 3) return all;
  return {all.front(), all[all.size() / 2], all.back()};
}

std::vector<Column> per_method_columns(std::vector<Column> rest) {
  std::vector<Column> columns = {{"scene", "scene"},
                                 {"lights", "lights"},
                                 {"method", "method"},
                                 {"tolerance", "tolerance"},
                                 {"time_cpu_s", "time (CPU s)"},
                                 {"time_wall_s", "time (s)", false},
                                 {"speedup_over_rt", "speedup over rt"},
                                 {"pixel_error_avg_pct", "avg error (%)"},
                                 {"pixel_error_max_pct", "max error (%)"}};
  columns.insert(columns.end(), rest.begin(), rest.end());
  return columns;
}

double error_on_log_axis(double error_pct) {
  return std::max(error_pct, kErrorFloorPct);
}

std::vector<Column> per_tolerance_columns(std::vector<Column> rest) {
  std::vector<Column> columns = {
      {"scene", "scene"}, {"lights", "lights"}, {"tolerance", "tolerance"}, {"pixels", "px"}};
  columns.insert(columns.end(), rest.begin(), rest.end());
  return columns;
}

void write_table(BenchRun& run, const std::string& out_dir, const std::string& name,
                 const Table& table) {
  if (run.planning()) {
    run.plan_output(name + ".csv");
  } else {
    app::write_text_file(out_dir + "/" + name + ".csv", table_csv(table));
  }
}

namespace {

std::string write_chart(BenchRun& run, const std::string& out_dir, const std::string& file,
                        const Chart& chart) {
  if (run.planning()) {
    run.plan_output(file);
  } else {
    write_chart_png(out_dir + "/" + file, chart);
  }
  return "![" + chart.title + "](" + file + ")\n\n";
}

std::string missing_scenes_note(const BenchRun& run) {
  const std::vector<std::string> missing = run.missing_scenes();
  if (missing.empty()) return "";
  std::string names;
  for (const std::string& m : missing) names += (names.empty() ? "" : ", ") + m;
  return "Not in this build's scene table, so skipped: " + names + ".\n\n";
}

std::string quick_note(const BenchRun& run) {
  return run.config().quick
             ? "*Quick run: small image and light counts; the figures check the harness, not the "
               "method.*\n\n"
             : "";
}

}  // namespace

// The level of `scene` among `levels` whose light count is nearest `lights` (in ratio).
int nearest_level(const BenchRun& run, const std::string& scene, const std::vector<int>& levels,
                  std::uint64_t lights) {
  int best = levels.empty() ? -1 : levels.front();
  double best_distance = 1e300;
  for (int level : levels) {
    const double d = std::abs(
        std::log(static_cast<double>(run.light_count(scene, level)) / static_cast<double>(lights)));
    if (d < best_distance) {
      best_distance = d;
      best = level;
    }
  }
  return best;
}

Section write_section(BenchRun& run, const std::string& out_dir, const std::string& name,
                      const SectionText& text, const Table& table,
                      const std::vector<NamedChart>& charts, std::vector<HeadlineRow> headline) {
  write_table(run, out_dir, name, table);
  std::string plots;
  for (const NamedChart& c : charts) plots += write_chart(run, out_dir, c.file, c.chart);
  Section section;
  section.markdown = "## " + text.heading + "\n\n" + quick_note(run) + text.intro +
                     missing_scenes_note(run) + text.before_table + table_markdown(table) + "\n" +
                     plots;
  section.headline = std::move(headline);
  return section;
}

std::vector<ScalingPlan> scaling_plan(const BenchRun& run) {
  std::vector<ScalingPlan> plan;
  for (const std::string& scene : run.available_scenes()) {
    plan.push_back(
        {scene, run.levels(scene, run.config().min_lights, run.config().max_scaling_lights)});
  }
  return plan;
}

MeasureRequest scaling_request(BenchRun& run, const std::string& scene, int level,
                               double tolerance) {
  return {scene,
          level,
          lev::Method::lev,
          tolerance,
          run.stride_for(scene, level, lev::Method::lev, tolerance),
          run.config().runs};
}

const Measurement& scaling_measure(BenchRun& run, const std::string& scene, int level,
                                   double tolerance) {
  return run.measure(scaling_request(run, scene, level, tolerance));
}

}  // namespace app::bench
