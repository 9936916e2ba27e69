// limit: levrt's render against a bare Embree loop on the same rays (new).
#include "app/bench/experiment_support.h"

#include <string>
#include <vector>

#include "app/interrupt.h"
#include "app/settings.h"
#include "lev/methods.h"
#include "renderer/process_cpu_time.h"
#include "renderer/ray_log.h"
#include "renderer/render_service.h"

namespace app::bench {
namespace {

constexpr double kLimitRatio = 2.0;
constexpr double kLimitMaxTests = 200.0;  // the limit experiment's ray log stays below ~1 GB

}  // namespace

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
          run.predicted_seconds({scene, level, lev::Method::lev, c.tolerance, 1, 1}) *
          (1.0 + 1.5 * c.runs);
      const std::string what =
          scene + " " + format_count(lights) + " lights: recorded one lev pass, cast its rays bare";
      const bool ran = run.run_job(what, cost, [&] {
        LoadedScene& loaded = run.scene(scene, level);
        Settings s;
        s.scene.name = scene;
        s.scene.level = level;
        s.method.tolerance = c.tolerance;
        s.image.width = c.width;
        s.image.height = c.height;
        s.image.threads = run.threads();
        const renderer::RenderSettings rs = render_settings_from(s);
        renderer::RayLog log;
        {
          renderer::RenderJob recording(loaded.scene, *loaded.rays, rs);
          renderer::record_rays(recording.state(), &log);
          if (!recording.pass(&InterruptScope::flag())) throw Interrupted();
        }
        rays = renderer::count_logged_rays(log);
        for (int r = 0; r < c.runs; ++r) {
          double start = renderer::process_cpu_seconds();
          renderer::RenderJob job(loaded.scene, *loaded.rays, rs);
          if (!job.pass(&InterruptScope::flag())) throw Interrupted();
          render_cpu.push_back(renderer::process_cpu_seconds() - start);
          render_wall.push_back(renderer::render_seconds(job.state()));
          start = renderer::process_cpu_seconds();
          bare_wall.push_back(renderer::cast_logged_rays(*loaded.rays, log, run.threads()).seconds);
          bare_cpu.push_back(renderer::process_cpu_seconds() - start);
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
  const std::vector<NamedChart> charts{{"limit.png", chart}};
  SectionText text;
  text.heading = "limit: levrt's render against the ray-casting limit (new)";
  text.intro =
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
      "\n\n";
  return write_section(run, out_dir, "limit", text, table, charts, section.headline);
}

}  // namespace app::bench
