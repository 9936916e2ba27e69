// The check every bad-glTF test makes: parsing `text` as `path` throws std::invalid_argument with
// one line that starts with "PATH: " and names the problem.
#pragma once

#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "scenes/gltf_scene.h"

namespace levrt_test {

inline void expect_gltf_refused(const std::string& text, const std::string& path,
                                const std::string& problem) {
  try {
    scenes::parse_gltf_scene(text, path);
    ADD_FAILURE() << "accepted: " << problem;
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace levrt_test
