#include "app/settings.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <utility>

#include "scenes/gltf_scene.h"
#include "scenes/scene_file.h"
#include "scenes/scene_models.h"

namespace app {

std::vector<std::string> method_options() {
  std::vector<std::string> names;
  for (const lev::MethodInfo& m : lev::method_table()) names.emplace_back(m.name);
  return names;
}

std::vector<std::string> resolution_options() {
  return {"fit", "fit/2", "fit/4", "typed"};
}

int fit_divisor(const std::string& resolution) {
  if (resolution == "fit") return 1;
  if (resolution == "fit/2") return 2;
  if (resolution == "fit/4") return 4;
  return 0;
}

namespace {

// The type of a member a pointer to member names.
template <typename MemberPointer>
struct MemberOf;
template <typename Class, typename T>
struct MemberOf<T Class::*> {
  using type = T;
};

// The table's access to settings.*group.*member: what names a setting's number in its group.
template <auto group, auto member>
constexpr SettingField<typename MemberOf<decltype(member)>::type> in_group() {
  using T = typename MemberOf<decltype(member)>::type;
  return {[](const Settings& s) -> const T& { return s.*group.*member; },
          [](Settings& s) -> T& { return s.*group.*member; }};
}

bool is_scene_file_setting(const std::string& text) {
  return scenes::is_scene_file_name(text);
}

const lev::MethodInfo& method_option(const std::string& option) {
  return lev::method_info(*lev::parse_method(option));
}

const char* display_option_summary(const std::string& option) {
  switch (*renderer::parse_display_curve(option)) {
    case renderer::DisplayCurve::linear:
      return "the exposed radiance clipped to [0, 1] (1.0 = 255), no curve";
    case renderer::DisplayCurve::srgb:
      return "the sRGB transfer curve";
    case renderer::DisplayCurve::neutral:
      return "Khronos PBR Neutral tone mapping, then sRGB";
  }
  return "";
}

const char* tolerance_unused(const Settings& s) {
  return lev::method_info(s.method.method).uses_tolerance
             ? nullptr
             : "this method has no tolerance (lightcuts and lev_cut cut by the relative error; "
               "rt tests every light)";
}

const char* samples_unused(const Settings& s) {
  return lev::method_info(s.method.method).stochastic
             ? nullptr
             : "only the sampling methods (lev_mc, light_tree) draw lights per point";
}

const char* relative_error_unused(const Settings& s) {
  return lev::method_info(s.method.method).uses_relative_error
             ? nullptr
             : "only lightcuts and lev_cut cut by the relative error";
}

const char* rt_fallback_unused(const Settings& s) {
  return lev::rt_fallback_applies(lev::method_info(s.method.method))
             ? nullptr
             : "rt is the fallback, and a sampler's passes converge to rt's image anyway";
}

std::vector<std::string> rt_fallback_options() {
  return {"on", "off"};
}

const char* rt_fallback_summary(const std::string& option) {
  return option == "on" ? "shade with rt's loop where a probe of the frame says the method's walk "
                          "would cost more than rt's shadow rays (exact, and no slower than rt)"
                        : "always the method's own selection";
}

const char* missed_draws_unused(const Settings& s) {
  return lev::method_info(s.method.method).missed_light_known
             ? nullptr
             : "this method does not estimate the light it leaves out (the estimate would read 0 "
               "where its pixels differ from rt's)";
}

const char* camera_unused(const Settings& s) {
  return scenes::reads_camera_index(s.scene) ? nullptr
                                             : "only glTF files have cameras of their own";
}

}  // namespace

std::vector<std::string> scene_options() {
  std::vector<std::string> names;
  for (const scenes::SceneModel& m : scenes::scene_models()) names.emplace_back(m.name);
  return names;
}

const std::vector<SettingSpec>& setting_table() {
  static const std::vector<SettingSpec> table = {
      {"scene", "Scene", "scene model, or a scene file FILE.json (scenes/README.md), .gltf or .glb",
       Choice{[](const Settings& s) { return s.scene.name; },
              [](Settings& s, const std::string& v) { s.scene.name = v; }, scene_options, nullptr,
              nullptr, is_scene_file_setting, "a .json/.gltf/.glb scene file"}},
      {"level", "Level", "scene model level (light count grows with it)",
       IntRange{in_group<&Settings::scene, &scenes::SceneChoice::level>(), 1, 10}},
      {"method", "Method", "many-light method",
       Choice{[](const Settings& s) { return std::string(lev::method_info(s.method.method).name); },
              [](Settings& s, const std::string& v) { s.method.method = *lev::parse_method(v); },
              method_options, [](const std::string& o) { return method_option(o).label; },
              [](const std::string& o) { return method_option(o).summary; }}},
      {"tolerance", "Tolerance", "irradiance tolerance, colour units (1.0 = 255); 0 = exact",
       RealRange{in_group<&Settings::method, &lev::MethodChoice::tolerance>(), 0.0,
                 std::numeric_limits<double>::max(), true, 1e-6, 1.0},
       tolerance_unused},
      {"resolution", "Resolution",
       "viewer image size: the image area's pixels (fit), 1/2 or 1/4 of them, or the typed width "
       "and height (typed; giving either selects it); headless renders always use width and height",
       Choice{[](const Settings& s) { return s.resolution; },
              [](Settings& s, const std::string& v) { s.resolution = v; }, resolution_options}},
      {"width", "Width", "image width in pixels",
       IntRange{in_group<&Settings::image, &renderer::ImageSettings::width>(), 1, kMaxImageSide}},
      {"height", "Height", "image height in pixels",
       IntRange{in_group<&Settings::image, &renderer::ImageSettings::height>(), 1, kMaxImageSide}},
      {"spp", "Passes", "passes, one sample per pixel each",
       IntRange{in_group<&Settings::image, &renderer::ImageSettings::spp>(), 1, 100000}},
      {"lights-per-point", "Lights per point",
       "lights lev_mc and light_tree draw per shading point and pass (each one shadow ray)",
       IntRange{in_group<&Settings::method, &lev::MethodChoice::lights_per_point>(), 1,
                lev::kMaxLightsPerPoint},
       samples_unused},
      {"relative-error", "Relative error",
       "lightcuts and lev_cut: refine the cut until every cluster's error bound is below this "
       "share of the point's estimated radiance (0 = exact)",
       RealRange{in_group<&Settings::method, &lev::MethodChoice::relative_error>(), 0.0, 1.0, true,
                 1e-4, 1.0},
       relative_error_unused},
      {"rt-fallback", "RT fallback",
       "deterministic methods: where a probe of the frame says the method would cost more than "
       "rt (its culling admits most lights), shade with rt's loop instead",
       Choice{[](const Settings& s) { return std::string(s.method.rt_fallback ? "on" : "off"); },
              [](Settings& s, const std::string& v) { s.method.rt_fallback = v == "on"; },
              rt_fallback_options, nullptr, rt_fallback_summary},
       rt_fallback_unused},
      {"depth", "Depth", "reflection and refraction depth",
       IntRange{in_group<&Settings::image, &renderer::ImageSettings::depth>(), 0, 64}},
      {"threads", "Threads", "worker threads (0 = all cores)",
       IntRange{in_group<&Settings::image, &renderer::ImageSettings::threads>(), 0, 1024}},
      {"subsample", "Subsample", "render every n-th pixel in x and y",
       IntRange{in_group<&Settings::image, &renderer::ImageSettings::subsample>(), 1, 64}},
      {"camera", "Camera",
       "glTF scenes: the camera (perspective or orthographic) to look through, in node order "
       "(0: the first, or a view framing the scene when there is none)",
       IntRange{in_group<&Settings::scene, &scenes::SceneChoice::camera>(), 0, 1000000},
       camera_unused},
      {"exposure", "Exposure",
       "exposure in EV: the displayed image is the radiance x 2^EV through the display curve; "
       "the tolerance and the error metrics are in these exposed units. auto: chosen from a "
       "coarse preview so the 99th-percentile luminance shows at 0.75 (default for glTF, else 0)",
       RealRange{in_group<&Settings::display, &DisplaySettings::exposure_ev>(), -64.0, 64.0, false,
                 -16.0, 16.0, "auto",
                 in_group<&Settings::display, &DisplaySettings::exposure_auto>()}},
      {"display", "Display",
       "display curve after the exposure (default: neutral for glTF, else linear)",
       Choice{[](const Settings& s) {
                return std::string(renderer::display_curve_name(s.display.curve));
              },
              [](Settings& s, const std::string& v) {
                s.display.curve = *renderer::parse_display_curve(v);
              },
              renderer::display_curve_names, nullptr,
              [](const std::string& o) { return display_option_summary(o); }}},
      {"missed-draws", "Missed light",
       "draws per shading point of the light a method left out, each with a shadow ray: the "
       "missed-light estimate and its standard error (0: off; --heatmap-missed turns it on with "
       "16; at least 2)",
       IntRange{in_group<&Settings::image, &renderer::ImageSettings::missed_draws>(), 0,
                lev::kMaxLightsPerPoint},
       missed_draws_unused},
  };
  return table;
}

const SettingSpec* find_setting(const std::string& name) {
  for (const SettingSpec& s : setting_table()) {
    if (name == s.name) return &s;
  }
  return nullptr;
}

const char* renamed_setting(const std::string& old_name) {
  // "samples" meant lights per point while the pixel samples were --spp; a sample is now a pixel's.
  static const std::pair<const char*, const char*> renamed[] = {
      {"samples", "lights-per-point"},
      {"missed-samples", "missed-draws"},
  };
  for (const auto& [before, now] : renamed) {
    if (old_name == before) return now;
  }
  return nullptr;
}

namespace {

// Advances past the decimal digits at text[i]; returns how many there were.
std::size_t skip_digits(const std::string& text, std::size_t& i) {
  const std::size_t start = i;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
  return i - start;
}

}  // namespace

bool is_decimal_integer(const std::string& text) {
  std::size_t i = !text.empty() && text[0] == '-' ? 1 : 0;
  return skip_digits(text, i) > 0 && i == text.size();
}

bool is_decimal_real(const std::string& text) {
  std::size_t i = !text.empty() && text[0] == '-' ? 1 : 0;
  std::size_t digits = skip_digits(text, i);
  if (i < text.size() && text[i] == '.') {
    ++i;
    digits += skip_digits(text, i);
  }
  if (digits == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (skip_digits(text, i) == 0) return false;
  }
  return i == text.size();
}

namespace {

[[noreturn]] void reject(const SettingSpec& spec, const std::string& what,
                         const std::string& text) {
  throw UsageError(std::string("--") + spec.name + ": " + what + ", got '" + text + "'");
}

}  // namespace

void set_setting(Settings& settings, const SettingSpec& spec, const std::string& text) {
  if (const auto* r = std::get_if<IntRange>(&spec.kind)) {
    const std::string what = "must be a decimal integer in [" + std::to_string(r->min) + ", " +
                             std::to_string(r->max) + "]";
    if (!is_decimal_integer(text)) reject(spec, what, text);
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(text.c_str(), &end, 10);
    if (errno != 0 || *end != '\0' || v < r->min || v > r->max) reject(spec, what, text);
    r->field.ref(settings) = static_cast<int>(v);
  } else if (const auto* d = std::get_if<RealRange>(&spec.kind)) {
    if (d->word && text == d->word) {
      d->word_flag.ref(settings) = true;
      return;
    }
    std::ostringstream range;
    range << "must be " << (d->word ? std::string(d->word) + " or " : std::string())
          << "a finite decimal number in [" << d->min << ", " << d->max << "]";
    if (!is_decimal_real(text)) reject(spec, range.str(), text);
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    // Overflow comes back infinite and is refused; underflow (ERANGE with a subnormal or zero
    // result) is the typed value rounded, so the smallest positive double is taken as itself.
    if (*end != '\0' || !std::isfinite(v) || v < d->min || v > d->max) {
      reject(spec, range.str(), text);
    }
    d->field.ref(settings) = v;
    if (d->word_flag.ref) d->word_flag.ref(settings) = false;
  } else {
    const auto& c = std::get<Choice>(spec.kind);
    std::string valid;
    for (const std::string& o : c.options()) {
      if (o == text) {
        c.set(settings, text);
        return;
      }
      valid += (valid.empty() ? "" : "|") + o;
    }
    if (c.also_accepts && c.also_accepts(text)) {
      c.set(settings, text);
      return;
    }
    if (c.also_accepts_label) valid += std::string(" or ") + c.also_accepts_label;
    reject(spec, "must be one of " + valid, text);
  }
}

std::string setting_text(const Settings& settings, const SettingSpec& spec) {
  if (const auto* r = std::get_if<IntRange>(&spec.kind))
    return std::to_string(r->field.get(settings));
  if (const auto* d = std::get_if<RealRange>(&spec.kind)) {
    if (d->word_flag.get && d->word_flag.get(settings)) return d->word;
    std::ostringstream s;
    s << d->field.get(settings);
    return s.str();
  }
  return std::get<Choice>(spec.kind).get(settings);
}

void apply_scene_display_defaults(Settings& settings, bool exposure_given, bool display_given) {
  if (!scenes::is_gltf_file_name(settings.scene.name)) return;
  if (!exposure_given) settings.display.exposure_auto = true;
  if (!display_given) settings.display.curve = renderer::DisplayCurve::neutral;
}

std::string method_settings_text(const Settings& settings) {
  const lev::MethodInfo& method = lev::method_info(settings.method.method);
  std::string text = method.name;
  char setting[64];
  if (method.uses_tolerance) {
    std::snprintf(setting, sizeof(setting), ", tolerance %g", settings.method.tolerance);
    text += setting;
  }
  if (method.uses_relative_error) {
    std::snprintf(setting, sizeof(setting), ", relative error %g", settings.method.relative_error);
    text += setting;
  }
  if (method.stochastic)
    text += ", " + std::to_string(settings.method.lights_per_point) + " lights per point";
  return text;
}

renderer::Display display_from(const Settings& settings) {
  return {settings.display.exposure_ev, settings.display.curve};
}

namespace {

// The image settings a render of these settings reads: the missed-light draws of a method that
// does not estimate the missed light change nothing (missed_draws_unused).
renderer::ImageSettings used_image_settings(const Settings& settings) {
  renderer::ImageSettings image = settings.image;
  if (missed_draws_unused(settings)) image.missed_draws = 0;
  return image;
}

}  // namespace

Restart restart_needed(const Settings& before, const Settings& after) {
  if (before.scene != after.scene) return Restart::scene;
  const renderer::ImageSettings before_image = used_image_settings(before);
  const renderer::ImageSettings after_image = used_image_settings(after);
  // The image settings the rt reference renders without (the method's render reads them) and
  // the pass count, taken from before: any other image setting restarts the view.
  renderer::ImageSettings view = after_image;
  view.threads = before_image.threads;
  view.missed_draws = before_image.missed_draws;
  view.spp = before_image.spp;
  if (view != before_image) return Restart::view;
  renderer::ImageSettings render = after_image;
  render.spp = before_image.spp;
  if (render != before_image || before.method != after.method) return Restart::render;
  // The tolerance (and lev_cut's drop) is in displayed units: a method that reads the display
  // scale renders other images at another exposure. Its radiance is all the rt reference and
  // the display curve depend on, so they go on. The auto flag by itself changes nothing: the
  // EV it chose is exposure_ev.
  if (renderer::exposure_scale(before.display.exposure_ev) !=
          renderer::exposure_scale(after.display.exposure_ev) &&
      lev::method_info(after.method.method).reads_display_scale)
    return Restart::render;
  if (before_image != after_image) return Restart::passes;
  return Restart::nothing;
}

}  // namespace app

namespace app {

renderer::RenderSettings render_settings_from(const Settings& settings) {
  const renderer::ImageSettings& image = settings.image;
  // Each pixel costs about 50 bytes of framebuffer; cap the image well below the machine's memory.
  constexpr long long kMaxPixels = 8192LL * 8192LL;
  if (static_cast<long long>(image.width) * image.height > kMaxPixels) {
    throw UsageError("--width/--height: " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + " exceeds the " + std::to_string(kMaxPixels) +
                     "-pixel limit");
  }
  renderer::RenderSettings rs;
  rs.width = image.width;
  rs.height = image.height;
  rs.max_depth = image.depth;
  rs.threads = image.threads;
  rs.pixel_stride = image.subsample;
  rs.method = settings.method.method;
  // Tolerances below the smallest float become 0 (no culling) and above the largest become
  // +inf (everything culled): both are the limits the user asked for.
  rs.tolerance = static_cast<float>(settings.method.tolerance);
  rs.lights_per_point = settings.method.lights_per_point;
  rs.relative_error = static_cast<float>(settings.method.relative_error);
  rs.rt_fallback = settings.method.rt_fallback;
  if (image.missed_draws != 0 && image.missed_draws < renderer::kMinMissedDraws) {
    throw UsageError("--missed-draws: must be 0 (off) or at least " +
                     std::to_string(renderer::kMinMissedDraws) + ", got '" +
                     std::to_string(image.missed_draws) + "'");
  }
  rs.missed_draws = image.missed_draws;
  rs.exposure_ev = settings.display.exposure_ev;
  return rs;
}

}  // namespace app
