// Every user setting of levrt in one struct with defaults, and one table that describes each
// setting once (flag, label, range, help). The CLI flags and the viewer's controls are both
// generated from this table, so they cannot drift apart.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "app/camera_flags.h"
#include "lev/methods.h"
#include "renderer/display_transform.h"
#include "renderer/render.h"
#include "scenes/gltf_scene.h"
#include "scenes/scene_models.h"

namespace app {

// The largest image side the settings take (width, height, the viewer's typed and fitted sizes).
inline constexpr int kMaxImageSide = 16384;

struct Settings {
  std::string scene = "building";
  int level = scenes::kDefaultSceneLevel;  // model level; --lights picks it by light count instead
  lev::Method method = lev::Method::lev;
  double tolerance = lev::kDefaultTolerance;  // colour units, 1.0 = 255
  // The viewer's image size: the image area's pixels (fit), half or a quarter of them, or
  // width x height (typed). Headless renders always use width x height.
  std::string resolution = "fit";
  int width = renderer::kDefaultImageWidth;
  int height = renderer::kDefaultImageHeight;
  int spp = 1;      // passes (one sample per pixel each)
  int samples = 1;  // lights lev_mc and light_tree draw per shading point and pass
  double relative_error =
      lev::kDefaultRelativeError;  // lightcuts: a cluster's bound / the point's total
  int depth = 5;                   // reflection/refraction depth
  int threads = 0;                 // 0 = all cores
  int subsample = 1;               // render every n-th pixel in x and y (for slow references)
  int camera = 0;                  // a glTF file's camera, in node order
  // --camera-position/-target/-up, --fov, --camera-from: parts of the preset camera replaced
  // (app/camera_flags.h). They belong to the scene they were given with: the viewer drops them
  // when another scene opens.
  CameraFlags camera_flags;
  // The display step (renderer/display_transform.h): radiance x 2^exposure_ev through the
  // display curve. exposure_auto: the EV is chosen before the first pass
  // (renderer/auto_exposure.h) and exposure_ev is then what it chose. Built-in scenes and scene
  // files default to linear at EV 0 (the images levrt always wrote); glTF files to auto and
  // neutral (apply_scene_display_defaults).
  double exposure_ev = 0.0;
  bool exposure_auto = false;
  renderer::DisplayCurve display = renderer::DisplayCurve::linear;
  // Draws per shading point of the missed-light estimate (renderer/missed_light.h); 0: off.
  int missed_samples = 0;
};

// The draws of the missed-light estimate when an output asks for it and none were given.
inline constexpr int kDefaultMissedSamples = 16;

// A command-line or input mistake: reported as one line, exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct IntRange {
  int Settings::*field;
  int min, max;
};
struct RealRange {
  double Settings::*field;
  double min, max;
  bool logarithmic;  // the viewer's slider
  // The viewer's log slider spans [slider_min, slider_max] (within [min, max]); typed values may
  // leave it, and a 0 button sits beside it when min allows 0.
  double slider_min = 0.0, slider_max = 0.0;
  // A word the setting also takes instead of a number (the exposure's "auto"), and the flag it
  // raises; a number lowers it.
  const char* word = nullptr;
  bool Settings::*word_flag = nullptr;
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

// The display the settings ask for (an auto exposure as last resolved).
renderer::Display display_from(const Settings& settings);

}  // namespace app

#include "renderer/render.h"

namespace app {

// The renderer's view of the settings (the tolerance as the hierarchy's float).
renderer::RenderSettings render_settings_from(const Settings& settings);

}  // namespace app
