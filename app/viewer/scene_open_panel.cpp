#include "app/viewer/scene_open_panel.h"

#include <array>
#include <cstring>
#include <string>

#include <imgui.h>

#include "app/viewer/scene_opening.h"

namespace app::viewer {

void draw_scene_open_row(ViewerState& state) {
  ControlRects* rects = state.record_controls ? &state.control_rects : nullptr;
  // ImGui edits a char buffer; the path lives in the state between frames.
  std::array<char, 4096> text{};
  std::strncpy(text.data(), state.scene_path_field.c_str(), text.size() - 1);
  const float button_width =
      ImGui::CalcTextSize("Open").x + 2.0f * ImGui::GetStyle().FramePadding.x;
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - button_width -
                          ImGui::GetStyle().ItemSpacing.x);
  const bool entered =
      ImGui::InputTextWithHint("##scene_path", "scene file: path, then Enter", text.data(),
                               text.size(), ImGuiInputTextFlags_EnterReturnsTrue);
  state.scene_path_field = text.data();
  record_item(rects, "scene_path_field");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "a .json, .gltf or .glb file (or drop one on the window); relative paths "
        "start in the folder levrt was started from");
  ImGui::SameLine();
  const bool clicked = ImGui::Button("Open");
  record_item(rects, "scene_open");
  if (entered || clicked) open_scene_file(state, state.scene_path_field);
  // The latest problem stays in view under the field, whole, until the next message.
  if (!state.messages.empty() && state.messages.back().problem) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", state.messages.back().text.c_str());
    ImGui::PopStyleColor();
  }
  if (state.recent_scenes.empty()) return;
  if (ImGui::BeginCombo("Recent", state.recent_scenes.front().c_str())) {
    for (std::size_t i = 0; i < state.recent_scenes.size(); ++i) {
      const std::string path = state.recent_scenes[i];  // opening reorders the list
      ImGui::PushID(static_cast<int>(i));
      if (ImGui::Selectable(path.c_str(), path == state.settings.scene.name)) {
        state.scene_path_field = path;
        open_scene_file(state, path);
      }
      record_item(rects, "recent:" + std::to_string(i));
      ImGui::PopID();
    }
    ImGui::EndCombo();
  }
  record_item(rects, "recent");
}

void draw_messages_section(const ViewerState& state) {
  const float lines = 6.0f;
  ImGui::BeginChild("messages", ImVec2(0.0f, lines * ImGui::GetTextLineHeightWithSpacing()), true);
  // Newest first, each wrapped whole.
  for (auto it = state.messages.rbegin(); it != state.messages.rend(); ++it) {
    if (it->problem) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", it->text.c_str());
    if (it->problem) ImGui::PopStyleColor();
  }
  ImGui::EndChild();
}

}  // namespace app::viewer
