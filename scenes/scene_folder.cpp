#include "scenes/scene_folder.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace scenes {
namespace {

namespace fs = std::filesystem;

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// RFC 3986: ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ) ":" before any '/'.
bool has_scheme(const std::string& uri) {
  const std::size_t colon = uri.find(':');
  if (colon == std::string::npos || colon == 0 || uri.find('/') < colon) return false;
  for (std::size_t i = 0; i < colon; ++i) {
    const char c = uri[i];
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (!letter && (i == 0 || !((c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.')))
      return false;
  }
  return true;
}

[[noreturn]] void refuse(const std::string& reason) {
  throw std::invalid_argument(reason);
}

// Whether `inside` (canonical) lies in `folder` (canonical): no ".." leads out of it.
bool lies_in(const fs::path& inside, const fs::path& folder) {
  const fs::path relative = inside.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != ".." && relative != ".";
}

[[noreturn]] void fail_read(const std::string& path, const std::string& role,
                            const std::string& reason) {
  throw std::invalid_argument(path + ": cannot read the " + role + " (" + reason + ")");
}

void check_size(const std::string& path, const std::string& role, const struct stat& status,
                std::uintmax_t max_bytes) {
  if (!S_ISREG(status.st_mode)) fail_read(path, role, "not a regular file");
  if (static_cast<std::uintmax_t>(status.st_size) > max_bytes) {
    throw std::invalid_argument(path + ": file of " + std::to_string(status.st_size) +
                                " bytes, more than the " + byte_limit_text(max_bytes) + " a " +
                                role + " may have");
  }
}

// Reads into any byte container with resize() and data().
template <typename Bytes>
void read_into(const std::string& path, std::uintmax_t max_bytes, const std::string& role,
               Bytes& out) {
  struct stat status {};
  // stat before open: a FIFO or device is refused without being opened.
  if (::stat(path.c_str(), &status) != 0)
    fail_read(path, role, errno == ENOENT ? "no such file" : std::strerror(errno));
  check_size(path, role, status, max_bytes);
  // Non-blocking: should the name become a FIFO after the stat, the open still returns.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) fail_read(path, role, std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  if (::fstat(fd, &status) != 0) fail_read(path, role, std::strerror(errno));
  check_size(path, role, status, max_bytes);
  out.resize(static_cast<std::size_t>(status.st_size));
  std::size_t got = 0;
  while (got < out.size()) {
    const ssize_t n = ::read(fd, reinterpret_cast<char*>(out.data()) + got, out.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail_read(path, role, std::strerror(errno));
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  char extra = 0;
  // One byte more than measured: a file that grew or shrank since fails too.
  if (got != out.size() || ::read(fd, &extra, 1) > 0)
    throw std::invalid_argument(path + ": the " + role + " changed while it was read");
}

}  // namespace

std::string byte_limit_text(std::uintmax_t bytes) {
  constexpr std::uintmax_t kMiB = std::uintmax_t{1} << 20;
  if (bytes >= kMiB && bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
  return std::to_string(bytes) + " bytes";
}

std::string uri_file_path(const std::string& uri) {
  if (has_scheme(uri))
    refuse("a URI with a scheme ('" + uri.substr(0, uri.find(':')) +
           ":'); only relative paths and data URIs are read");
  std::string path;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      path += ' ';
    } else if (uri[i] == '%') {
      const int high = i + 2 < uri.size() ? hex_digit(uri[i + 1]) : -1;
      const int low = high >= 0 ? hex_digit(uri[i + 2]) : -1;
      if (low < 0) refuse("a malformed percent escape at character " + std::to_string(i));
      if (high == 0 && low == 0) refuse("an escaped NUL byte (%00)");
      path += static_cast<char>(high * 16 + low);
      i += 2;
    } else {
      path += uri[i];
    }
  }
  if (path.empty()) refuse("empty");
  if (path.find('\0') != std::string::npos) refuse("a NUL byte");
  if (path.front() == '/') refuse("an absolute path; files are named relative to the scene");
  return path;
}

FolderFile resolve_in_folder(const std::string& folder, const std::string& relative_path) {
  const fs::path relative = fs::path(relative_path).lexically_normal();
  if (relative.is_absolute()) refuse("an absolute path; files are named relative to the scene");
  // Lexically first, so a name leading out is refused without looking at what it names.
  if (relative.empty() || relative == "." || relative.filename().empty())
    refuse("names a folder, not a file");
  if (*relative.begin() == "..") refuse("leads outside the scene's folder");
  std::error_code ec;
  const fs::path base = fs::canonical(folder.empty() ? fs::path(".") : fs::path(folder), ec);
  if (ec) refuse("the scene's folder cannot be resolved (" + ec.message() + ")");
  // Every symlink on the way resolved; the file itself need not exist for this.
  const fs::path target = fs::weakly_canonical(base / relative, ec);
  if (ec) refuse("cannot be resolved (" + ec.message() + ")");
  if (!lies_in(target, base)) refuse("leads outside the scene's folder through a symlink");
  struct stat status {};
  if (::stat(target.c_str(), &status) != 0)
    refuse(errno == ENOENT ? "no such file in the scene's folder" : std::strerror(errno));
  if (!S_ISREG(status.st_mode)) {
    refuse(S_ISDIR(status.st_mode) ? "a folder, not a file"
                                   : "not a regular file (a FIFO, socket or device)");
  }
  return {target.string(), static_cast<std::uintmax_t>(status.st_size)};
}

bool regular_file_starts_with(const std::string& path, const std::string& prefix) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0 || !S_ISREG(status.st_mode)) return false;
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return false;
  std::string head(prefix.size(), '\0');
  std::size_t got = 0;
  while (got < head.size()) {
    const ssize_t n = ::read(fd, head.data() + got, head.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  ::close(fd);
  return got == head.size() && head == prefix;
}

void read_regular_file(const std::string& path, std::uintmax_t max_bytes, const std::string& role,
                       std::string& out) {
  read_into(path, max_bytes, role, out);
}

void read_regular_file(const std::string& path, std::uintmax_t max_bytes, const std::string& role,
                       std::vector<unsigned char>& out) {
  read_into(path, max_bytes, role, out);
}

}  // namespace scenes
