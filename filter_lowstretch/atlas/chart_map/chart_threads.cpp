#include "atlas/chart_map/chart_threads.h"

#include <algorithm>

namespace lowstretch {

std::vector<int> largest_first(const std::vector<SolvedChart>& charts, size_t first, size_t end) {
  std::vector<int> order;
  for (size_t i = first; i < end; ++i) order.push_back(int(i - first));
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return charts[first + size_t(a)].faces.size() > charts[first + size_t(b)].faces.size();
  });
  return order;
}

Options for_share(Options options, size_t faces, size_t all_faces) {
  options.solver.threads = double(faces) * loop_threads() > double(all_faces) ? 2 : 1;
  return options;
}

size_t faces_in(const std::vector<SolvedChart>& charts, size_t first, size_t end) {
  size_t faces = 0;
  for (size_t i = first; i < end; ++i) faces += charts[i].cut_ahead ? 0 : charts[i].faces.size();
  return faces;
}

}  // namespace lowstretch
