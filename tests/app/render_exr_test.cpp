// `levrt render --out FILE.exr`: the scene-linear radiance as float, before the exposure, and the
// per-pixel counters and errors as further channels; the extension picks the format.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/render_command.h"
#include "app/scene_loading.h"
#include "tests/support/exr_file.h"
#include "tests/support/folder_test.h"
#include "tests/support/read_file.h"
#include "tests/support/run_command.h"

namespace {
namespace fs = std::filesystem;
using levrt_test::CommandRun;
using levrt_test::read_file;
using levrt_test::run_levrt;

class RenderExr : public levrt_test::FolderTest {};

TEST_F(RenderExr, WritesTheLinearRadianceAndEveryChannel) {
  const std::string exr = path("image.exr"), reference = path("rt.exr");
  const CommandRun r = run_levrt({"render", "--width", "24", "--height", "16", "--exposure", "3",
                                  "--display", "neutral", "--out", exr, "--reference", "rt",
                                  "--reference-out", reference, "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const levrt_test::ExrFile file = levrt_test::read_exr(read_file(exr));
  ASSERT_EQ(file.width, 24);
  ASSERT_EQ(file.height, 16);
  for (const char* name : {"R", "G", "B", "samples", "lights_tested", "nodes_visited",
                           "error_bound_pct", "noise_pct", "error_pct"})
    EXPECT_EQ(file.channels.count(name), 1u) << name;
  // The same render in process: the channels hold its mean radiance, unexposed.
  app::Settings settings;
  settings.image.width = 24;
  settings.image.height = 16;
  settings.display.exposure_ev = 3.0;
  const std::unique_ptr<app::LoadedScene> loaded = app::load_scene(settings.scene);
  const renderer::RenderResult result =
      app::render_image(*loaded, settings, settings.method.method);
  const renderer::Framebuffer& fb = result.framebuffer;
  float brightest = 0.0f;
  for (std::size_t i = 0; i < fb.samples.size(); ++i) {
    const glm::vec3 mean = fb.radiance_sum[i] / static_cast<float>(fb.samples[i]);
    EXPECT_EQ(file.channels.at("R")[i], mean.x) << i;
    EXPECT_EQ(file.channels.at("G")[i], mean.y) << i;
    EXPECT_EQ(file.channels.at("B")[i], mean.z) << i;
    EXPECT_EQ(file.channels.at("lights_tested")[i],
              static_cast<float>(static_cast<double>(fb.lights_tested[i]) / fb.samples[i]));
    brightest = std::max(brightest, mean.x);
  }
  EXPECT_GT(brightest, 0.0f);
  const levrt_test::ExrFile rt = levrt_test::read_exr(read_file(reference));
  EXPECT_EQ(rt.width, 24);
  EXPECT_EQ(rt.channels.count("R"), 1u);
}

TEST_F(RenderExr, AnImageExtensionOtherThanPngOrExrIsOneLineExitTwo) {
  for (const std::string name : {"image.jpg", "image.EXR", "image", "image.exr.txt", "image.hdr"}) {
    const std::string out = path(name);
    const CommandRun r = run_levrt({"render", "--width", "8", "--height", "8", "--out", out});
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.output;
    EXPECT_NE(r.output.find("--out"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(".png or .exr"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_TRUE(fs::is_empty(dir_)) << name;
  }
}

// All or none: with a PNG output that cannot be written, the EXR is not written either.
TEST_F(RenderExr, AllOrNoneWithTheOtherOutputs) {
  const std::string exr = path("image.exr");
  const CommandRun r = run_levrt({"render", "--width", "8", "--height", "8", "--out", exr,
                                  "--heatmap-lights", path("missing/heat.png")});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_FALSE(fs::exists(exr));
}

}  // namespace
