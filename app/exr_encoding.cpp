#include "app/exr_encoding.h"

#include <tinyexr.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace app {

std::vector<ExrChannel> rgb_channels(const std::vector<glm::vec3>& colours) {
  std::vector<ExrChannel> channels = {{"R", {}}, {"G", {}}, {"B", {}}};
  for (int c = 0; c < 3; ++c) {
    std::vector<float>& values = channels[static_cast<std::size_t>(c)].values;
    values.reserve(colours.size());
    for (const glm::vec3& colour : colours) values.push_back(colour[c]);
  }
  return channels;
}

std::string exr_bytes(int width, int height, std::vector<ExrChannel> channels) {
  const auto pixels =
      static_cast<std::size_t>(std::max(width, 0)) * static_cast<std::size_t>(std::max(height, 0));
  if (width <= 0 || height <= 0 || channels.empty())
    throw std::invalid_argument("EXR: an image needs a size and at least one channel");
  std::sort(channels.begin(), channels.end(),
            [](const ExrChannel& a, const ExrChannel& b) { return a.name < b.name; });
  for (std::size_t i = 0; i < channels.size(); ++i) {
    if (channels[i].values.size() != pixels)
      throw std::invalid_argument("EXR: channel " + channels[i].name + " does not match the size");
    if (channels[i].name.empty() || channels[i].name.size() > 255)
      throw std::invalid_argument("EXR: a channel name must have 1 to 255 bytes");
    if (i > 0 && channels[i].name == channels[i - 1].name)
      throw std::invalid_argument("EXR: two channels are named " + channels[i].name);
  }
  const int count = static_cast<int>(channels.size());
  std::vector<EXRChannelInfo> infos(channels.size());
  std::vector<int> pixel_types(channels.size(), TINYEXR_PIXELTYPE_FLOAT);
  std::vector<unsigned char*> planes(channels.size());
  for (std::size_t i = 0; i < channels.size(); ++i) {
    std::memset(&infos[i], 0, sizeof(EXRChannelInfo));
    std::memcpy(infos[i].name, channels[i].name.c_str(), channels[i].name.size() + 1);
    infos[i].pixel_type = TINYEXR_PIXELTYPE_FLOAT;
    planes[i] = reinterpret_cast<unsigned char*>(channels[i].values.data());
  }
  EXRHeader header;
  InitEXRHeader(&header);
  header.num_channels = count;
  header.channels = infos.data();
  header.pixel_types = pixel_types.data();
  header.requested_pixel_types = pixel_types.data();
  header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
  EXRImage image;
  InitEXRImage(&image);
  image.num_channels = count;
  image.width = width;
  image.height = height;
  image.images = planes.data();
  unsigned char* memory = nullptr;
  const char* error = nullptr;
  const std::size_t size = SaveEXRImageToMemory(&image, &header, &memory, &error);
  const std::unique_ptr<unsigned char, decltype(&std::free)> owned(memory, &std::free);
  if (size == 0 || memory == nullptr) {
    const std::string reason = error ? error : "unknown error";
    if (error) FreeEXRErrorMessage(error);
    throw std::runtime_error("EXR encoding failed: " + reason);
  }
  return std::string(reinterpret_cast<const char*>(memory), size);
}

}  // namespace app
