// A whole file as bytes, for tests that check what a command wrote (empty when it cannot be read).
#pragma once

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace levrt_test {

inline std::string read_file(const std::filesystem::path& path) {
  std::string text;
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return text;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), f)) > 0) text.append(buffer.data(), n);
  std::fclose(f);
  return text;
}

}  // namespace levrt_test
