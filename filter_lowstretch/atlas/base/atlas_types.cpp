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
  return r.error ? -1 : r.coverage / (r.layout.l2_stretch * r.layout.l2_stretch);
}

double largest_chart_stretch(const ChartsResult& r) {
  double largest = 0;
  for (const Chart& c : r.charts) largest = std::max(largest, c.l2_stretch);
  return largest;
}

}  // namespace lowstretch
