// scaling: thesis Tables 4, 5 (Test 2.1).
#include "app/bench/experiment_support.h"

#include <string>
#include <vector>

#include "app/bench/thesis_data.h"

namespace app::bench {
namespace {

constexpr double kScalingLimit = 2.5;
constexpr std::uint64_t kScalingTargetLights = 1u << 20;

}  // namespace

Section run_scaling(BenchRun& run, const std::string& out_dir) {
  const SuiteConfig& c = run.config();
  Table table;
  table.columns = {{"scene", "scene"}, {"lights", "lights"}};
  for (double t : c.scaling_tolerances) {
    const std::string ts = tolerance_text(t);
    table.columns.push_back({"lev_cpu_s_tol_" + ts, "lev (CPU s), tol " + ts});
    table.columns.push_back({"lev_wall_s_tol_" + ts, "lev (s), tol " + ts, false});
    table.columns.push_back({"pixels_tol_" + ts, "px"});
  }
  for (double t : c.scaling_tolerances) {
    table.columns.push_back(
        {"thesis_s_tol_" + tolerance_text(t), "thesis (s), tol " + tolerance_text(t)});
  }
  Section section;
  std::vector<NamedChart> charts;
  std::string ratios;
  for (const ScalingPlan& p : scaling_plan(run)) {
    Chart chart;
    chart.title = scene_label(p.scene) + ": lev time per frame against light count";
    chart.x_label = "lights";
    chart.y_label = "CPU seconds per frame";
    chart.log_x = true;
    std::vector<Series> series;
    for (double t : c.scaling_tolerances)
      series.push_back({"tolerance " + tolerance_text(t), {}, {}});
    double base = kNaN, top = kNaN;
    std::uint64_t base_lights = 0, top_lights = 0;
    const int base_level = nearest_level(run, p.scene, p.levels, c.scaling_base_lights);
    // Every level and tolerance of the scene in turns: the scaling ratio compares renders made
    // minutes apart otherwise, on a machine whose load changes.
    std::vector<MeasureRequest> requests;
    for (int level : p.levels) {
      for (double t : c.scaling_tolerances)
        requests.push_back(scaling_request(run, p.scene, level, t));
    }
    run.measure_together(requests);
    for (int level : p.levels) {
      const std::uint64_t lights = run.light_count(p.scene, level);
      std::vector<Cell> row{text_cell(p.scene), count_cell(lights)};
      for (std::size_t k = 0; k < c.scaling_tolerances.size(); ++k) {
        const double t = c.scaling_tolerances[k];
        const Measurement& m = scaling_measure(run, p.scene, level, t);
        const double s = m.full_frame_cpu_seconds();
        row.push_back(number_cell(s, 3));
        row.push_back(number_cell(m.full_frame_seconds(), 3));
        row.push_back(text_cell(pixels_text(m.request.stride)));
        series[k].x.push_back(static_cast<double>(lights));
        series[k].y.push_back(s);
        if (t == c.tolerance) {
          if (level == base_level) {
            base = s;
            base_lights = lights;
          }
          top = s;
          top_lights = lights;
        }
      }
      for (double t : c.scaling_tolerances)
        row.push_back(number_cell(thesis_lookup(thesis_scaling_seconds(p.scene), lights, t), 2));
      table.rows.push_back(row);
    }
    chart.series = series;
    charts.push_back({"scaling_" + p.scene + ".png", chart});
    ratios += "- " + p.scene + ": lev at tolerance " + tolerance_text(c.tolerance) + " takes " +
              format_ratio(top / base) + " as long with " + format_count(top_lights) +
              " lights as with " + format_count(base_lights) + ".\n";
    if (p.scene == "building") {
      section.headline.push_back(
          {"scaling: lev time at " + format_count(top_lights) + " / at " +
               format_count(base_lights) + " lights, building, tol " + tolerance_text(c.tolerance),
           "<= 2.5x", "1.9x (65,536 / 1,024)", format_ratio(top / base),
           status(!c.quick && top_lights == kScalingTargetLights, top / base <= kScalingLimit)});
    }
  }
  SectionText text;
  text.heading = "scaling: lev time against light count (thesis Tables 4, 5)";
  text.intro =
      "lev's CPU seconds per frame (median of at least " + std::to_string(c.runs) +
      " runs; every level and tolerance of a scene measured in turns) as the scene models grow, "
      "at three tolerances; the thesis' figure 5.6 plots the same against a logarithmic light "
      "count. The ratios below are of CPU seconds; the CSV has the wall-clock times too.\n\n";
  text.before_table = ratios + "\n";
  return write_section(run, out_dir, "scaling", text, table, charts, section.headline);
}

}  // namespace app::bench
