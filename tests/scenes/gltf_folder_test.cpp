// The glTF's folder is the scene's boundary (scenes/scene_folder.h): buffer and image URIs that
// lead out of it (`..`, percent-encoded or not, a symlink, an absolute path, file://) are
// refused without the outside file's size or content in the message; a FIFO, device or folder is
// refused before any open, so nothing blocks; files inside the folder, in subfolders and with
// escaped names, still read.

#include <sys/stat.h>

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scenes/scene_file.h"
#include "scenes/scene_folder.h"
#include "tests/support/gltf_files.h"
#include "tests/support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using levrt_test::expect_load_refused;
using levrt_test::gltf_document;
using levrt_test::triangle_buffers;
using levrt_test::write_file;

// The triangle's 36 bytes as a file.
std::string triangle_bytes() {
  const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  return std::string(reinterpret_cast<const char*>(xyz), sizeof xyz);
}

// The scene lives in <temp>/scene/; a secret sits beside that folder, outside it.
class GltfFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directory(scene_);
    write_file(dir_.path() / "secret.bin", triangle_bytes() + "0123456789");  // 46 bytes
  }
  fs::path file(const std::string& name) const { return scene_ / name; }
  // A scene drawing the triangle from the buffer at `uri`.
  fs::path scene_with_buffer(const std::string& uri) const {
    const fs::path path = file("scene.gltf");
    write_file(path, gltf_document(triangle_buffers(uri, 36) + R"(, "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}])"));
    return path;
  }
  levrt_test::TempDir dir_{"levrt_gltf_folder_"};
  fs::path scene_ = dir_.path() / "scene";
};

// Not the outside file's size (46) nor its content, in what the message adds to the names.
void expect_reveals_nothing(std::string message, const fs::path& temp) {
  for (std::size_t at; (at = message.find(temp.string())) != std::string::npos;)
    message.erase(at, temp.string().size());
  EXPECT_EQ(message.find("46"), std::string::npos) << message;
  EXPECT_EQ(message.find("0123456789"), std::string::npos) << message;
}

TEST_F(GltfFolder, UrisLeadingOutOfTheFolderAreRefused) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"../secret.bin", "leads outside the scene's folder"},
      {"%2e%2e/secret.bin", "leads outside the scene's folder"},
      {"%2E%2E%2Fsecret.bin", "leads outside the scene's folder"},
      {"sub/../../secret.bin", "leads outside the scene's folder"},
      {(dir_.path() / "secret.bin").string(), "an absolute path"},
      {"%2F" + (dir_.path() / "secret.bin").string().substr(1), "an absolute path"},
      {"file://" + (dir_.path() / "secret.bin").string(), "a URI with a scheme ('file:')"},
      {"http://example.com/x.bin", "a URI with a scheme ('http:')"},
      {".", "names a folder, not a file"},
      {"%00secret.bin", "an escaped NUL byte"},
      {"%zz.bin", "a malformed percent escape"},
  };
  for (const auto& [uri, problem] : cases) {
    const std::string message =
        expect_load_refused(scene_with_buffer(uri), {"buffers[0].uri: '", problem});
    expect_reveals_nothing(message, dir_.path());
  }
}

TEST_F(GltfFolder, ASymlinkLeadingOutIsRefusedByItsCanonicalPath) {
  fs::create_symlink("../secret.bin", file("inside.bin"));
  expect_reveals_nothing(expect_load_refused(scene_with_buffer("inside.bin"),
                                             {"buffers[0].uri: 'inside.bin'", "through a symlink"}),
                         dir_.path());
  fs::create_directory_symlink(dir_.path(), file("up"));
  expect_reveals_nothing(
      expect_load_refused(scene_with_buffer("up/secret.bin"),
                          {"buffers[0].uri: 'up/secret.bin'", "through a symlink"}),
      dir_.path());
}

TEST_F(GltfFolder, AnImageUriLeadingOutIsRefusedToo) {
  write_file(dir_.path() / "outside.png", levrt_test::zero_png(4, 4));
  write_file(file("image.gltf"), gltf_document(triangle_buffers() + R"(,
      "images": [{"uri": "../outside.png"}], "textures": [{"source": 0}],
      "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
      "nodes": [{"mesh": 0}])"));
  expect_load_refused(file("image.gltf"),
                      {"images[0].uri: '../outside.png'", "leads outside the scene's folder"});
}

// A FIFO would block open() and read() forever; a device would be read without end.
TEST_F(GltfFolder, AFifoOrDeviceIsRefusedBeforeItIsOpened) {
  ASSERT_EQ(::mkfifo(file("pipe.bin").c_str(), 0600), 0);
  expect_load_refused(scene_with_buffer("pipe.bin"),
                      {"buffers[0].uri: 'pipe.bin'", "not a regular file"});
  fs::create_symlink("/dev/zero", file("zero.bin"));
  expect_load_refused(scene_with_buffer("zero.bin"), {"buffers[0].uri: 'zero.bin'"});
  // The scene file itself too.
  ASSERT_EQ(::mkfifo(file("fifo.gltf").c_str(), 0600), 0);
  expect_load_refused(file("fifo.gltf"), {"not a regular file"});
}

TEST_F(GltfFolder, FilesInsideTheFolderStillRead) {
  write_file(file("plain.bin"), triangle_bytes());
  EXPECT_EQ(scenes::load_scene_file(scene_with_buffer("plain.bin").string()).meshes.size(), 1u);
  fs::create_directory(file("sub dir"));
  write_file(file("sub dir") / "a b.bin", triangle_bytes());
  EXPECT_EQ(
      scenes::load_scene_file(scene_with_buffer("sub%20dir/a%20b.bin").string()).meshes.size(), 1u);
  EXPECT_EQ(
      scenes::load_scene_file(scene_with_buffer("./sub dir/../plain.bin").string()).meshes.size(),
      1u);
  fs::create_symlink("plain.bin", file("link.bin"));  // a symlink that stays inside
  EXPECT_EQ(scenes::load_scene_file(scene_with_buffer("link.bin").string()).meshes.size(), 1u);
}

TEST_F(GltfFolder, AMissingFileIsNamedWithoutItsSize) {
  expect_load_refused(scene_with_buffer("absent.bin"),
                      {"buffers[0].uri: 'absent.bin'", "no such file in the scene's folder"});
}

}  // namespace
