#include "app/viewer/settings_panel.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/camera_flags.h"
#include "app/viewer/log_slider.h"
#include "app/viewer/scene_open_panel.h"
#include "app/viewer/scene_opening.h"
#include "renderer/render.h"
#include "scenes/scene_models.h"

namespace app::viewer {
namespace {

void help_tooltip(const SettingSpec& spec) {
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (--%s)", spec.help, spec.name);
}

// Light counts of the scene's levels, for the level control.
bool draw_light_count(Settings& settings, const SettingSpec& spec, const IntRange& range,
                      ControlRects* rects) {
  const scenes::SceneModel* model = scenes::find_scene_model(settings.scene.name);
  if (!model) {
    ImGui::LabelText("Lights", "from the scene");
    return false;
  }
  const int level = range.field.get(settings);
  const std::string current =
      std::to_string(model->light_count(level)) + " (level " + std::to_string(level) + ")";
  bool changed = false;
  if (ImGui::BeginCombo("Lights", current.c_str())) {
    for (int l = std::max(model->min_level, range.min); l <= std::min(model->max_level, range.max);
         ++l) {
      const std::string text =
          std::to_string(model->light_count(l)) + " (level " + std::to_string(l) + ")";
      if (ImGui::Selectable(text.c_str(), l == level) && l != level) {
        range.field.ref(settings) = l;
        changed = true;
      }
      record_item(rects, "lights:" + std::to_string(model->light_count(l)));
    }
    ImGui::EndCombo();
  }
  record_item(rects, "lights");
  help_tooltip(spec);
  return changed;
}

bool draw_int(Settings& settings, const SettingSpec& spec, const IntRange& range,
              ControlRects* rects) {
  if (std::string(spec.name) == "level") return draw_light_count(settings, spec, range, rects);
  int value = range.field.get(settings);
  const float width = ImGui::CalcItemWidth();
  const bool edited =
      ImGui::InputInt(spec.label, &value, 1, 10, ImGuiInputTextFlags_EnterReturnsTrue);
  // ImGui lays out the field, then square "-" and "+" buttons, within the item width.
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  const float button = ImGui::GetFrameHeight(), gap = ImGui::GetStyle().ItemInnerSpacing.x;
  record_rect(rects, std::string(spec.name) + "+", min.x + width - button, min.y, min.x + width,
              max.y);
  record_rect(rects, std::string(spec.name) + "-", min.x + width - 2.0f * button - gap, min.y,
              min.x + width - button - gap, max.y);
  help_tooltip(spec);
  value = panel_int_value(spec, range, range.field.get(settings), value);
  if (!edited || value == range.field.get(settings)) return false;
  range.field.ref(settings) = value;
  return true;
}

bool draw_real(Settings& settings, const SettingSpec& spec, const RealRange& range,
               ControlRects* rects, std::string& refusal) {
  double value = range.field.get(settings);
  bool changed = false;
  bool word_chosen = false;
  ImGui::PushID(spec.name);
  const float full = ImGui::CalcItemWidth();
  float field_width = full;  // the typed value's frame, without its label
  if (range.logarithmic) {
    // One row: the log slider, a 0 button and the typed value.
    const LogSpan span{std::max(range.min, range.slider_min),
                       std::min(range.max, range.slider_max)};
    float position = log_slider_position(value, span);
    const float left = log_slider_position(span.lo, span),
                right = log_slider_position(span.hi, span);
    ImGui::SetNextItemWidth(full * 0.55f);
    // The handle's text has no '%' conversion: ImGui prints it as it is.
    if (ImGui::SliderFloat("##log", &position, left, right, log_slider_text(value).c_str(),
                           ImGuiSliderFlags_NoRoundToFormat | ImGuiSliderFlags_AlwaysClamp)) {
      value = log_slider_value(position, span);
      changed = true;
    }
    record_item(rects, std::string(spec.name) + "_slider");
    help_tooltip(spec);
    ImGui::SameLine(0.0f, 2.0f);
    if (ImGui::Button("0") && range.min <= 0.0) {
      value = 0.0;
      changed = true;
    }
    record_item(rects, std::string(spec.name) + "_zero");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", zero_button_tooltip(spec).c_str());
    ImGui::SameLine(0.0f, 2.0f);
    field_width = std::max(full - (ImGui::GetCursorScreenPos().x - ImGui::GetWindowPos().x) +
                               ImGui::GetStyle().WindowPadding.x,
                           40.0f);
    ImGui::SetNextItemWidth(field_width);
  }
  if (!range.logarithmic && range.slider_max > range.slider_min) {
    // One row: a linear slider (the exposure's EV), the word button ("auto") and the typed value.
    float position = static_cast<float>(std::clamp(value, range.slider_min, range.slider_max));
    ImGui::SetNextItemWidth(full * 0.55f);
    if (ImGui::SliderFloat("##linear", &position, static_cast<float>(range.slider_min),
                           static_cast<float>(range.slider_max), "%.2f",
                           ImGuiSliderFlags_AlwaysClamp)) {
      value = position;
      changed = true;
    }
    record_item(rects, std::string(spec.name) + "_slider");
    help_tooltip(spec);
    if (range.word) {
      ImGui::SameLine(0.0f, 2.0f);
      const bool on = range.word_flag.get(settings);
      if (on)
        ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyle().Colors[ImGuiCol_ButtonActive]);
      if (ImGui::Button(range.word) && !on) {
        range.word_flag.ref(settings) = true;
        word_chosen = true;
      }
      if (on) ImGui::PopStyleColor();
      record_item(rects, std::string(spec.name) + "_" + range.word);
    }
    ImGui::SameLine(0.0f, 2.0f);
    field_width = std::max(full - (ImGui::GetCursorScreenPos().x - ImGui::GetWindowPos().x) +
                               ImGui::GetStyle().WindowPadding.x,
                           40.0f);
    ImGui::SetNextItemWidth(field_width);
  }
  double typed = value;
  if (ImGui::InputDouble(spec.label, &typed, 0.0, 0.0, "%g",
                         ImGuiInputTextFlags_EnterReturnsTrue)) {
    refusal = typed_value_refusal(spec, range, typed);
    if (refusal.empty()) {
      value = typed;
      changed = true;
    }
  }
  // The frame alone, not the label beside it: a click at the rectangle's centre types here.
  const ImVec2 field_min = ImGui::GetItemRectMin(), field_max = ImGui::GetItemRectMax();
  record_rect(rects, std::string(spec.name) + "_field", field_min.x, field_min.y,
              field_min.x + field_width, field_max.y);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s (--%s); type a value and press Enter", spec.help, spec.name);
  ImGui::PopID();
  if (word_chosen) return true;
  const bool word_was_on = range.word_flag.get && range.word_flag.get(settings);
  if (!changed || (value == range.field.get(settings) && !word_was_on)) return false;
  range.field.ref(settings) = value;
  if (range.word_flag.ref) range.word_flag.ref(settings) = false;
  return true;
}

bool draw_choice(Settings& settings, const SettingSpec& spec, const Choice& choice,
                 ControlRects* rects) {
  std::vector<std::string> options = choice.options();
  const std::string current = choice.get(settings);
  // A value from the command line outside the list (a scene file) stays selectable.
  if (std::find(options.begin(), options.end(), current) == options.end())
    options.push_back(current);
  bool changed = false;
  // The method table's labels name the methods; other choices show their values.
  const auto label = [&](const std::string& o) {
    return choice.option_label ? choice.option_label(o) : o.c_str();
  };
  // Tall enough for every method of the table without a scrollbar (the default stops at 8).
  if (ImGui::BeginCombo(spec.label, label(current), ImGuiComboFlags_HeightLarge)) {
    for (const std::string& o : options) {
      ImGui::PushID(o.c_str());
      if (ImGui::Selectable(label(o), o == current) && o != current) {
        choice.set(settings, o);
        changed = true;
      }
      record_item(rects, std::string(spec.name) + ":" + o);
      // After record_item: a tooltip is a window of its own and would become the last item.
      if (choice.option_summary && ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", choice.option_summary(o));
      ImGui::PopID();
    }
    ImGui::EndCombo();
  }
  record_item(rects, spec.name);
  help_tooltip(spec);
  return changed;
}

}  // namespace

std::string typed_value_refusal(const SettingSpec& spec, const RealRange& range, double typed) {
  if (typed >= range.min && typed <= range.max) return "";
  char text[192];
  std::snprintf(text, sizeof text, "%s: must be in [%g, %g], got %g (the value before is kept)",
                spec.name, range.min, range.max, typed);
  return text;
}

std::string zero_button_tooltip(const SettingSpec& spec) {
  if (std::string(spec.name) == "tolerance") return "tolerance 0: no culling, the image equals rt";
  return std::string(spec.name) + " 0: exact, every light (the image equals rt)";
}

int panel_int_value(const SettingSpec& spec, const IntRange& range, int held, int asked) {
  const int value = std::clamp(asked, range.min, range.max);
  if (std::string(spec.name) == "missed-draws" && value > 0 && value < renderer::kMinMissedDraws)
    return value > held ? renderer::kMinMissedDraws : 0;
  return value;
}

void draw_settings_section(ViewerState& state) {
  ControlRects* rects = state.record_controls ? &state.control_rects : nullptr;
  ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.62f);
  for (const SettingSpec& spec : setting_table()) {
    const Settings before = state.settings;
    // A setting these settings ignore is greyed out, saying why.
    const char* unused = spec.unused_because ? spec.unused_because(state.settings) : nullptr;
    if (unused) ImGui::BeginDisabled();
    bool changed = false;
    if (const auto* i = std::get_if<IntRange>(&spec.kind)) {
      changed = draw_int(state.settings, spec, *i, rects);
    } else if (const auto* r = std::get_if<RealRange>(&spec.kind)) {
      std::string refusal;
      changed = draw_real(state.settings, spec, *r, rects, refusal);
      if (!refusal.empty()) log_message(state, refusal, true);
    } else {
      changed = draw_choice(state.settings, spec, std::get<Choice>(spec.kind), rects);
    }
    if (unused) {
      ImGui::EndDisabled();
      if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s: %s", spec.label, unused);
    }
    if (changed)
      settings_changed(state, before,
                       std::string(spec.name) + "=" + setting_text(state.settings, spec));
    if (std::string(spec.name) == "scene") draw_scene_open_row(state);
  }
  ImGui::PopItemWidth();
  if (ImGui::Button("Reset camera")) reset_camera(state);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("back to the scene's preset view");
  ImGui::SameLine();
  if (ImGui::Button("Copy camera")) copy_camera_flags(state);
  record_item(rects, "copy_camera");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "%s\n(to the clipboard, as flags for levrt render or view)",
        app::camera_flags_text(app::world_camera(current_camera(state), state.status.world_origin))
            .c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("drag: orbit, right drag: pan, wheel: zoom");
  ImGui::PopStyleColor();
}

}  // namespace app::viewer
