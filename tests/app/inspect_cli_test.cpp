// `levrt inspect` (app/inspect_command.h): the table on standard output with its totals and the
// --top limit, the complete lists in --json (every light of the scene once per hit, tested,
// culled or clustered, and the totals agreeing with the lists), and bad input as one line and
// exit 2 with nothing written.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/gltf_files.h"
#include "tests/support/json_file.h"
#include "tests/support/read_file.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace {

using levrt_test::line_count;
using levrt_test::read_json;
using levrt_test::run_levrt;

TEST(InspectCli, PrintsTheTableAndWritesTheCompleteListsAsJson) {
  const levrt_test::TempDir dir("levrt-inspect-cli-");
  const std::string json_path = (dir.path() / "pixel.json").string();
  const auto run = run_levrt({"inspect", "--scene", "hall", "--level", "3", "--method", "lev",
                              "--tolerance", "0.1", "--width", "80", "--height", "60", "--pixel",
                              "40,40", "--top", "3", "--json", json_path});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("pixel 40,40"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("lost sum (true, with shadows)"), std::string::npos);
  EXPECT_NE(run.output.find("certified bound"), std::string::npos);
  EXPECT_NE(run.output.find("more rows"), std::string::npos) << "--top 3 cuts the table";
  EXPECT_NE(run.output.find("pixel totals"), std::string::npos);

  const nlohmann::json j = read_json(json_path);
  EXPECT_EQ(j["pixel"], nlohmann::json({40, 40}));
  ASSERT_FALSE(j["hits"].empty());
  for (const nlohmann::json& hit : j["hits"]) {
    std::size_t tested = 0;
    for (const nlohmann::json& shaded : hit["shaded"]) tested += shaded["role"] == "tested";
    const std::size_t culled = hit["culled"].size();
    EXPECT_EQ(tested + culled, 64u);
    EXPECT_EQ(hit["totals"]["tested_lights"], tested);
    EXPECT_EQ(hit["totals"]["culled_lights"], culled);
    // The culled list comes sorted by the light lost, largest first.
    double previous = 1e30;
    for (const nlohmann::json& c : hit["culled"]) {
      const double lost = std::max(
          {c["lost"][0].get<double>(), c["lost"][1].get<double>(), c["lost"][2].get<double>()});
      EXPECT_LE(lost, previous);
      previous = lost;
    }
  }
  EXPECT_TRUE(j["totals"]["certified_bound"].is_array());
}

TEST(InspectCli, ClusteringMethodsListClustersWithTheirMembers) {
  const auto run = run_levrt({"inspect", "--scene", "hall", "--level", "3", "--method", "lightcuts",
                              "--width", "80", "--height", "60", "--pixel", "40,40", "--json", "-",
                              "--rt-fallback", "off"});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::size_t start = run.output.find('{');
  ASSERT_NE(start, std::string::npos);
  // The table goes to stderr when the JSON takes standard output; it follows the JSON here.
  const std::size_t end = run.output.find("\n}\n");
  ASSERT_NE(end, std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(run.output.substr(start, end + 2 - start));
  for (const nlohmann::json& hit : j["hits"]) {
    std::size_t lights = hit["culled"].size();
    for (const nlohmann::json& shaded : hit["shaded"]) {
      if (shaded["role"] == "cluster") {
        EXPECT_EQ(shaded["member_count"], shaded["members"].size());
        lights += shaded["members"].size();
      } else {
        lights += 1;
      }
    }
    EXPECT_EQ(lights, 64u);
  }
}

// The JSON `levrt inspect` writes for car park pixel 30,21 of 32x24 with `flags`.
nlohmann::json inspect_fallback_json(const levrt_test::TempDir& dir,
                                     const std::vector<std::string>& flags) {
  const std::string json_path = (dir.path() / "pixel.json").string();
  std::vector<std::string> args = {"inspect", "--scene", "carpark", "--width", "32",     "--height",
                                   "24",      "--pixel", "30,21",   "--json",  json_path};
  args.insert(args.end(), flags.begin(), flags.end());
  const auto run = run_levrt(args);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  return read_json(json_path);
}

TEST(InspectCli, WhereTheRenderFallsBackToRtTheInspectorTracesRtsLoopToo) {
  // Car park 32x24, lightcuts: the probe picks rt's loop (the render's stats say so), so the
  // render's pixel is rt's. The inspector traced lightcuts' cut anyway: 100,97,85 where the
  // render wrote 99,96,84, and a lost sum that the render did not lose.
  const levrt_test::TempDir dir("levrt-inspect-fallback-");
  const std::string stats_path = (dir.path() / "stats.json").string();
  const auto render = run_levrt({"render", "--scene", "carpark", "--width", "32", "--height", "24",
                                 "--method", "lightcuts", "--quiet", "--stats", stats_path});
  ASSERT_EQ(render.exit_code, 0) << render.output;
  ASSERT_EQ(read_json(stats_path)["rt_fallback"]["used"], true);

  const nlohmann::json rt = inspect_fallback_json(dir, {"--method", "rt"});
  const nlohmann::json fallback = inspect_fallback_json(dir, {"--method", "lightcuts"});
  EXPECT_EQ(fallback["rt_fallback"], true);
  EXPECT_EQ(fallback["radiance"], rt["radiance"]);
  EXPECT_EQ(fallback["totals"]["clusters"], 0);
  EXPECT_EQ(rt["rt_fallback"], nullptr) << "rt has no fallback";

  const nlohmann::json own =
      inspect_fallback_json(dir, {"--method", "lightcuts", "--rt-fallback", "off"});
  EXPECT_EQ(own["rt_fallback"], nullptr);
  EXPECT_GT(own["totals"]["clusters"].get<int>(), 0);
  EXPECT_NE(own["radiance"], rt["radiance"]);
}

// The table's header names the method with the settings it reads, as `render`'s summary does:
// it said "lightcuts, tolerance 0.01" (a setting lightcuts ignores) and "rt, tolerance 0.01".
TEST(InspectCli, TheHeaderNamesTheSettingsTheMethodReads) {
  const auto header = [](const std::vector<std::string>& method) {
    std::vector<std::string> args = {"inspect", "--width", "16", "--height",
                                     "12",      "--pixel", "8,6"};
    args.insert(args.end(), method.begin(), method.end());
    const auto run = run_levrt(args);
    EXPECT_EQ(run.exit_code, 0) << run.output;
    return run.output.substr(0, run.output.find('\n'));
  };
  EXPECT_NE(header({"--method", "lightcuts", "--relative-error", "0.05"})
                .find(", lightcuts, relative error 0.05 at exposure 0 EV"),
            std::string::npos);
  EXPECT_NE(header({"--method", "rt"}).find(", rt at exposure 0 EV"), std::string::npos);
  EXPECT_NE(header({"--method", "lev_mc", "--lights-per-point", "3"})
                .find(", lev_mc, tolerance 0.01, 3 lights per point at exposure"),
            std::string::npos);
  EXPECT_NE(header({"--tolerance", "0.2"}).find(", lev, tolerance 0.2 at exposure"),
            std::string::npos);
}

// With --subsample N a render traces only the pixels on the N grid: inspect listed lights and a
// radiance for a pixel the render leaves unrendered. Refused in one line; a pixel on the grid is
// inspected.
TEST(InspectCli, APixelTheSubsampledRenderSkipsIsRefused) {
  for (const char* pixel : {"1,0", "0,3", "5,5"}) {
    const auto run = run_levrt(
        {"inspect", "--width", "16", "--height", "12", "--subsample", "4", "--pixel", pixel});
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_EQ(run.output.rfind("levrt: --pixel: a render with --subsample 4", 0), 0u) << run.output;
    EXPECT_EQ(line_count(run.output), 1) << run.output;
  }
  const auto on_grid = run_levrt(
      {"inspect", "--width", "16", "--height", "12", "--subsample", "4", "--pixel", "8,4"});
  EXPECT_EQ(on_grid.exit_code, 0) << on_grid.output;
}

TEST(InspectCli, BadPixelOrFlagsAreOneLineAndExitTwoWithNothingWritten) {
  const levrt_test::TempDir dir("levrt-inspect-cli-bad-");
  const std::string json_path = (dir.path() / "pixel.json").string();
  for (const std::vector<std::string>& args : {std::vector<std::string>{"--pixel", "320,10"},
                                               {"--pixel", "10,240"},
                                               {"--pixel", "-1,5"},
                                               {"--pixel", "a,b"},
                                               {"--pixel", "5"},
                                               {"--pixel", "5,5", "--top", "-2"},
                                               {"--pixel", "5,5", "--method", "nope"}}) {
    std::vector<std::string> command = {"inspect", "--json", json_path};
    command.insert(command.end(), args.begin(), args.end());
    const auto run = run_levrt(command);
    EXPECT_EQ(run.exit_code, 2) << args[1] << ": " << run.output;
    EXPECT_EQ(line_count(run.output), 1) << run.output;
    EXPECT_FALSE(std::filesystem::exists(json_path));
  }
  const auto missing = run_levrt({"inspect"});
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_EQ(line_count(missing.output), 1) << missing.output;
  const auto wrong_extension =
      run_levrt({"inspect", "--pixel", "1,1", "--json", (dir.path() / "pixel.txt").string()});
  EXPECT_EQ(wrong_extension.exit_code, 2) << wrong_extension.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "pixel.txt"));
}

// A glTF opens at an auto exposure, and the tolerance is in displayed units: inspect chooses the
// EV as render does, so it lists what the render culled (before: it inspected at EV 0, where the
// dim light of this file is tested, while the render at about -10.7 EV culls it).
TEST(InspectCli, AGltfIsInspectedAtTheExposureTheRenderChooses) {
  const levrt_test::TempDir dir("levrt-inspect-cli-exposure-");
  const std::string scene = (dir.path() / "two.gltf").string();
  levrt_test::write_file(scene, levrt_test::gltf_document(levrt_test::triangle_buffers() + R"(,
        "nodes": [{"mesh": 0, "children": [1, 2]},
                  {"translation": [0.2, 0.2, 1],
                   "extensions": {"KHR_lights_punctual": {"light": 0}}},
                  {"translation": [0.6, 0.2, 1],
                   "extensions": {"KHR_lights_punctual": {"light": 1}}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "point", "intensity": 1000}, {"type": "point", "intensity": 1}]}})"));
  const std::string stats = (dir.path() / "stats.json").string();
  const std::vector<std::string> view = {"--scene", scene, "--width", "32", "--height", "24"};
  std::vector<std::string> render = {"render", "--quiet", "--stats", stats};
  render.insert(render.end(), view.begin(), view.end());
  ASSERT_EQ(run_levrt(render).exit_code, 0);
  const double ev = read_json(stats)["exposure_ev"].get<double>();
  ASSERT_LT(ev, -5.0);
  const auto table = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> command = {"inspect", "--pixel", "16,12"};
    command.insert(command.end(), view.begin(), view.end());
    command.insert(command.end(), extra.begin(), extra.end());
    const auto run = run_levrt(command);
    EXPECT_EQ(run.exit_code, 0) << run.output;
    return run.output.substr(run.output.find("\npixel "));  // after the timed header
  };
  char typed[64];
  std::snprintf(typed, sizeof typed, "%.17g", ev);
  const std::string at_auto = table({});
  EXPECT_EQ(at_auto, table({"--exposure", typed}));
  EXPECT_NE(at_auto, table({"--exposure", "0"}));
  EXPECT_NE(at_auto.find("1 culled"), std::string::npos) << at_auto;
}

// The scene's name is the file's to choose: escaped in the table's first line, as `render` and
// `export` escape it, so it cannot split the line or drive the terminal.
TEST(InspectCli, ASceneNameWithControlCharactersStaysOnOneLineOfTheTable) {
  const levrt_test::TempDir dir("levrt-inspect-cli-name-");
  const std::string scene = (dir.path() / "scene.json").string();
  ASSERT_EQ(run_levrt({"export", "--scene", "building", "--out", scene}).exit_code, 0);
  nlohmann::json j = read_json(scene);
  j["name"] = "evil\x1b[31mred\nsecond line";
  std::ofstream(scene) << j.dump();
  const auto run = run_levrt({"inspect", "--scene", scene, "--pixel", "160,120", "--top", "0"});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output.find('\x1b'), std::string::npos) << run.output;
  EXPECT_EQ(run.output.rfind("evil\\x1b[31mred\\nsecond line, 64 lights, lev", 0), 0u)
      << run.output;
}

// The table is the command's output: appended to the scene it reads, refused before any work;
// written to a pipe whose reader is gone, one line and exit 1 (before: exit 0, or killed by
// SIGPIPE, with nothing said).
TEST(InspectCli, TheTableIsAnOutputThatMayNotBeAnInputAndReportsAFailedWrite) {
  const levrt_test::TempDir dir("levrt-inspect-cli-table-");
  const std::string scene = (dir.path() / "scene.json").string();
  ASSERT_EQ(run_levrt({"export", "--scene", "building", "--out", scene}).exit_code, 0);
  const std::string scene_bytes = levrt_test::read_file(scene);
  const auto appended = levrt_test::run_shell(
      levrt_test::shell_quote(LEVRT_BINARY) + " inspect --scene " + levrt_test::shell_quote(scene) +
      " --pixel 1,1 2>&1 >> " + levrt_test::shell_quote(scene) + "; echo exit $?");
  EXPECT_NE(appended.output.find("standard output is a file this command reads"), std::string::npos)
      << appended.output;
  EXPECT_NE(appended.output.find("exit 2"), std::string::npos) << appended.output;
  EXPECT_EQ(levrt_test::read_file(scene), scene_bytes);

  const std::string messages = (dir.path() / "messages.txt").string();
  const int status = levrt_test::run_levrt_into_closed_pipe(
      {"inspect", "--width", "32", "--height", "24", "--pixel", "16,12"}, messages);
  ASSERT_NE(status, -1);
  const std::string output = levrt_test::read_file(messages);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status) << ": " << output;
  EXPECT_EQ(WEXITSTATUS(status), 1) << output;
  EXPECT_EQ(line_count(output), 1) << output;
  EXPECT_NE(output.find("write to standard output failed (Broken pipe)"), std::string::npos)
      << output;

  // The JSON and the table are written all or none: the JSON was written before the table's
  // write failed (exit 1 with pixel.json in place).
  const std::string json = (dir.path() / "pixel.json").string();
  const int with_json = levrt_test::run_levrt_into_closed_pipe(
      {"inspect", "--width", "32", "--height", "24", "--pixel", "16,12", "--json", json}, messages);
  ASSERT_TRUE(WIFEXITED(with_json)) << levrt_test::read_file(messages);
  EXPECT_EQ(WEXITSTATUS(with_json), 1) << levrt_test::read_file(messages);
  EXPECT_FALSE(std::filesystem::exists(json));
}

}  // namespace
