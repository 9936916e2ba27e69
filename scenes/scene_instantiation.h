// From a scene description to a renderable scene (thesis 4.3, preprocessing). The lights become a
// lev::LightTree that keeps the description's masters as masters, so the hierarchy grows with the
// number of distinct masters, not of lights (thesis 3.5.3); a union holding many bare lights gets
// the automatic hierarchy (lev::build_light_bvh). The geometry becomes Embree prototypes placed by
// single-level instances, because Embree 3 has one instance level: a master whose expanded
// geometry is small is baked whole into one prototype, a larger one is flattened into the
// placements of its parts. Built-in models and scene files take this same path, so a file
// exported from a model renders the same image and builds the same hierarchy.
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "renderer/scene.h"
#include "scenes/scene_description.h"

namespace scenes {

// Limits that keep a description (in practice, a scene file) from exhausting memory, time or the
// stack. Each breach is reported with its own message.
inline constexpr std::size_t kMaxSceneNodes = std::size_t{1} << 22;
inline constexpr int kMaxNodeDepth = 100;        // nodes nested inside one master or the root
inline constexpr int kMaxInstanceDepth = 64;     // masters instancing masters
inline constexpr std::size_t kMaxMasters = 65536;
inline constexpr std::size_t kMaxMaterials = 65536;
inline constexpr std::uint64_t kMaxSceneLights = std::uint64_t{1} << 24;
inline constexpr std::uint64_t kMaxScenePlacements = std::uint64_t{1} << 22;  // Embree instances
inline constexpr std::uint64_t kMaxPrototypeTriangles = std::uint64_t{1} << 25;
inline constexpr float kMaxCoordinate = 1e6f;     // any position, length or radius
inline constexpr float kMinScale = 1e-6f;         // one affine node's scale
inline constexpr float kMaxScale = 1e6f;
inline constexpr double kMaxComposedScaleLog10 = 12.0;  // scales multiplied along any path
inline constexpr float kMaxIntensity = 1e12f;
inline constexpr int kMaxCylinderSegments = 1024;

// A master whose geometry, nested instances expanded, has at most this many triangles is baked
// into one prototype: fewer Embree instances trace faster, and the copies stay small.
inline constexpr std::uint64_t kBakeTriangleBudget = 16384;
// A union with more bare lights than this (a light under nothing but affine nodes) replaces them
// with an automatic hierarchy: a flat list has no volumes to cull with.
inline constexpr std::size_t kMaxUnstructuredLights = 8;

// Throws std::invalid_argument "/json/path: problem (value)" for the first problem found: values
// out of range, wrong child counts, undefined masters or materials, instance cycles, limits.
// The path is where a scene file (scene_file.h) holds the offending value.
void validate_description(const SceneDescription& scene);

// Render space. Floats near 1e6 are 0.0625 apart, and ray offsets grow with the coordinates, so a
// scene traced where it stands near 1e6 gets coarse hit points and shadow rays that start past
// the occluders (light leaks) or inside the surface (acne). A far scene is therefore
// instantiated moved by -origin, origin being the camera position rounded to whole units:
// geometry, lights, light hierarchy and camera alike, so every ray, hit and hierarchy query is
// computed near the origin. Moving is a subtraction of floats of like magnitude (exact).
// Far means: the camera is at least kRenderSpaceRebaseDistance from the world origin and more
// than kRenderSpaceRebaseRatio times farther from it than from its target (the size of what is
// in view). Moving gains little otherwise, and an instance moved gets a transform node of its
// own; so nearer scenes, and scenes that merely extend far from the origin such as the largest
// buildings, stay where they are (origin 0) and render exactly as before.
// renderer::Scene::world_origin records the origin.
inline constexpr float kRenderSpaceRebaseDistance = 4096.0f;
inline constexpr float kRenderSpaceRebaseRatio = 16.0f;
glm::vec3 render_space_origin(const renderer::Camera& camera);

// Validates, then builds the light hierarchy (its structure: each render fits the extent volumes
// for its own tolerance) and the geometry, in render space.
renderer::Scene instantiate_scene(const SceneDescription& scene);

}  // namespace scenes
