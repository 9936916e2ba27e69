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
  const bool folder_existed = fs::exists(job.folder, ec);
  try {
    const fs::path stem = fs::path(job.folder) / job.base;
    const std::string image = stem.string() + ".png";
    const std::string heatmap = stem.string() + "_" + job.heatmap_name + ".png";
    const std::string stats = stem.string() + "_stats.json";
    const std::string exr = stem.string() + ".exr";
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
    if (!folder_existed) fs::remove(job.folder, ec);  // only if empty
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
