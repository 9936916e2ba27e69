// PNG output that never leaves a half-written file: the image goes to a temporary name in the
// same folder and is renamed over the target only when complete.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace renderer {

// Throws std::runtime_error naming the path on failure.
void write_png_rgb8(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb);
// Same guarantee for text (stats JSON).
void write_text_file(const std::string& path, const std::string& text);

// For a command that writes many files (levrt bench): they are made in a staging folder inside
// the destination, then moved into the destination together, with the termination signals
// blocked, and the staging folder is removed. A run stopped before this leaves only the staging
// folder, which discard_staging_folder removes. Throws std::runtime_error naming the file.
void publish_staging_folder(const std::string& staging, const std::string& destination);
void discard_staging_folder(const std::string& staging) noexcept;

}  // namespace renderer
