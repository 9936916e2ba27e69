#include "app/viewer/scripted_changes.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

#include "app/render_command.h"
#include "app/scene_loading.h"
#include "app/settings.h"
#include "app/viewer/scene_opening.h"
#include "scenes/scene_file.h"
#include "scenes/scene_models.h"

namespace app::viewer {
namespace {

[[noreturn]] void reject(const std::string& text, const std::string& why) {
  throw UsageError("--set: " + why + ", got '" + text + "'");
}

// Decimal digits only, as --lights takes them: strtoull alone would read " -1" as 2^64 - 1.
std::uint64_t parse_count(const std::string& text, const std::string& change) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    reject(change, "lights needs a light count");
  errno = 0;
  const unsigned long long n = std::strtoull(text.c_str(), nullptr, 10);
  if (errno != 0) reject(change, "lights needs a light count");
  return n;
}

std::string change_text(const ScriptedChange& c) {
  return c.key + "=" + c.value + "@" + std::to_string(c.frame);
}

// The smallest window the viewer opens.
constexpr int kMinWindowWidth = 320;
constexpr int kMinWindowHeight = 240;

// "A<separator>B" with A in [min_a, kMaxImageSide] and B in [min_b, kMaxImageSide].
bool parse_int_pair(const std::string& text, char separator, long min_a, long min_b, int& a,
                    int& b) {
  const std::size_t at = text.find(separator);
  if (at == std::string::npos) return false;
  const std::string as = text.substr(0, at), bs = text.substr(at + 1);
  // The settings' integer grammar (no sign but '-', no space, no hex), as every flag takes it.
  if (!is_decimal_integer(as) || !is_decimal_integer(bs)) return false;
  char* end_a = nullptr;
  char* end_b = nullptr;
  const long la = std::strtol(as.c_str(), &end_a, 10);
  const long lb = std::strtol(bs.c_str(), &end_b, 10);
  if (as.empty() || bs.empty() || *end_a != '\0' || *end_b != '\0' || la < min_a || lb < min_b ||
      la > kMaxImageSide || lb > kMaxImageSide) {
    return false;
  }
  a = static_cast<int>(la);
  b = static_cast<int>(lb);
  return true;
}

bool parse_pixel(const std::string& text, int& x, int& y) {
  return parse_int_pair(text, ',', 0, 0, x, y);
}

// A finite number in [lo, hi], the whole text.
std::optional<double> parse_number(const std::string& text, double lo, double hi) {
  if (!is_decimal_real(text)) return std::nullopt;  // the settings' grammar, as parse_int_pair
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno != 0 || !std::isfinite(v) || v < lo || v > hi)
    return std::nullopt;
  return v;
}

std::string setting_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// The latest frame a change may name (about 19 days of frames at 60 per second).
constexpr long kMaxScriptFrame = 100000000;

// The error mask's largest threshold, in the error unit.
constexpr double kMaxMaskThresholdPct = 100.0;

}  // namespace

bool parse_window_size(const std::string& text, int& width, int& height) {
  return parse_int_pair(text, 'x', kMinWindowWidth, kMinWindowHeight, width, height);
}

ScriptedChange parse_scripted_change(const std::string& text) {
  const std::size_t eq = text.find('=');
  const std::size_t at = text.rfind('@');
  if (eq == std::string::npos || eq == 0 || at == std::string::npos || at < eq) {
    reject(text, "must be key=value@frame");
  }
  ScriptedChange c;
  c.key = text.substr(0, eq);
  c.value = text.substr(eq + 1, at - eq - 1);
  const std::string frame = text.substr(at + 1);
  char* end = nullptr;
  errno = 0;
  const long f = std::strtol(frame.c_str(), &end, 10);
  if (!is_decimal_integer(frame) || *end != '\0' || errno != 0 || f < 0 || f > kMaxScriptFrame) {
    reject(text, "the frame must be a whole number from 0 to " + std::to_string(kMaxScriptFrame));
  }
  c.frame = static_cast<int>(f);

  if (const SettingSpec* spec = find_setting(c.key)) {
    Settings scratch;
    try {
      set_setting(scratch, *spec, c.value);
    } catch (const UsageError& e) {
      reject(text, e.what());
    }
  } else if (c.key == "lights") {
    parse_count(c.value, text);
  } else if (c.key == "view") {
    if (!parse_view_mode(c.value)) reject(text, "view must be one of " + view_mode_names("|"));
  } else if (c.key == "reference") {
    if (c.value != "on" && c.value != "off") reject(text, "reference must be on or off");
  } else if (c.key == "ab") {
    if (c.value != "rt" && c.value != "method") reject(text, "ab must be rt or method");
  } else if (c.key == "swipe") {
    if (c.value != "off" && !parse_number(c.value, 0.0, 1.0))
      reject(text, "swipe needs a divider position in [0, 1] or off");
  } else if (c.key == "mask_threshold") {
    const std::optional<double> t = parse_number(c.value, 0.0, kMaxMaskThresholdPct);
    if (!t || *t <= 0.0) reject(text, "mask_threshold needs a percentage in (0, 100]");
  } else if (c.key == "range_lock") {
    if (c.value != "on" && c.value != "off") reject(text, "range_lock must be on or off");
  } else if (c.key == "trade") {
    if (c.value != "report") reject(text, "trade must be report");
  } else if (c.key == "hover") {
    int x = 0, y = 0;
    if (!parse_pixel(c.value, x, y)) reject(text, "hover needs a pixel X,Y");
  } else if (c.key == "inspect") {
    int x = 0, y = 0;
    if (c.value != "off" && !parse_pixel(c.value, x, y))
      reject(text, "inspect needs a pixel X,Y or off");
  } else if (c.key == "inspect_row") {
    int x = 0, y = 0;
    if (!parse_pixel(c.value + ",0", x, y)) reject(text, "inspect_row needs a row number");
  } else if (c.key == "window") {
    int w = 0, h = 0;
    if (!parse_window_size(c.value, w, h))
      reject(text, "window needs WIDTHxHEIGHT from 320x240 to " + std::to_string(kMaxImageSide) +
                       "x" + std::to_string(kMaxImageSide));
  } else if (c.key == "snapshot" || c.key == "screenshot" || c.key == "drop") {
    if (c.value.empty()) reject(text, c.key + " needs a path");
  } else if (c.key == "await") {
    if (c.value != "idle" && c.value != "preview") reject(text, "await must be idle or preview");
  } else if (c.key == "memory") {
    if (c.value != "report") reject(text, "memory must be report");
  } else if (c.key == "copy") {
    if (c.value != "camera") reject(text, "copy must be camera");
  } else if (const char* now = renamed_setting(c.key)) {
    reject(text, c.key + " is now called " + now);
  } else {
    std::string keys;
    for (const SettingSpec& s : setting_table()) keys += std::string(s.name) + "|";
    reject(text,
           "key must be one of " + keys +
               "lights|view|reference|ab|swipe|mask_threshold|range_lock|hover|inspect|inspect_row|"
               "window|snapshot|screenshot|drop|copy|await|memory|trade");
  }
  return c;
}

std::vector<ScriptedChange> parse_scripted_changes(const std::vector<std::string>& texts) {
  std::vector<ScriptedChange> changes;
  for (const std::string& t : texts) changes.push_back(parse_scripted_change(t));
  return changes;
}

std::vector<std::string> read_script_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw UsageError("--script: cannot read '" + path + "'");
  if (!fs::is_regular_file(status))
    throw UsageError("--script: is not a regular file, got '" + path + "'");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec || size > kMaxScriptFileBytes) {
    throw UsageError("--script: file of " + std::to_string(size) + " bytes, more than the " +
                     std::to_string(kMaxScriptFileBytes >> 20) + " MiB a script may have, got '" +
                     path + "'");
  }
  std::ifstream in(path);
  if (!in) throw UsageError("--script: cannot read '" + path + "'");
  std::vector<std::string> lines;
  std::uintmax_t bytes = 0;
  std::size_t number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    // A file that grew since it was measured stops at the limit too.
    bytes += line.size() + 1;
    if (bytes > kMaxScriptFileBytes + 1)
      throw UsageError("--script: the file changed while it was read, got '" + path + "'");
    if (!line.empty() && line.back() == '\r') line.pop_back();  // a script saved with CRLF
    if (line.empty()) continue;
    // A bad line is named by the file and its line number, not only by its text.
    try {
      parse_scripted_change(line);
    } catch (const UsageError& e) {
      std::string why = e.what();
      const std::string prefix = "--set: ";
      if (why.rfind(prefix, 0) == 0) why.erase(0, prefix.size());
      throw UsageError("--script: " + path + " line " + std::to_string(number) + ": " + why);
    }
    lines.push_back(line);
  }
  if (in.bad()) throw UsageError("--script: cannot read '" + path + "'");
  return lines;
}

std::uint64_t current_resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t size_pages = 0, resident_pages = 0;
  if (!(statm >> size_pages >> resident_pages)) return 0;
  return resident_pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

void check_script(const std::vector<ScriptedChange>& changes, const Settings& initial, int frames) {
  // A change at a frame the session never reaches would be dropped without a word (a screenshot
  // never taken, and exit 0).
  for (const ScriptedChange& c : changes) {
    if (frames > 0 && c.frame >= frames) {
      reject(change_text(c), "frame " + std::to_string(c.frame) +
                                 " is past the last frame (--frames " + std::to_string(frames) +
                                 " runs frames 0 to " + std::to_string(frames - 1) + ")");
    }
  }
  // The frame loop applies the changes frame by frame, each frame's in command-line order: the
  // settings at a change are the initial ones with the changes before it applied in that order.
  // What only the running viewer knows is not checked here: a fit resolution follows the window
  // (hovers outside a fitted image show nothing), and a scene file that fails to load keeps the
  // scene before it.
  std::vector<std::size_t> order(changes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return changes[a].frame < changes[b].frame;
  });
  // What a render refuses (a level the model lacks, an image over the memory budget, one
  // missed-light draw); a fit
  // resolution's size follows the window, so only a typed one is checked.
  const auto check_renders = [](const Settings& s) {
    check_scene_level(s.scene);  // a level the model lacks, as --level refuses it
    Settings probe = s;
    if (fit_divisor(s.resolution) != 0) probe.image.width = probe.image.height = 1;
    render_settings_from(probe);
    if (fit_divisor(s.resolution) == 0) check_memory_budget(s, false);
  };
  // What the command line's settings themselves break is named by their flags, not blamed on the
  // first change.
  check_renders(initial);
  Settings at = initial;
  for (const std::size_t h : order) {
    const ScriptedChange& c = changes[h];
    try {
      if (const SettingSpec* spec = find_setting(c.key)) {
        const Settings before = at;
        set_setting(at, *spec, c.value);
        const bool new_size =
            at.image.width != before.image.width || at.image.height != before.image.height;
        if (new_size && at.resolution == before.resolution) at.resolution = "typed";
        if (at.scene.name != before.scene.name) {
          if (const scenes::SceneModel* model = scenes::find_scene_model(at.scene.name))
            at.scene.level = model->default_level;
        }
        // What the worker refuses only when it renders is refused before the window opens.
        check_renders(at);
      } else if (c.key == "drop" && scenes::is_scene_file_name(c.value)) {
        at.scene.name = c.value;
      } else if (c.key == "lights") {
        apply_light_count_flag(at.scene, c.value);
      }
    } catch (const UsageError& e) {
      reject(change_text(c), e.what());
    }
    const bool pixel = c.key == "hover" || (c.key == "inspect" && c.value != "off");
    if (!pixel || fit_divisor(at.resolution) != 0) continue;
    int x = 0, y = 0;
    parse_pixel(c.value, x, y);
    if (x >= at.image.width || y >= at.image.height) {
      reject(change_text(c), c.key + " is in image pixels and must be inside the " +
                                 std::to_string(at.image.width) + "x" +
                                 std::to_string(at.image.height) + " image");
    }
  }
}

ScriptAction apply_scripted_change(ViewerState& state, const ScriptedChange& c) {
  const std::string label = c.key + "=" + c.value + " (frame " + std::to_string(c.frame) + ")";
  // A scene file opens as one typed into the panel would (logged, kept on failure).
  if (c.key == "scene" && scenes::is_scene_file_name(c.value)) {
    open_scene_file(state, c.value);
    return ScriptAction::none;
  }
  if (c.key == "drop") {
    open_dropped_files(state, {c.value});
    return ScriptAction::none;
  }
  if (c.key == "copy") {
    copy_camera_flags(state);
    return ScriptAction::none;
  }
  if (const SettingSpec* spec = find_setting(c.key)) {
    const Settings before = state.settings;
    set_setting(state.settings, *spec, c.value);
    settings_changed(state, before, label);
    return ScriptAction::none;
  }
  if (c.key == "lights") {
    // check_script refused a count the scene at this frame lacks; one a scene file that failed
    // to load left unmatched is logged, as the failed load is.
    const Settings before = state.settings;
    try {
      apply_light_count_flag(state.settings.scene, c.value);
    } catch (const UsageError& e) {
      log_message(state, label + ": " + e.what(), true);
      return ScriptAction::none;
    }
    settings_changed(state, before, label);
    return ScriptAction::none;
  }
  if (c.key == "view") {
    select_view(state, *parse_view_mode(c.value));
    return ScriptAction::none;
  }
  if (c.key == "reference") {
    set_want_reference(state, c.value == "on");
    return ScriptAction::none;
  }
  if (c.key == "ab") {
    set_ab_rt(state, c.value == "rt");
    return ScriptAction::none;
  }
  if (c.key == "swipe") {
    set_swipe(state, c.value == "off" ? std::nullopt : parse_number(c.value, 0.0, 1.0));
    return ScriptAction::none;
  }
  if (c.key == "mask_threshold") {
    state.mask_threshold_pct = *parse_number(c.value, 0.0, kMaxMaskThresholdPct);
    return ScriptAction::none;
  }
  if (c.key == "range_lock") {
    set_range_lock(state, c.value == "on");
    return ScriptAction::none;
  }
  if (c.key == "trade") {
    // For tests: the trade plot's points and the reference they belong to.
    std::fprintf(state.notes,
                 "levrt view: trade plot at frame %d: %zu points, reference %llu, rt passes %d\n",
                 c.frame, state.trade.points.size(),
                 static_cast<unsigned long long>(state.trade.reference_generation),
                 state.status.reference_passes_done);
    for (const TradePoint& p : state.trade.points) {
      const lev::MethodInfo& info = lev::method_info(p.method);
      std::string more;
      if (info.uses_relative_error) more += " relative error " + setting_number(p.relative_error);
      if (info.stochastic) more += " lights per point " + std::to_string(p.lights_per_point);
      std::fprintf(state.notes,
                   "levrt view: trade point %s tolerance %g%s: error %.6g%% over %d passes\n",
                   info.name, p.tolerance, more.c_str(), p.error_avg_pct, p.passes);
    }
    return ScriptAction::none;
  }
  if (c.key == "hover") {
    TileRect pixel;
    parse_pixel(c.value, pixel.x0, pixel.y0);
    pixel.x1 = pixel.x0 + 1;
    pixel.y1 = pixel.y0 + 1;
    state.scripted_hover = pixel;
    return ScriptAction::none;
  }
  if (c.key == "inspect") {
    std::optional<std::array<int, 2>> pixel;
    if (c.value != "off") {
      pixel.emplace();
      parse_pixel(c.value, (*pixel)[0], (*pixel)[1]);
    }
    set_inspect_pixel(state, pixel);
    return ScriptAction::none;
  }
  if (c.key == "inspect_row") {
    int row = 0, ignored = 0;
    parse_pixel(c.value + ",0", row, ignored);
    state.inspect_row = row;
    return ScriptAction::none;
  }
  if (c.key == "memory") {
    std::fprintf(state.notes, "levrt view: resident memory at frame %d: %llu bytes\n", c.frame,
                 static_cast<unsigned long long>(current_resident_bytes()));
    return ScriptAction::none;
  }
  if (c.key == "window") return ScriptAction::resize_window;
  if (c.key == "snapshot") return ScriptAction::snapshot;
  if (c.key == "screenshot") return ScriptAction::screenshot;
  return c.value == "preview" ? ScriptAction::await_preview : ScriptAction::await_idle;
}

}  // namespace app::viewer
