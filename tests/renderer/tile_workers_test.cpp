#include "renderer/tile_workers.h"

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace {

TEST(TileWorkers, EveryItemRunsOnceOnAWorkerInRange) {
  for (const int workers : {1, 2, 3, 8, 100}) {
    const int item_count = 37;
    std::vector<std::atomic<int>> runs(item_count);
    std::atomic<int> bad_worker{0};
    renderer::run_tile_workers(workers, item_count, [&](int worker, int item) {
      if (worker < 0 || worker >= std::min(workers, item_count)) bad_worker.fetch_add(1);
      runs[static_cast<std::size_t>(item)].fetch_add(1);
      return true;
    });
    for (int i = 0; i < item_count; ++i) EXPECT_EQ(runs[i].load(), 1) << workers << " " << i;
    EXPECT_EQ(bad_worker.load(), 0) << workers;
  }
}

TEST(TileWorkers, NoItemsRunNothingAndZeroWorkersStillRunsOnTheCaller) {
  int calls = 0;
  renderer::run_tile_workers(4, 0, [&](int, int) { return ++calls > 0; });
  EXPECT_EQ(calls, 0);
  renderer::run_tile_workers(0, 3, [&](int worker, int) { return (calls += worker == 0) > 0; });
  EXPECT_EQ(calls, 3);
}

TEST(TileWorkers, AFalseBodyStopsTheClaimingOfNewItems) {
  // One worker claims in order, so a stop at item 4 leaves 5 .. 99 unrun.
  std::vector<int> ran;
  renderer::run_tile_workers(1, 100, [&](int, int item) {
    ran.push_back(item);
    return item != 4;
  });
  EXPECT_EQ(ran, (std::vector<int>{0, 1, 2, 3, 4}));
  // With several workers each may finish the item it holds, never claim past the stop by more.
  std::atomic<int> count{0};
  renderer::run_tile_workers(4, 1000, [&](int, int item) {
    count.fetch_add(1);
    return item != 0;
  });
  EXPECT_LT(count.load(), 1000);
}

TEST(TileWorkers, AnExceptionIsRethrownAfterEveryThreadJoined) {
  std::atomic<int> running{0}, finished{0};
  EXPECT_THROW(
      renderer::run_tile_workers(3, 50,
                                 [&](int, int item) {
                                   running.fetch_add(1);
                                   if (item == 7) {
                                     running.fetch_sub(1);
                                     throw std::runtime_error("tile 7");
                                   }
                                   std::this_thread::sleep_for(std::chrono::milliseconds(2));
                                   finished.fetch_add(1);
                                   running.fetch_sub(1);
                                   return true;
                                 }),
      std::runtime_error);
  // Joined: no body is still running when the exception reaches the caller, and the claiming
  // stopped soon after item 7.
  EXPECT_EQ(running.load(), 0);
  EXPECT_LT(finished.load(), 49);
}

TEST(TileWorkers, TheCountOfASettingIsItselfOrTheCoresWhenZero) {
  EXPECT_EQ(renderer::worker_count(3), 3);
  EXPECT_GE(renderer::worker_count(0), 1);
}

}  // namespace
