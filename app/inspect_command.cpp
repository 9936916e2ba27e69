#include "app/inspect_command.h"

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/interrupt.h"
#include "app/json_text.h"
#include "app/output_files.h"
#include "app/scene_loading.h"
#include "lev/methods.h"
#include "renderer/auto_exposure.h"
#include "scenes/scene_file.h"
#include "scenes/scene_inputs.h"

namespace app {
namespace {

nlohmann::ordered_json vec_json(const glm::vec3& v) {
  return {v.x, v.y, v.z};
}
nlohmann::ordered_json vec_json(const glm::dvec3& v) {
  return {v.x, v.y, v.z};
}

std::string node_text(std::uint32_t node) {
  return node == lev::kOwnTest ? std::string("own test") : "node " + std::to_string(node);
}

nlohmann::ordered_json light_json(const lev::Light& light) {
  nlohmann::ordered_json j;
  j["kind"] = light.kind == lev::LightKind::spot ? "spot" : "point";
  j["position"] = vec_json(light.position);
  j["intensity"] = vec_json(light.intensity);
  if (light.kind == lev::LightKind::spot) j["direction"] = vec_json(light.direction);
  return j;
}

// A light of the scene the method did not shade itself, in pixel units (times the path weight).
nlohmann::ordered_json inspected_json(const lev::InspectedLight& l, double weight) {
  nlohmann::ordered_json j = light_json(l.light);
  j["node"] =
      l.node == lev::kOwnTest ? nlohmann::ordered_json("own test") : nlohmann::ordered_json(l.node);
  j["unshadowed"] = vec_json(glm::dvec3(l.unshadowed_radiance) * weight);
  j["visible"] = l.visible;
  j["lost"] = vec_json(glm::dvec3(l.visible_radiance()) * weight);
  return j;
}

nlohmann::ordered_json totals_json(const renderer::InspectedTotals& t) {
  nlohmann::ordered_json j;
  j["tested_sum"] = vec_json(t.tested);
  j["exact_sum"] = vec_json(t.exact);
  j["lost_sum"] = vec_json(t.lost);
  j["certified_bound"] = std::isfinite(t.bound.x) ? vec_json(t.bound) : nlohmann::ordered_json();
  j["shaded"] = t.shaded;
  j["tested_lights"] = t.tested_lights;
  j["culled_lights"] = t.culled_lights;
  j["clusters"] = t.clusters;
  j["clustered_lights"] = t.clustered_lights;
  return j;
}

double brightest(const glm::dvec3& v) {
  return std::max({v.x, v.y, v.z});
}

// One row of the table: a shaded term or a culled light, with its value for the pixel.
struct Row {
  glm::dvec3 pixel{0.0};  // contribution, or the light lost
  renderer::ContributionRank rank;
  std::string text;
};

std::string position_text(const glm::vec3& p) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.3g, %.3g, %.3g)", p.x, p.y, p.z);
  return buffer;
}

std::string rgb_text(const glm::dvec3& v) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return "none";
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%.6f %.6f %.6f", v.x, v.y, v.z);
  return buffer;
}

std::string totals_text(const renderer::InspectedTotals& t) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer,
                "%zu shaded (%zu single lights tested), %zu culled, %zu clusters of %zu lights",
                t.shaded, t.tested_lights, t.culled_lights, t.clusters, t.clustered_lights);
  return "  tested sum " + rgb_text(t.tested) + " | lost sum (true, with shadows) " +
         rgb_text(t.lost) + " | certified bound " + rgb_text(t.bound) + "\n  lights: " + buffer +
         "\n";
}

}  // namespace

void parse_inspect_pixel(const std::string& text, int width, int height, int& x, int& y) {
  // X,Y: 1 to 9 decimal digits each (std::regex would do, but GCC 12 warns inside it under the
  // sanitizer presets).
  const auto digits = [](const std::string& part, int& value) {
    if (part.empty() || part.size() > 9) return false;
    value = 0;
    for (const char c : part) {
      if (c < '0' || c > '9') return false;
      value = value * 10 + (c - '0');
    }
    return true;
  };
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos || !digits(text.substr(0, comma), x) ||
      !digits(text.substr(comma + 1), y))
    throw UsageError("--pixel: expected X,Y (image pixels from the top left), got '" + text + "'");
  if (x >= width || y >= height) {
    throw UsageError("--pixel: outside the " + std::to_string(width) + "x" +
                     std::to_string(height) + " image, got '" + text + "'");
  }
}

nlohmann::ordered_json inspection_json(const renderer::PixelInspection& inspection) {
  nlohmann::ordered_json j;
  j["pixel"] = {inspection.x, inspection.y};
  j["radiance"] = vec_json(inspection.radiance);
  j["lights_tested"] = inspection.counters.selection.lights_tested;
  j["shadow_rays"] = inspection.counters.selection.shadow_rays;
  j["nodes_visited"] = inspection.counters.selection.nodes_visited;
  nlohmann::ordered_json hits = nlohmann::ordered_json::array();
  for (const renderer::InspectedHit& hit : inspection.hits) {
    const double weight = hit.path_weight;
    nlohmann::ordered_json h;
    h["depth"] = hit.depth;
    h["path_weight"] = hit.path_weight;
    h["position"] = vec_json(hit.position);
    h["normal"] = vec_json(hit.normal);
    h["direct_radiance"] = vec_json(hit.direct_radiance);
    nlohmann::ordered_json shaded = nlohmann::ordered_json::array();
    for (const lev::ShadedLight& s : hit.record.shaded) {
      nlohmann::ordered_json e = light_json(s.light);
      e["role"] = lev::role_name(s.role);
      if (s.node != lev::kOwnTest) e["node"] = s.node;
      e["weight"] = s.weight;
      e["unshadowed"] = vec_json(glm::dvec3(s.unshadowed_radiance) * weight);
      e["shadow_ray"] = s.shadow_ray;
      e["visible"] = s.visible;
      e["contribution"] = vec_json(glm::dvec3(s.contribution) * weight);
      if (s.role == lev::InspectRole::cluster || s.role == lev::InspectRole::estimated) {
        e["member_count"] = s.members.size();
        nlohmann::ordered_json members = nlohmann::ordered_json::array();
        for (const lev::InspectedLight& m : s.members) members.push_back(inspected_json(m, weight));
        e["members"] = std::move(members);
      }
      shaded.push_back(std::move(e));
    }
    h["shaded"] = std::move(shaded);
    std::vector<std::pair<renderer::ContributionRank, const lev::InspectedLight*>> culled;
    for (const lev::InspectedLight& c : hit.record.culled) {
      culled.emplace_back(
          renderer::contribution_rank(glm::dvec3(c.visible_radiance()),
                                      glm::dvec3(c.unshadowed_radiance), culled.size()),
          &c);
    }
    std::sort(culled.begin(), culled.end(), [](const auto& a, const auto& b) {
      return renderer::ranks_before(a.first, b.first);
    });
    nlohmann::ordered_json culled_json = nlohmann::ordered_json::array();
    for (const auto& c : culled) culled_json.push_back(inspected_json(*c.second, weight));
    h["culled"] = std::move(culled_json);
    h["totals"] = totals_json(renderer::hit_totals(hit));
    hits.push_back(std::move(h));
  }
  j["hits"] = std::move(hits);
  j["totals"] = totals_json(inspection.totals);
  return j;
}

std::string inspection_table(const renderer::PixelInspection& inspection, int top) {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line, "pixel %d,%d: radiance %.6f %.6f %.6f, %zu hit%s\n",
                inspection.x, inspection.y, inspection.radiance.x, inspection.radiance.y,
                inspection.radiance.z, inspection.hits.size(),
                inspection.hits.size() == 1 ? "" : "s");
  out += line;
  for (const renderer::InspectedHit& hit : inspection.hits) {
    const double weight = hit.path_weight;
    std::snprintf(line, sizeof line, "hit %d (%s), path weight %.4g, at %s\n", hit.depth,
                  hit.depth == 0 ? "primary" : "reflected or refracted", weight,
                  position_text(hit.position).c_str());
    out += line;
    std::vector<Row> rows;
    for (const lev::ShadedLight& s : hit.record.shaded) {
      Row& row = rows.emplace_back();
      row.pixel = glm::dvec3(s.contribution) * weight;
      row.rank = renderer::contribution_rank(row.pixel, glm::dvec3(s.unshadowed_radiance) * weight,
                                             rows.size() - 1);
      std::string role = lev::role_name(s.role);
      if (s.role == lev::InspectRole::cluster || s.role == lev::InspectRole::estimated)
        role += "(" + std::to_string(s.members.size()) + ")";
      const std::string by = s.node == lev::kOwnTest ? "-" : node_text(s.node);
      std::snprintf(line, sizeof line, "%-14s %-5s %-28s %-12s %12.6f %-4s %9.4g %12.6f\n",
                    role.c_str(), s.light.kind == lev::LightKind::spot ? "spot" : "point",
                    position_text(s.light.position).c_str(), by.c_str(),
                    brightest(glm::dvec3(s.unshadowed_radiance) * weight),
                    !s.shadow_ray ? "-" : (s.visible ? "yes" : "no"), s.weight,
                    brightest(row.pixel));
      row.text = line;
    }
    for (const lev::InspectedLight& c : hit.record.culled) {
      Row& row = rows.emplace_back();
      row.pixel = glm::dvec3(c.visible_radiance()) * weight;
      row.rank = renderer::contribution_rank(row.pixel, glm::dvec3(c.unshadowed_radiance) * weight,
                                             rows.size() - 1);
      std::snprintf(line, sizeof line, "%-14s %-5s %-28s %-12s %12.6f %-4s %9s %12.6f\n", "culled",
                    c.light.kind == lev::LightKind::spot ? "spot" : "point",
                    position_text(c.light.position).c_str(), node_text(c.node).c_str(),
                    brightest(glm::dvec3(c.unshadowed_radiance) * weight),
                    c.unshadowed_radiance == glm::vec3(0.0f) ? "-" : (c.visible ? "yes" : "no"),
                    "-", brightest(row.pixel));
      row.text = line;
    }
    std::sort(rows.begin(), rows.end(),
              [](const Row& a, const Row& b) { return renderer::ranks_before(a.rank, b.rank); });
    std::snprintf(line, sizeof line, "%-14s %-5s %-28s %-12s %12s %-4s %9s %12s\n", "role", "kind",
                  "position", "node", "unshadowed", "seen", "weight", "to pixel");
    out += line;
    const std::size_t shown = std::min(rows.size(), static_cast<std::size_t>(top));
    for (std::size_t i = 0; i < shown; ++i) out += rows[i].text;
    if (rows.size() > shown) out += "... " + std::to_string(rows.size() - shown) + " more rows\n";
    out += totals_text(renderer::hit_totals(hit));
  }
  out += "pixel totals (every hit, times its path weight):\n" + totals_text(inspection.totals);
  return out;
}

int run_inspect(const Settings& flag_settings, const InspectFlags& flags) {
  Settings settings = flag_settings;
  render_settings_from(settings);  // refuses what a render refuses, before the scene is built
  int x = 0, y = 0;
  parse_inspect_pixel(flags.pixel, settings.image.width, settings.image.height, x, y);
  // A render with --subsample N traces only the pixels whose x and y are multiples of N.
  const int stride = settings.image.subsample;
  if (x % stride != 0 || y % stride != 0) {
    throw UsageError("--pixel: a render with --subsample " + std::to_string(stride) +
                     " does not trace it (x and y must be multiples of " + std::to_string(stride) +
                     "), got '" + flags.pixel + "'");
  }
  if (flags.top < 0)
    throw UsageError("--top: must be >= 0, got '" + std::to_string(flags.top) + "'");
  // The table is an output too: on standard output (a file it is redirected to may not be an
  // input, `>> scene.json`), or on stderr when the JSON takes standard output.
  const bool table_on_stdout = flags.json != kStandardOutputName;
  std::vector<OutputPath> outputs = {{"--json", flags.json, ".json", "JSON"}};
  if (table_on_stdout) outputs.push_back({"the table", kStandardOutputName, ".txt", "text"});
  check_output_paths(outputs, settings_input_files(settings.scene));
  // Ctrl-C and SIGTERM end the command as they end `render`: one line naming where it stopped,
  // exit 130, nothing written (app/interrupt.h).
  const InterruptScope interrupt_scope;
  const std::atomic<bool>* cancel = &InterruptScope::flag();
  std::optional<InterruptWatchdog> watchdog(std::in_place);
  std::unique_ptr<LoadedScene> loaded = load_scene_or_interrupt(settings.scene, cancel);
  // The tolerance is in displayed units: an auto exposure (a glTF's default) is chosen as
  // `render` chooses it, so the selector culls what the render's culls.
  if (settings.display.exposure_auto) {
    const CommandStage stage("choosing the exposure");
    settings.display.exposure_ev =
        renderer::auto_exposure_ev(loaded->scene, *loaded->rays, render_settings_from(settings),
                                   settings.display.curve, cancel);
    InterruptScope::throw_if_interrupted();
  }
  const renderer::RenderSettings render_settings = render_settings_from(settings);
  const CommandStage stage("inspecting the pixel");
  // The render's selector: where its rt fallback shades with rt's loop, so does the inspector.
  std::optional<renderer::RtFallbackProbe> rt_fallback;
  const std::unique_ptr<lev::LightSelector> selector =
      renderer::make_render_selector(loaded->scene, *loaded->rays, render_settings, &rt_fallback);
  InterruptScope::throw_if_interrupted();
  const auto start = std::chrono::steady_clock::now();
  const renderer::PixelInspection inspection = renderer::inspect_pixel(
      loaded->scene, *loaded->rays, render_settings, *selector, x, y, cancel);
  const double inspect_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  InterruptScope::throw_if_interrupted();  // a cancelled inspection's lists are discarded
  // Both outputs are made before either is written (with a million lights, minutes of text):
  // Ctrl-C ends the making as it ends the inspection, with nothing written.
  const CommandStage formatting("formatting the lists");
  nlohmann::ordered_json json = inspection_json(inspection);
  json["rt_fallback"] = rt_fallback ? nlohmann::ordered_json(rt_fallback->use_rt) : nullptr;
  const std::string json_bytes = flags.json.empty() ? std::string() : json_text(json, 1);
  json = nullptr;
  InterruptScope::throw_if_interrupted();
  // The scene's name is the file's to choose: escaped, so it cannot split the header line or
  // drive the terminal. The method with the settings it reads (lightcuts has a relative error,
  // rt nothing).
  char header[384];
  std::snprintf(header, sizeof header,
                ", %llu lights, %s at exposure %g EV (inspected in %.1f ms)\n",
                static_cast<unsigned long long>(loaded->scene.lights.light_count),
                method_settings_text(settings).c_str(), settings.display.exposure_ev, inspect_ms);
  const std::string fallback_note =
      rt_fallback && rt_fallback->use_rt
          ? "rt fallback: the render shades this frame with rt's loop (its probe found the "
            "method's work at least rt's), so the lists are rt's\n"
          : "";
  const std::string table = scenes::escape_control_characters(loaded->scene.name) + header +
                            fallback_note + inspection_table(inspection, flags.top);
  watchdog.reset();
  InterruptScope::throw_if_interrupted();  // from here on every output is written in full
  // One write for both outputs (all or none): a table that cannot be written (a full disk, a
  // reader gone: `| head`) is one line and exit 1, not exit 0 or death by SIGPIPE, and the JSON
  // is not written either.
  std::vector<OutputFile> files;
  if (!flags.json.empty()) files.push_back({flags.json, [&json_bytes] { return json_bytes; }});
  if (table_on_stdout) files.push_back({kStandardOutputName, [&table] { return table; }});
  write_output_files(files);
  if (!table_on_stdout) std::fputs(table.c_str(), stderr);
  return 0;
}

}  // namespace app
