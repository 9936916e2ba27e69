#include "renderer/image_io.h"

#include <pthread.h>
#include <unistd.h>

#include <csignal>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include <stb/stb_image_write.h>

namespace renderer {
namespace {

std::string temporary_name(const std::string& path) {
  return path + ".tmp" + std::to_string(static_cast<long>(::getpid()));
}

// Blocks the termination signals while the temporary exists, so Ctrl-C cannot leave it behind;
// a signal that arrives meanwhile is delivered when the file is complete and renamed.
class TerminationSignalsBlocked {
 public:
  TerminationSignalsBlocked() {
    sigset_t block;
    sigemptyset(&block);
    for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&block, s);
    pthread_sigmask(SIG_BLOCK, &block, &saved_);
  }
  ~TerminationSignalsBlocked() { pthread_sigmask(SIG_SETMASK, &saved_, nullptr); }
  TerminationSignalsBlocked(const TerminationSignalsBlocked&) = delete;
  TerminationSignalsBlocked& operator=(const TerminationSignalsBlocked&) = delete;

 private:
  sigset_t saved_;
};

void write_bytes_atomically(const std::string& path, const std::string& bytes) {
  const TerminationSignalsBlocked blocked;
  const std::string tmp = temporary_name(path);
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw std::runtime_error(path + ": cannot write (" + std::strerror(errno) + ")");
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  const bool closed = std::fclose(f) == 0;
  if (!written || !closed) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": write failed");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot rename into place (" + reason + ")");
  }
}

void append_to_string(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

void write_png_rgb8(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb) {
  if (rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3) {
    throw std::invalid_argument(path + ": image size does not match its pixels");
  }
  std::string png;
  if (!stbi_write_png_to_func(append_to_string, &png, width, height, 3, rgb.data(), width * 3)) {
    throw std::runtime_error(path + ": PNG encoding failed");
  }
  write_bytes_atomically(path, png);
}

void write_text_file(const std::string& path, const std::string& text) {
  write_bytes_atomically(path, text);
}

void publish_staging_folder(const std::string& staging, const std::string& destination) {
  namespace fs = std::filesystem;
  const TerminationSignalsBlocked blocked;
  for (const fs::directory_entry& entry : fs::directory_iterator(staging)) {
    const fs::path target = fs::path(destination) / entry.path().filename();
    std::error_code ec;
    fs::rename(entry.path(), target, ec);
    if (ec) throw std::runtime_error(target.string() + ": cannot move into place (" + ec.message() + ")");
  }
  std::error_code ec;
  fs::remove(staging, ec);
}

void discard_staging_folder(const std::string& staging) noexcept {
  std::error_code ec;
  std::filesystem::remove_all(staging, ec);
}

}  // namespace renderer
