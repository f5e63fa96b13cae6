// Where to put the four corners of the square boundary.
#pragma once
#include <array>
#include <vector>

#include "core/disk_mesh.h"

namespace lowstretch {

struct SquareCorners {
  std::array<int, 4> corners{};  // increasing positions in disk.boundary
  // Interior edges whose two boundary endpoints still end up on one side (each would collapse
  // the triangles between it and the side): 0 unless no choice of corners avoids it. For each,
  // the loop position halfway between its endpoints is in kinks: square_boundary bends the side
  // outward there.
  int collapsed_chords = 0;
  std::vector<int> kinks;
  std::vector<int> ear_tips;     // the kinks whose edge cuts off that one vertex (a boundary ear)
  bool moved = false;            // corners differ from the quarter-arc-length choice
};

// The paper's choice: the vertices nearest to the quarter arc lengths from the loop's first
// vertex. An interior edge between two boundary vertices of one side would be mapped onto that
// side and collapse its triangles; if the quarter choice makes such an edge, the corners are
// chosen instead so that every such edge has a corner strictly inside both of the boundary arcs
// it cuts off, with side lengths as close to a quarter as possible (dynamic programming).
// With `preferred` (if not null: increasing loop positions where a caller would rather have the
// corners): those, if they are distinct and collapse no triangle; else the choice above.
SquareCorners choose_square_corners(const DiskMesh& disk, const std::array<int, 4>* preferred = nullptr);

}  // namespace lowstretch
