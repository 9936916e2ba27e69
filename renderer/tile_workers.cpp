#include "renderer/tile_workers.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include <tbb/info.h>

namespace renderer {

int worker_count(int threads) {
  // oneTBB's count honours the process's affinity mask and cgroup quota, which
  // std::thread::hardware_concurrency does not.
  return threads > 0 ? threads : std::max(1, tbb::info::default_concurrency());
}

void run_tile_workers(int workers, int item_count,
                      const std::function<bool(int worker, int item)>& body) {
  if (item_count <= 0) return;
  workers = std::clamp(workers, 1, item_count);
  std::atomic<int> next_item{0};
  std::atomic<bool> stop{false};
  std::mutex error_mutex;
  std::exception_ptr error;
  const auto work = [&](int worker) {
    while (!stop.load(std::memory_order_relaxed)) {
      const int item = next_item.fetch_add(1, std::memory_order_relaxed);
      if (item >= item_count) break;
      try {
        if (!body(worker, item)) stop.store(true, std::memory_order_relaxed);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        stop.store(true, std::memory_order_relaxed);
      }
    }
  };
  std::vector<std::thread> threads;
  threads.reserve(static_cast<std::size_t>(workers - 1));
  try {
    for (int w = 1; w < workers; ++w) threads.emplace_back(work, w);
  } catch (...) {
    // No thread to be had (resource limits): the threads already started and this one finish
    // the items; the pass is slower, never wrong.
  }
  work(0);
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace renderer
