// Reading an EXR back in the tests: every channel of a file (tinyexr), by name.
#pragma once

#include <tinyexr.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace levrt_test {

struct ExrFile {
  int width = 0, height = 0;
  std::map<std::string, std::vector<float>> channels;
};

inline ExrFile read_exr(const std::string& bytes) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  EXRVersion version;
  if (ParseEXRVersionFromMemory(&version, data, bytes.size()) != TINYEXR_SUCCESS)
    throw std::runtime_error("not an EXR");
  EXRHeader header;
  InitEXRHeader(&header);
  const char* error = nullptr;
  if (ParseEXRHeaderFromMemory(&header, &version, data, bytes.size(), &error) != TINYEXR_SUCCESS) {
    const std::string what = error ? error : "header";
    FreeEXRErrorMessage(error);
    throw std::runtime_error(what);
  }
  for (int c = 0; c < header.num_channels; ++c)
    header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
  EXRImage image;
  InitEXRImage(&image);
  if (LoadEXRImageFromMemory(&image, &header, data, bytes.size(), &error) != TINYEXR_SUCCESS) {
    const std::string what = error ? error : "image";
    FreeEXRErrorMessage(error);
    FreeEXRHeader(&header);
    throw std::runtime_error(what);
  }
  ExrFile file;
  file.width = image.width;
  file.height = image.height;
  const auto pixels =
      static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  for (int c = 0; c < header.num_channels; ++c) {
    const auto* values = reinterpret_cast<const float*>(image.images[c]);
    file.channels[header.channels[c].name] = std::vector<float>(values, values + pixels);
  }
  FreeEXRImage(&image);
  FreeEXRHeader(&header);
  return file;
}

}  // namespace levrt_test
