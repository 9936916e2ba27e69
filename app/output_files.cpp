#include "app/output_files.h"

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <thread>
#include <system_error>

#include <stb/stb_image_write.h>

namespace app {
namespace {

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

[[noreturn]] void throw_errno(const std::string& path, const char* what, int error) {
  throw std::runtime_error(path + ": " + what + " (" + std::strerror(error) + ")");
}

// write() until done; returns 0 or the errno of the failure. SIGXFSZ is ignored from the first
// write on (setting SIG_IGN again is harmless, so concurrent writers cannot race to restore it),
// so a file-size limit (ulimit -f) comes back as EFBIG, reported and cleaned up, instead of
// killing the process with the temporary file left behind.
int write_all(int fd, const std::string& bytes) {
  std::signal(SIGXFSZ, SIG_IGN);
  int error = 0;
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error = n < 0 ? errno : EIO;
      break;
    }
    done += static_cast<std::size_t>(n);
  }
  return error;
}

// An existing pipe, device or socket is written in place: renaming over it would replace the
// special file (as root, /dev/null itself) and nothing would reach its reader.
void write_in_place(const std::string& path, const std::string& bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) throw_errno(path, "cannot write", errno);
  const int error = write_all(fd, bytes);
  const int close_error = ::close(fd) != 0 ? errno : 0;
  if (error != 0) throw_errno(path, "write failed", error);
  if (close_error != 0) throw_errno(path, "write failed", close_error);
}

void write_to_standard_output(const std::string& bytes) {
  std::fflush(stdout);
  const int error = write_all(STDOUT_FILENO, bytes);
  if (error != 0) throw_errno("-", "write to standard output failed", error);
}

// A regular file or a new name: the bytes go to a temporary in the target's own folder (so the
// rename is atomic) and are renamed onto it when complete. A symlink is followed, never
// replaced: the rename lands on the file it points to.
void write_by_rename(const std::string& path, const std::filesystem::path& target, const std::string& bytes) {
  const TerminationSignalsBlocked blocked;
  const std::filesystem::path folder = target.parent_path().empty() ? std::filesystem::path(".") : target.parent_path();
  // A short name (a target name near the 255-byte limit must not overflow the temporary's),
  // unique per process and thread; O_EXCL never reuses an existing file, and the mode 0666 goes
  // through the umask like any new file's.
  const std::string stem = ".levrt-" + std::to_string(static_cast<long>(::getpid())) + "-" +
                           std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id()) % 1000000);
  std::string tmp;
  int fd = -1;
  constexpr int kMaxNameAttempts = 100;
  for (int attempt = 0; fd < 0 && attempt < kMaxNameAttempts; ++attempt) {
    tmp = (folder / (stem + "-" + std::to_string(attempt) + ".tmp")).string();
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd < 0) throw_errno(path, "cannot write", errno);
  const int error = write_all(fd, bytes);
  const int close_error = ::close(fd) != 0 ? errno : 0;
  if (error != 0 || close_error != 0) {
    ::unlink(tmp.c_str());
    throw_errno(path, "write failed", error != 0 ? error : close_error);
  }
  if (std::rename(tmp.c_str(), target.c_str()) != 0) {
    const int rename_error = errno;
    ::unlink(tmp.c_str());
    throw_errno(path, "cannot rename into place", rename_error);
  }
}

void write_output_bytes(const std::string& path, const std::string& bytes) {
  namespace fs = std::filesystem;
  if (path == kStandardOutputName) {
    write_to_standard_output(bytes);
    return;
  }
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);  // follows symlinks
  if (!ec && fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status)) {
    write_in_place(path, bytes);
    return;
  }
  write_by_rename(path, output_target(path), bytes);
}

void append_to_string(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

std::filesystem::path output_target(const std::string& path) {
  namespace fs = std::filesystem;
  fs::path target(path);
  // The kernel's own bound on a chain of links (MAXSYMLINKS); a longer chain or a loop is left
  // as it is and fails when opened.
  constexpr int kMaxSymlinkHops = 40;
  for (int hop = 0; hop < kMaxSymlinkHops; ++hop) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(target, ec))) break;
    const fs::path link = fs::read_symlink(target, ec);
    if (ec) break;
    target = link.is_absolute() ? link : target.parent_path() / link;
  }
  return target;
}

void write_png_rgb8(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb) {
  if (rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3) {
    throw std::invalid_argument(path + ": image size does not match its pixels");
  }
  std::string png;
  if (!stbi_write_png_to_func(append_to_string, &png, width, height, 3, rgb.data(), width * 3)) {
    throw std::runtime_error(path + ": PNG encoding failed");
  }
  write_output_bytes(path, png);
}

void write_text_file(const std::string& path, const std::string& text) {
  write_output_bytes(path, text);
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

}  // namespace app
