// A JSON file a command wrote, parsed (nlohmann::json's parse error when it is not JSON).
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "tests/support/read_file.h"

namespace levrt_test {

inline nlohmann::json read_json(const std::filesystem::path& path) {
  return nlohmann::json::parse(read_file(path));
}

}  // namespace levrt_test
