#include "app/viewer/snapshot_writer.h"

#include <exception>
#include <filesystem>
#include <stdexcept>
#include <utility>
#include <vector>

#include "app/output_files.h"

namespace app::viewer {
namespace {
constexpr int kSteps = 3;

// The folders of `folder`'s path that do not exist yet, deepest first: those a snapshot makes,
// and removes again when it fails.
std::vector<std::filesystem::path> missing_folders(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path p = folder; !p.empty() && !fs::exists(fs::symlink_status(p, ec));
       p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  return missing;
}

}  // namespace

SnapshotWriter::~SnapshotWriter() {
  wait();
}

bool SnapshotWriter::start(SnapshotJob job) {
  if (busy_.load()) return false;
  if (thread_.joinable()) thread_.join();
  busy_.store(true);
  steps_done_.store(0);
  thread_ = std::thread([this, j = std::move(job)] { run(j); });
  return true;
}

float SnapshotWriter::progress() const {
  return static_cast<float>(steps_done_.load()) / kSteps;
}

std::string SnapshotWriter::message() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return message_;
}

bool SnapshotWriter::failed() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return failed_;
}

void SnapshotWriter::wait() {
  if (thread_.joinable()) thread_.join();
}

void SnapshotWriter::run(const SnapshotJob& job) {
  namespace fs = std::filesystem;
  std::string message;
  bool failed = false;
  std::error_code ec;
  const std::vector<fs::path> made = missing_folders(job.folder);
  try {
    // The panel's folder field, emptied: said so, not as filesystem_error's "Invalid argument []".
    if (job.folder.empty())
      throw std::invalid_argument("no folder given (the folder field is empty)");
    // The panel names a snapshot, not the user: one whose name is taken (an earlier snapshot of
    // the same method and tolerance, at another camera or relative error; any file) gets _2, _3,
    // ... instead of replacing it. A pipe or character device under the name is no file to keep:
    // it is written in place, as the outputs' rule says (a reader streaming the snapshot).
    const std::string first_stem = (fs::path(job.folder) / job.base).string();
    std::string stem = first_stem;
    const auto files_of = [&job](const std::string& s) {
      return std::vector<std::string>{s + ".png", s + "_" + job.heatmap_name + ".png",
                                      s + "_stats.json", s + ".exr"};
    };
    const auto taken = [&](const std::string& s) {
      for (const std::string& file : files_of(s)) {
        std::error_code status_error;
        if (!fs::exists(fs::symlink_status(file, status_error))) continue;
        const fs::file_status target = fs::status(file, status_error);
        if (!fs::is_fifo(target) && !fs::is_character_file(target)) return true;
      }
      return false;
    };
    for (int n = 2; taken(stem); ++n) stem = first_stem + "_" + std::to_string(n);
    const std::vector<std::string> names = files_of(stem);
    const std::string& image = names[0];
    const std::string& heatmap = names[1];
    const std::string& stats = names[2];
    const std::string& exr = names[3];
    std::vector<OutputPath> outputs = job.other_outputs;
    outputs.push_back({"snapshot", image, ".png", "PNG"});
    outputs.push_back({"snapshot", heatmap, ".png", "PNG"});
    outputs.push_back({"snapshot", stats, ".json", "JSON"});
    outputs.push_back({"snapshot", exr, ".exr", "EXR"});
    fs::create_directories(job.folder);
    app::check_output_paths(outputs, job.inputs);
    app::write_output_files(
        {{image,
          [&] {
            std::string png = app::png_rgb8_bytes(job.width, job.height, job.image_rgb);
            steps_done_.store(1);
            return png;
          }},
         {heatmap,
          [&] {
            std::string png = app::png_rgb8_bytes(job.width, job.height, job.heatmap_rgb);
            steps_done_.store(2);
            return png;
          }},
         {stats, [&] { return job.stats_json; }},
         {exr, [&] { return app::exr_bytes(job.width, job.height, job.exr_channels); }}});
    steps_done_.store(3);
    message = "wrote " + image + ", " + heatmap + ", " + stats + ", " + exr;
  } catch (const std::exception& e) {
    // Every folder made for it goes (each only if empty), not only the last of the path.
    for (const fs::path& folder : made) {
      if (fs::is_directory(fs::symlink_status(folder, ec))) fs::remove(folder, ec);
    }
    message = std::string("snapshot failed: ") + e.what();
    failed = true;
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    message_ = message;
    failed_ = failed;
  }
  busy_.store(false);
}

}  // namespace app::viewer
