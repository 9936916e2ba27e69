// The lines a scripted viewer prints for `--set trade=report@F` (app/viewer/scripted_changes.cpp):
// "levrt view: trade plot at frame F: N points, reference G, rt passes P", parsed from a run's
// output in order (sscanf: GCC 12's <regex> warns).
#pragma once

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace levrt_test {

struct TradeReport {
  int frame = 0, points = 0, passes = 0;
  unsigned long long reference = 0;  // the rt reference's generation the points belong to
};

inline std::vector<TradeReport> trade_reports(const std::string& output) {
  std::vector<TradeReport> reports;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    TradeReport r;
    if (std::sscanf(line.c_str(),
                    "levrt view: trade plot at frame %d: %d points, reference %llu, rt passes %d",
                    &r.frame, &r.points, &r.reference, &r.passes) == 4) {
      reports.push_back(r);
    }
  }
  return reports;
}

}  // namespace levrt_test
