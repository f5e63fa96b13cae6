#include "atlas/chart_map/chart_threads.h"

#include "atlas/base/tuning.h"

#include <algorithm>
#include <atomic>
#include <thread>

namespace lowstretch {

void for_each_index(int count, const std::function<void(int, int)>& job, const std::vector<int>& order) {
  const int threads = std::max(1, std::min<int>(int(std::thread::hardware_concurrency()), std::min(count, kTuning.most_threads)));
  std::atomic<int> next{0};
  const auto work = [&](int worker) {
    for (int k = next++; k < count; k = next++) job(order.empty() ? k : order[size_t(k)], worker);
  };
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t) workers.emplace_back(work, t);
  work(0);
  for (std::thread& w : workers) w.join();
}

std::vector<int> largest_first(const std::vector<SolvedChart>& charts, size_t first, size_t end) {
  std::vector<int> order;
  for (size_t i = first; i < end; ++i) order.push_back(int(i - first));
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return charts[first + size_t(a)].faces.size() > charts[first + size_t(b)].faces.size();
  });
  return order;
}

Options for_share(Options options, size_t faces, size_t all_faces) {
  options.solver.threads = 2 * faces > all_faces ? 2 : 1;
  return options;
}

size_t faces_in(const std::vector<SolvedChart>& charts, size_t first, size_t end) {
  size_t faces = 0;
  for (size_t i = first; i < end; ++i) faces += charts[i].cut_ahead ? 0 : charts[i].faces.size();
  return faces;
}

}  // namespace lowstretch
