// trade: time against pixel error, every method of the table at its tolerances (new).
#include "app/bench/experiment_support.h"

#include <algorithm>
#include <string>
#include <vector>

#include "lev/methods.h"

namespace app::bench {

Section run_trade(BenchRun& run, const std::string& out_dir) {
  const SuiteConfig& c = run.config();
  Table table;
  table.columns = per_method_columns({{"lights_tested_avg", "lights tested/pt"}});
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
      for (double t : swept_tolerances(run, m))
        requests.push_back({scene, level, m.id, t, 1, c.runs});
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
      for (double t : swept_tolerances(run, info)) {
        const Measurement& m = run.measure({scene, level, info.id, t, 1, c.runs});
        const PixelErrors e = pixel_errors(m, reference);
        const double seconds = m.full_frame_cpu_seconds();
        table.rows.push_back({text_cell(scene), count_cell(lights), text_cell(method),
                              text_cell(tolerance_text(t)), number_cell(seconds, 3),
                              number_cell(m.full_frame_seconds(), 3),
                              ratio_cell(rt_seconds / seconds), number_cell(e.average_pct, 4),
                              number_cell(e.max_pct, 3), number_cell(m.lights_tested_avg(), 1)});
        sa.x.push_back(error_on_log_axis(e.average_pct));
        sa.y.push_back(seconds);
        sm.x.push_back(error_on_log_axis(e.max_pct));
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
  std::vector<NamedChart> charts{{"trade_avg.png", avg}, {"trade_max.png", max}};
  SectionText text;
  text.heading = "trade: time against pixel error, per method and scene (new)";
  text.intro =
      "The speed/accuracy trade a user makes with the tolerance, at one light count "
      "per scene, full frame: CPU seconds, median of at least " +
      std::to_string(c.runs) +
      " runs, every method and tolerance of a scene measured in turns. lev's "
      "tolerance bounds each culled light's irradiance; ast's bounds the sum of the "
      "untested potential contributions (Ward's criterion), after which it "
      "estimates the rest from hit ratios.\n\n";
  return write_section(run, out_dir, "trade", text, table, charts);
}

}  // namespace app::bench
