// A seam made as cheap as it can be near where it was first drawn, as Iso-charts re-decides the
// boundary between two charts in a band around it (Zhou, Snyder, Guo, Shum 2004): the faces of
// the band take the side of a minimum cut of the seam costs between the faces fixed on either side.
#pragma once
#include <array>
#include <vector>

namespace lowstretch {

// corners: per face, its three vertices, edge k from corner k to corner k + 1; neighbour: per face,
// the face across each edge (-1 across the border); cost: that edge's seam cost (symmetric, at
// least 0). fixed: per face, 0 or 1 where its side is kept, -1 where the cut decides. Returns each
// face's side; the seam between the sides costs least among all that keep the fixed faces where
// they are: the shortest path between two border arcs where the chart and the fixed faces allow
// (seam_path.h), Boost's Boykov-Kolmogorov max flow elsewhere. With no face fixed on one side,
// every free face goes to the other.
std::vector<char> cheapest_seam(const std::vector<std::array<int, 3>>& corners, const std::vector<std::array<int, 3>>& neighbour,
                                const std::vector<std::array<double, 3>>& cost, const std::vector<signed char>& fixed);

// The same seam by the max flow alone (neither corners nor topology needed).
std::vector<char> cheapest_seam_by_max_flow(const std::vector<std::array<int, 3>>& neighbour,
                                            const std::vector<std::array<double, 3>>& cost, const std::vector<signed char>& fixed);

}  // namespace lowstretch
