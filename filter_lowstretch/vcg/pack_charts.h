// The chart packer of the non-disk path: vcglib's rectangle packer (what PolyPacker, as MeshLab's
// texture filters use it, packs: the charts' axis-aligned bounding boxes). Header-only, so that each consumer compiles it with its
// own vcglib (Debian's 2020.09 source for the tool and the 2020.09 plugin, MeshLab 2025.07's for
// the newer plugin).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include <vcg/space/rect_packer.h>

#include "../atlas/charts.h"

namespace lowstretch {

// Every box grows by a gutter of 1% of the largest box's side, so that charts never touch.
inline bool pack_charts_with_vcglib(const std::vector<Eigen::AlignedBox2d>& boxes, std::vector<ChartPlacement>& placements) {
  placements.clear();
  if (boxes.empty()) return true;
  if (boxes.size() == 1) {  // nothing to pack: the caller scales the layout into [0,1]^2
    ChartPlacement only;
    only.offset = -boxes[0].min();
    placements.push_back(only);
    return true;
  }
  double largest = 0;
  for (const Eigen::AlignedBox2d& b : boxes) largest = std::max(largest, b.sizes().maxCoeff());
  if (!(largest > 0)) return false;
  const double gutter = 0.01 * largest;
  // In units of the largest side: the packer works in float.
  std::vector<vcg::Box2f> rectangles;
  for (const Eigen::AlignedBox2d& b : boxes) {
    const Eigen::Vector2d low = (b.min().array() - gutter) / largest, high = (b.max().array() + gutter) / largest;
    rectangles.emplace_back(vcg::Point2f(float(low.x()), float(low.y())), vcg::Point2f(float(high.x()), float(high.y())));
  }
  // RectPacker::Pack raises the occupancy until a packing fails, which never happens when the
  // rectangles can fill the container (one square chart): it loops forever, in vcglib 2020.09
  // and 2025.07 alike. The same search, bounded.
  const vcg::Point2i grid(1024, 1024);  // the integer container the rectangles are placed in
  std::vector<vcg::Similarity2f> transforms, attempt;
  vcg::Point2f covered;
  // Then the step that failed is halved a few times: a denser packing often still fits.
  float packed = 0, occupancy = 0.1f, failed = 1;
  for (int tries = 0; tries < 40 && failed - packed > 1e-3f; ++tries) {
    if (vcg::RectPacker<float>::PackOccupancy(rectangles, grid, occupancy, attempt, covered)) {
      transforms = attempt;
      packed = occupancy;
    } else {
      failed = occupancy;
    }
    occupancy = failed < 1 ? (packed + failed) / 2 : (2 * packed + 1) / 3;
  }
  if (transforms.size() != boxes.size()) return false;
  for (const vcg::Similarity2f& t : transforms) {
    if (t.rotRad != 0) return false;  // axis-aligned packing never rotates
    ChartPlacement p;
    p.scale = double(t.sca) / largest;
    p.offset = Eigen::Vector2d(double(t.tra.X()), double(t.tra.Y()));
    placements.push_back(p);
  }
  return true;
}

}  // namespace lowstretch
