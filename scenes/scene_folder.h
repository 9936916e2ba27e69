// Reading files a scene names, and nothing else. A scene file is read whole under a byte cap; the
// files a glTF names (buffers, images) are resolved inside the glTF's own folder, which is the
// scene's boundary: a URI is percent-decoded, then refused when it is absolute, carries a scheme
// (file://, http://), leads out of the folder by `..` or through a symlink (the canonical path is
// checked), or names anything but a regular file (a FIFO or device is refused by stat before any
// open, and the open is non-blocking besides). Messages about a refused URI say what it is, never
// the size or content of a file outside the folder.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace scenes {

// A regular file inside a scene's folder, found by resolve_in_folder.
struct FolderFile {
  std::string canonical_path;
  std::uintmax_t bytes = 0;
};

// A glTF URI as a file path: percent escapes decoded and '+' read as a space, as tinygltf does
// before it opens a file, so the file checked is the file opened. Refused (std::invalid_argument
// with the reason alone, for the caller to prefix with the file and field): a scheme (file://,
// http://; data: URIs are not files and never come here), an absolute path, a malformed escape
// and an escaped NUL.
std::string uri_file_path(const std::string& uri);

// The regular file `relative_path` (decoded) names inside `folder` ("" is the working folder).
// Throws std::invalid_argument with the reason alone, like uri_file_path.
FolderFile resolve_in_folder(const std::string& folder, const std::string& relative_path);

// The whole of the regular file at `path` into `out`, refused with one line "PATH: ..." in a
// std::invalid_argument when it is missing, not a regular file (checked by stat before the open,
// which does not block), larger than max_bytes (before reading) or changes while it is read.
// `role` names the file in messages ("scene file").
void read_regular_file(const std::string& path, std::uintmax_t max_bytes, const std::string& role,
                       std::string& out);
void read_regular_file(const std::string& path, std::uintmax_t max_bytes, const std::string& role,
                       std::vector<unsigned char>& out);

// Whether `path` is a regular file whose first bytes are `prefix` (stat before a non-blocking
// open, as read_regular_file); false for anything else, which read_regular_file then reports.
bool regular_file_starts_with(const std::string& path, const std::string& prefix);

// "64 MiB" for whole mebibytes, else "N bytes".
std::string byte_limit_text(std::uintmax_t bytes);

}  // namespace scenes
