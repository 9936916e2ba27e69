#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/folder_test.h"
#include "tests/support/read_file.h"
#include "tests/support/run_command.h"

namespace {
namespace fs = std::filesystem;
using levrt_test::CommandRun;
using levrt_test::read_file;
using levrt_test::run_levrt;

class Cli : public levrt_test::FolderTest {
 protected:
  bool folder_is_empty() const { return fs::is_empty(dir_); }
};

TEST_F(Cli, EveryInvalidValueExitsTwoWithOneLineAndNoOutput) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"--width", {"0", "-1", "abc", "", "1e9", "nan", "3.5", "99999999999999999999"}},
      {"--height", {"0", "-4", "x", "", "16385"}},
      {"--spp", {"0", "-1", "two", "", "1.5"}},
      {"--depth", {"-1", "65", "deep", ""}},
      {"--threads", {"-1", "x", "", "100000"}},
      {"--subsample", {"0", "-2", "x"}},
      {"--tolerance", {"-1", "-0.001", "nan", "inf", "-inf", "abc", "", "1e999", "0.01x"}},
      {"--method", {"foo", "", "RT"}},
      {"--scene", {"castle", ""}},
      {"--level", {"0", "11", "x", ""}},
      {"--lights", {"1000", "-64", "abc", "", "65"}},
      {"--reference", {"lev", ""}},
      {"--lights-per-point", {"0", "-1", "1025", "99999999999999999999", "x", "", "2.5"}},
  };
  const std::string out = path("image.png");
  for (const auto& [flag, values] : cases) {
    for (const std::string& value : values) {
      const CommandRun r =
          run_levrt({"render", flag, value, "--width", "8", "--height", "8", "--out", out});
      const std::string label = flag + " '" + value + "': " + r.output;
      EXPECT_EQ(r.exit_code, 2) << label;
      EXPECT_NE(r.output.find(flag), std::string::npos) << label;
      EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << label;
      EXPECT_TRUE(folder_is_empty()) << label;
    }
  }
}

// Numbers in the one decimal grammar (app/settings.h) for every numeric flag, those of the
// settings table and the others: a leading space or '+', a trailing space and hex floats were
// taken by some (--tolerance 0x1p-3 rendered at 0.125, --width ' 64' and '+64' at 64, --fov and
// --camera-position took hex, --heatmap-range ' 0,1'). Each is one line naming the flag and the
// value as typed, exit 2, nothing written.
TEST_F(Cli, NumericFlagsTakeOnlyPlainDecimalNumbers) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"--width", {" 8", "+8", "8 ", "0x8"}},
      {"--spp", {" 1", "+1"}},
      {"--tolerance", {"0x1p-3", " 0.1", "+0.1", "0.1 ", "0X1P-3"}},
      {"--exposure", {"+1", " 1", "0x1p0"}},
      {"--lights", {" 64", "+64", "0x40"}},
      {"--fov", {"0x1p5", "+40", " 40"}},
      {"--camera-position", {"0x1p0,2,3", "+1,2,3", "1, 2,3"}},
      {"--ortho-half-height", {"0x1p2", "+4"}},
      {"--heatmap-range", {" 0,1", "0x1p-3,1", "+0,1", "0,1 "}},
      {"--fail-above", {"avg=+1", "max=0x1p0", "avg= 1"}},
  };
  const std::string out = path("image.png");
  for (const auto& [flag, values] : cases) {
    for (const std::string& value : values) {
      const CommandRun r =
          run_levrt({"render", flag, value, "--height", "8", "--out", out, "--reference", "rt"});
      const std::string label = flag + " '" + value + "': " + r.output;
      EXPECT_EQ(r.exit_code, 2) << label;
      EXPECT_EQ(r.output.rfind("levrt: " + flag + ": ", 0), 0u) << label;
      EXPECT_NE(r.output.find("'" + value + "'"), std::string::npos) << label;
      EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << label;
      EXPECT_TRUE(folder_is_empty()) << label;
    }
  }
  for (const std::string top : {"+3", " 3"}) {
    const CommandRun r =
        run_levrt({"inspect", "--width", "8", "--height", "8", "--pixel", "1,1", "--top", top});
    EXPECT_EQ(r.exit_code, 2) << top << ": " << r.output;
    EXPECT_NE(r.output.find("--top: must be a decimal integer"), std::string::npos) << r.output;
  }
  // Plain decimal in each form the grammar takes still renders.
  const CommandRun plain =
      run_levrt({"render", "--width", "008", "--height", "8", "--tolerance", ".5", "--exposure",
                 "-1.", "--fov", "4E1", "--camera-position", "-1e1,0.5,3", "--out", out});
  EXPECT_EQ(plain.exit_code, 0) << plain.output;
}

// --camera picks one of a glTF file's cameras: with a scene model or a scene file it chose
// nothing and was ignored (exit 0); it is refused as --level is for a scene file.
TEST_F(Cli, ACameraIndexForASceneWithoutCamerasIsRefused) {
  const std::string out = path("image.png");
  for (const char* value : {"0", "1", "7"}) {
    const CommandRun r = run_levrt({"render", "--scene", "maze", "--camera", value, "--width", "8",
                                    "--height", "8", "--out", out});
    EXPECT_EQ(r.exit_code, 2) << value << ": " << r.output;
    EXPECT_NE(r.output.find(std::string("--camera: only glTF files have cameras of their own, "
                                        "got '") +
                            value + "'"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_TRUE(folder_is_empty()) << value;
  }
}

// --relative-error out of [0, 1] with the method that reads it, and any value with a method that
// ignores it: one line naming the flag, exit 2, nothing written.
TEST_F(Cli, RelativeErrorOutOfRangeOrIgnoredIsRefused) {
  const std::string out = path("image.png");
  std::vector<std::vector<std::string>> cases;
  for (const char* method : {"lightcuts", "lev_cut"}) {
    for (const char* value : {"-0.01", "-1", "nan", "NaN", "1.0001", "2", "inf", "", "x"})
      cases.push_back({"--method", method, "--relative-error", value});
  }
  for (const char* method : {"rt", "lev", "lev_est", "ast", "light_tree"})
    cases.push_back({"--method", method, "--relative-error", "0.02"});
  for (std::vector<std::string> args : cases) {
    const std::string label = args[1] + " " + args[3];
    args.insert(args.begin(), "render");
    for (const char* a : {"--width", "8", "--height", "8", "--out"}) args.emplace_back(a);
    args.push_back(out);
    const CommandRun r = run_levrt(args);
    EXPECT_EQ(r.exit_code, 2) << label << ": " << r.output;
    EXPECT_NE(r.output.find("--relative-error"), std::string::npos) << label << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << label << ": " << r.output;
    EXPECT_TRUE(folder_is_empty()) << label;
  }
  for (const char* method : {"lightcuts", "lev_cut"}) {
    const CommandRun ok = run_levrt({"render", "--method", method, "--relative-error", "0.05",
                                     "--width", "8", "--height", "8", "--out", out});
    EXPECT_EQ(ok.exit_code, 0) << method << ": " << ok.output;
    // The summary names the setting the method reads, not the tolerance it ignores.
    EXPECT_NE(ok.output.find(std::string(method) + ", relative error 0.05:"), std::string::npos)
        << ok.output;
    EXPECT_EQ(ok.output.find("tolerance"), std::string::npos) << ok.output;
  }
  const CommandRun rt =
      run_levrt({"render", "--method", "rt", "--width", "8", "--height", "8", "--out", out});
  EXPECT_NE(rt.output.find(" lights, rt: "), std::string::npos) << rt.output;
}

// Every flag the chosen method ignores is refused, as --relative-error was: --tolerance with rt
// rendered rt (exit 0), --lights-per-point with lev, --rt-fallback with a sampler, and the
// missed-light estimate with a method that does not estimate it (ast, lightcuts, lev_cut: its
// stats, EXR channel and heatmap read 0 where the pixels differ from rt's). One line naming the
// flag, the method and the value, exit 2, nothing written; in `inspect` too.
TEST_F(Cli, AFlagTheMethodIgnoresIsRefused) {
  const std::string out = path("image.png");
  const std::vector<std::vector<std::string>> cases = {
      {"--method", "rt", "--tolerance", "0.5"},
      {"--method", "lightcuts", "--tolerance", "0.001"},
      {"--method", "lev_cut", "--tolerance", "0"},
      {"--method", "lev", "--lights-per-point", "4"},
      {"--method", "rt", "--rt-fallback", "off"},
      {"--method", "light_tree", "--rt-fallback", "on"},
      {"--method", "ast", "--missed-draws", "8"},
      {"--method", "lightcuts", "--missed-draws", "8"},
      {"--method", "lev_cut", "--missed-draws", "2"},
      {"--method", "lev_cut", "--heatmap-missed", path("missed.png")},
  };
  for (std::vector<std::string> args : cases) {
    const std::string flag = args[2], label = args[1] + " " + args[2];
    args.insert(args.begin(), "render");
    for (const char* a : {"--width", "8", "--height", "8", "--out"}) args.emplace_back(a);
    args.push_back(out);
    const CommandRun r = run_levrt(args);
    EXPECT_EQ(r.exit_code, 2) << label << ": " << r.output;
    EXPECT_EQ(r.output.rfind("levrt: " + flag + ": method " + args[2], 0), 0u)
        << label << ": " << r.output;
    EXPECT_NE(r.output.find("got '" + args[4] + "'"), std::string::npos) << label << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << label << ": " << r.output;
    EXPECT_TRUE(folder_is_empty()) << label;
  }
  const CommandRun inspect = run_levrt({"inspect", "--method", "rt", "--tolerance", "0.1",
                                        "--width", "8", "--height", "8", "--pixel", "1,1"});
  EXPECT_EQ(inspect.exit_code, 2) << inspect.output;
  EXPECT_EQ(inspect.output.rfind("levrt: --tolerance: method rt ignores it", 0), 0u)
      << inspect.output;
  // What the methods read is taken, the missed light of those that estimate it or leave none out.
  for (const char* method : {"lev", "lev_est", "lev_bounded", "rt", "lev_mc", "light_tree"}) {
    const CommandRun ok = run_levrt({"render", "--method", method, "--missed-draws", "2", "--width",
                                     "8", "--height", "8", "--out", out});
    EXPECT_EQ(ok.exit_code, 0) << method << ": " << ok.output;
  }
}

// --resolution sizes the viewer's image; render and inspect took it and rendered --width x
// --height (exit 0): one line naming the flag, exit 2, nothing written.
TEST_F(Cli, TheViewersResolutionIsRefusedHeadless) {
  for (const char* value : {"fit/4", "typed", "fit"}) {
    const CommandRun render = run_levrt({"render", "--resolution", value, "--width", "8",
                                         "--height", "8", "--out", path("image.png")});
    EXPECT_EQ(render.exit_code, 2) << render.output;
    EXPECT_EQ(render.output.rfind("levrt: --resolution: only the viewer", 0), 0u) << render.output;
    EXPECT_NE(render.output.find(std::string("got '") + value + "'"), std::string::npos);
    EXPECT_EQ(std::count(render.output.begin(), render.output.end(), '\n'), 1) << render.output;
    const CommandRun inspect = run_levrt(
        {"inspect", "--resolution", value, "--width", "8", "--height", "8", "--pixel", "1,1"});
    EXPECT_EQ(inspect.exit_code, 2) << inspect.output;
    EXPECT_EQ(inspect.output.rfind("levrt: --resolution: only the viewer", 0), 0u)
        << inspect.output;
  }
  EXPECT_TRUE(folder_is_empty());
}

// inspect lists a pixel's lights and makes no missed-light estimate: it took --missed-draws 4 and
// ignored it (exit 0). Refused now as a flag the method ignores is: one line, exit 2.
TEST_F(Cli, InspectRefusesTheMissedLightDrawsItWouldIgnore) {
  const CommandRun r = run_levrt({"inspect", "--missed-draws", "4", "--width", "8", "--height", "8",
                                  "--pixel", "1,1", "--json", path("pixel.json")});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("levrt: --missed-draws: inspect makes no missed-light estimate", 0), 0u)
      << r.output;
  EXPECT_NE(r.output.find("got '4'"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_TRUE(folder_is_empty());
  const CommandRun off = run_levrt(
      {"inspect", "--missed-draws", "0", "--width", "8", "--height", "8", "--pixel", "1,1"});
  EXPECT_EQ(off.exit_code, 0) << off.output;
}

// view --help listed eight of the scripted changes' keys (no ab, swipe, hover, inspect, window,
// drop, copy, trade, ...): every key the --set refusal names, but the settings (their own flags),
// is in the help.
TEST_F(Cli, TheViewersHelpNamesEveryScriptedChangeKey) {
  const CommandRun help = run_levrt({"view", "--help"});
  ASSERT_EQ(help.exit_code, 0) << help.output;
  const CommandRun refused = run_levrt({"view", "--frames", "1", "--set", "no_such_key=1@0"});
  ASSERT_EQ(refused.exit_code, 2) << refused.output;
  const std::string marker = "key must be one of ";
  const std::size_t at = refused.output.find(marker);
  ASSERT_NE(at, std::string::npos) << refused.output;
  std::stringstream keys(
      refused.output.substr(at + marker.size(), refused.output.find(',', at) - at - marker.size()));
  int named = 0;
  for (std::string key; std::getline(keys, key, '|');) {
    if (help.output.find("--" + key + " ") != std::string::npos) continue;  // a setting's flag
    ++named;
    EXPECT_TRUE(help.output.find(" " + key + ",") != std::string::npos ||
                help.output.find(" " + key + ")") != std::string::npos)
        << key << " is not named by view --help";
  }
  EXPECT_GE(named, 10);
}

// A flag given twice was refused in CLI11's words, "--tolerance: At Most 1 required but received
// 2", naming no value: one line naming the flag and each value as typed, exit 2, nothing written.
TEST_F(Cli, AFlagGivenTwiceIsRefusedNamingBothValues) {
  const CommandRun r = run_levrt({"render", "--tolerance", "0.1", "--width", "8", "--height", "8",
                                  "--tolerance=0.2", "--out", path("image.png")});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output, "levrt: --tolerance: may be given once, got '0.1', then '0.2'\n");
  const CommandRun out = run_levrt(
      {"render", "--width", "8", "--height", "8", "--out", path("a.png"), "--out", path("b.png")});
  EXPECT_EQ(out.exit_code, 2) << out.output;
  EXPECT_NE(out.output.find("--out: may be given once, got "), std::string::npos) << out.output;
  EXPECT_NE(out.output.find(path("b.png")), std::string::npos) << out.output;
  EXPECT_TRUE(folder_is_empty());
}

// view --resolution fit/2 --width 100 opened the window at the fitted size, the typed width
// ignored without a word: refused before the window opens, one line naming the flag.
TEST_F(Cli, TheViewerRefusesATypedSizeBesideAFittedResolution) {
  for (const char* flag : {"--width", "--height"}) {
    const CommandRun r = run_levrt({"view", "--resolution", "fit/2", flag, "100", "--frames", "1",
                                    "--screenshot", path("shot.png")});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(r.output.rfind(std::string("levrt: ") + flag + ": --resolution fit/2 sizes", 0), 0u)
        << r.output;
    EXPECT_NE(r.output.find("got '100'"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
  EXPECT_TRUE(folder_is_empty());
}

// The noise heatmap of one pass was written blank (range 0..0) while the stats said the noise
// is unknown (std_error_avg_pct null): refused, one line and exit 2, nothing written.
TEST_F(Cli, TheNoiseHeatmapOfOnePassIsRefused) {
  const CommandRun r = run_levrt({"render", "--width", "8", "--height", "8", "--heatmap-noise",
                                  path("noise.png"), "--stats", path("s.json")});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("levrt: --heatmap-noise: ", 0), 0u) << r.output;
  EXPECT_NE(r.output.find("--spp 2"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_TRUE(folder_is_empty());
  const CommandRun two = run_levrt({"render", "--width", "8", "--height", "8", "--spp", "2",
                                    "--heatmap-noise", path("noise.png")});
  EXPECT_EQ(two.exit_code, 0) << two.output;
}

TEST_F(Cli, AbsurdImageSizeIsRefusedBeforeRendering) {
  const CommandRun r =
      run_levrt({"render", "--width", "16384", "--height", "16384", "--out", path("a.png")});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--width"), std::string::npos) << r.output;
  EXPECT_TRUE(folder_is_empty());
}

TEST_F(Cli, LightsListsTheValidCounts) {
  const CommandRun r = run_levrt({"render", "--lights", "100", "--out", path("a.png")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("64, 256, 1024, 4096, 16384"), std::string::npos) << r.output;
}

TEST_F(Cli, LevelAndLightsTogetherAreRejected) {
  const CommandRun r = run_levrt({"render", "--level", "3", "--lights", "64"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
}

TEST_F(Cli, BadOutputPathsExitTwoAndWriteNothing) {
  const std::vector<std::vector<std::string>> cases = {
      {"--out", path("missing/a.png")},
      {"--stats", path("nope/s.json")},
      {"--heatmap-lights", dir_.string()},
      {"--heatmap-nodes", ""},
      {"--heatmap-noise", path("noise.jpg")},
      {"--heatmap-noise", path("missing/n.png")},
      {"--out", path("n.png"), "--heatmap-noise", path("n.png")},
      {"--out", path("same.png"), "--heatmap-lights", path("same.png")},
      {"--out", path("x.png"), "--stats", path("./x.png")},
      {"--heatmap-bound", path("missing/b.png")},
      {"--out", path("b.png"), "--heatmap-bound", path("b.png")},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"render", "--width", "8", "--height", "8"};
    args.insert(args.end(), c.begin(), c.end());
    const CommandRun r = run_levrt(args);
    EXPECT_EQ(r.exit_code, 2) << c[0] << " " << c[1] << ": " << r.output;
    EXPECT_NE(r.output.find(c.size() > 2 ? c[2] : c[0]), std::string::npos) << r.output;
    EXPECT_TRUE(folder_is_empty()) << r.output;
  }
  if (::geteuid() != 0) {  // root writes anywhere; the check only means something for users
    fs::create_directories(dir_ / "locked");
    fs::permissions(dir_ / "locked", fs::perms::owner_read | fs::perms::owner_exec);
    const CommandRun r = run_levrt({"render", "--out", path("locked/a.png")});
    EXPECT_EQ(r.exit_code, 2) << r.output;
  }
}

TEST_F(Cli, UnknownFlagsAndSubcommandsExitTwo) {
  EXPECT_EQ(run_levrt({"render", "--colour", "red"}).exit_code, 2);
  EXPECT_EQ(run_levrt({"paint"}).exit_code, 2);
  EXPECT_EQ(run_levrt({"render", "--help"}).exit_code, 0);
}

// Values the flags took or refused unclearly: inspect's --json '' and view's --screenshot,
// --script and --controls '' were taken as not given (exit 0); inspect's --top took "0x10" and
// " 3" and said "Could not convert: --top = 3.5"; view's --frames -1 printed the largest double in
// full (a 330-character line). Each is now one short line naming the flag and the value, exit 2.
TEST_F(Cli, AnEmptyJsonOrNegativeFrameCountIsOneShortLine) {
  const CommandRun json =
      run_levrt({"inspect", "--width", "8", "--height", "8", "--pixel", "1,1", "--json", ""});
  EXPECT_EQ(json.exit_code, 2) << json.output;
  EXPECT_NE(json.output.find("--json: needs a value, got ''"), std::string::npos) << json.output;
  EXPECT_EQ(std::count(json.output.begin(), json.output.end(), '\n'), 1) << json.output;
  for (const std::string top : {"3.5", "0x10", " 3", "-1", "99999999999999"}) {
    const CommandRun r =
        run_levrt({"inspect", "--width", "8", "--height", "8", "--pixel", "1,1", "--top", top});
    EXPECT_EQ(r.exit_code, 2) << top << ": " << r.output;
    EXPECT_NE(
        r.output.find("--top: must be a decimal integer in [0, 2147483647], got '" + top + "'"),
        std::string::npos)
        << r.output;
  }
  const CommandRun frames = run_levrt({"view", "--frames", "-1"});
  EXPECT_EQ(frames.exit_code, 2) << frames.output;
  EXPECT_NE(frames.output.find("--frames"), std::string::npos) << frames.output;
  EXPECT_NE(frames.output.find("-1"), std::string::npos) << frames.output;
  EXPECT_EQ(std::count(frames.output.begin(), frames.output.end(), '\n'), 1) << frames.output;
  EXPECT_LT(frames.output.size(), 120u) << frames.output;
  // The viewer's files and window: refused while the flags are read, display or none.
  for (const std::string flag : {"--screenshot", "--script", "--controls", "--window"}) {
    const CommandRun r = run_levrt({"view", "--frames", "1", flag, ""});
    EXPECT_EQ(r.exit_code, 2) << flag << ": " << r.output;
    EXPECT_NE(r.output.find(flag + ": needs a value, got ''"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
  EXPECT_TRUE(folder_is_empty());
}

// A setting an older levrt named otherwise ("samples" meant lights per point): one line naming
// the flag and what it is called now, exit 2, in every command that renders and in `=` form.
TEST_F(Cli, ARenamedFlagNamesItsNewName) {
  const std::vector<std::vector<std::string>> runs = {
      {"render", "--samples", "4", "--out", (dir_ / "a.png").string()},
      {"render", "--missed-samples=16", "--out", (dir_ / "b.png").string()},
      {"inspect", "--samples", "2", "--pixel", "1,1"},
  };
  for (const auto& args : runs) {
    const CommandRun r = run_levrt(args);
    EXPECT_EQ(r.exit_code, 2) << args[1];
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    const std::string now =
        args[1].find("missed") != std::string::npos ? "--missed-draws" : "--lights-per-point";
    EXPECT_NE(r.output.find("is now called " + now), std::string::npos) << r.output;
  }
  EXPECT_TRUE(folder_is_empty());
}

// Each command's help shows the default that command uses: the viewer accumulates passes.
TEST_F(Cli, HelpShowsEachCommandsOwnDefaults) {
  const CommandRun render = run_levrt({"render", "--help"});
  const CommandRun view = run_levrt({"view", "--help"});
  ASSERT_EQ(render.exit_code, 0) << render.output;
  ASSERT_EQ(view.exit_code, 0) << view.output;
  EXPECT_NE(render.output.find("--spp INT in [1, 100000]=1 "), std::string::npos) << render.output;
  EXPECT_NE(view.output.find("--spp INT in [1, 100000]=64 "), std::string::npos) << view.output;
}

TEST_F(Cli, RenderWritesEveryOutputWithTheDocumentedStats) {
  const CommandRun r = run_levrt({"render",
                                  "--scene",
                                  "building",
                                  "--lights",
                                  "64",
                                  "--method",
                                  "lev",
                                  "--tolerance",
                                  "0.01",
                                  "--width",
                                  "40",
                                  "--height",
                                  "30",
                                  "--spp",
                                  "2",
                                  "--out",
                                  path("i.png"),
                                  "--heatmap-lights",
                                  path("l.png"),
                                  "--heatmap-nodes",
                                  path("n.png"),
                                  "--heatmap-bound",
                                  path("b.png"),
                                  "--stats",
                                  path("s.json"),
                                  "--reference",
                                  "rt"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {"i.png", "l.png", "n.png", "b.png", "s.json"})
    EXPECT_TRUE(fs::exists(path(f))) << f;
  std::FILE* f = std::fopen(path("s.json").c_str(), "r");
  ASSERT_NE(f, nullptr);
  std::string json;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), f)) json += buffer.data();
  std::fclose(f);
  for (const char* key : {"\"scene\"",
                          "\"level\"",
                          "\"lights\": 64",
                          "\"method\": \"lev\"",
                          "\"tolerance\"",
                          "\"width\": 40",
                          "\"height\": 30",
                          "\"spp\": 2",
                          "\"threads\"",
                          "\"time_build_s\"",
                          "\"time_render_s\"",
                          "\"shading_points\"",
                          "\"shadow_rays\"",
                          "\"lights_tested_avg\"",
                          "\"nodes_visited_avg\"",
                          "\"hierarchy_bytes\"",
                          "\"pixel_error_avg_pct\"",
                          "\"pixel_error_max_pct\"",
                          "\"error_bound_avg_pct\"",
                          "\"error_bound_max_pct\""}) {
    EXPECT_NE(json.find(key), std::string::npos) << key;
  }
}

// --heatmap-bound takes the same checks as every output: a missing folder, or the file --out
// writes, is one line naming the flag, exit code 2, and nothing written.
TEST_F(Cli, HeatmapBoundIntoAMissingFolderOrOntoTheImageIsOneLineExitTwoAndNothingWritten) {
  const std::vector<std::vector<std::string>> cases = {
      {"--out", path("a.png"), "--heatmap-bound", path("missing/b.png")},
      {"--out", path("a.png"), "--heatmap-bound", path("a.png")},
      {"--out", path("a.png"), "--heatmap-bound", path("./a.png")},
      {"--heatmap-bound", path("b.json")},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"render", "--width", "8",           "--height",
                                     "8",      "--stats", path("s.json")};
    args.insert(args.end(), c.begin(), c.end());
    const CommandRun r = run_levrt(args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("--heatmap-bound"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_TRUE(folder_is_empty()) << r.output;
  }
}

// The headless main job writes every output into out/, the error bound's heatmap among them.
TEST_F(Cli, TheSnapshotWritesTheErrorBoundHeatmapBesideTheOthers) {
  const CommandRun r =
      levrt_test::run_shell("cd " + levrt_test::shell_quote(dir_.string()) + " && " +
                            levrt_test::shell_quote(LEVRT_BINARY) + " snapshot");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {"building.png", "building_lights_tested.png", "building_nodes_visited.png",
                        "building_error_bound.png", "building_stats.json"}) {
    EXPECT_TRUE(fs::exists(dir_ / "out" / f)) << f << "\n" << r.output;
  }
  std::ifstream in(dir_ / "out" / "building_stats.json");
  const nlohmann::json stats = nlohmann::json::parse(in);
  EXPECT_TRUE(stats.contains("error_bound_avg_pct") && stats.contains("pixel_error_avg_pct"));
}

// The stats report the certified bound without a reference: 0 for rt, which tests every light,
// and above 0 for lev on the hall at tolerance 0.1, where points have lights below the tolerance
// that reach them (at 0.01 lev culls only lights that cannot, and its bound there is 0).
TEST_F(Cli, StatsReportTheErrorBoundWithoutAReference) {
  const auto bound = [&](const std::string& method) {
    std::vector<std::string> args = {"render",
                                     "--scene",
                                     "hall",
                                     "--lights",
                                     "64",
                                     "--method",
                                     method,
                                     "--width",
                                     "16",
                                     "--height",
                                     "12",
                                     "--stats",
                                     path(method + ".json"),
                                     "--heatmap-bound",
                                     path(method + ".png"),
                                     "--quiet"};
    if (method != "rt") args.insert(args.end(), {"--tolerance", "0.1"});  // rt has none
    const CommandRun r = run_levrt(args);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    std::ifstream in(path(method + ".json"));
    const nlohmann::json stats = nlohmann::json::parse(in);
    EXPECT_FALSE(stats.contains("pixel_error_avg_pct"));
    EXPECT_TRUE(fs::exists(path(method + ".png")));
    EXPECT_LE(stats.at("error_bound_avg_pct").get<double>(),
              stats.at("error_bound_max_pct").get<double>());
    return stats.at("error_bound_max_pct").get<double>();
  };
  EXPECT_EQ(bound("rt"), 0.0);
  EXPECT_GT(bound("lev"), 0.0);
}

TEST_F(Cli, SamplingMethodsWriteTheNoiseHeatmapAndItsEstimate) {
  for (const char* method : {"lev_mc", "light_tree"}) {
    const std::string stats = path(std::string(method) + ".json");
    const std::string noise = path(std::string(method) + "_noise.png");
    std::vector<std::string> args = {"render", "--scene",
                                     "hall",   "--lights",
                                     "64",     "--method",
                                     method,   "--width",
                                     "32",     "--height",
                                     "24",     "--spp",
                                     "4",      "--lights-per-point",
                                     "2",      "--heatmap-noise",
                                     noise,    "--stats",
                                     stats,    "--reference",
                                     "rt"};
    // light_tree draws from the whole hierarchy: it has no tolerance.
    if (std::string(method) == "lev_mc") args.insert(args.end(), {"--tolerance", "0.3"});
    const CommandRun r = run_levrt(args);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("std error avg"), std::string::npos) << r.output;
    const std::string png = read_file(noise);
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << method;
    const nlohmann::json j = nlohmann::json::parse(read_file(stats));
    EXPECT_EQ(j["method"], method);
    EXPECT_GT(j["std_error_avg_pct"].get<double>(), 0.0) << method;
    EXPECT_GT(j["pixel_error_avg_pct"].get<double>(), 0.0) << method;
    EXPECT_TRUE(j["heatmap_noise_range"].is_array()) << method;
  }
  // One pass has no spread: no estimate is claimed.
  const CommandRun one = run_levrt(
      {"render", "--lights", "64", "--width", "8", "--height", "8", "--stats", path("one.json")});
  ASSERT_EQ(one.exit_code, 0) << one.output;
  EXPECT_TRUE(nlohmann::json::parse(read_file(path("one.json")))["std_error_avg_pct"].is_null());
}

}  // namespace
