// fraction: thesis Tables 6-9 (Tests 2.2, 2.3).
#include "app/bench/experiment_support.h"

#include <string>
#include <vector>

#include "app/bench/thesis_data.h"
#include "lev/methods.h"

namespace app::bench {

Section run_fraction(BenchRun& run, const std::string& out_dir) {
  const SuiteConfig& c = run.config();
  Table table;
  table.columns = per_tolerance_columns({{"lights_tested_avg", "lights tested/pt"},
                                         {"fraction_pct", "fraction (%)"},
                                         {"nodes_visited_avg", "volumes checked/pt"},
                                         {"thesis_lights_tested", "thesis: lights/pt"},
                                         {"thesis_fraction_pct", "thesis: fraction (%)"}});
  std::vector<NamedChart> charts;
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
        const Measurement& m = run.measure({scene, level, lev::Method::lev, t,
                                            run.stride_for(scene, level, lev::Method::lev, t), 1});
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
    charts.push_back({"fraction_" + scene + ".png", chart});
  }
  SectionText text;
  text.heading = "fraction: lights tested against tolerance (thesis Tables 6-9)";
  text.intro =
      "Average lights selected for a shadow test per shading point (primary and secondary hits), "
      "as a fraction of all lights. At tolerance 0 every light is selected by definition. Counts "
      "are exact averages of one deterministic render; `" +
      pixels_text(c.subsample_stride) + "` px marks the costly ones (a frame over " +
      format_fixed(c.max_full_frame_seconds, 0) +
      " s: tolerance 0 at many lights, the hall) taken on one pixel of every " +
      std::to_string(c.subsample_stride) + "x" + std::to_string(c.subsample_stride) + " block.\n\n";
  return write_section(run, out_dir, "fraction", text, table, charts);
}

}  // namespace app::bench
