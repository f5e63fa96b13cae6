// Small charts put into the texels a tiling leaves empty: the holes of charts with closed holes,
// the corners of free charts' cells, the parts of cells a chart fills only in part. The layout is
// drawn on the texture's own texel grid, every chart grown by the gutter, and each small chart's
// outline (the texels its triangles touch, at the texel density of the tiled charts) goes where it
// first fits: lowest row, then column, turned by quarter turns or not. A chart placed so leaves
// its own holes and concave sides to the charts after it. Nothing is moved that is already placed,
// so no overlap can come of it.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "atlas/base/atlas_types.h"
#include "atlas/chart_map/solved_chart.h"

namespace lowstretch {

// The share of the tiling's texels that its free charts and closed holes are expected to leave
// empty (own_area: each chart's cell area in the tiling, area / fill for those that do not fill it).
double expected_empty_share(const std::vector<SolvedChart>& charts, const std::vector<double>& own_area);

// Which charts leave the tiling for empty texels: the smallest first, while their own texels stay
// under a share of the expected empty texels; only rectangles that fill their box, or charts of any
// shape (free outlines fit into each other's concave sides and holes). And whether flat charts
// are seen along their normal first (see_flat_charts_along_normal: less stretch, more empty texels).
struct GuestChoice {
  bool any_shape = false;
  double share_of_empty = 0.5;
  bool flat_seen_along_normal = false;
};
// Each is tried on the kept atlas; the best layout is kept. Rectangles only suit most atlases;
// which choice fills the empty texels best depends on the atlas.
constexpr GuestChoice kGuestChoices[] = {{false, 0.5, false}, {true, 0.8, false}, {true, 0.5, true}};

std::vector<int> charts_to_put_in_empty_texels(const std::vector<SolvedChart>& charts, const std::vector<double>& own_area,
                                               const GuestChoice& choice);

// corner_uv holds the layout of every chart but `guests` in [0,1]^2 (store() moves it inside the
// gutter). Each guest goes into empty texels at the tiled charts' texel density, `gutter` texels or
// more from every other chart and from the border; its corners are written and face_chart set.
// Returns the guests that found no room (their corners are left as they were).
std::vector<int> put_in_empty_texels(const std::vector<SolvedChart>& charts, const std::vector<int>& guests,
                                     const ChartOptions& options, Eigen::MatrixXd& corner_uv, std::vector<int>& face_chart);

// The whole layout by outline: every chart placed as a guest is, on a grid with nothing else, at
// the highest texel density at which all fit (a bisection of kTuning.packing_bisections steps):
// placed largest first or, where that does not fit them all, longest box first (as xatlas orders
// charts), each turned so that its place has the lowest bottom or, where that does not fit them
// all, the lowest top. Free charts and charts with holes fit into each other; rectangles keep their
// own shape. False if even a tiny density leaves a chart without room (corner_uv and face_chart
// then mean nothing). density: in, 0 or one that held nearly these charts (the search starts
// there); out, the layout's (grid cells^2 per unit of 3D area).
bool pack_by_outline(const std::vector<SolvedChart>& charts, const ChartOptions& options, Eigen::MatrixXd& corner_uv,
                     std::vector<int>& face_chart, double& density);

// Whether the charts, packed by outline, may cover `coverage` of the texture: they fit at the
// density that would (one try of pack_by_outline's). A packing that must reach an efficiency is
// given up at once where they do not.
bool may_cover_by_outline(const std::vector<SolvedChart>& charts, const ChartOptions& options, double coverage);

}  // namespace lowstretch
