// A/B against rt in the real viewer window under Xvfb, scripted: flip (ab=rt|method), the swipe
// split, the signed difference view and the error mask are drawn and read back from screenshots,
// pixel by pixel, against the headless renders of the method and of rt over the same passes; a
// method change keeps the reference and the trade plot, whose points record their passes; the
// missed-light view turns the estimate on and a snapshot carries it. Skipped without Xvfb.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/viewer/heatmap_scale.h"
#include "lev/methods.h"
#include "tests/support/exr_file.h"
#include "tests/support/folder_test.h"
#include "tests/support/png_file.h"
#include "tests/support/read_file.h"
#include "tests/support/run_command.h"
#include "tests/support/trade_report.h"
#include "tests/support/xvfb_server.h"

namespace {

using levrt_test::CommandRun;
using levrt_test::read_file;
namespace fs = std::filesystem;

using AbPng = levrt_test::PngImage;

std::vector<int> rgb(const AbPng& png, int x, int y) {
  const unsigned char* p = png.at(x, y);
  return {p[0], p[1], p[2]};
}

AbPng read_png(const fs::path& path) {
  return levrt_test::read_png_image(path);
}

// Where the picture is in the window, and how many window pixels an image pixel spans.
struct Picture {
  double x0 = 0.0, y0 = 0.0, scale = 0.0;
  // The window pixel at the centre of image pixel (x, y).
  std::vector<int> at(const AbPng& window, int x, int y) const {
    return rgb(window, static_cast<int>(std::floor(x0 + (x + 0.5) * scale)),
               static_cast<int>(std::floor(y0 + (y + 0.5) * scale)));
  }
};

constexpr int kWidth = 96;
constexpr int kHeight = 64;

// The settings both the viewer and the headless renders take (the method aside).
const std::vector<std::string> kSettings = {"--scene",     "building",
                                            "--lights",    "256",
                                            "--tolerance", "0.3",
                                            "--width",     std::to_string(kWidth),
                                            "--height",    std::to_string(kHeight),
                                            "--spp",       "2"};

class AbWindow : public levrt_test::FolderTest {
 protected:
  // The headless render of `method` with the test's settings, as a PNG; the tolerance only where
  // the method reads it (render refuses a flag its method ignores).
  AbPng headless(const std::string& method) {
    const std::optional<lev::Method> id = lev::parse_method(method);
    EXPECT_TRUE(id.has_value()) << method;
    const bool reads_tolerance = id && lev::method_info(*id).uses_tolerance;
    std::string command = levrt_test::shell_quote(LEVRT_BINARY) + " render --quiet";
    for (std::size_t i = 0; i < kSettings.size(); ++i) {
      if (kSettings[i] == "--tolerance" && !reads_tolerance) {
        ++i;
        continue;
      }
      command += " " + levrt_test::shell_quote(kSettings[i]);
    }
    const std::string out = path("headless_" + method + ".png");
    command += " --method " + method + " --out " + levrt_test::shell_quote(out);
    const CommandRun r = levrt_test::run_shell(command);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_png(out);
  }

  Picture picture() {
    const nlohmann::json controls =
        nlohmann::json::parse(read_file(path("controls.json")), nullptr, false);
    Picture p;
    if (controls.is_discarded() || !controls["controls"].contains("image")) return p;
    const nlohmann::json& r = controls["controls"]["image"];
    p.x0 = r[0].get<double>();
    p.y0 = r[1].get<double>();
    p.scale = (r[2].get<double>() - p.x0) / kWidth;
    return p;
  }

  // The image rows clear of the labels drawn at the picture's top corners.
  int first_row(const Picture& p) const { return static_cast<int>(24.0 / p.scale) + 1; }
};

TEST_F(AbWindow, FlipSwipeDifferenceAndMaskDrawWhatTheyCompare) {
  if (!levrt_test::have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  std::vector<std::string> args = kSettings;
  // clang-format off
  for (const std::string& a : std::vector<std::string>{
           "--method", "lev", "--window", "1024x640", "--frames", "15",
           "--controls", path("controls.json"),
           "--set", "reference=on@0",
           "--set", "await=idle@1",
           "--set", "screenshot=" + path("method.png") + "@2",
           "--set", "ab=rt@3",
           "--set", "screenshot=" + path("rt.png") + "@4",
           "--set", "ab=method@5",
           "--set", "swipe=0.5@6",
           "--set", "screenshot=" + path("swipe.png") + "@7",
           "--set", "swipe=off@8",
           "--set", "view=difference@9",
           "--set", "screenshot=" + path("difference.png") + "@10",
           "--set", "view=mask@11",
           "--set", "mask_threshold=0.5@12",
           "--set", "screenshot=" + path("mask.png") + "@13"})
    args.push_back(a);
  // clang-format on
  const CommandRun view = levrt_test::run_viewer_on_xvfb(args);
  ASSERT_EQ(view.exit_code, 0) << view.output;
  const AbPng method = headless("lev");
  const AbPng rt = headless("rt");
  ASSERT_TRUE(method.ok() && rt.ok());
  const Picture p = picture();
  ASSERT_GE(p.scale, 2.0) << view.output;
  const AbPng shown_method = read_png(path("method.png"));
  const AbPng shown_rt = read_png(path("rt.png"));
  const AbPng swipe = read_png(path("swipe.png"));
  const AbPng difference = read_png(path("difference.png"));
  const AbPng mask = read_png(path("mask.png"));
  ASSERT_TRUE(shown_method.ok() && shown_rt.ok() && swipe.ok() && difference.ok() && mask.ok());

  int differing = 0, equal = 0, masked = 0;
  for (int y = first_row(p); y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      SCOPED_TRACE(std::to_string(x) + "," + std::to_string(y));
      const std::vector<int> m = rgb(method, x, y), r = rgb(rt, x, y);
      // Flip: the method's picture, then rt's (both over the same two passes).
      ASSERT_EQ(p.at(shown_method, x, y), m);
      ASSERT_EQ(p.at(shown_rt, x, y), r);
      // Swipe at 0.5: the method left of the divider, rt right of it (the divider's own
      // columns aside).
      if (x < kWidth / 2 - 2) {
        ASSERT_EQ(p.at(swipe, x, y), m);
      } else if (x > kWidth / 2 + 1) {
        ASSERT_EQ(p.at(swipe, x, y), r);
      }
      // The signed difference on its fixed symmetric range (±2 %): white where equal.
      const int signed_sum = m[0] + m[1] + m[2] - r[0] - r[1] - r[2];
      const int abs_sum = std::abs(m[0] - r[0]) + std::abs(m[1] - r[1]) + std::abs(m[2] - r[2]);
      const glm::u8vec3 d = app::viewer::diverging_rgb8(100.0 * signed_sum / 765.0 / 2.0);
      ASSERT_EQ(p.at(difference, x, y), (std::vector<int>{d.x, d.y, d.z}));
      if (abs_sum == 0) {
        ASSERT_EQ(p.at(difference, x, y), (std::vector<int>{235, 235, 235}));
        ++equal;
      } else {
        ++differing;
      }
      // The mask: red above 0.5 %, else the method's picture dimmed.
      if (100.0 * abs_sum / 765.0 > 0.5) {
        ASSERT_EQ(p.at(mask, x, y),
                  (std::vector<int>{app::viewer::kMaskRgb[0], app::viewer::kMaskRgb[1],
                                    app::viewer::kMaskRgb[2]}));
        ++masked;
      } else {
        ASSERT_EQ(p.at(mask, x, y), (std::vector<int>{m[0] / 3, m[1] / 3, m[2] / 3}));
      }
    }
  }
  // The comparison saw both kinds of pixel, and the mask marked some.
  EXPECT_GT(differing, 0);
  EXPECT_GT(equal, 0);
  EXPECT_GT(masked, 0);
}

TEST_F(AbWindow, AMethodChangeKeepsTheReferenceAndTheTradePlot) {
  if (!levrt_test::have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  std::vector<std::string> args = kSettings;
  // clang-format off
  for (const std::string& a : std::vector<std::string>{
           "--method", "lev", "--window", "1024x640", "--frames", "6",
           "--set", "reference=on@0",
           "--set", "await=idle@1",
           "--set", "trade=report@2",
           "--set", "method=lev_est@3",
           "--set", "await=idle@4",
           "--set", "trade=report@5"})
    args.push_back(a);
  // clang-format on
  const CommandRun view = levrt_test::run_viewer_on_xvfb(args);
  ASSERT_EQ(view.exit_code, 0) << view.output;
  // The method change kept the reference (same generation, its passes done) and the plot, which
  // now holds both methods, each error over both passes.
  const std::vector<levrt_test::TradeReport> reports = levrt_test::trade_reports(view.output);
  ASSERT_EQ(reports.size(), 2u) << view.output;
  EXPECT_EQ(reports[0].points, 1) << view.output;
  EXPECT_EQ(reports[1].points, 2) << view.output;
  EXPECT_NE(reports[0].reference, 0u) << view.output;
  EXPECT_EQ(reports[0].reference, reports[1].reference) << view.output;
  EXPECT_EQ(reports[1].passes, 2) << view.output;
  EXPECT_NE(view.output.find("trade point lev tolerance 0.3: error"), std::string::npos);
  EXPECT_NE(view.output.find("trade point lev_est tolerance 0.3: error"), std::string::npos);
  EXPECT_EQ(view.output.find("over 1 passes"), std::string::npos) << view.output;
}

TEST_F(AbWindow, TheMissedLightViewTurnsTheEstimateOnAndASnapshotCarriesIt) {
  if (!levrt_test::have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  std::vector<std::string> args = kSettings;
  // clang-format off
  for (const std::string& a : std::vector<std::string>{
           "--window", "1024x640", "--frames", "8",
           "--set", "await=idle@0",
           "--set", "snapshot=" + path("before") + "@1",
           "--set", "view=missed@2",
           "--set", "await=idle@3",
           "--set", "hover=40,40@4",
           "--set", "screenshot=" + path("missed.png") + "@5",
           "--set", "snapshot=" + path("after") + "@6"})
    args.push_back(a);
  // clang-format on
  const CommandRun view = levrt_test::run_viewer_on_xvfb(args);
  ASSERT_EQ(view.exit_code, 0) << view.output;
  const auto stats_in = [&](const std::string& folder) {
    for (const auto& entry : fs::directory_iterator(dir_ / folder)) {
      if (entry.path().string().find("_stats.json") != std::string::npos)
        return nlohmann::json::parse(read_file(entry.path()), nullptr, false);
    }
    return nlohmann::json();
  };
  const nlohmann::json before = stats_in("before");
  const nlohmann::json after = stats_in("after");
  ASSERT_TRUE(before.is_object() && after.is_object()) << view.output;
  // Off unless its view is shown: then on, as `render --heatmap-missed` reports it.
  EXPECT_FALSE(before.contains("missed_estimate_avg_pct"));
  ASSERT_TRUE(after.contains("missed_estimate_avg_pct")) << after.dump();
  EXPECT_GE(after["missed_estimate_avg_pct"].get<double>(), 0.0);
  EXPECT_EQ(after["missed_draws"].get<int>(), 16);
  EXPECT_TRUE(after.contains("heatmap_missed_range"));
  std::string exr;
  for (const auto& entry : fs::directory_iterator(dir_ / "after")) {
    if (entry.path().extension() == ".exr") exr = read_file(entry.path());
  }
  const levrt_test::ExrFile file = levrt_test::read_exr(exr);
  EXPECT_EQ(file.channels.count("missed_pct"), 1u);
  // The headless estimate of the same render: the same average.
  std::string command = levrt_test::shell_quote(LEVRT_BINARY) + " render --quiet";
  for (const std::string& a : kSettings) command += " " + levrt_test::shell_quote(a);
  command += " --method lev --heatmap-missed " +
             levrt_test::shell_quote(path("missed_headless.png")) + " --stats " +
             levrt_test::shell_quote(path("headless.json"));
  const CommandRun headless = levrt_test::run_shell(command);
  ASSERT_EQ(headless.exit_code, 0) << headless.output;
  const nlohmann::json h = nlohmann::json::parse(read_file(path("headless.json")));
  EXPECT_NEAR(after["missed_estimate_avg_pct"].get<double>(),
              h["missed_estimate_avg_pct"].get<double>(),
              1e-4 + 1e-4 * h["missed_estimate_avg_pct"].get<double>());
  EXPECT_TRUE(read_png(path("missed.png")).ok());
}

}  // namespace
