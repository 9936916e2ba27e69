// `levrt bench`: the quick suite writes results.md, every experiment's CSV with its columns and
// its plots (the figures themselves are benchmarks, never checked here); bad flags exit 2 with
// one line and write nothing.

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "app/bench/experiment_support.h"
#include "lev/methods.h"
#include "tests/support/folder_test.h"
#include "tests/support/read_file.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace {
namespace fs = std::filesystem;
using levrt_test::CommandRun;
using levrt_test::run_levrt;

using levrt_test::read_file;

std::string first_line(const fs::path& path) {
  const std::string text = read_file(path);
  return text.substr(0, text.find('\n'));
}

class Bench : public levrt_test::FolderTest {};

TEST_F(Bench, QuickSuiteWritesEveryFileWithItsColumns) {
  const fs::path out = dir_ / "results";
  const CommandRun r = run_levrt({"bench", "--suite", "thesis", "--quick", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("% done"), std::string::npos) << "progress goes to stderr";

  const std::map<std::string, std::string> columns = {
      {"speed",
       // Every method of the table, in its order.
       "scene,lights,rt_cpu_s,rt_wall_s,rt_pixels,ast_cpu_s,ast_wall_s,ast_pixels,lev_cpu_s,"
       "lev_wall_s,lev_pixels,lev_bounded_cpu_s,lev_bounded_wall_s,lev_bounded_pixels,"
       "lev_est_cpu_s,lev_est_wall_s,lev_est_pixels,lev_mc_cpu_s,lev_mc_wall_s,lev_mc_pixels,"
       "light_tree_cpu_s,light_tree_wall_s,light_tree_pixels,lightcuts_cpu_s,lightcuts_wall_s,"
       "lightcuts_pixels,lev_cut_cpu_s,lev_cut_wall_s,lev_cut_pixels,ast_over_rt_pct,"
       "lev_over_rt_pct,lev_bounded_over_rt_pct,lev_est_over_rt_pct,lev_mc_over_rt_pct,"
       "light_tree_over_rt_pct,lightcuts_over_rt_pct,lev_cut_over_rt_pct,"
       "rt_over_lev,ast_over_lev,lev_bounded_over_lev,lev_est_over_lev,lev_mc_over_lev,"
       "light_tree_over_lev,lightcuts_over_lev,lev_cut_over_lev,thesis_rt_over_lev,"
       "thesis_ast_over_lev,rt_tests_per_point,ast_tests_per_point,lev_tests_per_point,"
       "lev_bounded_tests_per_point,lev_est_tests_per_point,lev_mc_tests_per_point,"
       "light_tree_tests_per_point,lightcuts_tests_per_point,lev_cut_tests_per_point"},
      {"memory",
       "scene,lights,ast_bytes,ast_bytes_per_light,lev_flat_bytes,lev_flat_bytes_per_light,"
       "lev_flat_index_bytes_per_light,lev_instanced_bytes,thesis_ast_bytes,thesis_lev_flat_bytes,"
       "thesis_lev_instanced_bytes"},
      {"scaling",
       "scene,lights,lev_cpu_s_tol_0.001,lev_wall_s_tol_0.001,pixels_tol_0.001,lev_cpu_s_tol_0.01,"
       "lev_wall_s_tol_0.01,pixels_tol_0.01,lev_cpu_s_tol_0.1,lev_wall_s_tol_0.1,pixels_tol_0.1,"
       "thesis_s_tol_0.001,thesis_s_tol_0.01,thesis_s_tol_0.1"},
      {"fraction",
       "scene,lights,tolerance,pixels,lights_tested_avg,fraction_pct,nodes_visited_avg,"
       "thesis_lights_tested,thesis_fraction_pct"},
      {"error",
       "scene,lights,tolerance,pixels,pixel_error_avg_pct,pixel_error_max_pct,thesis_avg_pct,"
       "thesis_max_pct"},
      {"work",
       "scene,lights,tolerance,pixels,lights_tested_avg,nodes_visited_avg,shadow_rays_avg,"
       "thesis_lights_tested,thesis_nodes_visited"},
      {"trade",
       "scene,lights,method,tolerance,time_cpu_s,time_wall_s,speedup_over_rt,pixel_error_avg_pct,"
       "pixel_error_max_pct,lights_tested_avg"},
      {"control",
       "scene,lights,method,tolerance,time_cpu_s,time_wall_s,speedup_over_rt,pixel_error_avg_pct,"
       "pixel_error_max_pct,error_bound_avg_pct,error_bound_max_pct,bound_holds_pct,pixels,"
       "bound_over_error"},
      {"converge",
       "scene,lights,method,tolerance,pass_cpu_s,passes_in_rt_over_100,"
       "pixel_error_avg_pct_at_rt_over_100,pixel_error_max_pct_at_rt_over_100,passes_in_rt_over_10,"
       "pixel_error_avg_pct_at_rt_over_10,pixel_error_max_pct_at_rt_over_10,passes,"
       "pixel_error_avg_pct_at_last,pixel_error_max_pct_at_last,error_slope,target_passes,"
       "target_speedup_over_rt,pixels"},
      {"converge_passes",
       "scene,lights,method,tolerance,passes,time_cpu_s,time_wall_s,speedup_over_rt,"
       "pixel_error_avg_pct,pixel_error_max_pct,std_error_avg_pct,pixels"},
      {"targets",
       "scene,lights,rt_seconds,target,method,tolerance,seconds,speedup,pixel_error_avg_pct,"
       "pixel_error_max_pct,lights_tested_avg,search_round,pixels"},
      {"targets_sweep",
       "scene,lights,method,tolerance,time_cpu_s,time_wall_s,speedup_over_rt,pixel_error_avg_pct,"
       "pixel_error_max_pct,lights_tested_avg,rt_fallback,search_round,pixels"},
      {"limit",
       "scene,lights,render_cpu_s,bare_cpu_s,render_over_bare,render_wall_s,bare_wall_s,"
       "closest_hit_rays,shadow_rays,bare_mrays_per_cpu_s"},
  };
  for (const auto& [name, header] : columns) {
    const fs::path csv = out / (name + ".csv");
    ASSERT_TRUE(fs::exists(csv)) << name;
    EXPECT_EQ(first_line(csv), header) << name;
    const std::string text = read_file(csv);
    EXPECT_GE(std::count(text.begin(), text.end(), '\n'), 2)
        << name << ": a header and at least one row";
  }
  for (const char* png :
       {"speed_building.png", "memory_building.png", "scaling_building.png",
        "fraction_building.png", "error_avg_building.png", "error_max_building.png",
        "work_lights_building.png", "work_volumes_building.png", "trade_avg.png", "trade_max.png",
        "control_building_64.png", "control_hall_256.png", "converge_avg_hall_256.png",
        "converge_max_maze_45.png", "targets_speedup.png", "limit.png"}) {
    const fs::path p = out / png;
    ASSERT_TRUE(fs::exists(p)) << png;
    EXPECT_EQ(read_file(p).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << png;
  }
  const std::string md = read_file(out / "results.md");
  EXPECT_NE(md.find("## Headline"), std::string::npos);
  for (const auto& [name, header] : columns) {
    if (name == "converge_passes" || name == "targets_sweep") continue;  // CSVs beside a section
    EXPECT_NE(md.find("## " + name + ":"), std::string::npos) << name;
  }
  EXPECT_NE(md.find("(speed_building.png)"), std::string::npos);
  for (const auto& entry : fs::directory_iterator(out)) {
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
  }
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  for (char ch : line + ",") {
    if (ch == ',') {
      cells.push_back(cell);
      cell.clear();
    } else {
      cell += ch;
    }
  }
  return cells;
}

// The index of a CSV column by its name (a failure, and the header's size, when it is missing).
std::size_t column_of(const std::vector<std::string>& header, const std::string& name) {
  const auto at = std::find(header.begin(), header.end(), name);
  EXPECT_NE(at, header.end()) << name;
  return static_cast<std::size_t>(at - header.begin());
}

// control: a row for every method of the table at every scene of the experiment, each with its
// bound and errors, and the bound holding on every pixel.
TEST_F(Bench, ControlBoundHoldsOnEveryPixelForEveryMethod) {
  const fs::path out = dir_ / "control";
  const CommandRun r = run_levrt({"bench", "--quick", "--only", "control", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::istringstream csv(read_file(out / "control.csv"));
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  const std::vector<std::string> header = split_csv_line(line);
  const auto column = [&](const std::string& name) { return column_of(header, name); };
  const std::size_t scene = column("scene"), lights = column("lights"), method = column("method"),
                    held = column("bound_holds_pct"), error_max = column("pixel_error_max_pct"),
                    bound_max = column("error_bound_max_pct");
  std::map<std::string, std::set<std::string>> methods_per_scene;  // "hall 256" -> methods
  double largest_error = 0.0;
  while (std::getline(csv, line)) {
    const std::vector<std::string> cells = split_csv_line(line);
    ASSERT_EQ(cells.size(), header.size()) << line;
    const std::string where = cells[scene] + " " + cells[lights];
    methods_per_scene[where].insert(cells[method]);
    EXPECT_EQ(std::stod(cells[held]), 100.0) << line;
    largest_error = std::max(largest_error, std::stod(cells[error_max]));
    if (cells[method] == "rt") {
      EXPECT_EQ(std::stod(cells[bound_max]), 0.0) << line;
      EXPECT_EQ(cells[column("bound_over_error")], "-") << line;
    } else if (std::stod(cells[column("pixel_error_avg_pct")]) > 0.0) {
      // A ratio wherever the method erred (the bound may be infinite: lev_mc, light_tree).
      const std::string ratio = cells[column("bound_over_error")];
      EXPECT_TRUE(ratio == "inf" || std::stod(ratio) > 0.0) << line;
    }
  }
  // building, maze and the hall at two light counts.
  EXPECT_EQ(methods_per_scene.size(), 4u);
  for (const auto& [where, methods] : methods_per_scene) {
    for (const lev::MethodInfo& info : lev::method_table())
      EXPECT_EQ(methods.count(info.name), 1u) << where << " " << info.name;
  }
  EXPECT_GT(largest_error, 0.0) << "some method erred, so the check met real errors";
  EXPECT_NE(read_file(out / "results.md").find("| 100.00 |"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "control_maze_45.png"));
}

// A CSV as rows of named cells.
std::vector<std::map<std::string, std::string>> read_csv_rows(const fs::path& path) {
  std::istringstream csv(read_file(path));
  std::string line;
  std::vector<std::map<std::string, std::string>> rows;
  if (!std::getline(csv, line)) return rows;
  const std::vector<std::string> header = split_csv_line(line);
  while (std::getline(csv, line)) {
    const std::vector<std::string> cells = split_csv_line(line);
    EXPECT_EQ(cells.size(), header.size()) << line;
    std::map<std::string, std::string>& row = rows.emplace_back();
    for (std::size_t i = 0; i < cells.size() && i < header.size(); ++i) row[header[i]] = cells[i];
  }
  return rows;
}

// targets: per scene, one row per error target naming the fastest render of the sweep that meets
// it (or "none" when none does), every method of the table swept on every scene.
TEST_F(Bench, TargetsNamesTheFastestSettingThatMeetsEachTarget) {
  const fs::path out = dir_ / "targets";
  const CommandRun r = run_levrt({"bench", "--quick", "--only", "targets", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto sweep = read_csv_rows(out / "targets_sweep.csv");
  const auto summary = read_csv_rows(out / "targets.csv");
  std::map<std::string, std::set<std::string>> methods_per_scene;
  for (const auto& row : sweep) methods_per_scene[row.at("scene")].insert(row.at("method"));
  EXPECT_EQ(methods_per_scene.size(), 6u);  // the quick suite's six renders
  for (const auto& [scene, methods] : methods_per_scene) {
    for (const lev::MethodInfo& info : lev::method_table()) {
      if (info.is_reference) continue;
      EXPECT_EQ(methods.count(info.name), 1u) << scene << " " << info.name;
    }
  }
  ASSERT_EQ(summary.size(), 2 * methods_per_scene.size());
  int met = 0;
  for (const auto& row : summary) {
    const bool max_only = row.at("target").rfind("max", 0) == 0;
    const std::map<std::string, std::string>* fastest = nullptr;
    for (const auto& s : sweep) {
      if (s.at("scene") != row.at("scene")) continue;
      const double avg = std::stod(s.at("pixel_error_avg_pct")),
                   max = std::stod(s.at("pixel_error_max_pct"));
      const bool meets = max_only ? max < 2.0 : (avg < 0.5 && max < 5.0);
      if (meets && (!fastest ||
                    std::stod(s.at("speedup_over_rt")) > std::stod(fastest->at("speedup_over_rt"))))
        fastest = &s;
    }
    if (!fastest) {
      EXPECT_EQ(row.at("method"), "none") << row.at("scene") << " " << row.at("target");
      continue;
    }
    ++met;
    EXPECT_EQ(row.at("method"), fastest->at("method"))
        << row.at("scene") << " " << row.at("target");
    EXPECT_EQ(row.at("tolerance"), fastest->at("tolerance"))
        << row.at("scene") << " " << row.at("target");
    EXPECT_EQ(row.at("seconds"), fastest->at("time_cpu_s"));
    EXPECT_EQ(row.at("speedup"), fastest->at("speedup_over_rt"));
    EXPECT_EQ(row.at("search_round"), fastest->at("search_round"));
    // Round 0 shares the first round's rt, so its speedup is rt CPU s over the row's time.
    if (row.at("search_round") == "0") {
      EXPECT_NEAR(std::stod(row.at("speedup")),
                  std::stod(row.at("rt_seconds")) / std::stod(row.at("seconds")),
                  1e-4 * std::stod(row.at("speedup")));
    }
  }
  // The search's renders lie strictly between two of their method's grid settings, after a round
  // that could ask for them.
  for (const auto& s : sweep) {
    const int round = std::stoi(s.at("search_round"));
    ASSERT_GE(round, 0);
    ASSERT_LE(round, 2);
    if (round == 0 || s.at("tolerance") == "-") continue;
    const double setting = std::stod(s.at("tolerance"));
    bool looser = false, tighter = false;
    for (const auto& g : sweep) {
      if (g.at("scene") != s.at("scene") || g.at("method") != s.at("method") ||
          g.at("search_round") != "0")
        continue;
      looser = looser || std::stod(g.at("tolerance")) > setting;
      tighter = tighter || std::stod(g.at("tolerance")) < setting;
    }
    EXPECT_TRUE(looser && tighter) << s.at("scene") << " " << s.at("method") << " " << setting;
  }
  // The progress counts the search's renders in its plan as they are asked for, and no probe as a
  // render: "[targets N/M]" never has N > M, the last line has N = M, and the plan grows ahead of
  // the renders (a line with N < M and M above the first line's M) when the search asks for more.
  std::istringstream lines(r.output);
  std::string line;
  int last_done = 0, last_planned = 0, first_planned = 0, search_renders = 0;
  bool grew_ahead = false;
  for (const auto& s : sweep) search_renders += s.at("search_round") != "0";
  while (std::getline(lines, line)) {
    int done = 0, planned = 0;
    const std::size_t at = line.find("[targets ");
    if (at == std::string::npos ||
        std::sscanf(line.c_str() + at, "[targets %d/%d]", &done, &planned) != 2)
      continue;
    EXPECT_LE(done, planned) << line;
    if (first_planned == 0) first_planned = planned;
    grew_ahead = grew_ahead || (done < planned && planned > first_planned);
    EXPECT_EQ(line.find(" 1/64 px"), std::string::npos) << "a probe counted as a render: " << line;
    last_done = done;
    last_planned = planned;
  }
  EXPECT_GT(search_renders, 0) << "the quick suite's sweeps leave something to search";
  EXPECT_GT(last_done, 0);
  EXPECT_EQ(last_done, last_planned);
  EXPECT_TRUE(grew_ahead) << "the search's renders were not added to the plan";
  EXPECT_GT(met, 0) << "some setting met some target";
  const std::string png = read_file(out / "targets_speedup.png");
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_NE(read_file(out / "results.md").find("## targets:"), std::string::npos);
}

// converge: every pass at the pixel centres, so lev repeats its image (its error never moves)
// while the sampling methods' means approach rt; times grow with the passes.
TEST_F(Bench, ConvergeFollowsEachMethodPassByPass) {
  const fs::path out = dir_ / "converge";
  const CommandRun r = run_levrt({"bench", "--quick", "--only", "converge", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::istringstream csv(read_file(out / "converge_passes.csv"));
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  const std::vector<std::string> header = split_csv_line(line);
  const auto column = [&](const std::string& name) { return column_of(header, name); };
  const std::size_t scene = column("scene"), lights = column("lights"), method = column("method"),
                    passes = column("passes"), time = column("time_cpu_s"),
                    error = column("pixel_error_avg_pct"), noise = column("std_error_avg_pct"),
                    speedup = column("speedup_over_rt"), tolerance = column("tolerance");
  struct Point {
    int passes;
    double seconds, error, noise, speedup;
  };
  // "hall 256 lev_mc 0.1" -> its snapshots (a method that ignores the tolerance shows "-")
  std::map<std::string, std::vector<Point>> curves;
  while (std::getline(csv, line)) {
    const std::vector<std::string> cells = split_csv_line(line);
    ASSERT_EQ(cells.size(), header.size()) << line;
    curves[cells[scene] + " " + cells[lights] + " " + cells[method] + " " + cells[tolerance]]
        .push_back({std::stoi(cells[passes]), std::stod(cells[time]), std::stod(cells[error]),
                    std::stod(cells[noise]), std::stod(cells[speedup])});
  }
  int sampled_curves = 0, converging = 0;
  for (const auto& [what, points] : curves) {
    const bool lev = what.find(" lev ") != std::string::npos;
    const bool sampled =
        what.find(" lev_mc") != std::string::npos || what.find(" light_tree") != std::string::npos;
    // A sampling method makes every pass; a deterministic one stops early only once its passes
    // cost more than rt.
    ASSERT_FALSE(points.empty()) << what;
    if (sampled || points.back().speedup >= 1.0) {
      ASSERT_EQ(points.size(), 6u) << what << ": 1, 2, 3, 4, 6 and 8 passes";
    }
    const std::vector<int> snapshots = app::bench::snapshot_pass_counts(8);
    for (std::size_t i = 0; i < points.size() && i < snapshots.size(); ++i)
      EXPECT_EQ(points[i].passes, snapshots[i]) << what;
    for (std::size_t i = 1; i < points.size(); ++i) {
      EXPECT_GT(points[i].seconds, points[i - 1].seconds) << what;
      if (!sampled) {
        EXPECT_GE(points[i - 1].speedup, 1.0) << what << ": went on after passing rt's time";
      }
    }
    if (lev) {
      for (const Point& p : points) {
        // The same image every pass, up to a rare flip of an 8-bit step by the float rounding of
        // the sums (one step in one pixel moves the average by about 3e-4 %).
        EXPECT_NEAR(p.error, points.front().error, 0.005) << what;
        EXPECT_LT(p.noise, 0.01) << what;
      }
    }
    if (sampled && points.front().error > 0.0) {
      ++sampled_curves;
      converging += points.back().error < points.front().error ? 1 : 0;
      EXPECT_GT(points.back().noise, 0.0) << what;
    }
  }
  EXPECT_EQ(curves.count("hall 256 lev 0.01"), 1u);
  EXPECT_EQ(curves.count("hall 256 lev_mc 0.01"), 1u);
  EXPECT_EQ(curves.count("hall 256 lev_mc 0.1"), 1u);
  EXPECT_EQ(curves.count("hall 256 light_tree -"), 1u);
  for (const auto& [what, points] : curves)
    EXPECT_EQ(what.find(" rt "), std::string::npos) << "rt is the reference, not a curve";
  ASSERT_GT(sampled_curves, 0);
  EXPECT_EQ(converging, sampled_curves) << "every sampled curve ends nearer rt than it starts";
  EXPECT_NE(read_file(out / "results.md").find("## converge:"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "converge.csv"));
}

TEST_F(Bench, OnlyRunsTheNamedExperiments) {
  const fs::path out = dir_ / "only";
  const CommandRun r = run_levrt(
      {"bench", "--quick", "--only", "memory,limit", "--threads", "1", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "memory.csv"));
  EXPECT_TRUE(fs::exists(out / "limit.csv"));
  EXPECT_FALSE(fs::exists(out / "speed.csv"));
  EXPECT_FALSE(fs::exists(out / "scaling.csv"));
  EXPECT_NE(read_file(out / "results.md").find("--only memory,limit --threads 1"),
            std::string::npos);
}

TEST_F(Bench, ScenesRendersOnlyTheNamedSceneModels) {
  const fs::path out = dir_ / "scenes";
  const CommandRun r = run_levrt({"bench", "--quick", "--only", "targets,memory", "--scenes",
                                  "stage,hall", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::set<std::string> scenes;
  for (const char* csv : {"targets.csv", "memory.csv"}) {
    const std::string text = read_file(out / csv);
    std::size_t line = text.find('\n');  // after the header
    while (line != std::string::npos && line + 1 < text.size()) {
      scenes.insert(text.substr(line + 1, text.find(',', line + 1) - line - 1));
      line = text.find('\n', line + 1);
    }
  }
  EXPECT_EQ(scenes, (std::set<std::string>{"hall", "stage"}));
  EXPECT_NE(read_file(out / "results.md").find("--scenes stage,hall"), std::string::npos);
}

TEST_F(Bench, BadFlagsExitTwoWithOneLineAndWriteNothing) {
  const std::string out = (dir_ / "never").string();
  const std::string file = (dir_ / "a_file").string();
  std::FILE* f = std::fopen(file.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs("x", f);
  std::fclose(f);
  const std::vector<std::vector<std::string>> cases = {
      {"--suite", "tables", "--out", out},
      {"--suite", "", "--out", out},
      {"--quick"},
      {"--out", ""},
      {"--out", file},
      {"--only", "speeed", "--out", out},
      {"--only", "", "--out", out},
      {"--only", "speed,", "--out", out},
      {"--scenes", "stadium", "--out", out},
      {"--scenes", "", "--out", out},
      {"--scenes", "hall,", "--out", out},
      {"--threads", "-1", "--out", out},
      {"--threads", "x", "--out", out},
      {"--threads", "", "--out", out},
      {"--threads", "2000", "--out", out},
      {"--quick", "--only", "limit", "--threads", " 2", "--out", out},
      {"--quick", "--only", "limit", "--threads", "+2", "--out", out},
      {"--quick", "--only", "limit", "--threads", "0x2", "--out", out},
      {"--colour", "red", "--out", out},
  };
  for (const std::vector<std::string>& c : cases) {
    std::vector<std::string> args = {"bench"};
    args.insert(args.end(), c.begin(), c.end());
    const CommandRun r = run_levrt(args);
    std::string label;
    for (const std::string& a : c) label += a + " ";
    label += ": " + r.output;
    EXPECT_EQ(r.exit_code, 2) << label;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << label;
    EXPECT_FALSE(fs::exists(out)) << label;
  }
  EXPECT_EQ(read_file(file), "x");
  EXPECT_EQ(run_levrt({"bench", "--help"}).exit_code, 0);
}

TEST_F(Bench, AnOutFolderThatCannotBeMadeIsRefusedWithOneLineNamingWhy) {
  const fs::path file = dir_ / "plain_file";
  { std::ofstream(file) << "x"; }
  fs::create_symlink(dir_ / "missing_target", dir_ / "dangling");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {file.string() + "/sub", "' is not a folder"},
      {file.string() + "/../sub", "' is not a folder"},
      {(dir_ / "dangling").string(), "' is a symlink to nothing"},
      {(dir_ / "dangling" / "sub").string(), "' is a symlink to nothing"},
  };
  for (const auto& [out, says] : cases) {
    const CommandRun r =
        run_levrt({"bench", "--quick", "--only", "memory", "--scenes", "building", "--out", out});
    EXPECT_EQ(r.exit_code, 2) << out << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << out << ": " << r.output;
    EXPECT_NE(r.output.find("--out: '"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
  }
  EXPECT_EQ(read_file(file), "x");
  EXPECT_FALSE(fs::exists(dir_ / "missing_target"));
  EXPECT_TRUE(fs::is_symlink(dir_ / "dangling"));
}

TEST_F(Bench, AFileOfTheSuiteTheOutFolderCannotTakeIsRefusedBeforeAnyRender) {
  const fs::path out = dir_ / "results";
  fs::create_directories(out / "results.md");
  const CommandRun r = run_levrt({"bench", "--quick", "--only", "memory", "--scenes", "building",
                                  "--threads", "1", "--out", out.string()});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--out: is a folder, got '" + (out / "results.md").string() + "'"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("planned"), std::string::npos) << "refused before rendering";
  std::vector<fs::path> left;
  for (const fs::directory_entry& e : fs::directory_iterator(out)) left.push_back(e.path());
  EXPECT_EQ(left, std::vector<fs::path>{out / "results.md"}) << "no staging folder left";
}

TEST_F(Bench, TheWroteLineEscapesAFolderNameWithANewline) {
  const fs::path out = dir_ / "two\nlines";
  const CommandRun r = run_levrt({"bench", "--quick", "--only", "memory", "--scenes", "building",
                                  "--threads", "1", "--out", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "results.md"));
  const std::size_t wrote = r.output.find("levrt bench: wrote ");
  ASSERT_NE(wrote, std::string::npos) << r.output;
  const std::string line = r.output.substr(wrote, r.output.find('\n', wrote) - wrote);
  EXPECT_NE(line.find("two\\nlines/results.md"), std::string::npos) << line;
}

TEST_F(Bench, ScenesThatAnExperimentOfOnlyDoesNotRenderAreRefused) {
  const fs::path out = dir_ / "idle";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"memory", "--scenes: none of these scenes is rendered by memory, got 'stage'"},
      {"memory,error", "--scenes: none of these scenes is rendered by memory, error, got 'stage'"},
  };
  for (const auto& [only, says] : cases) {
    const CommandRun r = run_levrt({"bench", "--quick", "--only", only, "--scenes", "stage",
                                    "--threads", "1", "--out", out.string()});
    EXPECT_EQ(r.exit_code, 2) << only << ": " << r.output;
    EXPECT_NE(r.output.find(says), std::string::npos) << only << ": " << r.output;
    EXPECT_EQ(r.output.find("planned"), std::string::npos) << "refused before rendering";
    EXPECT_FALSE(fs::exists(out)) << only;
  }
}

TEST_F(Bench, AStagingFolderLeftByAKilledRunOfTheSamePidLendsNothing) {
  // The shell makes the staging folder a killed run with its process id would have left, then
  // execs levrt with that id.
  const fs::path out = dir_ / "results";
  fs::create_directories(out);
  const std::string command =
      "cd " + levrt_test::shell_quote(out.string()) +
      " && mkdir .levrt-bench-$$ && echo stale > .levrt-bench-$$/speed.csv && exec " +
      levrt_test::shell_quote(LEVRT_BINARY) +
      " bench --quick --only memory --scenes building --threads 1 --out . 2>&1";
  const CommandRun r = levrt_test::run_shell(command);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "memory.csv"));
  EXPECT_FALSE(fs::exists(out / "speed.csv")) << "a stale file was published as a result";
}

}  // namespace
