// The text of a JSON output file (render's and a snapshot's stats, inspect's table, the viewer's
// control rectangles): indented, one newline at the end, and a string that is not UTF-8 (a scene
// named after a Latin-1 file name) written with U+FFFD for its invalid bytes rather than thrown
// about once the render is done.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace app {

template <typename Json>
std::string json_text(const Json& json, int indent) {
  return json.dump(indent, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace app
