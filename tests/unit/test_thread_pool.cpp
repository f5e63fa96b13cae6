// The thread pool: every index run once, slots distinct among the threads of a loop and below
// kMostThreads, and nested loops run on the pool's threads, never on new ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "atlas/chart_map/chart_threads.h"
#include "core/thread_pool.h"

namespace lowstretch {
namespace {

int pool_size() { return std::max(1, std::min<int>(int(std::thread::hardware_concurrency()), kMostThreads)); }

TEST(ThreadPool, RunsEveryIndexOnceInTheGivenOrder) {
  std::vector<std::atomic<int>> runs(1000);
  for (auto& r : runs) r = 0;
  for_each_index(1000, [&](int i, int) { ++runs[size_t(i)]; });
  for (const auto& r : runs) EXPECT_EQ(r.load(), 1);

  // With an order, the i-th index taken is order[i]: on one thread (a single index) exactly that.
  std::vector<int> seen;
  for_each_index(1, [&](int i, int slot) {
    seen.push_back(i);
    EXPECT_EQ(slot, 0);
  }, {7});
  EXPECT_EQ(seen, std::vector<int>{7});
  for_each_index(0, [&](int, int) { FAIL() << "no index to run"; });
}

TEST(ThreadPool, SlotsAreDistinctAmongTheThreadsOfALoop) {
  std::mutex m;
  std::set<std::pair<std::thread::id, int>> thread_slot;
  for_each_index(200, [&](int, int slot) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
    std::lock_guard<std::mutex> lock(m);
    thread_slot.insert({std::this_thread::get_id(), slot});
  });
  std::set<std::thread::id> threads;
  std::set<int> slots;
  for (const auto& ts : thread_slot) {
    threads.insert(ts.first);
    slots.insert(ts.second);
    EXPECT_GE(ts.second, 0);
    EXPECT_LT(ts.second, kMostThreads);
  }
  // One slot per thread, and each thread keeps its slot for the whole loop.
  EXPECT_EQ(threads.size(), thread_slot.size());
  EXPECT_EQ(slots.size(), threads.size());
  EXPECT_LE(int(threads.size()), loop_threads());
}

TEST(ThreadPool, LoopThreadsCountsThePoolAndTheCaller) {
  EXPECT_GE(loop_threads(), 1);
  EXPECT_LE(loop_threads(), pool_size());
}

// A chart with more than one thread's share of the faces solved at once takes two threads (u and
// v at once), any other one, whatever the machine's core count; on one thread, one.
TEST(ThreadPool, AChartAboveOneThreadsShareSolvesOnTwoThreads) {
  const size_t all = 1000 * size_t(loop_threads());
  if (loop_threads() > 1) EXPECT_EQ(for_share(Options(), all / size_t(loop_threads()) + 1, all).solver.threads, 2);
  EXPECT_EQ(for_share(Options(), all / size_t(loop_threads()), all).solver.threads, 1);
  EXPECT_EQ(for_share(Options(), all, all).solver.threads, loop_threads() > 1 ? 2 : 1);
}

TEST(ThreadPool, NestedLoopsStartNoThreadAndRunEveryIndex) {
  std::mutex m;
  std::set<std::thread::id> threads;
  std::atomic<int> inner_runs{0};
  for_each_index(8, [&](int, int) {
    for_each_index(50, [&](int, int slot) {
      EXPECT_LT(slot, kMostThreads);
      std::this_thread::sleep_for(std::chrono::microseconds(100));
      ++inner_runs;
      std::lock_guard<std::mutex> lock(m);
      threads.insert(std::this_thread::get_id());
    });
  });
  EXPECT_EQ(inner_runs.load(), 8 * 50);
  // The caller and the pool's threads, however deep the nesting: never more threads than cores.
  EXPECT_LE(int(threads.size()), pool_size());
}

}  // namespace
}  // namespace lowstretch
