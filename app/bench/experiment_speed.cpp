// speed: thesis Tables 1, 2 (Test 1.1). Every method of the table, in turns, per light count.
#include "app/bench/experiment_support.h"

#include <cstdio>
#include <string>
#include <vector>

#include "app/bench/thesis_data.h"
#include "lev/methods.h"
#include "scenes/scene_models.h"

namespace app::bench {
namespace {

constexpr double kSpeedupOverRt = 300.0;
constexpr double kSpeedupOverAst = 100.0;

}  // namespace

Section run_speed(BenchRun& run, const std::string& out_dir) {
  const SuiteConfig& c = run.config();
  // Every method of the table, measured in turns; ratios are over the reference (rt) and of
  // the thesis' method (lev) over the others.
  const std::vector<lev::MethodInfo>& methods = lev::method_table();
  const std::size_t count = methods.size();
  const lev::Method rt = lev::reference_method();
  const std::string rt_name = lev::method_info(rt).name;
  const std::string lev_name = lev::method_info(lev::Method::lev).name;
  Table table;
  table.columns = {{"scene", "scene"}, {"lights", "lights"}};
  for (const lev::MethodInfo& m : methods) {
    const std::string n = m.name;
    table.columns.push_back({n + "_cpu_s", n + " (CPU s)"});
    table.columns.push_back({n + "_wall_s", n + " (s)", m.id == lev::Method::lev});
    table.columns.push_back({n + "_pixels", n + " px"});
  }
  for (const lev::MethodInfo& m : methods) {
    if (m.id != rt)
      table.columns.push_back({std::string(m.name) + "_over_" + rt_name + "_pct",
                               std::string(m.name) + "/" + rt_name + " (%)"});
  }
  for (const lev::MethodInfo& m : methods) {
    if (m.id != lev::Method::lev) {
      table.columns.push_back(
          {std::string(m.name) + "_over_" + lev_name, lev_name + " speedup over " + m.name});
    }
  }
  table.columns.push_back({"thesis_rt_over_lev", "thesis: over rt"});
  table.columns.push_back({"thesis_ast_over_lev", "thesis: over ast"});
  for (const lev::MethodInfo& m : methods) {
    table.columns.push_back(
        {std::string(m.name) + "_tests_per_point", std::string(m.name) + " tests/pt"});
  }
  const std::size_t rt_index = static_cast<std::size_t>(rt);
  const std::size_t lev_index = static_cast<std::size_t>(lev::Method::lev);
  const std::size_t ast_index = static_cast<std::size_t>(lev::Method::ast);
  Section section;
  std::vector<NamedChart> charts;
  for (const std::string& scene : run.available_scenes()) {
    Chart chart;
    chart.title =
        scene_label(scene) + ": time per frame at tolerance " + tolerance_text(c.tolerance);
    chart.x_label = "lights";
    chart.y_label = "CPU seconds per frame";
    chart.log_x = chart.log_y = true;
    std::vector<Series> series(count);
    for (std::size_t i = 0; i < count; ++i) series[i].label = methods[i].name;
    double rt_over_lev = kNaN, ast_over_lev = kNaN;
    std::uint64_t last_lights = 0;
    for (int level : run.levels(scene, c.min_lights, c.max_lights)) {
      const std::uint64_t lights = run.light_count(scene, level);
      std::vector<double> cpu(count), wall(count), tests(count);
      std::vector<int> stride(count);
      std::vector<MeasureRequest> requests;
      for (std::size_t i = 0; i < count; ++i) {
        stride[i] = run.stride_for(scene, level, methods[i].id, c.tolerance);
        requests.push_back({scene, level, methods[i].id, c.tolerance, stride[i], c.runs});
      }
      const std::vector<const Measurement*> measured = run.measure_together(requests);
      for (std::size_t i = 0; i < count; ++i) {
        const Measurement& m = *measured[i];
        cpu[i] = m.full_frame_cpu_seconds();
        wall[i] = m.full_frame_seconds();
        tests[i] = m.lights_tested_avg();
        series[i].x.push_back(static_cast<double>(lights));
        series[i].y.push_back(cpu[i]);
      }
      double thesis_rt = kNaN, thesis_ast = kNaN;
      for (const ThesisSpeed& t : thesis_speed(scene)) {
        if (t.lights == lights) {
          thesis_rt = t.rt / t.lev;
          thesis_ast = t.ast / t.lev;
        }
      }
      rt_over_lev = cpu[rt_index] / cpu[lev_index];
      ast_over_lev = cpu[ast_index] / cpu[lev_index];
      last_lights = lights;
      std::vector<Cell> row{text_cell(scene), count_cell(lights)};
      for (std::size_t i = 0; i < count; ++i) {
        row.push_back(number_cell(cpu[i], 3));
        row.push_back(number_cell(wall[i], 3));
        row.push_back(text_cell(pixels_text(stride[i])));
      }
      for (std::size_t i = 0; i < count; ++i) {
        if (i != rt_index) row.push_back(number_cell(100.0 * cpu[i] / cpu[rt_index], 2));
      }
      for (std::size_t i = 0; i < count; ++i) {
        if (i != lev_index) row.push_back(ratio_cell(cpu[i] / cpu[lev_index]));
      }
      row.push_back(ratio_cell(thesis_rt));
      row.push_back(ratio_cell(thesis_ast));
      for (std::size_t i = 0; i < count; ++i) row.push_back(number_cell(tests[i], 1));
      table.rows.push_back(row);
    }
    chart.series = series;
    charts.push_back({"speed_" + scene + ".png", chart});
    if (scene == "building" || scene == "maze") {
      const std::uint64_t target =
          scene == "building" ? scenes::kBuildingHeadlineLights : scenes::kMazeHeadlineLights;
      const bool comparable = !c.quick && last_lights == target;
      const ThesisSpeed& t = thesis_speed(scene).back();
      const std::string where = scene + ", " + format_count(last_lights) + " lights";
      section.headline.push_back({"speed: lev speedup over rt, " + where, ">= 300x",
                                  format_ratio(t.rt / t.lev), format_ratio(rt_over_lev),
                                  status(comparable, rt_over_lev >= kSpeedupOverRt)});
      section.headline.push_back({"speed: lev speedup over ast, " + where, ">= 100x",
                                  format_ratio(t.ast / t.lev), format_ratio(ast_over_lev),
                                  status(comparable, ast_over_lev >= kSpeedupOverAst)});
    }
  }
  char intro[1200];
  std::snprintf(
      intro, sizeof intro,
      "CPU seconds per %dx%d frame (all threads, user and system, as /bin/time sums them; median "
      "of at least %d runs, made in turns with the other methods of the row) at tolerance %s; "
      "lev's wall-clock seconds beside them. The ratios are of CPU seconds, taken within this "
      "run. Where a column says `1/%d` px, that method rendered one pixel of every %dx%d block "
      "and its time is scaled to the whole frame (rt and ast above %s lights, and any frame that "
      "would take over %.0f s). The thesis timed whole runs on a 300 MHz SUN ULTRA10, so only its "
      "ratios compare. The CSV has every wall-clock time too.\n\n",
      c.width, c.height, c.runs, tolerance_text(c.tolerance).c_str(),
      c.subsample_stride * c.subsample_stride, c.subsample_stride, c.subsample_stride,
      format_count(c.subsample_above).c_str(), c.max_full_frame_seconds);
  SectionText text;
  text.heading = "speed: rt, ast and lev (thesis Tables 1, 2)";
  text.intro = intro;
  return write_section(run, out_dir, "speed", text, table, charts, section.headline);
}

}  // namespace app::bench
