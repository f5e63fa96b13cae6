#include "atlas/measure/valid_as_stored.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "atlas/bound/cut_invalid_charts.h"
#include "atlas/measure/atlas_result.h"
#include "atlas/measure/free_squares.h"
#include "core/parameterize.h"
#include "core/stretch.h"

namespace lowstretch {

namespace {

// A face whose height is under this share of its longest side is a needle: alone, it is laid out
// as a right triangle, whose UV area float keeps.
constexpr double kNeedle = 0.05;
constexpr int kRounds = 3;
// The strip takes at most half the texture's height (strip_for): what stays shrinks to a quarter
// of its area and half its size at most, a little more for the gutter store() adds.
constexpr double kSqueezed = 4.5;
constexpr double kSqueezedSide = 2.1;

// Faces laid out together in one cell of the strip: their corners' UV (#faces x 6) in units of
// their own.
struct Piece {
  std::vector<int> faces;
  Eigen::MatrixXd corner_uv;
};

// A face alone: its triangle laid flat, counter-clockwise; a needle (or a face without area) as a
// right triangle.
Piece single_face(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, int f) {
  const Eigen::Vector3d a = unit_V.row(F(f, 0)), b = unit_V.row(F(f, 1)), c = unit_V.row(F(f, 2));
  const double ab = (b - a).norm(), twice_area = (b - a).cross(c - a).norm();
  const double longest = std::max({ab, (c - b).norm(), (a - c).norm()});
  Piece piece{{f}, Eigen::MatrixXd(1, 6)};
  if (ab > 0 && twice_area > kNeedle * longest * longest)
    piece.corner_uv << 0, 0, ab, 0, (c - a).dot(b - a) / ab, twice_area / ab;
  else
    piece.corner_uv << 0, 0, 1, 0, 0, 1;
  return piece;
}

// The chart's faces mapped again by the paper's method onto a square with Floater's weights
// (positive weights, convex boundary: no triangle folds); false if they are not a disk.
bool mapped_again(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const std::vector<int>& faces,
                  const ChartOptions& options, Piece& piece) {
  std::vector<int> local(size_t(unit_V.rows()), -1), global;
  Eigen::MatrixXi chart_F(Eigen::Index(faces.size()), 3);
  for (size_t j = 0; j < faces.size(); ++j)
    for (int k = 0; k < 3; ++k) {
      int& l = local[size_t(F(faces[j], k))];
      if (l < 0) {
        l = int(global.size());
        global.push_back(F(faces[j], k));
      }
      chart_F(Eigen::Index(j), k) = l;
    }
  Eigen::MatrixXd chart_V(Eigen::Index(global.size()), 3);
  for (size_t i = 0; i < global.size(); ++i) chart_V.row(Eigen::Index(i)) = unit_V.row(global[i]);
  Options floater;  // the defaults: Floater's weights onto the square
  floater.solver = options.disk.solver;
  floater.measure_distortions = false;
  const Result map = parameterize(chart_V, chart_F, floater);
  if (map.error) return false;
  piece.faces = faces;
  piece.corner_uv.resize(chart_F.rows(), 6);
  for (Eigen::Index f = 0; f < chart_F.rows(); ++f)
    for (int k = 0; k < 3; ++k) piece.corner_uv.block(f, 2 * k, 1, 2) = map.uv.row(chart_F(f, k));
  return true;
}

// The gutter in [0,1]^2 as the layout is before store() moves it inside the gutter, shrinking it
// by 1 - 2g.
double gutter_before_store(const ChartOptions& options) {
  const double g = options.gutter / options.texture_size;
  return g / (1 - 2 * g);
}

// Square cells in rows along the top of [0,1]^2, as many as the pieces; the strip is as high as
// the moved faces' share of the area (at least 8 gutters, at most half the texture, all of it if
// no face stays).
struct Strip {
  double side = 0, height = 0, margin = 0;
  int columns = 1;
  double share_side = 0;  // the side the moved faces' share of the area gives (free texels start there)
};

Strip strip_for(size_t pieces, double area_share, bool none_stays, const ChartOptions& options) {
  const double g = options.gutter / options.texture_size, n = double(pieces);
  const double target = none_stays ? 1 : std::min(0.5, std::max(area_share, 8 * g));
  const auto rows = [&](double side) { return std::ceil(n / std::floor(1 / side)); };
  Strip strip;
  strip.side = std::min(target, std::sqrt(target / n));
  while (rows(strip.side) * strip.side > target) strip.side *= 0.95;
  strip.share_side = strip.side;
  // Half a gutter on each side of a cell: cells at least 1.5 gutters wide (a face half a gutter
  // across), the strip higher than the moved faces' share if need be, up to the height it may
  // take; beyond, an eighth of a cell.
  const double gutter = gutter_before_store(options), least = 1.5 * gutter;
  if (strip.side < least && rows(least) * least <= (none_stays ? 1 : 0.5)) strip.side = least;
  strip.columns = int(std::floor(1 / strip.side));
  strip.height = rows(strip.side) * strip.side;
  strip.margin = strip.side >= least ? gutter / 2 : strip.side / 8;
  return strip;
}

// How a round went: faces made charts of their own, charts mapped again.
struct Moved {
  int faces = 0, charts = 0;
};

// What leaves its chart in one round: the charts mapped again, then the faces alone, as pieces.
struct Moving {
  std::vector<char> moves;  // per face
  std::vector<Piece> pieces;
  size_t mapped = 0;        // pieces[0, mapped) are charts mapped again
};

// The charts holding a flipped face mapped again (`map_again`; taken apart where they are no
// disk), every other invalid face alone.
Moving pieces_to_move(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const ChartOptions& options,
                      const ChartsResult& result, const std::vector<std::vector<int>>& faces_of,
                      const std::vector<int>& invalid, bool map_again, Moved& moved) {
  Moving m;
  std::vector<char> alone(size_t(F.rows()), 0), folded(faces_of.size(), 0);
  for (const int f : invalid) {
    alone[size_t(f)] = 1;
    if (corner_area(result.corner_uv, f) < 0) folded[size_t(result.face_chart[size_t(f)])] = 1;
  }
  for (size_t c = 0; c < faces_of.size() && map_again; ++c) {
    if (!folded[c]) continue;
    Piece piece;
    const bool disk = mapped_again(unit_V, F, faces_of[c], options, piece);
    for (const int f : faces_of[c]) alone[size_t(f)] = !disk;
    if (disk) {
      m.pieces.push_back(std::move(piece));
      ++moved.charts;
    }
  }
  m.mapped = m.pieces.size();
  m.moves.assign(size_t(F.rows()), 0);
  for (const Piece& piece : m.pieces)
    for (const int f : piece.faces) m.moves[size_t(f)] = 1;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    if (alone[size_t(f)]) {
      m.pieces.push_back(single_face(unit_V, F, int(f)));
      m.moves[size_t(f)] = 1;
      ++moved.faces;
    }
  return m;
}

// The piece scaled uniformly into the square of `side` at `origin`, into uv.
void put_in_square(const Piece& piece, const Eigen::Vector2d& origin, double side, Eigen::MatrixXd& uv) {
  Eigen::AlignedBox2d box;
  for (Eigen::Index j = 0; j < piece.corner_uv.rows(); ++j)
    for (int k = 0; k < 3; ++k) box.extend(Eigen::Vector2d(piece.corner_uv.block(j, 2 * k, 1, 2).transpose()));
  const double scale = side / box.sizes().maxCoeff();
  for (size_t j = 0; j < piece.faces.size(); ++j)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d corner = piece.corner_uv.block(Eigen::Index(j), 2 * k, 1, 2).transpose();
      uv.block(piece.faces[j], 2 * k, 1, 2) = (origin + scale * (corner - box.min())).transpose();
    }
}

// The pieces in squares of the texels the layout that stays leaves free, as large as the moved
// faces' share of the area gives (strip.share_side) or down to an eighth of that, the layout kept as it is (in [0,1]^2, which store() moves
// inside the gutter again): its gutters stay. False if they do not all fit.
bool put_in_free_texels(const ChartsResult& result, const Moving& m, const Strip& strip, const ChartOptions& options,
                        Eigen::MatrixXd& uv) {
  const double g = options.gutter / options.texture_size;
  std::vector<char> stays(m.moves.size());
  for (size_t f = 0; f < stays.size(); ++f) stays[f] = !m.moves[f];
  for (double side = strip.share_side; side >= strip.share_side / 8; side /= 2) {
    const std::vector<Eigen::Vector2d> squares = free_squares(result.corner_uv, stays, m.pieces.size(), side * (1 - 2 * g), options);
    if (squares.empty()) continue;
    uv = ((result.corner_uv.array() - g) / (1 - 2 * g)).matrix();
    for (size_t p = 0; p < m.pieces.size(); ++p)
      put_in_square(m.pieces[p], ((squares[p].array() - g) / (1 - 2 * g)).matrix(), side, uv);
    return true;
  }
  return false;
}

// The pieces in the cells of the strip along the top, the layout that stays scaled below it,
// a gutter lower. Its gutters shrink with it: each chart that stays also shrinks about its box's
// centre by what they lost, which gives them back (a speck under 1.1 times that loss shrinks to a
// tenth of its size and keeps less).
void put_in_strip(const ChartsResult& result, const Moving& m, const Strip& strip, const ChartOptions& options,
                  Eigen::MatrixXd& uv) {
  const double g = options.gutter / options.texture_size;
  const double scale = 1 - strip.height - strip.margin;
  uv = ((result.corner_uv.array() - g) / (1 - 2 * g) * scale).matrix();
  const double lost = gutter_before_store(options) * (1 - scale);
  std::vector<Eigen::AlignedBox2d> boxes(result.charts.size());
  const auto corner = [&](Eigen::Index f, int k) { return Eigen::Vector2d(uv.block(f, 2 * k, 1, 2).transpose()); };
  for (Eigen::Index f = 0; f < uv.rows(); ++f)
    for (int k = 0; k < 3 && !m.moves[size_t(f)]; ++k) boxes[size_t(result.face_chart[size_t(f)])].extend(corner(f, k));
  for (Eigen::Index f = 0; f < uv.rows(); ++f) {
    if (m.moves[size_t(f)]) continue;
    const Eigen::AlignedBox2d& box = boxes[size_t(result.face_chart[size_t(f)])];
    const double shrink = std::max(0.1, 1 - lost / box.sizes().minCoeff());
    for (int k = 0; k < 3; ++k) uv.block(f, 2 * k, 1, 2) = (box.center() + shrink * (corner(f, k) - box.center())).transpose();
  }
  for (size_t p = 0; p < m.pieces.size(); ++p) {
    const Eigen::Vector2d origin(double(p % size_t(strip.columns)) * strip.side + strip.margin,
                                 1 - strip.height + double(p / size_t(strip.columns)) * strip.side + strip.margin);
    put_in_square(m.pieces[p], origin, strip.side - 2 * strip.margin, uv);
  }
}

// The charts after a round: the old ones with the faces that stay (if any), then the pieces.
void regroup(const ChartsResult& result, const std::vector<std::vector<int>>& faces_of, const Moving& m,
             std::vector<Chart>& charts, std::vector<std::vector<int>>& new_faces_of, std::vector<int>& face_chart) {
  for (size_t c = 0; c < faces_of.size(); ++c) {
    std::vector<int> staying;
    for (const int f : faces_of[c])
      if (!m.moves[size_t(f)]) staying.push_back(f);
    if (staying.empty()) continue;
    for (const int f : staying) face_chart[size_t(f)] = int(charts.size());
    charts.push_back(result.charts[c]);
    charts.back().faces = int(staying.size());
    new_faces_of.push_back(std::move(staying));
  }
  for (size_t p = 0; p < m.pieces.size(); ++p) {
    Chart chart;
    chart.faces = int(m.pieces[p].faces.size());
    chart.kept_whole = p < m.mapped ? "mapped again onto a square where its map folded"
                                    : "a face on its own, where its chart's map was invalid";
    for (const int f : m.pieces[p].faces) face_chart[size_t(f)] = int(charts.size());
    charts.push_back(chart);
    new_faces_of.push_back(m.pieces[p].faces);
  }
}

// One round: the pieces laid out in free texels (or in the strip, the rest of the layout below
// it); stored and measured again.
ChartsResult with_invalid_faces_moved(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, double unit, int vertex_rows,
                                      const ChartOptions& options, ChartsResult result, const std::vector<int>& invalid,
                                      bool map_again, Moved& moved) {
  std::vector<std::vector<int>> faces_of(result.charts.size());
  for (Eigen::Index f = 0; f < F.rows(); ++f) faces_of[size_t(result.face_chart[size_t(f)])].push_back(int(f));
  const Moving m = pieces_to_move(unit_V, F, options, result, faces_of, invalid, map_again, moved);
  double moved_area = 0, area = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    area += face_area_3d(unit_V, F, f);
    if (m.moves[size_t(f)]) moved_area += face_area_3d(unit_V, F, f);
  }
  const bool none_stays = std::count(m.moves.begin(), m.moves.end(), 1) == F.rows();
  const Strip strip = strip_for(m.pieces.size(), area > 0 ? moved_area / area : 0, none_stays, options);

  Eigen::MatrixXd uv;
  if (none_stays || !put_in_free_texels(result, m, strip, options, uv)) put_in_strip(result, m, strip, options, uv);

  std::vector<Chart> charts;
  std::vector<std::vector<int>> new_faces_of;
  std::vector<int> face_chart(size_t(F.rows()));
  regroup(result, faces_of, m, charts, new_faces_of, face_chart);
  result.seam_length += unit * (length_between_charts(unit_V, F, face_chart) - length_between_charts(unit_V, F, result.face_chart));
  result.charts = std::move(charts);
  result.face_chart = std::move(face_chart);
  result.corner_uv = std::move(uv);
  result.subtexel_triangles = result.float_collapsed = 0;
  store(unit_V, F, vertex_rows, new_faces_of, options, result);
  if (result.input_is_disk) {  // a disk's layout is its kept pass, as stored (as disk_result keeps it)
    const PassMetrics measured = result.layout;
    result.layout = result.disk_passes.at(size_t(result.chosen_pass));
    copy_measures(measured, result.layout);
  }
  for (Chart& chart : result.charts) chart.above_bound = !(chart.l2_stretch <= options.max_stretch);
  return result;
}

}  // namespace

ChartsResult valid_as_stored(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, double unit, int vertex_rows,
                             const ChartOptions& options, ChartsResult result) {
  if (result.error) return result;
  Moved moved;
  for (int round = 0;; ++round) {
    if (invalid_faces(unit_V, F, result.corner_uv, kTuning.least_uv_area, kTuning.written_uv_rounding).empty()) break;
    if (round == kRounds) return failed_result({ErrorCode::ChartsNotPacked, int(result.charts.size()), ""});
    // The layout that stays is squeezed below the strip, at most to half its height: the faces
    // that would then fall under the least area (a scan's specks) move too.
    const std::vector<int> moving = invalid_faces(unit_V, F, result.corner_uv, kSqueezed * kTuning.least_uv_area,
                                                  kSqueezedSide * kTuning.written_uv_rounding);
    result = with_invalid_faces_moved(unit_V, F, unit, vertex_rows, options, std::move(result), moving, round == 0, moved);
  }
  const auto count = [](int n, const char* one, const char* many) { return std::to_string(n) + (n == 1 ? one : many); };
  if (moved.faces + moved.charts > 0)
    result.notes.push_back("flipped or zero-area UV triangles as stored: " +
                           count(moved.charts, " chart", " charts") + " mapped again onto a square, " +
                           count(moved.faces, " face", " faces") + " made charts of their own, laid out anew");
  return result;
}

}  // namespace lowstretch
