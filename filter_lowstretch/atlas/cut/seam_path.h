// The cheapest seam of a chart of genus 0 as a shortest path (planar duality). Where one border
// loop meets the faces fixed on each side in one run each, every seam between them holds a path
// along edges from one of the two border arcs between those runs to the other, through the holes
// as through single points; the cheapest seam is the shortest such path (Dijkstra), found in
// near-linear time where a max flow over a large band is not (Boykov-Kolmogorov's orphans
// multiply as the band grows).
#pragma once
#include <array>
#include <vector>

namespace lowstretch {

// corners: per face, its three vertices (any numbering), edge k from corner k to corner k + 1;
// neighbour, cost, fixed: as cheapest_seam (cheapest_seam.h) takes them. Writes each face's side
// and returns true where the chart is of genus 0 (Euler characteristic 2 less its border loops)
// and one of its border loops meets the faces fixed on side 1 and those on side 0 in one run
// each, and the path's sides keep every fixed face; returns false, and leaves `side` as it was,
// otherwise.
bool cheapest_seam_as_path(const std::vector<std::array<int, 3>>& corners, const std::vector<std::array<int, 3>>& neighbour,
                           const std::vector<std::array<double, 3>>& cost, const std::vector<signed char>& fixed,
                           std::vector<char>& side);

}  // namespace lowstretch
