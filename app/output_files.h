// The commands' output files (render, export, bench, viewer snapshots): PNG and text that never
// leave a half-written file. A regular file (or a new name) is written to a temporary in the
// target's folder, with the termination signals blocked, and renamed onto it when complete; a
// symlink is followed and stays a symlink; an existing pipe or device is written in place, never replaced;
// "-" is standard output. Write errors name their reason (strerror).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace app {

// The output name that means standard output.
inline constexpr const char* kStandardOutputName = "-";

// The file an output path writes: symlinks followed, dangling ones too (their target is made).
std::filesystem::path output_target(const std::string& path);

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

}  // namespace app
