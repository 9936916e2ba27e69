#include "renderer/ray_log.h"

#include <chrono>
#include <limits>

#include "renderer/denormal_mode.h"
#include "renderer/tile_workers.h"

namespace renderer {

RayLogTotals count_logged_rays(const RayLog& log) {
  RayLogTotals t;
  for (const std::vector<LoggedRay>& tile : log.tiles) {
    for (const LoggedRay& r : tile) {
      if (r.kind == RayKind::shadow) {
        ++t.shadow;
      } else {
        ++t.closest_hit;
      }
    }
  }
  return t;
}

BareCastResult cast_logged_rays(const RayScene& rays, const RayLog& log, int threads) {
  struct TileCount {
    std::uint64_t hits = 0, occluded = 0;
  };
  std::vector<TileCount> counts(log.tiles.size());
  const auto start = std::chrono::steady_clock::now();
  run_tile_workers(worker_count(threads), static_cast<int>(log.tiles.size()), [&](int, int tile) {
    const DenormalModeGuard denormals;
    TileCount& c = counts[static_cast<std::size_t>(tile)];
    for (const LoggedRay& r : log.tiles[static_cast<std::size_t>(tile)]) {
      if (r.kind == RayKind::shadow) {
        c.occluded += rays.occluded(r.origin, r.direction, r.max_distance) ? 1 : 0;
      } else {
        c.hits += rays.closest_distance(Ray{r.origin, r.direction}) <
                          std::numeric_limits<float>::infinity()
                      ? 1
                      : 0;
      }
    }
    return true;
  });
  BareCastResult result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const TileCount& c : counts) {
    result.hits += c.hits;
    result.occluded += c.occluded;
  }
  return result;
}

}  // namespace renderer
