// Saving a snapshot from the panel: the image, the current heatmap, the stats JSON and the EXR of
// the radiance with its per-pixel channels, written on
// a thread of its own (PNG encoding of a large image takes a while) with a progress fraction the
// panel shows. The job carries copies of the pixels, so the UI keeps drawing meanwhile. The four
// files obey the outputs' rule (app/output_files.h): checked against the viewer's inputs and its
// other outputs, then written all or none. A snapshot never replaces a file: a name taken
// already gets _2, _3, ... (SnapshotWriter::message names the files written).
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "app/exr_encoding.h"
#include "app/output_files.h"

namespace app::viewer {

struct SnapshotJob {
  std::string folder = "out";
  std::string base;  // file name stem
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> image_rgb;
  std::string heatmap_name;  // file name suffix (view name)
  std::vector<std::uint8_t> heatmap_rgb;
  std::string stats_json;
  // The EXR beside the PNGs (app/exr_encoding.h): the scene-linear radiance and the per-pixel
  // channels, as `levrt render --out FILE.exr` writes them.
  std::vector<ExrChannel> exr_channels;
  std::vector<std::string> inputs;        // the files the viewer reads (scene, script)
  std::vector<OutputPath> other_outputs;  // the viewer's other outputs (screenshot, controls)
};

class SnapshotWriter {
 public:
  SnapshotWriter() = default;
  ~SnapshotWriter();  // waits for the files in progress
  SnapshotWriter(const SnapshotWriter&) = delete;
  SnapshotWriter& operator=(const SnapshotWriter&) = delete;

  // Starts writing; false (and nothing happens) while a previous job still runs.
  bool start(SnapshotJob job);
  bool busy() const { return busy_.load(); }
  float progress() const;
  // The last job's outcome: the files written, or the error (then failed() is true).
  std::string message() const;
  bool failed() const;
  // Waits for the job in progress (scripted mode, exit).
  void wait();

 private:
  void run(const SnapshotJob& job);

  std::thread thread_;
  std::atomic<bool> busy_{false};
  std::atomic<int> steps_done_{0};
  mutable std::mutex mutex_;
  std::string message_;
  bool failed_ = false;
};

}  // namespace app::viewer
