// One chart of an atlas: its faces made into a disk (holes closed virtually, closed parts cut open
// along short seams), the paper's map of it onto a rectangle (or a free map) with every pass
// measured over its real faces, and what the atlas asks of a chart: what it costs in texture and
// whether the bound cuts it.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

#include "atlas/base/atlas_types.h"
#include "core/parameterize.h"
#include "core/prepared_disk.h"

namespace lowstretch {

// The problems a chart's cut into disks solves (several parts, closed, holes, genus); the manifold
// copy (split_vertex_fans.h) solves non-manifold and misoriented ones before.
bool cutting_into_disks_fixes(ErrorCode code);

// prepare_disk of a chart's mesh, made once by its first caller, from any thread.
class LazyPreparedDisk {
 public:
  const PreparedDisk& get(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, InitialWeights kind, Error& error) {
    std::call_once(once_, [&] { error_ = prepare_disk(V, F, kind, prepared_); });
    error = error_;
    return prepared_;
  }

 private:
  std::once_flag once_;
  PreparedDisk prepared_;
  Error error_;
};

// One component made into a disk: its faces first (in input order), then the virtual faces
// that close its holes.
struct ChartMesh {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  std::vector<int> input_face;  // real face -> input face
  int closed_holes = 0;
  double seam_length = 0;       // in unit-box lengths
  // V and F as the core's disk with its initial weights, made when the chart is first mapped: a
  // chart is mapped onto many rectangles, and copies of it share this; a large chart cut again
  // before it is mapped never needs it.
  std::shared_ptr<LazyPreparedDisk> prepared;
};

// local_of: -1 for every vertex, and left so (one array for all components keeps many small
// components linear in time).
Error make_chart_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::vector<int>& faces,
                      std::vector<int>& local_of, ChartMesh& chart);

// One pass of one chart, over its real faces (the faces closing holes are not the mesh's).
struct ChartPass {
  double area_3d = 0, l2_stretch = 0;
  int flipped = 0, degenerate = 0;
  double l2_of_valid = 0;  // over the faces that are neither flipped nor degenerate
};
inline ChartPass as_chart_pass(const PassMetrics& p) { return {0, p.l2_stretch, p.flipped, p.degenerate, p.l2_stretch}; }
ChartPass measure_real_faces(const ChartMesh& chart, const Eigen::MatrixXd& uv);

// One chart: its mesh, the method's map of it onto a rectangle and that map's passes measured
// over the real faces.
struct SolvedChart {
  std::vector<int> faces;  // input faces
  ChartMesh mesh;
  Result map;
  std::vector<ChartPass> passes;
  ChartPass kept;          // passes[map.chosen_pass]
  Eigen::AlignedBox2d box; // of the real faces' UV: the rectangle it is mapped onto
  const char* kept_whole = nullptr;  // why a chart above the bound was not cut
  bool deciding_map = false;  // made while deciding where to cut (fewer passes, looser solve)
  bool free_boundary = false;  // mapped with the natural boundary: its shape is kept in its cell
  bool cut_ahead = false;  // cut again before it was mapped (cuts_ahead): it has no map
  bool cut_for_validity = false;  // a piece of a chart whose map was invalid (cut_invalid_charts.h)
  double aspect() const { return box.sizes().y() > 0 ? box.sizes().x() / box.sizes().y() : 1; }  // width / height
  // box := the box of the real faces' UV, after the map changed.
  void fit_box();
  // The area of its real faces' UV, in its map's units.
  double uv_area() const;
  // The share of its box that its real faces cover (about 1 on a rectangle).
  double fill() const;
  // Whether its faces leave part of its box empty: a free outline, or closed holes.
  bool leaves_box_empty() const { return free_boundary || mesh.closed_holes > 0; }
};

// What a chart costs in texture at one texel density: its area times L2^2, over the share of its
// box it fills where it has closed holes (their texels are lost; a rectangle without holes fills
// its box but for its ears' bulge, which every chart shares). Counting the holes gets faces with
// holes (as CAD parts have) cut open, which wastes fewer texels.
double texture_cost(const SolvedChart& chart);

// Whether a pass folds or stretches more than the bound.
bool needs_split(const ChartPass& p, double max_stretch);
// Whether the bound cuts a chart: it folds or stretches more than the bound, or its closed holes
// waste as much texture as stretching to the bound would.
bool bound_cuts(const SolvedChart& chart, double max_stretch);

// The method on a chart whose mesh is built, onto a rectangle of `aspect` (0: its own), or with
// the natural boundary if `free_boundary`; the multigrid solves only charts of at least
// kTuning.chart_amg_minimum_rows unknowns, the sparse LU the others.
void solve_onto(SolvedChart& chart, Options options, double aspect, bool free_boundary = false);

// The method on a chart whose mesh is built, onto a rectangle of `aspect`; aspect 0: onto the
// better of its own rectangle (sides as long as its boundary arcs) and the square, the square
// tried only if the rectangle's L2 stretch is at most `square_below`.
void solve_chart(SolvedChart& chart, const Options& options, double aspect,
                 double square_below = std::numeric_limits<double>::infinity());

}  // namespace lowstretch
