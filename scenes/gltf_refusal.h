// How the glTF importer refuses a file: one line "FILE: glTF.path: value" in a
// std::invalid_argument (exit 2), numbers written as the file has them to nine digits.
#pragma once

#include <string>

namespace scenes {

[[noreturn]] void fail_gltf(const std::string& path, const std::string& where,
                            const std::string& value);

std::string gltf_number_text(double value);

}  // namespace scenes
