#include "app/viewer/snapshot_writer.h"

#include <exception>
#include <filesystem>
#include <utility>

#include "app/output_files.h"

namespace app::viewer {
namespace {
constexpr int kSteps = 3;
}

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

void SnapshotWriter::wait() {
  if (thread_.joinable()) thread_.join();
}

void SnapshotWriter::run(const SnapshotJob& job) {
  std::string message;
  try {
    std::filesystem::create_directories(job.folder);
    const std::filesystem::path stem = std::filesystem::path(job.folder) / job.base;
    const std::string image = stem.string() + ".png";
    const std::string heatmap = stem.string() + "_" + job.heatmap_name + ".png";
    const std::string stats = stem.string() + "_stats.json";
    app::write_png_rgb8(image, job.width, job.height, job.image_rgb);
    steps_done_.store(1);
    app::write_png_rgb8(heatmap, job.width, job.height, job.heatmap_rgb);
    steps_done_.store(2);
    app::write_text_file(stats, job.stats_json);
    steps_done_.store(3);
    message = "wrote " + image + ", " + heatmap + ", " + stats;
  } catch (const std::exception& e) {
    message = std::string("snapshot failed: ") + e.what();
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    message_ = message;
  }
  busy_.store(false);
}

}  // namespace app::viewer
