// Every user setting of levrt, in groups owned by the layers that read them, and one table that
// describes each setting once (flag, label, range, help). The CLI flags and the viewer's
// controls are both generated from this table, so they cannot drift apart; what a change
// restarts is derived once from the groups (restart_needed).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "lev/methods.h"
#include "renderer/display_transform.h"
#include "renderer/render.h"
#include "scenes/gltf_scene.h"
#include "scenes/scene_choice.h"
#include "scenes/scene_models.h"

namespace app {

// The largest image side the settings take (width, height, the viewer's typed and fitted sizes).
inline constexpr int kMaxImageSide = 16384;

// The display step (renderer/display_transform.h): radiance x 2^exposure_ev through the display
// curve. exposure_auto: the EV is chosen before the first pass (renderer/auto_exposure.h) and
// exposure_ev is then what it chose. Built-in scenes and scene files default to linear at EV 0
// (the images levrt always wrote); glTF files to auto and neutral
// (apply_scene_display_defaults). The tolerance is in these exposed units, so a new scale
// (2^EV) restarts the render of a method that reads it (lev::MethodInfo::reads_display_scale);
// otherwise, and for a new curve, the viewer re-maps what it holds.
struct DisplaySettings {
  double exposure_ev = 0.0;
  bool exposure_auto = false;
  renderer::DisplayCurve curve = renderer::DisplayCurve::linear;
};

// The user's settings: one group per layer that reads it, each comparing itself
// (restart_needed), and the viewer's sizing rule.
struct Settings {
  scenes::SceneChoice scene;      // scenes/scene_choice.h
  lev::MethodChoice method;       // lev/methods.h
  renderer::ImageSettings image;  // renderer/render.h
  DisplaySettings display;
  // The viewer's image size: the image area's pixels (fit), half or a quarter of them, or
  // image.width x image.height (typed). Headless renders always use width x height. The viewer
  // turns it into image.width and image.height, so by itself it restarts nothing.
  std::string resolution = "fit";
};

// What a change of the settings makes the renders redo, least first.
enum class Restart {
  nothing,  // the display (but the exposure of a method that reads it) or the viewer's sizing
            // rule changed: the viewer re-maps its pixels
  passes,   // only the pass count: the render goes on towards the new count
  render,   // the method's render starts again; the rt reference of the same view goes on
  view,     // every render of the view starts again, the rt reference too
  scene,    // the scene is loaded again
};

// Derived from which group changed, each group comparing itself (so a setting the current scene
// or method does not read restarts nothing): the scene choice reloads; an image setting restarts
// the view, but for those only the method's render reads (threads, the missed-light draws: the
// render) and the pass count (passes); the method choice restarts the render, and so does the
// exposure for a method whose images depend on it (DisplaySettings). A member added to
// a group restarts the view or the scene without an edit here.
Restart restart_needed(const Settings& before, const Settings& after);

// The draws of the missed-light estimate when an output asks for it and none were given.
inline constexpr int kDefaultMissedDraws = 16;

// A command-line or input mistake: reported as one line, exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A number of the settings inside its group (settings.group.member), read and written.
template <typename T>
struct SettingField {
  const T& (*get)(const Settings& settings) = nullptr;
  T& (*ref)(Settings& settings) = nullptr;
};

struct IntRange {
  SettingField<int> field;
  int min, max;
};
struct RealRange {
  SettingField<double> field;
  double min, max;
  bool logarithmic;  // the viewer's slider
  // The viewer's log slider spans [slider_min, slider_max] (within [min, max]); typed values may
  // leave it, and a 0 button sits beside it when min allows 0.
  double slider_min = 0.0, slider_max = 0.0;
  // A word the setting also takes instead of a number (the exposure's "auto"), and the flag it
  // raises (null ref: none); a number lowers it.
  const char* word = nullptr;
  SettingField<bool> word_flag = {};
};
struct Choice {
  std::string (*get)(const Settings& settings);
  void (*set)(Settings& settings, const std::string& option);  // an option, or a value also_accepts
  std::vector<std::string> (*options)();                       // valid values
  // What an option is, for the CLI help and the viewer's tooltip (null: the options say it).
  const char* (*option_label)(const std::string& option) = nullptr;
  const char* (*option_summary)(const std::string& option) = nullptr;
  // Values outside `options` this choice also takes (the scene: a .json scene file), and how
  // the error message names them.
  bool (*also_accepts)(const std::string& text) = nullptr;
  const char* also_accepts_label = nullptr;
};

struct SettingSpec {
  const char* name;   // CLI flag without dashes, JSON key
  const char* label;  // viewer
  const char* help;
  std::variant<IntRange, RealRange, Choice> kind;
  // Null when the setting matters for these settings, else why it does not ("lev_cut has no
  // tolerance..."): the viewer greys the control and shows the reason.
  const char* (*unused_because)(const Settings& settings) = nullptr;
};

const std::vector<SettingSpec>& setting_table();
const SettingSpec* find_setting(const std::string& name);
// The table's name of a setting that an older levrt called `old_name` ("samples" is now
// "lights-per-point"), or null: the CLI and the viewer's scripts name the new one in their error.
const char* renamed_setting(const std::string& old_name);

// The one grammar of the numbers typed to levrt: every numeric flag (the settings below, --lights,
// the camera flags' components, --heatmap-range, --fail-above, inspect's --top) and the viewer's
// typed values and scripted changes, which go through set_setting. Decimal only: an integer is an
// optional '-' and digits; a real number an optional '-', digits with an optional '.' and fraction
// ("0.5", ".5" and "5." too) and an optional exponent ("1e-3", "2E+2"). Refused as typed: a
// leading '+' or space, a trailing space, hex ("0x10", "0x1p-3"), "inf" and "nan". The range of
// each value is its flag's to check.
bool is_decimal_integer(const std::string& text);
bool is_decimal_real(const std::string& text);

// Parses text for the setting and stores it; throws UsageError "--name: ..., got 'text'".
void set_setting(Settings& settings, const SettingSpec& spec, const std::string& text);
std::string setting_text(const Settings& settings, const SettingSpec& spec);

std::vector<std::string> method_options();
std::vector<std::string> resolution_options();
// The divisor of the image area's size a fit resolution names (1, 2, 4), or 0 for typed.
int fit_divisor(const std::string& resolution);
std::vector<std::string> scene_options();

// What a scene opens with when neither --exposure nor --display was given: glTF files auto and
// neutral (as their authors' viewers show them), everything else linear at EV 0.
void apply_scene_display_defaults(Settings& settings, bool exposure_given, bool display_given);

// The method and the settings it reads, as the commands' summaries name them: "rt",
// "lev, tolerance 0.01", "lightcuts, relative error 0.02", "lev_mc, tolerance 0.01, 1 lights per
// point".
std::string method_settings_text(const Settings& settings);

// The display the settings ask for (an auto exposure as last resolved).
renderer::Display display_from(const Settings& settings);

}  // namespace app

#include "renderer/render.h"

namespace app {

// The renderer's view of the settings (the tolerance as the hierarchy's float).
renderer::RenderSettings render_settings_from(const Settings& settings);

}  // namespace app
