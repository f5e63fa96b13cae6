#include "charts.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <thread>
#include <utility>

#include "boundary_crossing.h"
#include "boundary_loops.h"
#include "close_holes.h"
#include "cut_graph.h"
#include "cut_mesh.h"
#include "disk_mesh.h"
#include "half_edges.h"
#include "mesh_components.h"
#include "one_blas_thread.h"
#include "plane_projection.h"
#include "rectangle_layout.h"
#include "sharp_patches.h"
#include "split_chart.h"
#include "split_vertex_fans.h"
#include "stretch.h"

namespace lowstretch {

namespace {

using Clock = std::chrono::steady_clock;
const double kInf = std::numeric_limits<double>::infinity();

// The problems that charts solve (besides non-manifold vertices, split per fan before: see
// parameterize_charts); anything else (non-manifold edges, non-orientable, bad indices or
// coordinates) stays an error.
bool charts_can_fix(ErrorCode code) {
  return code == ErrorCode::SeveralComponents || code == ErrorCode::Closed || code == ErrorCode::SeveralBoundaryLoops ||
         code == ErrorCode::NotGenusZero;
}

// The used vertices moved into make_disk_mesh's unit box, so that huge coordinates do not
// overflow lengths and areas; `unit` converts lengths back to the input's units.
Eigen::MatrixXd unit_box_of_used(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, double& unit) {
  std::vector<char> used(static_cast<size_t>(V.rows()), 0);
  std::vector<int> rows;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (!used[size_t(F(f, k))]) {
        used[size_t(F(f, k))] = 1;
        rows.push_back(F(f, k));
      }
  Eigen::MatrixXd points(Eigen::Index(rows.size()), 3);
  for (size_t i = 0; i < rows.size(); ++i) points.row(Eigen::Index(i)) = V.row(rows[i]);
  const UnitBox box = unit_box(points);
  unit = box.unit();
  Eigen::MatrixXd scaled = Eigen::MatrixXd::Zero(V.rows(), 3);
  for (int r : rows) scaled.row(r) = box.map(V.row(r));
  return scaled;
}

// One component made into a disk: its faces first (in input order), then the virtual faces
// that close its holes.
struct ChartMesh {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  std::vector<int> input_face;  // real face -> input face
  int closed_holes = 0;
  double seam_length = 0;       // in unit-box lengths
};

// local_of: -1 for every vertex, and left so (one array for all components keeps many small
// components linear in time).
Error make_chart_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::vector<int>& faces,
                      std::vector<int>& local_of, ChartMesh& chart) {
  std::vector<int> input_vertex;
  Eigen::MatrixXi local_F(Eigen::Index(faces.size()), 3);
  for (size_t j = 0; j < faces.size(); ++j)
    for (int k = 0; k < 3; ++k) {
      int& l = local_of[size_t(F(faces[j], k))];
      if (l < 0) {
        l = int(input_vertex.size());
        input_vertex.push_back(F(faces[j], k));
      }
      local_F(Eigen::Index(j), k) = l;
    }
  Eigen::MatrixXd local_V(Eigen::Index(input_vertex.size()), 3);
  for (size_t i = 0; i < input_vertex.size(); ++i) {
    local_V.row(Eigen::Index(i)) = V.row(input_vertex[i]);
    local_of[size_t(input_vertex[i])] = -1;
  }

  DiskMesh check;
  Error e = make_disk_mesh(local_V, local_F, check);
  if (e.code == ErrorCode::NonManifoldVertices) {
    // A cut that passes a hole can leave faces that meet at one vertex only: each fan gets its
    // own copy of it (an armadillo with 200 one-face holes: a 42690-face chart at L2 1201 found
    // no cut into disks without this). Parts held together by that vertex alone stay refused.
    SplitFans split = split_vertex_fans(local_V, local_F);
    local_V = std::move(split.V);
    local_F = std::move(split.F);
    e = make_disk_mesh(local_V, local_F, check);
    if (e.code == ErrorCode::SeveralComponents) return e;
  }
  if (e && !charts_can_fix(e.code)) return e;

  const int real_vertices = int(local_V.rows());
  const std::vector<std::vector<int>> loops = boundary_loops(local_F, opposite_half_edges(local_F), real_vertices);
  std::vector<int> outer;
  if (!loops.empty()) {
    const size_t keep = longest_loop(local_V, loops);
    outer = loops[keep];
    close_holes(local_V, local_F, loops, keep);
    chart.closed_holes = int(loops.size()) - 1;
  }
  const std::vector<std::array<int, 2>> seams = cut_graph(local_V, local_F, outer);
  for (const auto& s : seams)
    if (s[0] < real_vertices && s[1] < real_vertices) chart.seam_length += (local_V.row(s[0]) - local_V.row(s[1])).norm();
  const CutMesh cut = cut_along(local_F, seams);
  chart.F = cut.F;
  chart.V.resize(Eigen::Index(cut.original_vertex.size()), 3);
  for (size_t i = 0; i < cut.original_vertex.size(); ++i) chart.V.row(Eigen::Index(i)) = local_V.row(cut.original_vertex[i]);
  chart.input_face = faces;
  return {};
}

// One pass of one chart, over its real faces (the faces closing holes are not the mesh's).
struct ChartPass {
  double area_3d = 0, l2_stretch = 0;
  int flipped = 0, degenerate = 0;
};
ChartPass as_chart_pass(const PassMetrics& p) { return {0, p.l2_stretch, p.flipped, p.degenerate}; }
ChartPass measure_real_faces(const ChartMesh& chart, const Eigen::MatrixXd& uv) {
  const Eigen::Index real = Eigen::Index(chart.input_face.size());
  const FaceStretch s = face_stretch(chart.V, chart.F.topRows(real), uv);
  return {s.area_3d.sum(), l2_stretch(s), s.flipped, s.degenerate};
}

// L2 stretch of the whole layout from the charts' own: with every chart at one texel density,
// L2^2 is the 3D-area-weighted mean of the charts' normalized L2^2.
std::vector<LayoutPass> layout_passes(const std::vector<std::vector<ChartPass>>& passes, const std::vector<int>& kept) {
  size_t most = 0;
  for (const auto& p : passes) most = std::max(most, p.size());
  std::vector<LayoutPass> layout(most);
  for (size_t k = 0; k < most; ++k) {
    double weighted = 0, area = 0;
    layout[k].pass = int(k);
    for (size_t c = 0; c < passes.size(); ++c) {
      const ChartPass& p = k < passes[c].size() ? passes[c][k] : passes[c][size_t(kept[c])];
      layout[k].flipped += p.flipped;
      layout[k].degenerate += p.degenerate;
      weighted += p.area_3d * p.l2_stretch * p.l2_stretch;
      area += p.area_3d;
    }
    const bool bad = layout[k].flipped + layout[k].degenerate > 0 || !(area > 0);
    layout[k].l2_stretch = bad ? kInf : std::sqrt(weighted / area);
  }
  return layout;
}

Error check_chart_options(const ChartOptions& o) {
  if (!(o.max_stretch >= 1 && o.max_stretch < 1e6))
    return {ErrorCode::InvalidOption, 0, "must be at least 1, got " + number_text(o.max_stretch), "max_stretch"};
  if (o.most_cuts_ahead < 0 || o.most_cuts_ahead > 16)
    return {ErrorCode::InvalidOption, 0, "must be from 0 to 16, got " + std::to_string(o.most_cuts_ahead), "most_cuts_ahead"};
  if (o.max_charts < 1) return {ErrorCode::InvalidOption, 0, "must be at least 1, got " + std::to_string(o.max_charts), "max_charts"};
  if (o.texture_size < 8 || o.texture_size > 65536)
    return {ErrorCode::InvalidOption, 0, "must be from 8 to 65536, got " + std::to_string(o.texture_size), "texture_size"};
  if (!(o.gutter >= 0.5 && o.gutter <= o.texture_size / 8.0))
    return {ErrorCode::InvalidOption, 0, "must be from 0.5 to an eighth of the texture size (" +
                                             number_text(o.texture_size / 8.0) + "), got " + number_text(o.gutter),
            "gutter"};
  return {};
}

// Moves a layout of [0,1]^2 uniformly into [g, 1 - g]^2, g = gutter / texture_size.
void keep_inside_gutter(const ChartOptions& o, Eigen::MatrixXd& corner_uv) {
  const double g = o.gutter / o.texture_size;
  corner_uv = (corner_uv.array() * (1 - 2 * g) + g).matrix();
}

ChartsResult failed(Error error) {
  ChartsResult result;
  result.error = std::move(error);
  return result;
}

// A disk as one chart: parameterize's map and pass history; measured later, like a layout.
ChartsResult from_disk(const Eigen::MatrixXi& F, Result disk) {
  ChartsResult result;
  result.input_is_disk = true;
  result.corner_uv.resize(F.rows(), 6);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) result.corner_uv.block(f, 2 * k, 1, 2) = disk.uv.row(F(f, k));
  result.face_chart.assign(size_t(F.rows()), 0);
  for (const PassMetrics& p : disk.passes) result.passes.push_back({p.pass, p.l2_stretch, p.flipped, p.degenerate});
  Chart chart;
  chart.faces = int(F.rows());
  chart.chosen_pass = disk.chosen_pass;
  chart.passes = int(disk.passes.size());
  result.charts.push_back(chart);
  result.seconds_total = disk.seconds_total;
  result.notes = std::move(disk.notes);
  result.disk_passes = std::move(disk.passes);
  result.chosen_pass = disk.chosen_pass;
  result.stop_reason = disk.stop_reason;
  return result;
}

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
  double aspect() const { return box.sizes().y() > 0 ? box.sizes().x() / box.sizes().y() : 1; }  // width / height
  // box := the box of the real faces' UV, after the map changed.
  void fit_box() {
    box.setEmpty();
    for (size_t j = 0; j < faces.size(); ++j)
      for (int k = 0; k < 3; ++k) box.extend(map.uv.row(mesh.F(Eigen::Index(j), k)).transpose());
  }
  // The share of its box that its real faces cover (about 1 on a rectangle).
  double fill() const {
    double area = 0;
    for (size_t j = 0; j < faces.size(); ++j) {
      const auto corner = [&](int k) { return Eigen::Vector2d(map.uv.row(mesh.F(Eigen::Index(j), k)).transpose()); };
      area += std::abs(signed_uv_area(corner(0), corner(1), corner(2)));
    }
    return box.volume() > 0 ? std::min(1.0, area / box.volume()) : 0;
  }
};

// What a chart costs in texture at one texel density: its area times L2^2, over the share of its
// box it fills where it has closed holes (their texels are lost; a rectangle without holes fills
// its box but for its ears' bulge, which every chart shares). Counting the holes cut CAD parts'
// faces with holes open: efficiency rotor 0.601 -> 0.721, turbine 0.443 -> 0.611.
double texture_cost(const SolvedChart& chart) {
  const ChartPass& p = chart.kept;
  const double fill = chart.mesh.closed_holes > 0 ? chart.fill() : 1;
  return p.flipped + p.degenerate > 0 || !(fill > 0) ? kInf : p.area_3d * p.l2_stretch * p.l2_stretch / fill;
}

// The tips of a chart's boundary ears go a quarter of their chord out of the rectangle: a cut
// along mesh edges leaves many ears, which a straight side squeezes to slivers (an 830k-face
// scan: L2 2.69 without, 1.46 with).
const double kEarBulge = 0.25;

bool needs_split(const ChartPass& p, double max_stretch) {
  return p.flipped + p.degenerate > 0 || !(p.l2_stretch <= max_stretch);
}

// Whether the bound cuts a chart: it folds or stretches more than the bound, or its closed holes
// waste as much texture as stretching to the bound would.
bool bound_cuts(const SolvedChart& chart, double max_stretch) {
  return needs_split(chart.kept, max_stretch) || texture_cost(chart) > chart.kept.area_3d * max_stretch * max_stretch;
}

// The method on a chart whose mesh is built, onto a rectangle of `aspect` (0: its own), or with
// the natural boundary if `free_boundary`.
void solve_onto(SolvedChart& chart, Options options, double aspect, bool free_boundary = false) {
  options.boundary = free_boundary ? BoundaryShape::Natural : BoundaryShape::Square;
  options.rectangle_aspect = aspect;
  options.corners_at_turns = true;
  options.ear_bulge = kEarBulge;
  options.progress = nullptr;  // called from worker threads: the caller reports between rounds
  chart.free_boundary = free_boundary;
  chart.deciding_map = false;
  chart.passes.clear();
  options.pass_uv = [&chart](int, const Eigen::MatrixXd& uv) { chart.passes.push_back(measure_real_faces(chart.mesh, uv)); };
  chart.map = parameterize(chart.mesh.V, chart.mesh.F, options);
  if (chart.map.error) return;
  chart.kept = chart.passes.at(size_t(chart.map.chosen_pass));
  chart.fit_box();
}

// Fewer flipped and zero-area triangles first, then lower L2 stretch (as parameterize ranks passes).
bool better(const ChartPass& a, const ChartPass& b) {
  return std::make_pair(a.flipped + a.degenerate, a.l2_stretch) < std::make_pair(b.flipped + b.degenerate, b.l2_stretch);
}

// The method on a chart whose mesh is built, onto a rectangle of `aspect`; aspect 0: onto the
// better of its own rectangle (sides as long as its boundary arcs) and the square, the square
// tried only if the rectangle's L2 stretch is at most `square_below`.
void solve(SolvedChart& chart, const Options& options, double aspect, double square_below = kInf) {
  solve_onto(chart, options, aspect);
  if (chart.map.error.code == ErrorCode::SolverFailed && options.max_passes > 0) {
    // A pass whose weights overflow on a tiny part: the initial map, which no weight breaks.
    Options initial = options;
    initial.max_passes = 0;
    solve_onto(chart, initial, aspect);
  }
  if (aspect != 0 || chart.map.error || std::abs(std::log(chart.aspect())) < 0.02) return;
  if (!(chart.kept.l2_stretch <= square_below)) return;
  SolvedChart square;
  square.mesh = chart.mesh;  // small beside the solve
  square.faces = chart.faces;
  solve_onto(square, options, 1);
  if (!square.map.error && better(square.kept, chart.kept)) chart = std::move(square);
}

// The method's options for a chart of `faces` among `all_faces` solved at once. A chart with
// most of the faces solves u and v on two threads while the rest share the second core (the
// armadillo is cut into parts of 4422 and 47578 faces first: 3.4 -> 3.0 s, the same atlas); any
// other builds one multigrid hierarchy for u and v instead of two, the threads keeping the cores busy.
Options for_share(Options options, size_t faces, size_t all_faces) {
  options.solver.columns_on_two_threads = 2 * faces > all_faces;
  return options;
}

// The faces of charts [first, end) that are mapped (not cut ahead).
size_t faces_in(const std::vector<SolvedChart>& charts, size_t first, size_t end) {
  size_t faces = 0;
  for (size_t i = first; i < end; ++i) faces += charts[i].cut_ahead ? 0 : charts[i].faces.size();
  return faces;
}

const int kMostThreads = 8;

// Runs job(i, worker) for i < count on up to kMostThreads threads, each taking the next index
// left, in `order` (largest charts first, so that no thread is left with a big one at the end);
// worker (0 .. kMostThreads - 1) names the thread, for scratch space. A job's result depends on
// its index alone, never on the thread or the timing, so the atlas is the same every run.
void for_each_index(int count, const std::function<void(int, int)>& job, const std::vector<int>& order = {}) {
  const int threads = std::max(1, std::min<int>(int(std::thread::hardware_concurrency()), std::min(count, kMostThreads)));
  std::atomic<int> next{0};
  const auto work = [&](int worker) {
    for (int k = next++; k < count; k = next++) job(order.empty() ? k : order[size_t(k)], worker);
  };
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t) workers.emplace_back(work, t);
  work(0);
  for (std::thread& w : workers) w.join();
}

// The indices of charts, most faces first (ties by index).
std::vector<int> largest_first(const std::vector<SolvedChart>& charts, size_t first, size_t end) {
  std::vector<int> order;
  for (size_t i = first; i < end; ++i) order.push_back(int(i - first));
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return charts[first + size_t(a)].faces.size() > charts[first + size_t(b)].faces.size();
  });
  return order;
}

// How many more times the largest part of a chart is cut before any part is mapped: a chart far
// above the bound is mostly a body with protrusions, which the cuts take off one at a time, and
// mapping the body again after each took most of the time (the armadillo's body, 47,578 faces
// down to 22,226, was mapped in 7 rounds). One more cut per doubling of the L2 stretch over the
// bound; none for a chart with flipped triangles, whose stretch says little.
int cuts_ahead(const ChartPass& p, const ChartOptions& options) {
  if (p.flipped + p.degenerate > 0 || !std::isfinite(p.l2_stretch)) return 0;
  return std::min(options.most_cuts_ahead, std::max(0, int(std::floor(std::log2(p.l2_stretch / options.max_stretch)))));
}
// Only parts this large are cut ahead: smaller ones are cheap to map, and cutting them unmapped
// changes atlases. From 30 faces the cow's efficiency fell 0.619 -> 0.611; from 1000, the 15 bench
// meshes kept their atlas but Atlas.CutsAheadGiveTheSameAtlasAsMappingEveryPart's ball did not;
// from 3000 all keep theirs (the armadillo 3.27 -> 2.40 s, median of 5; 2.25 s from 1000).
const int kLeastCutAhead = 3000;  // faces
// And only a body, a part that kept two thirds of the faces of the chart it was cut from: the parts
// of a chart cut nearer its middle may meet the bound (the 769k-face scan without this rule: 2576
// charts and efficiency 0.601 instead of 2344 and 0.607; with it, 2400 and 0.607).
const double kLeastBodyShare = 0.67;

// A chart's cut: its parts, then the parts of its largest part cut ahead, and so on; parent: -1
// for a part of the chart itself, else the index of the piece it was cut from. Every piece but
// those cut ahead has its mesh built.
struct Cut {
  std::vector<SolvedChart> pieces;
  std::vector<int> parent;
  int ahead() const {  // pieces cut ahead
    return int(std::count_if(pieces.begin(), pieces.end(), [](const SolvedChart& p) { return p.cut_ahead; }));
  }
};

// Empty if the chart cannot be cut into parts that are disks with holes (a part whose faces meet
// at a single vertex); a cut ahead that leaves such a part is not made.
Cut cut_with_cuts_ahead(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const std::vector<int>& twin,
                        const SolvedChart& chart, int ahead, std::vector<int>& local_of) {
  Cut cut;
  std::vector<size_t> level_start = {0};  // pieces [level_start[k], level_start[k + 1]) are level k's
  const auto add_parts = [&](const std::vector<int>& faces, int parent) {
    std::vector<std::vector<int>> parts = split_chart(unit_V, F, twin, faces);
    if (parts.size() < 2) return false;
    for (std::vector<int>& part : parts) {
      cut.pieces.emplace_back();
      cut.pieces.back().faces = std::move(part);
      cut.parent.push_back(parent);
    }
    return true;
  };
  if (!add_parts(chart.faces, -1)) return {};
  size_t cut_faces = chart.faces.size();
  for (int cuts = 0; cuts < ahead; ++cuts) {
    const size_t first = level_start.back();
    size_t largest = first;
    for (size_t j = first; j < cut.pieces.size(); ++j)
      if (cut.pieces[j].faces.size() > cut.pieces[largest].faces.size()) largest = j;
    const size_t faces = cut.pieces[largest].faces.size();
    if (int(faces) < kLeastCutAhead || double(faces) < kLeastBodyShare * double(cut_faces)) break;
    level_start.push_back(cut.pieces.size());
    if (!add_parts(cut.pieces[largest].faces, int(largest))) {
      level_start.pop_back();
      break;
    }
    cut.pieces[largest].cut_ahead = true;
    cut_faces = faces;
  }
  // The meshes, built only now: a piece cut ahead never needs one. A part that is no disk with
  // holes undoes the cut ahead it came from, as if that had not been made.
  std::vector<char> built(cut.pieces.size(), 0);
  for (size_t j = 0; j < cut.pieces.size();) {
    SolvedChart& piece = cut.pieces[j];
    if (built[j] || piece.cut_ahead || !make_chart_mesh(unit_V, F, piece.faces, local_of, piece.mesh)) {
      built[j] = !piece.cut_ahead;
      ++j;
      continue;
    }
    const size_t level = size_t(std::upper_bound(level_start.begin(), level_start.end(), j) - level_start.begin()) - 1;
    if (level == 0) return {};
    const size_t from = size_t(cut.parent[j]);
    cut.pieces.resize(level_start[level]);
    cut.parent.resize(level_start[level]);
    level_start.resize(level);
    cut.pieces[from].cut_ahead = false;
    j = from;  // its mesh next
  }
  return cut;
}

// The chart's own parts only, without the cuts ahead (which would pass the chart limit): the part
// that was cut ahead gets its mesh; if it is no disk with holes, the chart is not cut at all.
void keep_only_the_first_cut(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, Cut& cut, std::vector<int>& local_of) {
  while (!cut.parent.empty() && cut.parent.back() >= 0) {
    cut.pieces.pop_back();
    cut.parent.pop_back();
  }
  bool built = true;
  for (SolvedChart& piece : cut.pieces)
    if (piece.cut_ahead) {
      piece.cut_ahead = false;
      built = built && !make_chart_mesh(unit_V, F, piece.faces, local_of, piece.mesh);
    }
  if (!built) cut = Cut();
}

// The charts cut from one another: node 0.. are the components, a node's parts come after it.
struct ChartTree {
  std::vector<SolvedChart> nodes;
  std::vector<std::vector<int>> parts;  // per node, empty for a leaf
};

// Undoes the cuts that did not pay: bottom up, a chart whose parts (all its leaves) together
// cost at least as much texture (texture_cost) as it does alone becomes a leaf again, so that its
// seams go. A cut that pays only after further cuts is kept: the leaves are compared, not the
// first parts. A chart cut ahead has no map: `map_cut_ahead` maps it when its leaves cost more
// than the bound's stretch would (its cut may not have paid); otherwise, or if it cannot be
// mapped, it stays cut.
void undo_cuts_that_did_not_pay(ChartTree& tree, double max_stretch, const std::function<bool(SolvedChart&)>& map_cut_ahead) {
  const size_t n = tree.nodes.size();
  std::vector<double> weighted(n, 0.0);  // over each node's leaves: their texture_cost (the leaves cover its area)
  std::vector<double> area(n, 0.0);      // and sum A
  for (size_t i = n; i-- > 0;) {
    SolvedChart& node = tree.nodes[i];
    for (int p : tree.parts[i]) {
      weighted[i] += weighted[size_t(p)];
      area[i] += area[size_t(p)];
    }
    if (node.cut_ahead && weighted[i] > max_stretch * max_stretch * area[i] && map_cut_ahead(node)) node.cut_ahead = false;
    const ChartPass& alone = node.kept;
    const bool valid = alone.flipped + alone.degenerate == 0 && !node.cut_ahead;  // no map: stays cut
    const double own = valid ? texture_cost(node) : kInf;
    if (!tree.parts[i].empty()) {
      if (!(own <= weighted[i]) || !valid) continue;  // an invalid chart stays cut
      tree.parts[i].clear();
      node.kept_whole = "its parts stretched more";
    }
    weighted[i] = own;
    area[i] = alone.area_3d;
  }
}

// The multigrid's relative residual for the maps that decide the cuts (the final maps keep the
// method's 1e-10). At 1e-8 the 15 meshes of the bench table give the same charts (at 1e-7 the
// closed Max Planck head is cut into 41 charts instead of staying one).
const double kDecidingTolerance = 1e-8;

// Where the square may turn a chart that the bound cuts into one it keeps: the square took
// the 15 bench meshes' charts from at most 1.13 x the bound on their own rectangle to under it
// (75 of the 5166 charts tried both ways). Above, the chart is cut whatever its map: its square
// would only cost a second solve (the armadillo 3.0 -> 2.2 s with the same atlas; 11 of the 15
// meshes give the same atlas, the others' efficiency moves by less than 1%).
const double kSquareMayMeet = 1.5;

// The map that decides whether a chart is cut: onto its own rectangle, or the square where that
// may bring it under the bound (a chart too small to cut takes the better of the two).
void map_to_decide(SolvedChart& chart, const Options& deciding, double max_stretch) {
  const bool may_cut = int(chart.faces.size()) >= 2 * kSmallestChart;
  solve(chart, deciding, 0, may_cut ? kSquareMayMeet * max_stretch : kInf);
  chart.deciding_map = true;
}

// A chart of fewer than 2 x kSmallestChart faces stays whole unless it stretches more than
// kSmallCutAbove times the bound and has kSmallestCutChart faces or more (charts.h).
bool too_small_to_cut(const SolvedChart& chart, double max_stretch) {
  const int faces = int(chart.faces.size());
  if (faces >= 2 * kSmallestChart) return false;
  return faces < kSmallestCutChart || chart.kept.l2_stretch <= kSmallCutAbove * max_stretch;
}

// Cuts the charts that stretch too much and maps the parts again, round after round, until every
// chart meets the bound, is too small to cut or the chart limit is reached; then undoes the cuts
// that did not pay. Returns the leaves, and if any part was cut, the components as they were.
Error split_until_bounded(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, std::vector<std::vector<int>> components,
                          const ChartOptions& options, std::vector<SolvedChart>& leaves, std::vector<SolvedChart>& uncut,
                          std::vector<std::string>& notes) {
  const std::vector<int> twin = opposite_half_edges(F);
  std::vector<std::vector<int>> local_of(kMostThreads);  // make_chart_mesh's scratch, per worker
  local_of[0].assign(size_t(unit_V.rows()), -1);
  ChartTree tree;
  for (std::vector<int>& faces : components) {
    tree.nodes.emplace_back();
    if (Error e = make_chart_mesh(unit_V, F, faces, local_of[0], tree.nodes.back().mesh)) return e;
    tree.nodes.back().faces = std::move(faces);
  }
  tree.parts.resize(tree.nodes.size());
  int charts = int(tree.nodes.size());
  bool limit_reached = false;
  // Deciding where to cut needs the map's stretch, not its last digits: U0 and U1 only (the atlas
  // came out the same on the shared meshes, 30-50% sooner), solved to kDecidingTolerance. The
  // layout maps each chart fully.
  Options deciding = options.disk;
  deciding.max_passes = std::min(deciding.max_passes, 1);
  deciding.solver.tolerance = std::max(deciding.solver.tolerance, kDecidingTolerance);
  deciding.solver.residual_accepted = std::max(deciding.solver.residual_accepted, 100 * deciding.solver.tolerance);
  for (size_t first = 0, end = tree.nodes.size(); first < end; first = end, end = tree.nodes.size()) {
    const size_t round_faces = faces_in(tree.nodes, first, end);
    for_each_index(int(end - first), [&](int i, int) {
      SolvedChart& chart = tree.nodes[first + size_t(i)];
      if (!chart.cut_ahead) map_to_decide(chart, for_share(deciding, chart.faces.size(), round_faces), options.max_stretch);
    }, largest_first(tree.nodes, first, end));
    // The charts the bound cuts, cut on both cores (a chart's parts depend on it alone: on the
    // 769k-face scan the cuts took 5.3 s on one); the chart limit is applied after, in order.
    std::vector<int> to_cut;
    for (size_t i = first; i < end; ++i) {
      if (tree.nodes[i].cut_ahead) continue;
      if (tree.nodes[i].map.error) return tree.nodes[i].map.error;
      if (!bound_cuts(tree.nodes[i], options.max_stretch)) continue;
      if (too_small_to_cut(tree.nodes[i], options.max_stretch)) tree.nodes[i].kept_whole = "too few faces to cut";
      else to_cut.push_back(int(i));
    }
    std::vector<Cut> cuts(to_cut.size());
    std::vector<int> order(to_cut.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      return tree.nodes[size_t(to_cut[size_t(a)])].faces.size() > tree.nodes[size_t(to_cut[size_t(b)])].faces.size();
    });
    for_each_index(int(to_cut.size()), [&](int k, int worker) {
      if (local_of[size_t(worker)].empty()) local_of[size_t(worker)].assign(size_t(unit_V.rows()), -1);
      const SolvedChart& chart = tree.nodes[size_t(to_cut[size_t(k)])];
      cuts[size_t(k)] = cut_with_cuts_ahead(unit_V, F, twin, chart, cuts_ahead(chart.kept, options),
                                                local_of[size_t(worker)]);
    }, order);
    for (size_t k = 0; k < to_cut.size(); ++k) {
      const size_t i = size_t(to_cut[k]);
      if (charts >= options.max_charts) {
        tree.nodes[i].kept_whole = "the chart limit is reached";
        limit_reached = true;
        continue;
      }
      Cut& cut = cuts[k];
      if (charts + int(cut.pieces.size()) - cut.ahead() - 1 > options.max_charts)
        keep_only_the_first_cut(unit_V, F, cut, local_of[0]);
      if (cut.pieces.empty()) tree.nodes[i].kept_whole = "no cut into disks was found";
      charts += std::max(0, int(cut.pieces.size()) - cut.ahead() - 1);
      const size_t base = tree.nodes.size();
      for (size_t j = 0; j < cut.pieces.size(); ++j) {
        tree.parts[cut.parent[j] < 0 ? i : base + size_t(cut.parent[j])].push_back(int(tree.nodes.size()));
        tree.nodes.push_back(std::move(cut.pieces[j]));
        tree.parts.emplace_back();
      }
    }
    if (options.disk.progress && !options.disk.progress(0.9 * (1 - std::pow(0.5, double(end))), "charts"))
      return {ErrorCode::Cancelled, 0, ""};
  }
  undo_cuts_that_did_not_pay(tree, options.max_stretch, [&](SolvedChart& chart) {
    if (make_chart_mesh(unit_V, F, chart.faces, local_of[0], chart.mesh)) return false;
    map_to_decide(chart, deciding, options.max_stretch);
    return !chart.map.error;
  });
  bool cut = false;
  for (size_t root = 0; root < components.size(); ++root) cut = cut || !tree.parts[root].empty();
  for (size_t root = 0; root < components.size() && cut; ++root) {
    uncut.push_back(tree.nodes[root]);
    if (!tree.parts[root].empty()) uncut.back().kept_whole = "one chart per part stretched less";
  }
  std::vector<int> stack;
  for (size_t root = components.size(); root-- > 0;) stack.push_back(int(root));
  while (!stack.empty()) {  // the leaves, depth first, parts in order
    const int i = stack.back();
    stack.pop_back();
    if (tree.parts[size_t(i)].empty()) leaves.push_back(std::move(tree.nodes[size_t(i)]));
    for (size_t k = tree.parts[size_t(i)].size(); k-- > 0;) stack.push_back(tree.parts[size_t(i)][k]);
  }
  if (limit_reached)
    notes.push_back("the chart limit (" + std::to_string(options.max_charts) + ") stopped the splitting");
  return {};
}

// How much better a free map must use its box: the rectangle's further passes and the free
// chart's cell, rarely of its shape, eat smaller gains (1: the camel 0.611 -> 0.575 in efficiency,
// 2: 0.604, 4: 0.614).
const double kFreeMustPay = 4;

// The chart's own shape seen along its normal, as a free map (one pass, already the map).
void map_as_seen_along_normal(SolvedChart& chart) {
  chart.free_boundary = true;
  chart.deciding_map = false;
  chart.map = Result();
  chart.map.uv = project_onto_own_plane(chart.mesh.V, chart.mesh.F.topRows(Eigen::Index(chart.faces.size())));
  chart.kept = measure_real_faces(chart.mesh, chart.map.uv);
  chart.passes = {chart.kept};
  PassMetrics only;
  only.l2_stretch = chart.kept.l2_stretch;
  only.flipped = chart.kept.flipped;
  only.degenerate = chart.kept.degenerate;
  chart.map.passes = {only};
  chart.fit_box();
}

// A chart whose rectangle uses its box poorly (kept above the bound: too small to cut, or its parts
// stretched more; or a hole closed for the map left empty) is mapped again free: with the natural
// boundary, or seen along its normal (a flat face of a CAD part, whose needles the natural boundary
// folds). It keeps the free map that uses its box best (fill / L2^2) if that beats the rectangle
// `must_pay` times and it does not fold over itself: a jagged sliver has no good rectangle (a
// 37-face strip of a scan: L2 46.7 on its rectangle, 1.0 free).
void free_the_charts_that_stretch(std::vector<SolvedChart>& charts, const ChartOptions& options, double must_pay = kFreeMustPay) {
  std::vector<int> above;
  // What a chart's map makes of its box: fill / L2^2 (a rectangle with a closed hole fills less than 1).
  const auto uses = [](const SolvedChart& c) {
    return c.kept.flipped + c.kept.degenerate > 0 ? 0 : c.fill() / (c.kept.l2_stretch * c.kept.l2_stretch);
  };
  // A free map covers at most its box at L2 at least 1: it can pay only below 1 / must_pay.
  for (size_t i = 0; i < charts.size(); ++i)
    if (!(uses(charts[i]) * must_pay > 1)) above.push_back(int(i));
  size_t above_faces = 0;
  for (const int i : above) above_faces += charts[size_t(i)].faces.size();
  for_each_index(int(above.size()), [&](int k, int) {
    SolvedChart& chart = charts[size_t(above[size_t(k)])];
    double best = must_pay * uses(chart);
    for (const bool seen_along_normal : {false, true}) {
      SolvedChart free;
      free.mesh = chart.mesh;
      free.faces = chart.faces;
      free.kept_whole = chart.kept_whole;
      if (seen_along_normal) map_as_seen_along_normal(free);
      else solve_onto(free, for_share(options.disk, chart.faces.size(), above_faces), 0, true);
      if (free.map.error || free.kept.flipped + free.kept.degenerate > 0) continue;
      if (!(uses(free) > best)) continue;
      if (uv_boundary_crosses_itself(free.mesh.F.topRows(Eigen::Index(free.faces.size())), free.map.uv)) continue;
      best = uses(free);
      chart = std::move(free);
    }
  });
}

// A free chart stretched along its box's sides to the box's width / height `aspect` (a map the
// method made is scaled, not solved again), and measured again.
void stretch_to_aspect(SolvedChart& chart, double aspect) {
  const double by = aspect / chart.aspect();
  chart.map.uv.col(0) *= std::sqrt(by);
  chart.map.uv.col(1) /= std::sqrt(by);
  chart.fit_box();
  chart.kept = measure_real_faces(chart.mesh, chart.map.uv);
  chart.passes.at(size_t(chart.map.chosen_pass)) = chart.kept;
}

// Above this share of the texture in cells raised to the smallest a gutter allows, a note says so.
const double kMostFlooredShare = 0.1;

// Every chart onto its cell of the tiling: mapped again onto a rectangle of the cell's shape
// (turned a quarter if the chart is wider the other way), then fitted into the cell less half
// the gutter on each side. Fills corner_uv and face_chart.
Error lay_out(std::vector<SolvedChart>& charts, const ChartOptions& options, Eigen::Index face_count, ChartsResult& result) {
  // Half the gutter around every cell, in [0,1]^2 before store() moves it into [g, 1 - g]^2.
  const double g = options.gutter / options.texture_size, inset = 0.5 * g / (1 - 2 * g);
  // A free chart's cell holds its box at the texel density of the others.
  std::vector<double> own_area;
  double total = 0;
  for (const SolvedChart& c : charts) {
    own_area.push_back(c.free_boundary ? c.kept.area_3d / std::max(c.fill(), 0.05) : c.kept.area_3d);
    total += own_area.back();
  }
  std::vector<double> preferred;
  // Cells no longer than four times their width, whatever the chart: a long thin cell has no
  // room for its gutter (the chart then fills part of it, kMostCellMismatch).
  for (const SolvedChart& c : charts) preferred.push_back(std::min(4.0, std::max(0.25, c.aspect())));
  // Every cell at least a few texels wide inside its gutter, whatever its chart's area: tiny
  // charts get a floor of area, raised until no cell is thinner than that (rows of many tiny
  // charts can be thin).
  std::vector<Eigen::AlignedBox2d> cells;
  double least = 0, floored_share = 0;
  int floored = 0;
  for (double texels = 2 * options.gutter + 4;; texels *= 1.5) {
    least = total * texels * texels / (double(options.texture_size) * options.texture_size);
    std::vector<double> areas;
    for (const double area : own_area) areas.push_back(std::max({area, least, 1e-300}));
    cells = slice_unit_square(areas, preferred);
    double thinnest = 1;
    for (const Eigen::AlignedBox2d& cell : cells) thinnest = std::min(thinnest, cell.sizes().minCoeff());
    floored = int(std::count_if(own_area.begin(), own_area.end(), [&](double a) { return a < least; }));
    floored_share = floored * least / std::accumulate(areas.begin(), areas.end(), 0.0);
    if (thinnest > 2 * inset + 2.0 / options.texture_size) break;
    if (least * double(charts.size()) > total) return {ErrorCode::ChartsNotPacked, static_cast<long long>(charts.size()), ""};
  }
  // Scan debris: tiny parts, each given a cell it cannot fill, leave the rest of the mesh little
  // texture (tests/bench/make_defects.py's debris30000: 66% of it, efficiency 0.25).
  if (floored_share > kMostFlooredShare)
    result.notes.push_back(std::to_string(floored) + " charts too small for the " + std::to_string(options.texture_size) +
                           "-texel texture take " + std::to_string(int(std::lround(100 * floored_share))) +
                           "% of it: remove tiny parts (MeshLab: Cleaning and Repairing > Remove Isolated pieces) "
                           "or use a larger texture");
  std::vector<char> turned(charts.size(), 0);
  const size_t all_faces = faces_in(charts, 0, charts.size());
  for_each_index(int(charts.size()), [&](int i, int) {
    SolvedChart& c = charts[size_t(i)];
    const double cell = cells[size_t(i)].sizes().x() / cells[size_t(i)].sizes().y();
    turned[size_t(i)] = std::abs(std::log(c.aspect() * cell)) < std::abs(std::log(c.aspect() / cell));
    // A cell far from the chart's shape (a small chart beside a large one gets a strip) is
    // filled only in part: stretching the chart to fit would cost more than the empty texels.
    const double fits = turned[size_t(i)] ? 1 / cell : cell;
    const double wanted = std::min(c.aspect() * kMostCellMismatch, std::max(c.aspect() / kMostCellMismatch, fits));
    if (c.free_boundary) {  // stretched to its cell's shape as far as a rectangle would be
      if (std::abs(std::log(wanted / c.aspect())) > 0.02) stretch_to_aspect(c, wanted);
      return;
    }
    // A map made while deciding where to cut had fewer passes and a looser solve.
    if (std::abs(std::log(wanted / c.aspect())) > 0.02 || c.deciding_map) solve(c, for_share(options.disk, c.faces.size(), all_faces), wanted);
  }, largest_first(charts, 0, charts.size()));
  result.corner_uv.resize(face_count, 6);
  result.face_chart.assign(size_t(face_count), 0);
  for (size_t c = 0; c < charts.size(); ++c) {
    if (charts[c].map.error) return charts[c].map.error;
    const ChartMesh& mesh = charts[c].mesh;
    const Eigen::MatrixXd& uv = charts[c].map.uv;
    const Eigen::AlignedBox2d& box = charts[c].box;
    Eigen::AlignedBox2d target = cells[c];
    target.min().array() += inset;
    target.max().array() -= inset;
    if (!(target.sizes().minCoeff() > 0) || !(box.sizes().minCoeff() > 0))
      return {ErrorCode::ChartsNotPacked, static_cast<long long>(charts.size()), ""};
    const double chart = turned[c] ? box.sizes().y() / box.sizes().x() : box.sizes().x() / box.sizes().y();
    Eigen::Vector2d size = target.sizes();
    if (std::abs(std::log(chart * size.y() / size.x())) > 0.02) {  // the part of the cell of the chart's shape
      if (chart > size.x() / size.y()) size.y() = size.x() / chart;
      else size.x() = size.y() * chart;
      target.max() = target.min() + size;
    }
    for (size_t j = 0; j < charts[c].faces.size(); ++j) {
      const int f = charts[c].faces[j];
      result.face_chart[size_t(f)] = int(c);
      for (int k = 0; k < 3; ++k) {
        Eigen::Vector2d p = ((uv.row(mesh.F(Eigen::Index(j), k)).transpose() - box.min()).array() / box.sizes().array()).matrix();
        if (turned[c]) p = Eigen::Vector2d(1 - p.y(), p.x());  // a quarter turn counter-clockwise
        p = target.min() + p.cwiseProduct(target.sizes());
        result.corner_uv.block(f, 2 * k, 1, 2) = p.transpose();
      }
    }
  }
  return {};
}

// The layout measured like a disk's pass, as a mesh of its own: three vertices per face, and an
// edge for every pair of corners that is one edge of the input and one edge of the layout.
void measure_layout(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, int vertex_rows,
                    const std::vector<std::vector<int>>& faces_of, ChartsResult& result) {
  Eigen::MatrixXd corner_V(3 * F.rows(), 3), corner_uv(3 * F.rows(), 2);
  Eigen::MatrixXi corner_F(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      corner_V.row(3 * f + k) = unit_V.row(F(f, k));
      corner_F(f, k) = int(3 * f + k);
      corner_uv.row(3 * f + k) = result.corner_uv.block(f, 2 * k, 1, 2);
    }
  std::vector<std::array<int, 2>> edges;
  const std::vector<int> twin = opposite_half_edges(F);
  for (int h = 0; h < int(twin.size()); ++h) {
    const int t = twin[size_t(h)];
    const bool joined = t >= 0 && result.face_chart[size_t(h / 3)] == result.face_chart[size_t(t / 3)] &&
                        corner_uv.row(h) == corner_uv.row(next_half_edge(t)) &&
                        corner_uv.row(next_half_edge(h)) == corner_uv.row(t);
    if (!joined || h < t) edges.push_back({h, next_half_edge(h)});
  }
  Eigen::MatrixXi corner_edges(Eigen::Index(edges.size()), 2);
  for (size_t e = 0; e < edges.size(); ++e) corner_edges.row(Eigen::Index(e)) << edges[e][0], edges[e][1];
  const FaceStretch s = face_stretch(corner_V, corner_F, corner_uv);
  result.layout = measure(corner_V, corner_F, corner_edges, corner_uv, s);
  result.coverage = s.area_uv.cwiseAbs().sum();
  result.face_stretch.resize(F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) result.face_stretch(f) = s.valid(f) ? s.normalization * s.sigma(f) : kInf;
  result.vertex_stretch = vertex_stretch(F, vertex_rows, s);
  std::vector<char> used(size_t(vertex_rows), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) used[size_t(F(f, k))] = 1;
  for (int v = 0; v < vertex_rows; ++v)
    if (!used[size_t(v)]) result.vertex_stretch(v) = 0;
  for (size_t c = 0; c < faces_of.size(); ++c) {
    double area_3d = 0, area_uv = 0, linf = 0;
    for (int f : faces_of[c]) {
      area_3d += s.area_3d(f);
      area_uv += std::abs(s.area_uv(f));
      linf = std::max(linf, s.valid(f) ? s.gamma(f) : kInf);
    }
    result.charts[c].l2_stretch = l2_stretch(s, faces_of[c]);
    result.charts[c].linf_stretch = area_3d > 0 ? std::sqrt(area_uv / area_3d) * linf : kInf;
  }
}

// 3D length of the edges whose two faces are in different charts.
double length_between_charts(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::vector<int>& face_chart) {
  const std::vector<int> twin = opposite_half_edges(F);
  double length = 0;
  for (int h = 0; h < int(twin.size()); ++h) {
    const int t = twin[size_t(h)];
    if (t > h && face_chart[size_t(h / 3)] != face_chart[size_t(t / 3)])
      length += (V.row(half_edge_tail(F, h)) - V.row(half_edge_head(F, h))).norm();
  }
  return length;
}

// The measures of `from` (stretch, distortions, flips) into `to`, whose pass and timings stay.
void copy_measures(const PassMetrics& from, PassMetrics& to) {
  to.l2_stretch = from.l2_stretch;
  to.linf_stretch = from.linf_stretch;
  to.edge_distortion = from.edge_distortion;
  to.angle_distortion = from.angle_distortion;
  to.area_distortion = from.area_distortion;
  to.flipped = from.flipped;
  to.degenerate = from.degenerate;
}

double corner_area(const Eigen::MatrixXd& corner_uv, Eigen::Index f) {
  const auto c = [&](int k) { return Eigen::Vector2d(corner_uv.block(f, 2 * k, 1, 2).transpose()); };
  return signed_uv_area(c(0), c(1), c(2));
}

// The layout as MeshLab stores it: inside the gutter, rounded to float, then measured; counts
// the triangles no texture shows (smaller than a texel of 4096^2) and those that rounding flips or
// collapses (a note).
void store(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, int vertex_rows,
           const std::vector<std::vector<int>>& faces_of, const ChartOptions& options, ChartsResult& result) {
  keep_inside_gutter(options, result.corner_uv);
  std::vector<char> positive(size_t(F.rows()));
  for (Eigen::Index f = 0; f < F.rows(); ++f) positive[size_t(f)] = corner_area(result.corner_uv, f) > 0;
  result.corner_uv = result.corner_uv.cast<float>().cast<double>();
  const double texel = 1.0 / (4096.0 * 4096.0);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const double area = corner_area(result.corner_uv, f);
    result.subtexel_triangles += std::abs(area) < texel;
    result.float_collapsed += positive[size_t(f)] && !(area > 0);
  }
  if (result.float_collapsed > 0)
    result.notes.push_back(std::to_string(result.float_collapsed) +
                           " UV triangles flip or collapse when their texture coordinates are rounded to float, "
                           "as MeshLab stores them: the metrics count them");
  measure_layout(unit_V, F, vertex_rows, faces_of, result);
}

// "chart 3", "charts 1, 4, 9", "charts 1, 4, 9 and 812 more".
std::string charts_text(const std::vector<int>& charts) {
  std::string text = charts.size() == 1 ? "chart " : "charts ";
  for (size_t i = 0; i < charts.size() && i < 3; ++i) text += (i ? ", " : "") + std::to_string(charts[i]);
  if (charts.size() > 3) text += " and " + std::to_string(charts.size() - 3) + " more";
  return text;
}

// The charts laid out and measured as the result.
ChartsResult atlas_of(std::vector<SolvedChart> charts, const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, double unit,
                      int vertex_rows, const ChartOptions& options) {
  ChartsResult result;
  if (Error e = lay_out(charts, options, F.rows(), result)) return failed(e);
  std::vector<std::vector<int>> faces_of;
  std::vector<std::vector<ChartPass>> passes;
  std::vector<int> kept;
  std::vector<std::string> chart_notes;  // the core's notes, each with the charts it was given for
  std::vector<std::vector<int>> noted;
  for (const SolvedChart& c : charts) {
    Chart chart;
    chart.kept_whole = c.kept_whole ? c.kept_whole : "its cell's shape stretched it";
    chart.faces = int(c.faces.size());
    chart.closed_holes = c.mesh.closed_holes;
    chart.seam_length = c.mesh.seam_length * unit;
    chart.chosen_pass = c.map.chosen_pass;
    chart.passes = int(c.map.passes.size());
    result.charts.push_back(chart);
    result.seam_length += chart.seam_length;
    for (std::string note : c.map.notes) {
      const size_t digits = note.find_first_not_of("0123456789");  // "6 interior edges ...": one note for all counts
      if (digits > 0 && digits != std::string::npos && note[digits] == ' ') note = "some" + note.substr(digits);
      const size_t k = size_t(std::find(chart_notes.begin(), chart_notes.end(), note) - chart_notes.begin());
      if (k == chart_notes.size()) {
        chart_notes.push_back(note);
        noted.emplace_back();
      }
      noted[k].push_back(int(faces_of.size()));
    }
    faces_of.push_back(c.faces);
    passes.push_back(c.passes);
    kept.push_back(c.map.chosen_pass);
  }
  result.passes = layout_passes(passes, kept);
  result.seam_length += unit * length_between_charts(unit_V, F, result.face_chart);
  store(unit_V, F, vertex_rows, faces_of, options, result);
  for (size_t k = 0; k < chart_notes.size(); ++k) result.notes.push_back(charts_text(noted[k]) + ": " + chart_notes[k]);
  // Every chart above the bound is one note while they are few; past that, one note per reason.
  std::vector<int> above;
  for (size_t c = 0; c < result.charts.size(); ++c) {
    Chart& chart = result.charts[c];
    chart.above_bound = !(chart.l2_stretch <= options.max_stretch);
    if (chart.above_bound) above.push_back(int(c));
  }
  const size_t listed = 10;
  for (size_t k = 0; k < above.size() && (above.size() <= listed || k < listed); ++k) {
    const Chart& chart = result.charts[size_t(above[k])];
    result.notes.push_back("chart " + std::to_string(above[k]) + " (" + std::to_string(chart.faces) + " faces) keeps L2 stretch " +
                           number_text(chart.l2_stretch) + " above " + number_text(options.max_stretch) + ": " +
                           chart.kept_whole);
  }
  if (above.size() > listed) {
    std::vector<std::string> reasons;
    std::vector<std::vector<int>> of;
    for (int c : above) {
      const std::string reason = result.charts[size_t(c)].kept_whole;
      const size_t k = size_t(std::find(reasons.begin(), reasons.end(), reason) - reasons.begin());
      if (k == reasons.size()) {
        reasons.push_back(reason);
        of.emplace_back();
      }
      of[k].push_back(c);
    }
    for (size_t k = 0; k < reasons.size(); ++k)
      result.notes.push_back(charts_text(of[k]) + " keep an L2 stretch above " + number_text(options.max_stretch) + ": " +
                             reasons[k]);
  }
  return result;
}

// What one chart per part could reach at best, from the parts' maps while deciding (U1; the
// layout's further passes lower L2 by some percent): coverage 1 over their L2^2.
double best_possible_efficiency(const std::vector<SolvedChart>& parts) {
  double weighted = 0, area = 0;
  for (const SolvedChart& c : parts) {
    if (c.kept.flipped + c.kept.degenerate > 0) return 0;
    weighted += c.kept.area_3d * c.kept.l2_stretch * c.kept.l2_stretch;
    area += c.kept.area_3d;
  }
  return weighted > 0 ? area / weighted : 0;
}
// An atlas this much more efficient than that bound skips laying out one chart per part.
const double kClearlyBetter = 1.25;

// Normals more than this apart make an edge sharp. On CGAL's CAD parts (efficiency cut along
// sharp edges at 60 / 80 / 85 degrees, with kFreeFacesMustPay 1): pinion 0.780 / 0.878 / 0.878, fandisk 0.704 / 0.759 / 0.739;
// couplingdown, rotor, anchor, joint the same at all three.
const double kSharpEdgeDegrees = 80;
// The share of the area that the sharp edges must split off the parts' largest patches for the
// model to be tried cut along them: CGAL's CAD parts 0.25 or more, its statues and animals 0.001
// or less (their sharp edges are creases and spikes).
const double kFacesShare = 0.01;
// A face of a model cut along its sharp edges is mostly a plane, a cylinder or a fillet, which a free
// map keeps with little stretch; so a free map need pay less than on a statue. Which of these pays
// best depends on the part, so both are laid out (tool's efficiency, free maps paying 1 / 2 / either:
// joint 0.814 / 0.670 / 0.814, couplingdown 0.556 / 0.528 / 0.556, anchor 0.428 / 0.474 / 0.474).
const double kFreeFacesMustPay[] = {2, 1};
// A model made of faces is also cut to a tighter bound, this share of the bound's excess over 1
// (1.2 -> 1.1): its faces are mostly flat, so more cuts leave charts that fill their rectangles
// with little stretch (tool's efficiency cut to 1.2 / 1.1: rotor 0.486 / 0.599, dragknob 0.640 / 0.833,
// fandisk 0.759 / 0.798).
const double kFacesExcessKept = 0.5;

// Whether the sharp edges split the parts into faces of their own (a CAD model), rather than nick
// them (a statue's creases): the patches beside each part's largest hold kFacesShare of the area.
bool has_faces_of_its_own(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const std::vector<int>& component,
                          const std::vector<std::vector<int>>& patches) {
  std::vector<double> largest;
  double total = 0;
  for (const std::vector<int>& patch : patches) {
    double area = 0;
    for (const int f : patch) {
      const Eigen::Vector3d a = unit_V.row(F(f, 0)), b = unit_V.row(F(f, 1)), c = unit_V.row(F(f, 2));
      area += 0.5 * (b - a).cross(c - a).norm();
    }
    const size_t part = size_t(component[size_t(patch.front())]);
    if (largest.size() <= part) largest.resize(part + 1, 0);
    largest[part] = std::max(largest[part], area);
    total += area;
  }
  return total - std::accumulate(largest.begin(), largest.end(), 0.0) >= kFacesShare * total;
}

// Any mesh as charts: its components, cut until they meet the bound, laid out; or one chart per
// component if that uses the texture better.
ChartsResult make_atlas(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options) {
  // parameterize checked indices, coordinates, edges and orientation of the whole mesh before it
  // found the topology wrong; vertex fans are checked per component and between components.
  int count = 0;
  const std::vector<int> component = face_components(F, count);
  if (const int shared = vertices_shared_by_components(F, int(V.rows()), component))
    return failed({ErrorCode::NonManifoldVertices, shared, ""});
  std::vector<std::vector<int>> components(static_cast<size_t>(count));
  for (Eigen::Index f = 0; f < F.rows(); ++f) components[size_t(component[size_t(f)])].push_back(int(f));

  double unit = 1;
  const Eigen::MatrixXd unit_V = unit_box_of_used(V, F, unit);
  std::vector<std::string> notes;
  if (options.disk.boundary != BoundaryShape::Square)
    notes.push_back("an atlas maps every chart onto a rectangle: the boundary option applies to disks only");
  std::vector<SolvedChart> leaves, uncut;
  const size_t part_count = components.size(), common_notes = notes.size();
  // The atlases tried after the first start their progress again: it is reported as the most reached.
  double reached = 0;
  ChartOptions reporting = options;
  if (options.disk.progress)
    reporting.disk.progress = [&](double fraction, const char* stage) {
      reached = std::max(reached, fraction);
      return options.disk.progress(reached, stage);
    };
  if (Error e = split_until_bounded(unit_V, F, std::move(components), reporting, leaves, uncut, notes)) return failed(e);
  free_the_charts_that_stretch(leaves, options);
  const size_t cut_into = leaves.size();
  const bool bound_cut = !uncut.empty();
  ChartsResult result = atlas_of(std::move(leaves), unit_V, F, unit, int(V.rows()), options);
  if (!uncut.empty() && !(texture_efficiency(result) > kClearlyBetter * best_possible_efficiency(uncut))) {
    ChartsResult whole = atlas_of(std::move(uncut), unit_V, F, unit, int(V.rows()), options);
    if (texture_efficiency(whole) > texture_efficiency(result) || (texture_efficiency(whole) == texture_efficiency(result) &&
                                                                   whole.layout.flipped + whole.layout.degenerate <
                                                                       result.layout.flipped + result.layout.degenerate)) {
      whole.notes.push_back("one chart per part: cut into " + std::to_string(cut_into) + " charts, the atlas had efficiency " +
                            number_text(texture_efficiency(result)) + " (coverage / L2^2) against " + number_text(texture_efficiency(whole)));
      result = std::move(whole);
    }
  }
  // A model made of faces (a CAD part) whose parts the bound cuts, or would cut but for the undo,
  // is tried cut along its sharp edges first.
  const bool above = bound_cut || std::any_of(result.charts.begin(), result.charts.end(), [](const Chart& c) { return c.above_bound; });
  std::vector<std::vector<int>> patches;
  if (above) patches = patches_between_sharp_edges(unit_V, F, kSharpEdgeDegrees);
  if (patches.size() > part_count && has_faces_of_its_own(unit_V, F, component, patches)) {
    const double best_before = texture_efficiency(result);
    for (const double excess_kept : {1.0, kFacesExcessKept}) {
      ChartOptions by_faces_options = reporting;
      by_faces_options.max_stretch = 1 + excess_kept * (options.max_stretch - 1);
      std::vector<SolvedChart> by_faces_leaves, unused;
      std::vector<std::string> by_faces_notes;
      const Error e = split_until_bounded(unit_V, F, patches, by_faces_options, by_faces_leaves, unused, by_faces_notes);
      if (e.code == ErrorCode::Cancelled) return failed(e);
      if (e) continue;
      for (const double must_pay : kFreeFacesMustPay) {
        std::vector<SolvedChart> leaves_of_try = by_faces_leaves;
        free_the_charts_that_stretch(leaves_of_try, options, must_pay);
        ChartsResult by_faces = atlas_of(std::move(leaves_of_try), unit_V, F, unit, int(V.rows()), options);
        if (!(texture_efficiency(by_faces) > texture_efficiency(result))) continue;
        result = std::move(by_faces);
        notes.resize(common_notes);  // the first cut's notes go with its atlas
        notes.insert(notes.end(), by_faces_notes.begin(), by_faces_notes.end());
        notes.push_back("charts cut along the sharp edges first (a model made of faces)" +
                        std::string(excess_kept < 1 ? ", to L2 stretch " + number_text(by_faces_options.max_stretch) : "") +
                        ": efficiency " + number_text(texture_efficiency(result)) + " (coverage / L2^2) against " +
                        number_text(best_before));
      }
    }
  }
  result.notes.insert(result.notes.begin(), notes.begin(), notes.end());
  return result;
}

}  // namespace

ChartsResult parameterize_charts(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options) {
  const Clock::time_point start = Clock::now();
  if (Error e = check_chart_options(options)) return failed(e);
  Result whole = parameterize(V, F, options.disk);
  const auto disk_result = [&]() {
    ChartsResult result = from_disk(F, std::move(whole));
    double unit = 1;
    std::vector<int> all(static_cast<size_t>(F.rows()));
    for (Eigen::Index f = 0; f < F.rows(); ++f) all[size_t(f)] = int(f);
    store(unit_box_of_used(V, F, unit), F, int(V.rows()), {all}, options, result);
    // The layout is the kept pass, as stored: its number, timings and solver stay.
    const PassMetrics measured = result.layout;
    result.layout = result.disk_passes.at(size_t(result.chosen_pass));
    copy_measures(measured, result.layout);
    result.seconds_total = std::chrono::duration<double>(Clock::now() - start).count();
    return result;
  };
  // Parts or holes that touch at a vertex: the charts are made on the mesh with that vertex split
  // into one per fan of faces. (Such a vertex is found after several components, so both codes.)
  const ErrorCode found = whole.error.code;
  if (options.non_disk != NonDisk::Reject && (found == ErrorCode::NonManifoldVertices || found == ErrorCode::SeveralComponents)) {
    const SplitFans split = split_vertex_fans(V, F);
    if (split.split_vertices > 0) {
      ChartsResult result = parameterize_charts(split.V, split.F, options);
      if (result.error) return result;
      result.vertex_stretch = join_vertex_values(split, result.vertex_stretch, int(V.rows()));
      const bool one = split.split_vertices == 1;
      result.notes.insert(result.notes.begin(), std::to_string(split.split_vertices) +
                                                    (one ? " non-manifold vertex" : " non-manifold vertices") +
                                                    " (where parts or holes touch) split per fan of faces for the "
                                                    "charts; the mesh is unchanged");
      result.seconds_total = std::chrono::duration<double>(Clock::now() - start).count();
      return result;
    }
  }
  const bool split_disk = !whole.error && options.non_disk == NonDisk::Atlas &&
                          needs_split(as_chart_pass(whole.passes.at(size_t(whole.chosen_pass))), options.max_stretch);
  if (!whole.error && !split_disk) return disk_result();
  if (!split_disk && (options.non_disk == NonDisk::Reject || !charts_can_fix(whole.error.code))) return failed(whole.error);
  const OneBlasThread one_blas_thread;  // both cores go to the charts
  ChartsResult atlas = make_atlas(V, F, options);
  // A disk whose atlas uses the texture worse than its single map keeps the single map.
  if (split_disk && !atlas.error) {
    ChartsResult disk = disk_result();
    if (texture_efficiency(disk) >= texture_efficiency(atlas)) {
      disk.notes.push_back("the disk stays one chart: cut into " + std::to_string(atlas.charts.size()) +
                           " charts it had efficiency " + number_text(texture_efficiency(atlas)) + " (coverage / L2^2) against " +
                           number_text(texture_efficiency(disk)));
      return disk;
    }
  }
  atlas.seconds_total = std::chrono::duration<double>(Clock::now() - start).count();
  atlas.layout.seconds = atlas.seconds_total;
  return atlas;
}

double texture_efficiency(const ChartsResult& r) {
  return r.error ? -1 : r.coverage / (r.layout.l2_stretch * r.layout.l2_stretch);
}

double largest_chart_stretch(const ChartsResult& r) {
  double largest = 0;
  for (const Chart& c : r.charts) largest = std::max(largest, c.l2_stretch);
  return largest;
}

const char* to_string(NonDisk non_disk) {
  switch (non_disk) {
    case NonDisk::Reject: return "reject";
    case NonDisk::Charts: return "charts";
    case NonDisk::Atlas: return "atlas";
  }
  return "?";
}

}  // namespace lowstretch
