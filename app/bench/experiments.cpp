#include "app/bench/experiments.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/bench/plot.h"
#include "app/bench/table.h"
#include "app/bench/thesis_data.h"
#include "app/interrupt.h"
#include "app/settings.h"
#include "lev/important_lights.h"
#include "lev/light_bvh.h"
#include "lev/light_hierarchy.h"
#include "lev/methods.h"
#include "renderer/image_io.h"
#include "renderer/ray_log.h"
#include "renderer/render_service.h"
#include "scenes/scene_models.h"

namespace app::bench {
namespace {

// The targets (benchmarks, not tests).
constexpr double kSpeedupOverRt = 300.0;
constexpr double kSpeedupOverAst = 100.0;
constexpr double kScalingLimit = 2.5;
constexpr double kInstancedBytesLimit = 16.0 * 1024.0;
constexpr std::uint64_t kInstancedBytesLights = 65536;
constexpr double kFlatBytesPerLightLimit = 64.0;
constexpr double kErrorAvgLimitPct = 0.1;
constexpr double kErrorMaxLimitPct = 5.0;
constexpr double kLimitRatio = 2.0;
constexpr double kLimitMaxTests = 200.0;  // the limit experiment's ray log stays below ~1 GB
// Where the thesis measured its headline speedups.
constexpr std::uint64_t kBuildingTargetLights = 16384;
constexpr std::uint64_t kMazeTargetLights = 12285;
constexpr std::uint64_t kScalingTargetLights = 1u << 20;

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

void write_table(const BenchRun& run, const std::string& out_dir, const std::string& name,
                 const Table& table) {
  if (!run.planning()) renderer::write_text_file(out_dir + "/" + name + ".csv", table_csv(table));
}

std::string write_chart(const BenchRun& run, const std::string& out_dir, const std::string& file,
                        const Chart& chart) {
  if (!run.planning()) write_chart_png(out_dir + "/" + file, chart);
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

// ---------------------------------------------------------------------------------------------
// speed: thesis Tables 1, 2 (Test 1.1)

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
    if (m.id != rt) table.columns.push_back({std::string(m.name) + "_over_" + rt_name + "_pct", std::string(m.name) + "/" + rt_name + " (%)"});
  }
  for (const lev::MethodInfo& m : methods) {
    if (m.id != lev::Method::lev) {
      table.columns.push_back({std::string(m.name) + "_over_" + lev_name, lev_name + " speedup over " + m.name});
    }
  }
  table.columns.push_back({"thesis_rt_over_lev", "thesis: over rt"});
  table.columns.push_back({"thesis_ast_over_lev", "thesis: over ast"});
  for (const lev::MethodInfo& m : methods) {
    table.columns.push_back({std::string(m.name) + "_tests_per_point", std::string(m.name) + " tests/pt"});
  }
  const std::size_t rt_index = static_cast<std::size_t>(rt);
  const std::size_t lev_index = static_cast<std::size_t>(lev::Method::lev);
  const std::size_t ast_index = static_cast<std::size_t>(lev::Method::ast);
  Section section;
  std::string plots;
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
    plots += write_chart(run, out_dir, "speed_" + scene + ".png", chart);
    if (scene == "building" || scene == "maze") {
      const std::uint64_t target = scene == "building" ? kBuildingTargetLights : kMazeTargetLights;
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
  write_table(run, out_dir, "speed", table);
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
  section.markdown = "## speed: rt, ast and lev (thesis Tables 1, 2)\n\n" + quick_note(run) +
                     intro + missing_scenes_note(run) + table_markdown(table) + "\n" + plots;
  return section;
}

// ---------------------------------------------------------------------------------------------
// memory: thesis Table 3 (Test 1.2)

Section run_memory(BenchRun& run, const std::string& out_dir) {
  const SuiteConfig& c = run.config();
  Table table;
  table.columns = {{"scene", "scene"},
                   {"lights", "lights"},
                   {"ast_bytes", "ast bookkeeping"},
                   {"ast_bytes_per_light", "ast B/light"},
                   {"lev_flat_bytes", "lev flattened"},
                   {"lev_flat_bytes_per_light", "lev flattened B/light"},
                   {"lev_flat_index_bytes_per_light", "lev flattened, above the lights, B/light"},
                   {"lev_instanced_bytes", "lev instanced"},
                   {"thesis_ast_bytes", "thesis: ast"},
                   {"thesis_lev_flat_bytes", "thesis: lev flattened"},
                   {"thesis_lev_instanced_bytes", "thesis: lev instanced"}};
  Section section;
  std::string plots;
  double instanced_at_target = kNaN, flat_index_per_light = kNaN, flat_per_light = kNaN;
  std::uint64_t flat_lights = 0, instanced_lights = 0;
  for (const std::string& scene : run.available_scenes()) {
    Chart chart;
    chart.title = scene_label(scene) + ": memory for shadow-testing acceleration";
    chart.x_label = "lights";
    chart.y_label = "bytes";
    chart.log_x = chart.log_y = true;
    std::vector<Series> series{{"ast bookkeeping", {}, {}},
                               {"lev flattened (all)", {}, {}},
                               {"lev flattened (above the lights)", {}, {}},
                               {"lev instanced", {}, {}}};
    for (int level : run.levels(scene, c.min_lights, c.max_memory_lights)) {
      const std::uint64_t lights = run.light_count(scene, level);
      std::size_t ast = 0, flat = 0, instanced = 0;
      const bool ran = run.run_job(
          scene + " " + format_count(lights) + " lights: hierarchies and ast bookkeeping",
          0.01 + 2e-6 * static_cast<double>(lights), [&] {
            const renderer::Scene s = scenes::find_scene_model(scene)->build(level);
            instanced = lev::hierarchy_bytes(s.lights);
            // Without instancing: the same lights as a flat list, under the automatic BVH a scene
            // file without structure gets (DESIGN.md).
            lev::LightTree flat_tree;
            flat_tree.root = lev::build_light_bvh(lev::flatten_lights(s.lights));
            flat = lev::hierarchy_bytes(lev::build_hierarchy(flat_tree));
            ast = lev::make_selector(lev::Method::ast, s.lights, static_cast<float>(c.tolerance))
                      ->bookkeeping_bytes();
          });
      if (!ran) continue;
      const double n = static_cast<double>(lights);
      // The thesis counts the nodes above the lights only (Test 1.2: "excludes light nodes");
      // each light's own node and record are what any method stores for a light.
      const double per_light_storage = sizeof(lev::Light) + sizeof(lev::FittedNode);
      const double index_per_light = (static_cast<double>(flat) - per_light_storage * n) / n;
      double thesis_ast = kNaN, thesis_flat = kNaN, thesis_instanced = kNaN;
      if (scene == "building") {
        for (const ThesisMemory& t : thesis_memory()) {
          if (t.lights == lights) {
            thesis_ast = t.ast;
            thesis_flat = t.lev_flat;
            thesis_instanced = t.lev_instanced;
          }
        }
        // The target's light count, or (a --quick run) the largest there is.
        if (lights <= kInstancedBytesLights) {
          instanced_at_target = static_cast<double>(instanced);
          instanced_lights = lights;
        }
        flat_index_per_light = index_per_light;
        flat_per_light = static_cast<double>(flat) / n;
        flat_lights = lights;
      }
      table.rows.push_back({text_cell(scene), count_cell(lights), count_cell(ast),
                            number_cell(ast / n, 1), count_cell(flat), number_cell(flat / n, 1),
                            number_cell(index_per_light, 1), count_cell(instanced),
                            number_cell(thesis_ast, 0), number_cell(thesis_flat, 0),
                            number_cell(thesis_instanced, 0)});
      const double values[4] = {static_cast<double>(ast), static_cast<double>(flat),
                                index_per_light * n, static_cast<double>(instanced)};
      for (int k = 0; k < 4; ++k) {
        series[static_cast<std::size_t>(k)].x.push_back(n);
        series[static_cast<std::size_t>(k)].y.push_back(values[k]);
      }
    }
    chart.series = series;
    plots += write_chart(run, out_dir, "memory_" + scene + ".png", chart);
  }
  write_table(run, out_dir, "memory", table);
  const bool has_building = scenes::find_scene_model("building") != nullptr;
  section.headline.push_back({"memory: lev hierarchy with instancing, building " +
                                  format_count(instanced_lights) + " lights",
                              "< 16 KB", "6.3 KB (at 16,384)", format_bytes(instanced_at_target),
                              status(has_building && instanced_lights == kInstancedBytesLights,
                                     instanced_at_target < kInstancedBytesLimit)});
  section.headline.push_back(
      {"memory: lev flattened, bytes per light above the lights, building " +
           format_count(flat_lights) + " lights",
       "< 64 B", "136 B",
       format_fixed(flat_index_per_light, 1) + " B (" + format_fixed(flat_per_light, 1) +
           " B with each light's own node and record)",
       status(has_building && !c.quick, flat_index_per_light < kFlatBytesPerLightLimit)});
  section.markdown = "## memory: hierarchy bytes with and without instancing (thesis Table 3)\n\n" +
                     quick_note(run) +
                     "What each method keeps to speed up shadow testing, from the structures "
                     "themselves (`hierarchy_bytes`, "
                     "`bookkeeping_bytes`). *lev instanced* is the scene's own hierarchy: one "
                     "master per level, so it grows by a "
                     "constant per level. *lev flattened* is the same lights as a flat list under "
                     "the automatic 4-wide BVH (no "
                     "instancing); its *above the lights* column leaves out each light's own node "
                     "and record, which is how the "
                     "thesis counted (Test 1.2). *ast* keeps a world-space copy of every light (48 "
                     "B) and four counters (16 B); "
                     "the thesis' AST kept 24 B of counters.\n\n" +
                     missing_scenes_note(run) + table_markdown(table) + "\n" + plots;
  return section;
}

// ---------------------------------------------------------------------------------------------
// scaling: thesis Tables 4, 5 (Test 2.1); work: Tables 12-15 reuse its runs

struct ScalingPlan {
  std::string scene;
  std::vector<int> levels;
};

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
  std::string plots, ratios;
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
    plots += write_chart(run, out_dir, "scaling_" + p.scene + ".png", chart);
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
  write_table(run, out_dir, "scaling", table);
  section.markdown =
      "## scaling: lev time against light count (thesis Tables 4, 5)\n\n" + quick_note(run) +
      "lev's CPU seconds per frame (median of at least " + std::to_string(c.runs) +
      " runs; every level and tolerance of a scene measured in turns) as the scene models grow, "
      "at three tolerances; the thesis' figure 5.6 plots the same against a logarithmic light "
      "count. The ratios below are of CPU seconds; the CSV has the wall-clock times too.\n\n" +
      missing_scenes_note(run) + ratios + "\n" + table_markdown(table) + "\n" + plots;
  return section;
}

Section run_work(BenchRun& run, const std::string& out_dir) {
  const SuiteConfig& c = run.config();
  Table table;
  table.columns = {{"scene", "scene"},
                   {"lights", "lights"},
                   {"tolerance", "tolerance"},
                   {"pixels", "px"},
                   {"lights_tested_avg", "lights tested/pt"},
                   {"nodes_visited_avg", "volumes checked/pt"},
                   {"shadow_rays_avg", "shadow rays/pt"},
                   {"thesis_lights_tested", "thesis: lights/pt"},
                   {"thesis_nodes_visited", "thesis: volumes/pt"}};
  std::string plots;
  for (const ScalingPlan& p : scaling_plan(run)) {
    Chart tested, nodes;
    tested.title = scene_label(p.scene) + ": lights tested per shading point";
    nodes.title = scene_label(p.scene) + ": extent volumes checked per shading point";
    tested.x_label = nodes.x_label = "lights";
    tested.y_label = "lights tested per point";
    nodes.y_label = "volumes checked per point";
    tested.log_x = tested.log_y = nodes.log_x = nodes.log_y = true;
    for (double t : c.scaling_tolerances) {
      Series st{"tolerance " + tolerance_text(t), {}, {}}, sn = st;
      for (int level : p.levels) {
        const std::uint64_t lights = run.light_count(p.scene, level);
        const Measurement& m = scaling_measure(run, p.scene, level, t);
        table.rows.push_back(
            {text_cell(p.scene), count_cell(lights), text_cell(tolerance_text(t)),
             text_cell(pixels_text(m.request.stride)), number_cell(m.lights_tested_avg(), 1),
             number_cell(m.nodes_visited_avg(), 1), number_cell(m.shadow_rays_avg(), 1),
             number_cell(thesis_lookup(thesis_work_tested(p.scene), lights, t), 0),
             number_cell(thesis_lookup(thesis_work_nodes(p.scene), lights, t), 0)});
        st.x.push_back(static_cast<double>(lights));
        st.y.push_back(m.lights_tested_avg());
        sn.x.push_back(static_cast<double>(lights));
        sn.y.push_back(m.nodes_visited_avg());
      }
      tested.series.push_back(st);
      nodes.series.push_back(sn);
    }
    plots += write_chart(run, out_dir, "work_lights_" + p.scene + ".png", tested);
    plots += write_chart(run, out_dir, "work_volumes_" + p.scene + ".png", nodes);
  }
  write_table(run, out_dir, "work", table);
  Section section;
  section.markdown =
      "## work: lights tested and extent volumes checked per shading point (thesis Tables "
      "12-15)\n\n" +
      quick_note(run) +
      "From the scaling runs. *Lights tested* are the lights the walk returns (each gets a shadow "
      "ray unless it "
      "is behind the surface: *shadow rays*). *Volumes checked* counts every box test of the walk "
      "(a union "
      "tests its children's boxes before descending) and every light's exact irradiance test.\n\n" +
      missing_scenes_note(run) + table_markdown(table) + "\n" + plots;
  return section;
}

// ---------------------------------------------------------------------------------------------
// fraction: thesis Tables 6-9 (Tests 2.2, 2.3)

Section run_fraction(BenchRun& run, const std::string& out_dir) {
  const SuiteConfig& c = run.config();
  Table table;
  table.columns = {{"scene", "scene"},
                   {"lights", "lights"},
                   {"tolerance", "tolerance"},
                   {"pixels", "px"},
                   {"lights_tested_avg", "lights tested/pt"},
                   {"fraction_pct", "fraction (%)"},
                   {"nodes_visited_avg", "volumes checked/pt"},
                   {"thesis_lights_tested", "thesis: lights/pt"},
                   {"thesis_fraction_pct", "thesis: fraction (%)"}};
  std::string plots;
  for (const std::string& scene : run.available_scenes()) {
    Chart chart;
    chart.title = scene_label(scene) + ": fraction of lights tested per shading point";
    chart.x_label = "tolerance";
    chart.y_label = "lights tested / lights (%)";
    chart.log_y = true;
    for (int level : run.levels(scene, c.min_lights, c.max_lights)) {
      const std::uint64_t lights = run.light_count(scene, level);
      Series s{format_count(lights) + " lights", {}, {}};
      for (double t : c.fraction_tolerances) {
        const Measurement& m =
            run.measure({scene, level, lev::Method::lev, t, run.stride_for(scene, level, lev::Method::lev, t), 1});
        const double fraction = 100.0 * m.lights_tested_avg() / static_cast<double>(lights);
        const double thesis = thesis_lookup(thesis_fraction_tested(scene), lights, t);
        table.rows.push_back({text_cell(scene), count_cell(lights), text_cell(tolerance_text(t)),
                              text_cell(pixels_text(m.request.stride)),
                              number_cell(m.lights_tested_avg(), 1), number_cell(fraction, 2),
                              number_cell(m.nodes_visited_avg(), 1), number_cell(thesis, 0),
                              number_cell(100.0 * thesis / static_cast<double>(lights), 2)});
        s.x.push_back(t);
        s.y.push_back(fraction);
      }
      chart.series.push_back(s);
    }
    plots += write_chart(run, out_dir, "fraction_" + scene + ".png", chart);
  }
  write_table(run, out_dir, "fraction", table);
  Section section;
  section.markdown =
      "## fraction: lights tested against tolerance (thesis Tables 6-9)\n\n" + quick_note(run) +
      "Average lights selected for a shadow test per shading point (primary and secondary hits), "
      "as a fraction of all lights. At tolerance 0 every light is selected by definition. Counts "
      "are exact averages of one deterministic render; `" + pixels_text(c.subsample_stride) +
      "` px marks the costly ones (a frame over " + format_fixed(c.max_full_frame_seconds, 0) +
      " s: tolerance 0 at many lights, the hall) taken on one pixel of every " +
      std::to_string(c.subsample_stride) + "x" + std::to_string(c.subsample_stride) +
      " block.\n\n" + missing_scenes_note(run) + table_markdown(table) + "\n" + plots;
  return section;
}

// ---------------------------------------------------------------------------------------------
// error: thesis Tables 10, 11 (Test 2.4)

Section run_error(BenchRun& run, const std::string& out_dir) {
  const SuiteConfig& c = run.config();
  Table table;
  table.columns = {{"scene", "scene"},
                   {"lights", "lights"},
                   {"tolerance", "tolerance"},
                   {"pixels", "px"},
                   {"pixel_error_avg_pct", "avg error (%)"},
                   {"pixel_error_max_pct", "max error (%)"},
                   {"thesis_avg_pct", "thesis: avg (%)"},
                   {"thesis_max_pct", "thesis: max (%)"}};
  Section section;
  std::string plots;
  for (const std::string& scene : run.available_scenes()) {
    Chart avg, max;
    avg.title = scene_label(scene) + ": average pixel error of lev against rt";
    max.title = scene_label(scene) + ": maximum pixel error of lev against rt";
    avg.x_label = max.x_label = "tolerance";
    avg.y_label = "average pixel error (% of 765)";
    max.y_label = "maximum pixel error (% of 765)";
    double worst_avg = 0.0, worst_max = 0.0;  // at the suite's tolerance, over light counts
    std::uint64_t worst_avg_lights = 0, worst_max_lights = 0;
    for (int level : run.levels(scene, c.min_lights, c.max_lights)) {
      const std::uint64_t lights = run.light_count(scene, level);
      const lev::Method rt = lev::reference_method();
      const int stride = run.stride_for(scene, level, rt, 0.0);
      const Measurement& reference = run.measure({scene, level, rt, 0.0, stride, 1});
      Series sa{format_count(lights) + " lights", {}, {}}, sm = sa;
      for (double t : c.error_tolerances) {
        const Measurement& m = run.measure({scene, level, lev::Method::lev, t, stride, 1});
        const PixelErrors e = pixel_errors(m, reference);
        table.rows.push_back(
            {text_cell(scene), count_cell(lights), text_cell(tolerance_text(t)),
             text_cell(pixels_text(stride)), number_cell(e.average_pct, 4),
             number_cell(e.max_pct, 3),
             number_cell(thesis_lookup(thesis_error_avg_pct(scene), lights, t), 4),
             number_cell(thesis_lookup(thesis_error_max_pct(scene), lights, t), 3)});
        sa.x.push_back(t);
        sa.y.push_back(e.average_pct);
        sm.x.push_back(t);
        sm.y.push_back(e.max_pct);
        if (t == c.tolerance) {
          if (e.average_pct >= worst_avg) {
            worst_avg = e.average_pct;
            worst_avg_lights = lights;
          }
          if (e.max_pct >= worst_max) {
            worst_max = e.max_pct;
            worst_max_lights = lights;
          }
        }
      }
      avg.series.push_back(sa);
      max.series.push_back(sm);
    }
    plots += write_chart(run, out_dir, "error_avg_" + scene + ".png", avg);
    plots += write_chart(run, out_dir, "error_max_" + scene + ".png", max);
    if (scene == "building" || scene == "maze") {
      const std::string thesis_avg =
          scene == "building" ? "0.175% (4,096 lights)" : "0.172% (90-degree spots, Table 11)";
      const std::string thesis_max =
          scene == "building" ? "20.9% (4,096 lights)" : "6.28% (90-degree spots, Table 11)";
      const std::string where =
          ", " + scene + ", tol " + tolerance_text(c.tolerance) + ", worst over light counts";
      section.headline.push_back(
          {"accuracy: average pixel error" + where, "< 0.1%", thesis_avg,
           format_fixed(worst_avg, 4) + "% (" + format_count(worst_avg_lights) + " lights)",
           status(!c.quick, worst_avg < kErrorAvgLimitPct)});
      section.headline.push_back(
          {"accuracy: maximum pixel error" + where, "< 5%", thesis_max,
           format_fixed(worst_max, 3) + "% (" + format_count(worst_max_lights) + " lights)",
           status(!c.quick, worst_max < kErrorMaxLimitPct)});
    }
  }
  write_table(run, out_dir, "error", table);
  section.markdown =
      "## error: pixel error of lev against rt (thesis Tables 10, 11)\n\n" + quick_note(run) +
      "Per pixel |dR|+|dG|+|dB| on the 0..255 scale as a percentage of 765, against the rt image "
      "of the same "
      "view; average and maximum over the pixels. Where the rt reference was subsampled (px `" + pixels_text(c.subsample_stride) +
      "`, as in the speed table) lev is taken on the same pixels, so the maximum is over fewer of "
      "them. The thesis' Table 11 measured the maze per streetlight cone (25 to 90 degrees) rather "
      "than per light count; levrt's streetlights are 90-degree Warn spots with a cosine dropoff, "
      "so the headline quotes that column.\n\n" +
      missing_scenes_note(run) + table_markdown(table) + "\n" + plots;
  return section;
}

// ---------------------------------------------------------------------------------------------
// trade: time against pixel error (new)

// A method's trade sweep: its row's bench_tolerances (none for the reference); a quick run takes
// the first, middle and last.
std::vector<double> trade_tolerances(const BenchRun& run, const lev::MethodInfo& method) {
  const std::vector<double>& all = method.bench_tolerances;
  if (method.is_reference || !run.config().quick || all.size() <= 3) return method.is_reference ? std::vector<double>{} : all;
  return {all.front(), all[all.size() / 2], all.back()};
}

Section run_trade(BenchRun& run, const std::string& out_dir) {
  const SuiteConfig& c = run.config();
  // Errors of exactly 0 cannot sit on a log axis; they are drawn at this floor.
  constexpr double kErrorFloorPct = 1e-4;
  Table table;
  table.columns = {{"scene", "scene"},
                   {"lights", "lights"},
                   {"method", "method"},
                   {"tolerance", "tolerance"},
                   {"time_cpu_s", "time (CPU s)"},
                   {"time_wall_s", "time (s)", false},
                   {"speedup_over_rt", "speedup over rt"},
                   {"pixel_error_avg_pct", "avg error (%)"},
                   {"pixel_error_max_pct", "max error (%)"},
                   {"lights_tested_avg", "lights tested/pt"}};
  Chart avg, max;
  avg.title = "Time against average pixel error (dashed: rt, exact)";
  max.title = "Time against maximum pixel error (dashed: rt, exact)";
  avg.x_label = "average pixel error (%, 0 drawn at 1e-4)";
  max.x_label = "maximum pixel error (%, 0 drawn at 1e-4)";
  avg.y_label = max.y_label = "CPU seconds per frame";
  avg.log_x = avg.log_y = max.log_x = max.log_y = true;
  std::vector<Series> references;
  for (const std::string& scene : run.available_scenes()) {
    const std::vector<int> levels = run.levels(scene, c.min_lights, c.max_lights);
    if (levels.empty()) continue;
    const auto wanted = c.trade_lights.find(scene);
    const int level =
        nearest_level(run, scene, levels,
                      wanted != c.trade_lights.end() ? wanted->second : c.trade_default_lights);
    const std::uint64_t lights = run.light_count(scene, level);
    const lev::Method rt = lev::reference_method();
    const char* rt_name = lev::method_info(rt).name;
    std::vector<MeasureRequest> requests{{scene, level, rt, 0.0, 1, c.runs}};
    for (const lev::MethodInfo& m : lev::method_table()) {
      for (double t : trade_tolerances(run, m)) requests.push_back({scene, level, m.id, t, 1, c.runs});
    }
    run.measure_together(requests);
    const Measurement& reference = run.measure(requests.front());
    const double rt_seconds = reference.full_frame_cpu_seconds();
    table.rows.push_back({text_cell(scene), count_cell(lights), text_cell(rt_name), text_cell("-"),
                          number_cell(rt_seconds, 3),
                          number_cell(reference.full_frame_seconds(), 3), ratio_cell(1.0),
                          number_cell(0.0, 4), number_cell(0.0, 3),
                          number_cell(reference.lights_tested_avg(), 1)});
    references.push_back({scene + " " + rt_name, {0.0}, {rt_seconds}, true});
    for (const lev::MethodInfo& info : lev::method_table()) {
      if (info.is_reference) continue;
      const char* method = info.name;
      Series sa{scene + " " + method, {}, {}}, sm = sa;
      for (double t : trade_tolerances(run, info)) {
        const Measurement& m = run.measure({scene, level, info.id, t, 1, c.runs});
        const PixelErrors e = pixel_errors(m, reference);
        const double seconds = m.full_frame_cpu_seconds();
        table.rows.push_back({text_cell(scene), count_cell(lights), text_cell(method),
                              text_cell(tolerance_text(t)), number_cell(seconds, 3),
                              number_cell(m.full_frame_seconds(), 3),
                              ratio_cell(rt_seconds / seconds), number_cell(e.average_pct, 4),
                              number_cell(e.max_pct, 3), number_cell(m.lights_tested_avg(), 1)});
        sa.x.push_back(std::max(e.average_pct, kErrorFloorPct));
        sa.y.push_back(seconds);
        sm.x.push_back(std::max(e.max_pct, kErrorFloorPct));
        sm.y.push_back(seconds);
      }
      avg.series.push_back(sa);
      max.series.push_back(sm);
    }
  }
  for (const Series& r : references) {
    avg.series.push_back(r);
    max.series.push_back(r);
  }
  write_table(run, out_dir, "trade", table);
  const std::string plots = write_chart(run, out_dir, "trade_avg.png", avg) +
                            write_chart(run, out_dir, "trade_max.png", max);
  Section section;
  section.markdown = "## trade: time against pixel error, per method and scene (new)\n\n" +
                     quick_note(run) +
                     "The speed/accuracy trade a user makes with the tolerance, at one light count "
                     "per scene, full frame: CPU seconds, median of at least " +
                     std::to_string(c.runs) +
                     " runs, every method and tolerance of a scene measured in turns. lev's "
                     "tolerance bounds each culled light's irradiance; ast's bounds the sum of the "
                     "untested potential contributions (Ward's criterion), after which it "
                     "estimates the rest from hit ratios.\n\n" +
                     missing_scenes_note(run) + table_markdown(table) + "\n" + plots;
  return section;
}

// ---------------------------------------------------------------------------------------------
// limit: levrt's render against a bare Embree loop on the same rays (new)

Section run_limit(BenchRun& run, const std::string& out_dir) {
  const SuiteConfig& c = run.config();
  Table table;
  table.columns = {{"scene", "scene"},
                   {"lights", "lights"},
                   {"render_cpu_s", "levrt render (CPU s)"},
                   {"bare_cpu_s", "bare Embree (CPU s)"},
                   {"render_over_bare", "render / bare"},
                   {"render_wall_s", "levrt render (s)", false},
                   {"bare_wall_s", "bare Embree (s)", false},
                   {"closest_hit_rays", "closest-hit rays"},
                   {"shadow_rays", "shadow rays"},
                   {"bare_mrays_per_cpu_s", "bare Mrays per CPU s"}};
  Chart chart;
  chart.title = "lev at tolerance " + tolerance_text(c.tolerance) +
                ": whole render and bare Embree on the same rays";
  chart.x_label = "lights";
  chart.y_label = "CPU seconds per frame";
  chart.log_x = chart.log_y = true;
  Section section;
  std::string skipped;
  for (const std::string& scene : run.available_scenes()) {
    Series render_series{scene + ": levrt render", {}, {}};
    Series bare_series{scene + ": bare Embree", {}, {}};
    double last_ratio = kNaN;
    std::uint64_t last_lights = 0;
    for (int level : run.levels(scene, c.min_lights, c.max_lights)) {
      const std::uint64_t lights = run.light_count(scene, level);
      // The log holds every ray of the frame (32 bytes each): keep it to frames of a few million.
      if (run.lev_tests_per_point(scene, level, c.tolerance) > kLimitMaxTests) {
        skipped += (skipped.empty() ? "" : ", ") + scene + " " + format_count(lights);
        continue;
      }
      renderer::RayLogTotals rays;
      std::vector<double> render_cpu, bare_cpu, render_wall, bare_wall;
      // One recording pass, then whole renders and bare loops in turns, so that both see the
      // same machine load; a bare loop takes about half a render.
      const double cost =
          run.predicted_seconds({scene, level, lev::Method::lev, c.tolerance, 1, 1}) * (1.0 + 1.5 * c.runs);
      const std::string what =
          scene + " " + format_count(lights) + " lights: recorded one lev pass, cast its rays bare";
      const bool ran = run.run_job(what, cost, [&] {
        LoadedScene& loaded = run.scene(scene, level);
        Settings s;
        s.scene = scene;
        s.level = level;
        s.tolerance = c.tolerance;
        s.width = c.width;
        s.height = c.height;
        s.threads = run.threads();
        const renderer::RenderSettings rs = render_settings_from(s);
        renderer::RayLog log;
        {
          renderer::RenderJob recording(loaded.scene, *loaded.rays, rs);
          renderer::record_rays(recording.state(), &log);
          if (!recording.pass(&InterruptScope::flag())) throw Interrupted();
        }
        rays = renderer::count_logged_rays(log);
        for (int r = 0; r < c.runs; ++r) {
          double start = process_cpu_seconds();
          renderer::RenderJob job(loaded.scene, *loaded.rays, rs);
          if (!job.pass(&InterruptScope::flag())) throw Interrupted();
          render_cpu.push_back(process_cpu_seconds() - start);
          render_wall.push_back(renderer::render_seconds(job.state()));
          start = process_cpu_seconds();
          bare_wall.push_back(renderer::cast_logged_rays(*loaded.rays, log, run.threads()).seconds);
          bare_cpu.push_back(process_cpu_seconds() - start);
          InterruptScope::throw_if_interrupted();
        }
      });
      if (!ran) continue;
      const double render = median(render_cpu), bare = median(bare_cpu);
      const double ratio = render / bare;
      const double total_rays = static_cast<double>(rays.closest_hit + rays.shadow);
      table.rows.push_back({text_cell(scene), count_cell(lights), number_cell(render, 3),
                            number_cell(bare, 3), ratio_cell(ratio),
                            number_cell(median(render_wall), 3), number_cell(median(bare_wall), 3),
                            count_cell(rays.closest_hit), count_cell(rays.shadow),
                            number_cell(total_rays / bare * 1e-6, 2)});
      render_series.x.push_back(static_cast<double>(lights));
      render_series.y.push_back(render);
      bare_series.x.push_back(static_cast<double>(lights));
      bare_series.y.push_back(bare);
      last_ratio = ratio;
      last_lights = lights;
    }
    chart.series.push_back(render_series);
    chart.series.push_back(bare_series);
    if (last_lights > 0 || run.planning()) {
      section.headline.push_back({"limit: levrt render / bare Embree on its rays, " + scene + " " +
                                      format_count(last_lights) + " lights",
                                  "<= 2x", "-", format_ratio(last_ratio),
                                  status(!c.quick, last_ratio <= kLimitRatio)});
    }
  }
  write_table(run, out_dir, "limit", table);
  const std::string plots = write_chart(run, out_dir, "limit.png", chart);
  section.markdown =
      "## limit: levrt's render against the ray-casting limit (new)\n\n" + quick_note(run) +
      "One lev pass (tolerance " + tolerance_text(c.tolerance) +
      ", full frame) records every ray it casts (renderer/ray_log.h); the same rays are then cast "
      "again by a bare loop, `rtcIntersect1` for primary and secondary rays and `rtcOccluded1` "
      "for shadow rays, tile by tile on the same threads, with no selection and no shading. "
      "Then " +
      std::to_string(c.runs) + " whole renders and " + std::to_string(c.runs) +
      " bare loops run in turns; the table has the medians of their CPU seconds (the CSV the "
      "wall-clock ones too). A ratio of 1 would mean levrt spends all its time in Embree." +
      (skipped.empty() ? std::string()
                       : " Left out (lev tests over " + format_fixed(kLimitMaxTests, 0) +
                             " lights per point there, too many rays to log): " + skipped + ".") +
      "\n\n" + missing_scenes_note(run) + table_markdown(table) + "\n" + plots;
  return section;
}

}  // namespace

const std::vector<ExperimentInfo>& experiments() {
  static const std::vector<ExperimentInfo> table = {
      {"speed", "Tables 1, 2", "time of rt, ast and lev per light count, and their ratios",
       run_speed},
      {"memory", "Table 3", "hierarchy bytes with and without instancing; ast's bookkeeping",
       run_memory},
      {"scaling", "Tables 4, 5", "lev time per light count at three tolerances", run_scaling},
      {"fraction", "Tables 6-9", "lights tested per point against tolerance", run_fraction},
      {"error", "Tables 10, 11", "pixel error of lev against rt per tolerance and light count",
       run_error},
      {"work", "Tables 12-15", "lights tested and volumes checked per point", run_work},
      {"trade", "new", "time against pixel error per method and scene", run_trade},
      {"limit", "new", "levrt's render against a bare Embree loop on the same rays", run_limit},
  };
  return table;
}

}  // namespace app::bench
