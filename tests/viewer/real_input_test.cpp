// The viewer's panel driven by real X input: a private Xvfb display, the viewer with
// `--real-input --controls FILE`, and xdotool clicking and dragging at the rectangles the viewer
// recorded for its named controls (no hard-coded pixels). The settings the clicks produced are
// read back from the same file: tolerance slider clicks give values inside the slider's span,
// growing with x; a drag lands between the clicks around it; the 0 button gives 0; the method
// combo, the depth "+" button, the missed-light draws' "+" and "-" and a view radio button do
// what they say. Skipped when Xvfb or
// xdotool is missing. Labelled "threads" with the other window tests.
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <variant>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/settings.h"
#include "tests/support/read_file.h"
#include "tests/support/run_command.h"

namespace {

using levrt_test::read_file;
namespace fs = std::filesystem;
using levrt_test::shell_quote;
using Json = nlohmann::json;

bool have_command(const char* name) {
  return std::system(("command -v " + std::string(name) + " > /dev/null 2>&1").c_str()) == 0;
}

class RealInput : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!have_command("Xvfb") || !have_command("xdotool"))
      GTEST_SKIP() << "Xvfb or xdotool is not installed (third_party/install-deps.sh)";
    dir_ = fs::temp_directory_path() / ("levrt_real_input_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // -displayfd picks a free display number and writes it once the server accepts clients.
    run_in_background(
        "Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp 3>" + shell_quote(path("display")),
        "xvfb.pid", "xvfb.rc");
    ASSERT_TRUE(wait_for([&] {
      return read_file(path("display")).find('\n') != std::string::npos;
    })) << "Xvfb did not start";
    display_ = ":" + read_file(path("display")).substr(0, read_file(path("display")).find('\n'));
  }

  void TearDown() override {
    if (dir_.empty()) return;
    stop("viewer.pid");
    stop("xvfb.pid");
    for (const std::string name : {"viewer", "xvfb"}) {
      if (!read_file(path(name + ".pid")).empty())
        wait_for([&] { return !read_file(path(name + ".rc")).empty(); });
    }
    fs::remove_all(dir_);
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Runs `command` in the background; its pid and, when it ends, its exit code go to files.
  void run_in_background(const std::string& command, const std::string& pid_file,
                         const std::string& rc_file) {
    const std::string shell = "(" + command + " > " + shell_quote(path(rc_file + ".log")) +
                              " 2>&1 & echo $! > " + shell_quote(path(pid_file)) +
                              "; wait $!; echo $? > " + shell_quote(path(rc_file)) + ") &";
    ASSERT_EQ(std::system(shell.c_str()), 0);
    ASSERT_TRUE(wait_for([&] { return !read_file(path(pid_file)).empty(); }));
  }

  void stop(const std::string& pid_file) {
    const std::string pid = read_file(path(pid_file));
    if (!pid.empty()) ::kill(std::stoi(pid), SIGTERM);
  }

  // Polls until the condition holds; the generous limit only stops a hung test.
  static bool wait_for(const std::function<bool()>& condition) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < give_up) {
      if (condition()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
  }

  Json controls() const { return Json::parse(read_file(dir_ / "controls.json"), nullptr, false); }

  // Waits until the viewer's file satisfies the condition with the mouse released and no control
  // held, and returns it.
  Json wait_for_controls(const std::function<bool(const Json&)>& condition) {
    Json latest;
    wait_for([&] {
      latest = controls();
      return !latest.is_discarded() && latest.is_object() && latest.contains("mouse_busy") &&
             !latest["mouse_busy"].get<bool>() && condition(latest);
    });
    return latest;
  }

  void xdotool(const std::string& arguments) {
    const std::string command = "DISPLAY=" + display_ + " xdotool " + arguments;
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
  }

  // A point inside a recorded rectangle, at fractions of its width and height.
  static std::string point(const Json& rect, double fx, double fy) {
    const double x = rect[0].get<double>() + fx * (rect[2].get<double>() - rect[0].get<double>());
    const double y = rect[1].get<double>() + fy * (rect[3].get<double>() - rect[1].get<double>());
    return std::to_string(static_cast<int>(x)) + " " + std::to_string(static_cast<int>(y));
  }

  // Moves the pointer onto a named control and waits until the viewer sees it there, so the
  // click that follows reaches the window whatever the load. The rectangle is read again while
  // waiting and the pointer follows it: a popup (the method combo's list) lays its items out in
  // the frame it opens, before ImGui has sized and placed it, so its first rectangles can be stale.
  bool hover(const std::string& control, double fx) {
    std::string moved_to;
    Json c;
    wait_for([&] {
      c = controls();
      if (c.is_discarded() || !c.is_object() || !c.contains("controls") ||
          !c["controls"].contains(control) || !c["controls"][control].is_array())
        return false;
      const std::string target = point(c["controls"][control], fx, 0.5);
      if (target != moved_to) {
        xdotool("mousemove " + target);
        moved_to = target;
        return false;
      }
      return c.contains("mouse_busy") && !c["mouse_busy"].get<bool>() &&
             setting(c, "hovered") == control;
    });
    EXPECT_FALSE(moved_to.empty()) << control << " is not among the recorded controls";
    // On failure: whether the viewer still runs (its exit code once it ended) and what it said.
    EXPECT_EQ(setting(c, "hovered"), control)
        << "viewer exit code: '" << read_file(path("viewer.rc"))
        << "', output: " << read_file(path("viewer.rc.log"));
    return setting(c, "hovered") == control;
  }

  // Clicks a named control and waits until the file shows `key` different from `before`.
  Json click_and_wait(const std::string& control, double fx, const std::string& key,
                      const std::string& before) {
    if (!hover(control, fx)) return Json{};
    xdotool("click 1");
    return wait_for_controls([&](const Json& c) { return setting(c, key) != before; });
  }

  static std::string setting(const Json& c, const std::string& key) {
    // The view and the hovered control are top-level keys, the settings under "settings".
    const bool top = key == "view" || key == "hovered";
    const Json* holder = top ? &c : (c.contains("settings") ? &c["settings"] : nullptr);
    if (!holder || !holder->contains(key) || !(*holder)[key].is_string()) return "";
    return (*holder)[key].get_ref<const std::string&>();
  }

  fs::path dir_;
  std::string display_;
};

TEST_F(RealInput, ClicksAndDragsOnThePanelSetWhatTheControlsShow) {
  const std::string levrt = LEVRT_BINARY;
  run_in_background("DISPLAY=" + display_ + " ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:detect_leaks=0\" " +
                        shell_quote(levrt) +
                        " view --lights 64 --width 96 --height 72 --depth 2 --window 1280x800 "
                        "--frames 100000000 --real-input --controls " +
                        shell_quote(path("controls.json")),
                    "viewer.pid", "viewer.rc");
  Json c =
      wait_for_controls([](const Json& j) { return j["controls"].contains("tolerance_slider"); });
  ASSERT_TRUE(c.is_object() && c["controls"].contains("tolerance_slider"))
      << read_file(path("viewer.rc.log"));

  const auto& range = std::get<app::RealRange>(app::find_setting("tolerance")->kind);
  // Slider clicks from left to right: every value inside the span, each larger than the last.
  double previous = -1.0;
  std::string shown = setting(c, "tolerance");
  std::vector<double> clicked;
  for (double fx : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    c = click_and_wait("tolerance_slider", fx, "tolerance", shown);
    shown = setting(c, "tolerance");
    ASSERT_FALSE(shown.empty());
    const double value = std::stod(shown);
    EXPECT_GE(value, range.slider_min) << fx;
    EXPECT_LE(value, range.slider_max) << fx;
    EXPECT_GT(value, previous) << fx;
    previous = value;
    clicked.push_back(value);
  }
  EXPECT_LT(clicked.front(), 1e-4);  // the left end reaches small tolerances, not only 1e-6 or 1
  EXPECT_GT(clicked.back(), 0.1);

  // A drag from the right end back to a fifth of the width lands between the clicks at 0.1 and
  // 0.3 of the width.
  const Json slider = c["controls"]["tolerance_slider"];
  // The pauses let the viewer draw frames between the steps (ImGui reads the pointer once a
  // frame), as a hand would; the result is checked by value, not by time.
  ASSERT_TRUE(hover("tolerance_slider", 0.9));
  xdotool("sleep 0.2 mousedown 1 sleep 0.2 mousemove " + point(slider, 0.6, 0.5) +
          " sleep 0.2 mousemove " + point(slider, 0.2, 0.5) + " sleep 0.2 mouseup 1");
  c = wait_for_controls([&](const Json& j) {
    const std::string t = setting(j, "tolerance");
    return !t.empty() && std::stod(t) < clicked[2];
  });
  const double dragged = std::stod(setting(c, "tolerance"));
  EXPECT_GT(dragged, clicked[0]);
  EXPECT_LT(dragged, clicked[1]);

  c = click_and_wait("tolerance_zero", 0.5, "tolerance", setting(c, "tolerance"));
  EXPECT_EQ(setting(c, "tolerance"), "0");

  // The method combo: open it, then pick rt from the list it shows.
  ASSERT_EQ(setting(c, "method"), "lev");
  ASSERT_TRUE(hover("method", 0.5));
  xdotool("click 1");
  c = wait_for_controls([](const Json& j) { return j["controls"].contains("method:rt"); });
  c = click_and_wait("method:rt", 0.5, "method", "lev");
  EXPECT_EQ(setting(c, "method"), "rt");

  c = click_and_wait("depth+", 0.5, "depth", "2");
  EXPECT_EQ(setting(c, "depth"), "3");

  // The missed-light draws step over the 1 a render refuses: 0 (off), then 2, and back to 0.
  c = click_and_wait("missed-draws+", 0.5, "missed-draws", "0");
  EXPECT_EQ(setting(c, "missed-draws"), "2");
  c = click_and_wait("missed-draws-", 0.5, "missed-draws", "2");
  EXPECT_EQ(setting(c, "missed-draws"), "0");

  // Six hundred wheel notches out over the picture: the zoom stops at the camera's bound (it used
  // to go past 1.8e18, where Embree asserts and the viewer died); the panel still answers.
  ASSERT_TRUE(hover("image", 0.5));
  xdotool("click --repeat 600 --delay 1 5 sleep 1");

  // A typed value's rectangle is its frame alone: it held the label beside it too, so its centre
  // fell on the label "Relative error", where a click focuses nothing and the typing was lost.
  ASSERT_TRUE(hover("method", 0.5));
  xdotool("click 1");
  c = wait_for_controls([](const Json& j) { return j["controls"].contains("method:lightcuts"); });
  c = click_and_wait("method:lightcuts", 0.5, "method", "rt");
  ASSERT_EQ(setting(c, "method"), "lightcuts");
  for (const char* field : {"tolerance_field", "relative-error_field", "exposure_field"}) {
    ASSERT_TRUE(c["controls"].contains(field)) << field;
    EXPECT_LE(c["controls"][field][2].get<double>(), c["controls"]["depth+"][2].get<double>())
        << field << " reaches past the panel's number column onto its label";
  }
  ASSERT_TRUE(hover("relative-error_field", 0.5));
  xdotool("click 1 sleep 0.2 type --delay 50 0.05");
  xdotool("sleep 0.2 keydown Return sleep 0.1 keyup Return");
  c = wait_for_controls([](const Json& j) { return setting(j, "relative-error") == "0.05"; });
  EXPECT_EQ(setting(c, "relative-error"), "0.05");

  // A value outside the range is refused with a message (the scripted session prints it), not
  // dropped without a word; the setting keeps its value.
  ASSERT_TRUE(hover("relative-error_field", 0.5));
  xdotool("click 1 sleep 0.2 type --delay 50 5");
  xdotool("sleep 0.2 keydown Return sleep 0.1 keyup Return");
  EXPECT_TRUE(wait_for([&] {
    return read_file(path("viewer.rc.log")).find("relative-error: must be in [0, 1], got 5") !=
           std::string::npos;
  })) << read_file(path("viewer.rc.log"));
  EXPECT_EQ(setting(controls(), "relative-error"), "0.05");

  c = click_and_wait("view:nodes", 0.5, "view", "image");
  EXPECT_EQ(setting(c, "view"), "nodes");

  // SIGTERM closes the window like its close button (exit 130).
  stop("viewer.pid");
  ASSERT_TRUE(wait_for([&] { return !read_file(path("viewer.rc")).empty(); }));
  EXPECT_EQ(std::stoi(read_file(path("viewer.rc"))), 130) << read_file(path("viewer.rc.log"));
}

}  // namespace
