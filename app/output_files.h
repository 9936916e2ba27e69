// The one rule every command's output files obey (render, export, bench, the viewer's screenshot,
// snapshot and controls files), and the one writer that keeps it. Before any work,
// check_output_paths refuses an output that is an input (the scene file, a glTF's buffers and
// textures, a script) or that another output also names, compared resolved (device and inode,
// or the canonical path of a new name), never by spelling; a symlink loop is refused too.
// write_output_files then writes all outputs or none: each regular file (or new name) goes to a
// temporary in its target's folder, and only when every output is complete are the temporaries
// renamed onto their targets, together, with the termination signals blocked; on any failure
// the temporaries go and the old files stay. A symlink is followed and stays a symlink; an
// existing pipe, terminal, /dev/null, /dev/zero or /dev/full is written in place, never replaced;
// a block device (a disk or partition) or any other character device (/dev/port, /dev/kmsg, a
// CPU's msr) is refused, never written; "-" is standard output. Write
// errors name their reason (strerror). A new file format only adds an encoder: an OutputFile is
// a name and a function producing its bytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace app {

// The output name that means standard output.
inline constexpr const char* kStandardOutputName = "-";

// The file an output path writes: symlinks followed, dangling ones too (their target is made).
std::filesystem::path output_target(const std::string& path);

// One output a command was asked for: the flag that names it (for messages), the path, and the
// extension and format its encoder writes.
struct OutputPath {
  std::string flag;
  std::string path;       // empty: not written
  std::string extension;  // ".png", ".json"; several separated by '|' (".png|.exr")
  std::string format;     // for the message
};

// Throws UsageError, before any work, for an output that could not or must not be written:
// empty, a folder, a block device, a character device other than those written in place, a symlink
// loop, a missing or unwritable folder, an existing file that is not writable (read-only,
// immutable), a name longer than the folder allows, the wrong extension (not checked for an
// existing pipe or device, which is written in place, nor for "-", standard output), one of
// `inputs` (the files the command reads; missing ones are skipped), or the file another output
// names.
void check_output_paths(const std::vector<OutputPath>& outputs,
                        const std::vector<std::string>& inputs = {});

// One file to write: its path and the encoder that produces its bytes.
struct OutputFile {
  std::string path;
  std::function<std::string()> bytes;
};

// All or none, as the header says. Throws std::runtime_error naming the path and the reason; an
// encoder's exception passes through, with nothing written.
void write_output_files(const std::vector<OutputFile>& files);

// Whether an image output writes EXR (its name ends in .exr; anything else written is PNG: a
// checked name ends in .png, standard output and a pipe or device take PNG).
bool is_exr_path(const std::string& path);

// The encoders (EXR: app/exr_encoding.h). PNG throws std::invalid_argument when the pixels do
// not match the size.
std::string png_rgb8_bytes(int width, int height, const std::vector<std::uint8_t>& rgb);

// One output alone, under the same guarantee.
void write_png_rgb8(const std::string& path, int width, int height,
                    const std::vector<std::uint8_t>& rgb);
void write_text_file(const std::string& path, const std::string& text);

// For a command that writes many files (levrt bench): they are made in a staging folder inside
// the destination, then written into the destination by write_output_files (all or none, the
// same rule), and the staging folder is removed. A run stopped before this leaves only the
// staging folder, which discard_staging_folder removes. Throws std::runtime_error naming the file.
void publish_staging_folder(const std::string& staging, const std::string& destination);
void discard_staging_folder(const std::string& staging) noexcept;

}  // namespace app
