#include "app/output_files.h"

#include <fcntl.h>
#include <linux/magic.h>
#include <poll.h>
#include <pthread.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <thread>

#include <stb/stb_image_write.h>

#include "app/interrupt.h"
#include "app/settings.h"

namespace app {
namespace fs = std::filesystem;

namespace {

// Whether path ends in one of the '|'-separated extensions.
bool has_extension(const std::string& path, const std::string& extensions) {
  const std::string actual = fs::path(path).extension().string();
  std::size_t start = 0;
  while (true) {
    const std::size_t bar = extensions.find('|', start);
    if (actual == extensions.substr(start, bar - start)) return true;
    if (bar == std::string::npos) return false;
    start = bar + 1;
  }
}

// Blocks the termination signals while temporaries exist, so Ctrl-C cannot leave one behind; a
// signal that arrives meanwhile is delivered when the files are complete and renamed.
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

// A symlink whose chain never ends in a file (a loop, or longer than the kernel follows).
bool is_symlink_loop(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return false;
  return ::stat(path.c_str(), &st) != 0 && errno == ELOOP;
}

// An existing block device (a disk or a partition), symlinks followed: never an output. Writing
// an image there in place would overwrite the start of the disk.
bool is_block_device(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISBLK(st.st_mode);
}

[[noreturn]] void refuse_block_device(const std::string& path) {
  throw std::runtime_error(path + ": cannot write (a block device: a disk or partition)");
}

// The character devices written in place: /dev/null, /dev/zero, /dev/full, /dev/random and
// /dev/urandom (major 1, whose other minors are /dev/mem, /dev/kmem, /dev/port and /dev/kmsg) and
// terminals (major 4: tty0-63 and serial lines; 5: /dev/tty, the console, ptmx; 136-143:
// pseudo-terminals). Any other (a CPU's msr, a watchdog, a flash chip, a hardware RNG) could be
// changed by the bytes of an image, or fail only after the work: never an output.
bool is_character_device_levrt_writes(dev_t device) {
  const unsigned int kind = major(device);
  const unsigned int unit = minor(device);
  if (kind == 1) return unit == 3 || unit == 5 || unit == 7 || unit == 8 || unit == 9;
  return kind == 4 || kind == 5 || (kind >= 136 && kind <= 143);
}

// An existing character device (symlinks followed) that levrt does not write.
bool is_unwritten_character_device(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode) &&
         !is_character_device_levrt_writes(st.st_rdev);
}

[[noreturn]] void refuse_character_device(const std::string& path) {
  throw std::runtime_error(path +
                           ": cannot write (a device other than /dev/null, /dev/zero, /dev/full "
                           "and terminals)");
}

// An existing file that is neither a regular file nor a folder: a pipe, device or socket.
bool is_existing_special_file(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);  // follows symlinks
  return !ec && fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status);
}

// write() until done; returns 0 or the errno of the failure. SIGXFSZ and SIGPIPE are ignored from
// the first write on (setting SIG_IGN again is harmless, so concurrent writers cannot race to
// restore it), so a file-size limit (ulimit -f) comes back as EFBIG and a reader that went away
// (`levrt render --out - | true`, a FIFO closed early) as EPIPE, reported and cleaned up, instead
// of killing the process with the other outputs' temporary files left behind.
// The kernel's own file systems (sysfs, procfs and their kin) take no new file, whatever access()
// says of their folders (root may "write" /sys/kernel): an output there could only fail after the
// work. Named here so that it is refused before. Null for any other file system.
const char* kernel_file_system(const std::string& folder) {
  struct statfs info {};
  if (::statfs(folder.c_str(), &info) != 0) return nullptr;
  switch (static_cast<unsigned long>(info.f_type)) {
    case SYSFS_MAGIC:
      return "sysfs";
    case PROC_SUPER_MAGIC:
      return "procfs";
    case DEBUGFS_MAGIC:
      return "debugfs";
    case TRACEFS_MAGIC:
      return "tracefs";
    case SECURITYFS_MAGIC:
      return "securityfs";
    case CGROUP_SUPER_MAGIC:
      return "cgroupfs";
    case CGROUP2_SUPER_MAGIC:
      return "cgroup2fs";
    case BPF_FS_MAGIC:
      return "bpffs";
    case PSTOREFS_MAGIC:
      return "pstorefs";
    case EFIVARFS_MAGIC:
      return "efivarfs";
    case SELINUX_MAGIC:
      return "selinuxfs";
    case DEVPTS_SUPER_MAGIC:
      return "devpts";
    default:
      return nullptr;
  }
}

int write_all(int fd, const std::string& bytes) {
  std::signal(SIGXFSZ, SIG_IGN);
  std::signal(SIGPIPE, SIG_IGN);
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

// Whether the user asked levrt to stop while it waits on a pipe, the termination signals being
// blocked in this thread: the interrupt flag (app/interrupt.h; its handler runs in a thread that
// does not block them), or a termination signal pending here, taken so that the command ends by
// the Interrupted thrown, its temporaries removed, rather than by the signal's default action.
// Waits up to `wait_ms` for such a signal.
bool termination_requested(long wait_ms) {
  if (InterruptScope::flag().load()) return true;
  sigset_t termination;
  sigemptyset(&termination);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&termination, s);
  const timespec wait{0, wait_ms * 1000000L};
  return ::sigtimedwait(&termination, nullptr, &wait) > 0 || InterruptScope::flag().load();
}

// An existing pipe, character device or socket is written in place: renaming over it would
// replace the special file (as root, /dev/null itself) and nothing would reach its reader. What
// was opened is checked again: a name that became a block device since is not written. The open
// and the writes do not block: a FIFO with no reader yet (or one that stopped reading) is waited
// for in steps, each ending the command with Interrupted when Ctrl-C or SIGTERM came meanwhile;
// before, the wait was in the kernel with the signals blocked, and only SIGKILL ended it.
void write_in_place(const std::string& path, const std::string& bytes) {
  constexpr long kWaitStepMs = 20;
  int fd = -1;
  while ((fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC)) < 0) {
    if (errno == EINTR) continue;
    // ENXIO is a FIFO without a reader, to wait for; anything else (a socket's ENXIO too) fails.
    const int error = errno;
    struct stat status {};
    if (error != ENXIO || ::stat(path.c_str(), &status) != 0 || !S_ISFIFO(status.st_mode))
      throw_errno(path, "cannot write", error);
    if (termination_requested(kWaitStepMs)) throw Interrupted();
  }
  struct Closer {
    int fd;
    ~Closer() {
      if (fd >= 0) ::close(fd);
    }
  } closer{fd};
  struct stat opened {};
  if (::fstat(fd, &opened) != 0 || S_ISBLK(opened.st_mode)) refuse_block_device(path);
  if (S_ISCHR(opened.st_mode) && !is_character_device_levrt_writes(opened.st_rdev))
    refuse_character_device(path);
  std::signal(SIGPIPE, SIG_IGN);  // a reader that went away is EPIPE, as in write_all
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
    } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      pollfd ready{fd, POLLOUT, 0};
      if (::poll(&ready, 1, 0) <= 0 && termination_requested(kWaitStepMs)) throw Interrupted();
    } else if (!(n < 0 && errno == EINTR)) {
      throw_errno(path, "write failed", n < 0 ? errno : EIO);
    }
  }
  const int fd_to_close = closer.fd;
  closer.fd = -1;
  if (::close(fd_to_close) != 0) throw_errno(path, "write failed", errno);
}

void write_to_standard_output(const std::string& bytes) {
  std::fflush(stdout);
  const int error = write_all(STDOUT_FILENO, bytes);
  if (error != 0) throw_errno("-", "write to standard output failed", error);
}

fs::path folder_of(const fs::path& target) {
  return target.parent_path().empty() ? fs::path(".") : target.parent_path();
}

// Creates a new, empty file with a short unique name in `folder` (a target name near the
// 255-byte limit must not overflow the temporary's), unique per process and thread; O_EXCL never
// reuses an existing file, and the mode 0666 goes through the umask like any new file's. Returns
// the descriptor, or -1 with errno set.
int create_temporary(const fs::path& folder, std::string& name) {
  const std::string stem =
      ".levrt-" + std::to_string(static_cast<long>(::getpid())) + "-" +
      std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id()) % 1000000);
  constexpr int kMaxNameAttempts = 1000;
  for (int attempt = 0; attempt < kMaxNameAttempts; ++attempt) {
    name = (folder / (stem + "-" + std::to_string(attempt) + ".tmp")).string();
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  return -1;
}

// A complete file waiting to be renamed onto its target, and the backup (a hard link to the old
// target, empty when there was none) that puts the old file back if a later rename fails.
struct StagedFile {
  std::string path;  // as the user named it, for messages
  fs::path target;
  std::string temporary;
  std::string backup;
  bool renamed = false;
};

// Writes the bytes to a temporary in the target's folder. A symlink is followed, never replaced:
// the rename lands on the file it points to. The temporary takes an existing target's permission
// bits (and, where allowed, its owner and group), so replacing a private 0600 file does not leave
// a world-readable 0644 one in its place.
StagedFile stage(const std::string& path, const std::string& bytes) {
  StagedFile staged{path, output_target(path), "", "", false};
  const int fd = create_temporary(folder_of(staged.target), staged.temporary);
  if (fd < 0) throw_errno(path, "cannot write", errno);
  struct stat old {};
  if (::stat(staged.target.c_str(), &old) == 0 && S_ISREG(old.st_mode)) {
    // Owner first (fchown may clear the set-ID bits fchmod sets). Only root may give a file
    // away: for anyone else it fails and the file stays theirs, as a new file would be.
    [[maybe_unused]] const int owner_kept = ::fchown(fd, old.st_uid, old.st_gid);
    [[maybe_unused]] const int mode_kept = ::fchmod(fd, old.st_mode & 07777);
  }
  const int error = write_all(fd, bytes);
  const int close_error = ::close(fd) != 0 ? errno : 0;
  if (error != 0 || close_error != 0) {
    ::unlink(staged.temporary.c_str());
    throw_errno(path, "write failed", error != 0 ? error : close_error);
  }
  return staged;
}

// Removes what is left of staged files that were not committed: temporaries and backups.
void discard(std::vector<StagedFile>& staged) noexcept {
  for (StagedFile& s : staged) {
    if (!s.renamed && !s.temporary.empty()) ::unlink(s.temporary.c_str());
    if (!s.backup.empty()) ::unlink(s.backup.c_str());
  }
}

// Renames every temporary onto its target. The old targets are first hard-linked to backups
// (where the file system allows), so a rename that fails (a rare event: the temporaries are
// complete and in their targets' folders) puts the files renamed before it back as they were.
void commit(std::vector<StagedFile>& staged) {
  for (StagedFile& s : staged) {
    struct stat st {};
    if (::lstat(s.target.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
    const int fd = create_temporary(folder_of(s.target), s.backup);
    if (fd < 0) {
      s.backup.clear();
      continue;
    }
    ::close(fd);
    ::unlink(s.backup.c_str());
    if (::link(s.target.c_str(), s.backup.c_str()) != 0) s.backup.clear();
  }
  for (std::size_t i = 0; i < staged.size(); ++i) {
    if (std::rename(staged[i].temporary.c_str(), staged[i].target.c_str()) == 0) {
      staged[i].renamed = true;
      continue;
    }
    const int error = errno;
    for (std::size_t j = 0; j < i; ++j) {
      if (!staged[j].backup.empty()) {
        if (std::rename(staged[j].backup.c_str(), staged[j].target.c_str()) == 0)
          staged[j].backup.clear();
      } else {
        ::unlink(staged[j].target.c_str());
      }
    }
    discard(staged);
    throw_errno(staged[i].path, "cannot rename into place", error);
  }
  discard(staged);  // the backups
}

void append_to_string(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<std::size_t>(size));
}

// The bytes that name a file in `folder` may have (255 on the usual file systems).
std::size_t name_max_bytes(const fs::path& folder) {
  const long limit = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  return limit > 0 ? static_cast<std::size_t>(limit) : 255;
}

// Device and inode of an existing file (symlinks followed), so hard links and symlinks match.
bool file_identity(const std::string& path, std::string& identity) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return false;
  identity = "inode " + std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
  return true;
}

// The identity of "-" for the same-file check: the file or pipe standard output is, so that
// `--out /dev/stdout --stats -` (one stream, a PNG and a JSON run together) and `--out - >>
// scene.json` (the scene appended to) are caught like any other spelling. A terminal or other
// character device stays "-": two outputs to /dev/null or a terminal harm nothing.
std::string standard_output_identity() {
  struct stat st {};
  if (::fstat(STDOUT_FILENO, &st) != 0 || S_ISCHR(st.st_mode)) return kStandardOutputName;
  return "inode " + std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
}

// The identity of an output for the same-file check: its file's, or for a new name the absolute
// path with symlinks and ".." resolved.
std::string output_identity(const std::string& path) {
  std::string identity;
  if (file_identity(path, identity)) return identity;
  std::error_code ec;
  const fs::path target = output_target(path);
  const fs::path resolved = fs::weakly_canonical(fs::absolute(target, ec), ec);
  return "path " + (ec ? target.string() : resolved.string());
}

void check_output_path(const OutputPath& output, const std::set<std::string>& inputs,
                       std::set<std::string>& seen) {
  const std::string& path = output.path;
  const std::string& flag = output.flag;
  if (path.empty()) throw UsageError(flag + ": needs a file name, got ''");
  if (path == kStandardOutputName) {
    const std::string identity = standard_output_identity();
    if (inputs.count(identity) != 0) {
      throw UsageError(flag + ": standard output is a file this command reads (an input), got '-'");
    }
    if (!seen.insert(identity).second)
      throw UsageError(flag + ": standard output is written by another output too, got '-'");
    return;
  }
  if (is_symlink_loop(path)) throw UsageError(flag + ": is a symlink loop, got '" + path + "'");
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw UsageError(flag + ": is a folder, got '" + path + "'");
  if (is_block_device(path)) {
    throw UsageError(flag + ": is a block device (a disk or partition), never written, got '" +
                     path + "'");
  }
  if (is_unwritten_character_device(path)) {
    throw UsageError(flag +
                     ": is a device levrt does not write (it writes /dev/null, /dev/zero, "
                     "/dev/full and terminals in place), got '" +
                     path + "'");
  }
  struct stat socket_status {};
  if (::stat(path.c_str(), &socket_status) == 0 && S_ISSOCK(socket_status.st_mode)) {
    // open() refuses a socket (ENXIO): it could only fail after the work.
    throw UsageError(flag + ": is a socket, which cannot be opened as a file, got '" + path + "'");
  }
  const std::string identity = output_identity(path);
  if (inputs.count(identity) != 0) {
    throw UsageError(flag + ": names a file this command reads (an input), got '" + path + "'");
  }
  if (is_existing_special_file(path)) {
    // A pipe or device is written in place: it needs no folder, extension or rename.
    if (::access(path.c_str(), W_OK) != 0)
      throw UsageError(flag + ": is not writable, got '" + path + "'");
  } else {
    if (!has_extension(path, output.extension)) {
      std::string names = output.extension;
      for (std::size_t bar = names.find('|'); bar != std::string::npos; bar = names.find('|'))
        names.replace(bar, 1, " or ");
      throw UsageError(flag + ": must end in " + names + " (" + output.format + "), got '" + path +
                       "'");
    }
    // A symlink is followed: the rename happens in its target's folder.
    const fs::path target = output_target(path);
    const fs::path parent = folder_of(target);
    if (!fs::is_directory(parent, ec))
      throw UsageError(flag + ": folder does not exist, got '" + path + "'");
    if (const char* kernel = kernel_file_system(parent.string())) {
      throw UsageError(flag + ": folder is on " + kernel +
                       ", a kernel file system that takes no new file, got '" + path + "'");
    }
    if (::access(parent.c_str(), W_OK) != 0)
      throw UsageError(flag + ": folder is not writable, got '" + path + "'");
    // An existing file the user may not write (read-only, or immutable even for root) is not
    // replaced by the rename either: refused here, before any work.
    struct stat existing {};
    if (::stat(target.c_str(), &existing) == 0 && ::access(target.c_str(), W_OK) != 0)
      throw UsageError(flag + ": is not writable, got '" + path + "'");
    const std::size_t name_bytes = target.filename().string().size();
    if (name_bytes > name_max_bytes(parent)) {
      throw UsageError(flag + ": file name of " + std::to_string(name_bytes) +
                       " bytes, more than the " + std::to_string(name_max_bytes(parent)) +
                       " its folder allows, got '" + path + "'");
    }
  }
  if (!seen.insert(identity).second) {
    throw UsageError(flag + ": names a file another output also writes, got '" + path + "'");
  }
}

}  // namespace

fs::path output_target(const std::string& path) {
  fs::path target(path);
  // The kernel's own bound on a chain of links (MAXSYMLINKS); a longer chain or a loop is
  // refused by check_output_paths and write_output_files.
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

void check_output_paths(const std::vector<OutputPath>& outputs,
                        const std::vector<std::string>& inputs) {
  std::set<std::string> input_identities;
  for (const std::string& input : inputs) {
    std::string identity;
    if (file_identity(input, identity)) input_identities.insert(identity);
  }
  std::set<std::string> seen;
  for (const OutputPath& output : outputs) {
    if (!output.path.empty()) check_output_path(output, input_identities, seen);
  }
}

void write_output_files(const std::vector<OutputFile>& files) {
  // Pipes, devices and standard output are written after every temporary is complete (a full
  // disk stops the command before anything reached them), then the temporaries are renamed.
  std::vector<std::pair<std::string, std::string>> in_place;
  std::vector<StagedFile> staged;
  const OutputWriteScope writing;  // a watchdog (app/interrupt.h) waits for these files
  const TerminationSignalsBlocked blocked;
  try {
    for (const OutputFile& file : files) {
      std::string bytes = file.bytes();
      if (file.path != kStandardOutputName && is_symlink_loop(file.path)) {
        throw std::runtime_error(file.path + ": cannot write (is a symlink loop)");
      }
      if (file.path != kStandardOutputName && is_block_device(file.path))
        refuse_block_device(file.path);
      if (file.path != kStandardOutputName && is_unwritten_character_device(file.path))
        refuse_character_device(file.path);
      if (file.path == kStandardOutputName || is_existing_special_file(file.path)) {
        in_place.emplace_back(file.path, std::move(bytes));
      } else {
        staged.push_back(stage(file.path, bytes));
      }
    }
    for (const auto& [path, bytes] : in_place) {
      if (path == kStandardOutputName) {
        write_to_standard_output(bytes);
      } else {
        write_in_place(path, bytes);
      }
    }
    commit(staged);
  } catch (...) {
    discard(staged);
    throw;
  }
}

bool is_exr_path(const std::string& path) {
  return fs::path(path).extension() == ".exr";
}

std::string png_rgb8_bytes(int width, int height, const std::vector<std::uint8_t>& rgb) {
  if (width <= 0 || height <= 0 ||
      rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3) {
    throw std::invalid_argument("image size does not match its pixels");
  }
  std::string png;
  if (!stbi_write_png_to_func(append_to_string, &png, width, height, 3, rgb.data(), width * 3)) {
    throw std::runtime_error("PNG encoding failed");
  }
  return png;
}

void write_png_rgb8(const std::string& path, int width, int height,
                    const std::vector<std::uint8_t>& rgb) {
  try {
    const std::string png = png_rgb8_bytes(width, height, rgb);
    write_output_files({{path, [&png] { return png; }}});
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(path + ": " + e.what());
  }
}

void write_text_file(const std::string& path, const std::string& text) {
  write_output_files({{path, [&text] { return text; }}});
}

void publish_staging_folder(const std::string& staging, const std::string& destination) {
  // Each staged file is copied to its destination through write_output_files, so the results obey
  // the outputs' rule too: all or none, symlinks followed, a pipe or device written in place.
  std::vector<OutputFile> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(staging)) {
    const std::string source = entry.path().string();
    files.push_back({(fs::path(destination) / entry.path().filename()).string(), [source] {
                       std::ifstream in(source, std::ios::binary);
                       std::ostringstream bytes;
                       bytes << in.rdbuf();
                       if (!in && !in.eof()) throw std::runtime_error(source + ": cannot read");
                       return bytes.str();
                     }});
  }
  write_output_files(files);
  std::error_code ec;
  fs::remove_all(staging, ec);
}

void discard_staging_folder(const std::string& staging) noexcept {
  std::error_code ec;
  fs::remove_all(staging, ec);
}

}  // namespace app
