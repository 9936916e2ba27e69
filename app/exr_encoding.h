// The OpenEXR encoder of levrt's float outputs (tinyexr, Debian's libtinyexr-dev): `--out
// FILE.exr` and the viewer's snapshot write one scanline file of 32-bit float channels, ZIP
// compressed: R, G, B the scene-linear radiance (before the exposure and the display curve) and
// further named channels for the per-pixel counters and error figures (exr_channel_names below).
// It only produces bytes; app/output_files writes them, all or none.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace app {

struct ExrChannel {
  std::string name;           // at most 255 bytes
  std::vector<float> values;  // width x height, rows top to bottom
};

// The R, G and B channels of an image of colours (pixel order).
std::vector<ExrChannel> rgb_channels(const std::vector<glm::vec3>& colours);

// The file's bytes; the channels are stored sorted by name, as OpenEXR requires. Throws
// std::invalid_argument when a channel's size is not width x height or two share a name, and
// std::runtime_error when tinyexr fails.
std::string exr_bytes(int width, int height, std::vector<ExrChannel> channels);

}  // namespace app
