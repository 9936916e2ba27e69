// The threads of one pass: a fork-join over numbered work items (a render's tiles, a ray log's
// tiles) on plain std::threads. Items are claimed in order from one atomic counter, so the load
// balances as work stealing would, and what an item computes never depends on which thread ran
// it. Plain threads rather than oneTBB's scheduler: ThreadSanitizer sees every edge of a
// std::thread (start and join), where Debian's uninstrumented libtbb hands task memory between
// threads unseen and makes TSan report races that are not there.
#pragma once

#include <functional>

namespace renderer {

// The threads a setting asks for: `threads` when positive, else the cores this process may use.
int worker_count(int threads);

// Runs body(worker, item) for items 0 .. item_count-1 on `workers` threads (the caller is worker
// 0; workers is clamped to [1, item_count]). A body returning false stops the claiming of new
// items on every thread (a cancel); items already running finish. The first exception a body
// throws stops the claiming too and is rethrown here after every thread has joined.
void run_tile_workers(int workers, int item_count,
                      const std::function<bool(int worker, int item)>& body);

}  // namespace renderer
