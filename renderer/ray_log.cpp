#include "renderer/ray_log.h"

#include <chrono>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "renderer/denormal_mode.h"
#include "renderer/thread_annotations.h"

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
  const auto arena = threads > 0 ? std::make_unique<tbb::task_arena>(threads)
                                 : std::make_unique<tbb::task_arena>();
  char start_edge = 0, end_edge = 0;  // happens-before edges for ThreadSanitizer only
  const auto start = std::chrono::steady_clock::now();
  annotate_release(&start_edge);
  arena->execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, log.tiles.size(), 1),
        [&](const tbb::blocked_range<std::size_t>& range) {
          annotate_acquire(&start_edge);
          for (std::size_t tile = range.begin(); tile != range.end(); ++tile) {
            const DenormalModeGuard denormals;
            TileCount& c = counts[tile];
            for (const LoggedRay& r : log.tiles[tile]) {
              if (r.kind == RayKind::shadow) {
                c.occluded += rays.occluded(r.origin, r.direction, r.max_distance) ? 1 : 0;
              } else {
                c.hits += rays.closest_distance(Ray{r.origin, r.direction}) <
                                  std::numeric_limits<float>::infinity()
                              ? 1
                              : 0;
              }
            }
          }
          annotate_release(&end_edge);
        },
        tbb::simple_partitioner());
  });
  annotate_acquire(&end_edge);
  BareCastResult result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const TileCount& c : counts) {
    result.hits += c.hits;
    result.occluded += c.occluded;
  }
  return result;
}

}  // namespace renderer
