// Another valid value of a setting of the table (app/settings.h), as text, for tests that
// change every setting the table has without naming them: a new table entry is then covered too.
#pragma once

#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "app/scene_loading.h"
#include "app/settings.h"

namespace levrt_test {

// The first of the candidates (the range's ends and the values next to its minimum, the
// choice's options in order) that differs from the setting's value in `settings` and that the
// settings take: set_setting parses it, the renderer's settings are made, and the scene is
// described. Empty when there is none.
inline std::string other_setting_value(const app::Settings& settings,
                                       const app::SettingSpec& spec) {
  std::vector<std::string> candidates;
  const auto text = [](auto value) {
    std::ostringstream s;
    s.precision(17);
    s << value;
    return s.str();
  };
  if (const auto* r = std::get_if<app::IntRange>(&spec.kind)) {
    for (int v : {r->min, r->min + 1, r->min + 2, r->max}) candidates.push_back(text(v));
  } else if (const auto* d = std::get_if<app::RealRange>(&spec.kind)) {
    candidates = {text(d->min), text(d->max), text((d->min + d->max) / 2.0)};
  } else {
    candidates = std::get<app::Choice>(spec.kind).options();
  }
  const std::string current = app::setting_text(settings, spec);
  for (const std::string& candidate : candidates) {
    if (candidate == current) continue;
    app::Settings changed = settings;
    try {
      app::set_setting(changed, spec, candidate);
      app::render_settings_from(changed);
      app::describe_scene(changed.scene);
    } catch (const std::exception&) {
      continue;
    }
    if (app::setting_text(changed, spec) != current) return candidate;
  }
  return "";
}

}  // namespace levrt_test
