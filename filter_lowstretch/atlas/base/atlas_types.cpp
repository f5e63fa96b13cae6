#include "atlas/base/atlas_types.h"

#include <algorithm>

namespace lowstretch {

const char* to_string(NonDisk non_disk) {
  switch (non_disk) {
    case NonDisk::Reject: return "reject";
    case NonDisk::Charts: return "charts";
    case NonDisk::Atlas: return "atlas";
  }
  return "?";
}

double texture_efficiency(const ChartsResult& r) {
  if (r.error) return -1;
  const int invalid = r.layout.flipped + r.layout.degenerate;
  const double l2 = invalid > 0 && invalid <= r.float_collapsed ? r.l2_of_valid : r.layout.l2_stretch;
  return r.coverage / (l2 * l2);
}

double largest_chart_stretch(const ChartsResult& r) {
  double largest = 0;
  for (const Chart& c : r.charts) largest = std::max(largest, c.l2_stretch);
  return largest;
}

}  // namespace lowstretch
