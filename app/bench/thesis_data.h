// The thesis' own figures (Appendix B, Tables 1-15), shown next to ours in the report. Scene Model
// 1 is `building`, 2 is `maze`, 3 is `hall`. The thesis timed whole runs on a 300 MHz SUN ULTRA10,
// so only its ratios and counts compare with ours, never its seconds.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace app::bench {

struct ThesisSpeed {  // Tables 1, 2: seconds per method at tolerance 0.01
  std::uint64_t lights;
  double rt, ast, lev;
};
const std::vector<ThesisSpeed>& thesis_speed(const std::string& scene);

struct ThesisMemory {  // Table 3 (building): extra bytes for shadow-testing acceleration
  std::uint64_t lights;
  double ast, lev_flat, lev_instanced;
};
const std::vector<ThesisMemory>& thesis_memory();

struct ThesisPoint {  // one cell of a table indexed by light count and tolerance
  std::uint64_t lights;
  double tolerance;
  double value;
};

const std::vector<ThesisPoint>& thesis_scaling_seconds(const std::string& scene);  // Tables 4, 5
const std::vector<ThesisPoint>& thesis_fraction_tested(
    const std::string& scene);  // Tables 6-9: average lights tested
const std::vector<ThesisPoint>& thesis_work_tested(const std::string& scene);  // Tables 12, 14
const std::vector<ThesisPoint>& thesis_work_nodes(const std::string& scene);   // Tables 13, 15
const std::vector<ThesisPoint>& thesis_error_avg_pct(
    const std::string& scene);  // Table 10 (building)
const std::vector<ThesisPoint>& thesis_error_max_pct(
    const std::string& scene);  // Table 10 (building)

// The cell for (lights, tolerance), or NaN.
double thesis_lookup(const std::vector<ThesisPoint>& table, std::uint64_t lights, double tolerance);

}  // namespace app::bench
