#include "app/camera_flags.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/settings.h"
#include "renderer/denormal_mode.h"
#include "scenes/scene_validation.h"

namespace app {
namespace {

std::string float_text(float v) {
  // %.9g is the shortest notation that always reads back as the same float.
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(v));
  return text;
}

// A number in the settings' grammar (is_decimal_real), read as the nearest float.
bool parse_float(const std::string& text, float& value) {
  if (!is_decimal_real(text)) return false;
  char* end = nullptr;
  errno = 0;
  const float v = std::strtof(text.c_str(), &end);
  // ERANGE also flags a subnormal, which is a float like any other (Copy camera may print one).
  if (*end != '\0' || !std::isfinite(v) || (errno == ERANGE && v == 0.0f)) return false;
  value = v;
  return true;
}

// The magnitude a camera's position, target and orthographic half height may have: a scene's
// (scenes::kMaxCoordinate). Rays start there, and Embree refuses (asserts on) ray origins past
// about 1.8e18; the up direction is only normalized, so it has no such bound.
constexpr float kMaxCameraCoordinate = scenes::kMaxCoordinate;

bool within_camera_bound(const glm::vec3& v) {
  return std::abs(v.x) <= kMaxCameraCoordinate && std::abs(v.y) <= kMaxCameraCoordinate &&
         std::abs(v.z) <= kMaxCameraCoordinate;
}

std::string bound_text() {
  return float_text(kMaxCameraCoordinate);
}

// X,Y,Z; a point (bounded) has each magnitude at most kMaxCameraCoordinate.
glm::vec3 parse_vec3(const std::string& flag, const std::string& text, bool bounded) {
  const std::string what =
      bounded
          ? "must be X,Y,Z (three finite decimal numbers of magnitude at most " + bound_text() + ")"
          : "must be X,Y,Z (three finite decimal numbers)";
  glm::vec3 v(0.0f);
  std::size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = text.find(',', start);
    const bool last = i == 2;
    if (last != (comma == std::string::npos) ||
        !parse_float(text.substr(start, last ? std::string::npos : comma - start), v[i])) {
      throw UsageError(flag + ": " + what + ", got '" + text + "'");
    }
    start = comma + 1;
  }
  if (bounded && !within_camera_bound(v))
    throw UsageError(flag + ": " + what + ", got '" + text + "'");
  return v;
}

float parse_fov(const std::string& flag, const std::string& text) {
  float fov = 0.0f;
  if (!parse_float(text, fov) || !(fov > 0.0f && fov < 180.0f))
    throw UsageError(flag + ": must be a decimal number of degrees in (0, 180), got '" + text +
                     "'");
  return fov;
}

// The "camera" object of a stats JSON levrt wrote.
CameraFlags read_camera_file(const std::string& path) {
  const std::string flag = "--camera-from";
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw UsageError(flag + ": cannot read '" + path + "'");
  if (!fs::is_regular_file(status))
    throw UsageError(flag + ": is not a regular file, got '" + path + "'");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec || size > kMaxCameraFileBytes)
    throw UsageError(flag + ": a stats file is at most 1 MiB, got '" + path + "' of " +
                     std::to_string(size) + " bytes");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw UsageError(flag + ": cannot read '" + path + "'");
  const nlohmann::json doc = nlohmann::json::parse(text.str(), nullptr, false);
  if (doc.is_discarded()) throw UsageError(flag + ": " + path + ": not JSON");
  if (!doc.is_object() || !doc.contains("camera") || !doc["camera"].is_object())
    throw UsageError(flag + ": " + path +
                     ": no \"camera\" object (a stats file levrt wrote has one)");
  const nlohmann::json& camera = doc["camera"];
  const auto vec = [&](const char* name, bool bounded) {
    const nlohmann::json* v = camera.contains(name) ? &camera[name] : nullptr;
    if (!v || !v->is_array() || v->size() != 3 || !(*v)[0].is_number() || !(*v)[1].is_number() ||
        !(*v)[2].is_number())
      throw UsageError(flag + ": " + path + ": camera." + name + ": must be 3 numbers");
    const glm::vec3 out((*v)[0].get<float>(), (*v)[1].get<float>(), (*v)[2].get<float>());
    if (!std::isfinite(out.x) || !std::isfinite(out.y) || !std::isfinite(out.z))
      throw UsageError(flag + ": " + path + ": camera." + name + ": must be finite");
    if (bounded && !within_camera_bound(out))
      throw UsageError(flag + ": " + path + ": camera." + name + ": magnitude above " +
                       bound_text());
    return out;
  };
  CameraFlags flags;
  flags.position = vec("position", true);
  flags.target = vec("target", true);
  flags.up = vec("up", false);
  if (!camera.contains("vertical_fov_deg") || !camera["vertical_fov_deg"].is_number())
    throw UsageError(flag + ": " + path + ": camera.vertical_fov_deg: must be a number");
  const float fov = camera["vertical_fov_deg"].get<float>();
  if (!(fov > 0.0f && fov < 180.0f))
    throw UsageError(flag + ": " + path + ": camera.vertical_fov_deg: must be in (0, 180)");
  flags.vertical_fov_deg = fov;
  // Older stats files have no such member: a perspective camera.
  flags.orthographic_half_height = 0.0f;
  if (camera.contains("orthographic_half_height")) {
    const nlohmann::json& h = camera["orthographic_half_height"];
    if (!h.is_number() || !std::isfinite(h.get<float>()) || !(h.get<float>() >= 0.0f) ||
        h.get<float>() > kMaxCameraCoordinate)
      throw UsageError(flag + ": " + path +
                       ": camera.orthographic_half_height: must be a number in [0, " +
                       bound_text() + "]");
    flags.orthographic_half_height = h.get<float>();
  }
  return flags;
}

std::string vec3_text(const glm::vec3& v) {
  return float_text(v.x) + "," + float_text(v.y) + "," + float_text(v.z);
}

}  // namespace

CameraFlags parse_camera_flags(const CameraFlagTexts& texts) {
  CameraFlags flags;
  if (!texts.from_file.empty()) {
    flags = read_camera_file(texts.from_file);
    flags.from_file = texts.from_file;
  }
  if (!texts.position.empty())
    flags.position = parse_vec3("--camera-position", texts.position, true);
  if (!texts.target.empty()) flags.target = parse_vec3("--camera-target", texts.target, true);
  if (!texts.up.empty()) flags.up = parse_vec3("--camera-up", texts.up, false);
  if (!texts.fov_deg.empty() && !texts.ortho_half_height.empty())
    throw UsageError(
        "--ortho-half-height: give --fov (perspective) or --ortho-half-height "
        "(orthographic), not both");
  if (!texts.fov_deg.empty()) {
    flags.vertical_fov_deg = parse_fov("--fov", texts.fov_deg);
    flags.orthographic_half_height = 0.0f;
  }
  if (!texts.ortho_half_height.empty()) {
    float h = 0.0f;
    if (!parse_float(texts.ortho_half_height, h) || !(h > 0.0f) || h > kMaxCameraCoordinate)
      throw UsageError("--ortho-half-height: must be a positive number of scene units, at most " +
                       bound_text() + ", got '" + texts.ortho_half_height + "'");
    flags.orthographic_half_height = h;
  }
  return flags;
}

renderer::Camera apply_camera_flags(const renderer::Camera& preset, const CameraFlags& flags,
                                    const glm::vec3& world_origin) {
  renderer::Camera camera = preset;
  if (flags.position) camera.position = *flags.position - world_origin;
  if (flags.target) camera.target = *flags.target - world_origin;
  if (flags.up) camera.up = *flags.up;
  if (flags.vertical_fov_deg) camera.vertical_fov_deg = *flags.vertical_fov_deg;
  if (flags.orthographic_half_height)
    camera.orthographic_half_height = *flags.orthographic_half_height;
  if (flags.empty()) return camera;
  // The frame as the render threads compute it, in their float mode (denormals flushed to zero),
  // as the scene check does (scenes/scene_validation.cpp): an up of 1e-38, or a target 1e-38
  // from the position, has a frame here but none there (a background-only image in a release
  // build, the assertion on castable rays in a checked one).
  renderer::CameraBasis basis;
  {
    const renderer::DenormalModeGuard render_float_mode;
    basis = renderer::camera_basis(camera);
  }
  if (basis.forward == glm::vec3(0.0f)) {
    // Named by what gave the camera: a stats file's camera may have no view of its own; else the
    // flag given that moved it (an up alone, along the preset's view; a position alone, at the
    // preset's target), the target when both ends were given.
    std::string source = "--camera-from: " + flags.from_file;
    if (flags.from_file.empty()) {
      if (flags.target) {
        source = "--camera-target";
      } else if (flags.position) {
        source = "--camera-position";
      } else {
        source = "--camera-up";
      }
    }
    throw UsageError(source + ": the camera at " + vec3_text(camera.position + world_origin) +
                     " looking at " + vec3_text(camera.target + world_origin) + " with up " +
                     vec3_text(camera.up) +
                     " has no view (target at the position, or up along the view)");
  }
  return camera;
}

renderer::Camera world_camera(const renderer::Camera& render_space, const glm::vec3& world_origin) {
  renderer::Camera camera = render_space;
  camera.position += world_origin;
  camera.target += world_origin;
  return camera;
}

std::string camera_flags_text(const renderer::Camera& camera) {
  return "--camera-position " + vec3_text(camera.position) + " --camera-target " +
         vec3_text(camera.target) + " --camera-up " + vec3_text(camera.up) +
         (camera.orthographic()
              ? " --ortho-half-height " + float_text(camera.orthographic_half_height)
              : " --fov " + float_text(camera.vertical_fov_deg));
}

}  // namespace app
