#include "app/viewer/control_rects.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/json_text.h"

namespace app::viewer {

void record_item(ControlRects* rects, const std::string& name) {
  if (!rects) return;
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  rects->push_back(ControlRect{name, min.x, min.y, max.x, max.y, ImGui::IsItemHovered()});
}

void record_rect(ControlRects* rects, const std::string& name, float x0, float y0, float x1,
                 float y1) {
  if (!rects) return;
  const bool hovered =
      ImGui::IsItemHovered() && ImGui::IsMouseHoveringRect(ImVec2(x0, y0), ImVec2(x1, y1));
  rects->push_back(ControlRect{name, x0, y0, x1, y1, hovered});
}

std::string controls_json(const ControlRects& rects, const Settings& settings, ViewMode view,
                          bool mouse_busy) {
  nlohmann::json out;
  out["controls"] = nlohmann::json::object();
  out["hovered"] = "";
  for (const ControlRect& r : rects) {
    out["controls"][r.name] = {r.x0, r.y0, r.x1, r.y1};
    if (r.hovered) out["hovered"] = r.name;
  }
  out["unused"] = nlohmann::json::object();
  for (const SettingSpec& spec : setting_table()) {
    out["settings"][spec.name] = setting_text(settings, spec);
    if (const char* why = spec.unused_because ? spec.unused_because(settings) : nullptr)
      out["unused"][spec.name] = why;
  }
  out["view"] = view_info(view).name;
  out["mouse_busy"] = mouse_busy;
  // A scene path need not be UTF-8 (a Latin-1 file name): its invalid bytes are written as
  // U+FFFD rather than failing the dump.
  return json_text(out, 1);
}

}  // namespace app::viewer
