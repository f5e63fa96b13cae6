#include "atlas/bound/cut_invalid_charts.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "atlas/base/tuning.h"
#include "atlas/chart_map/chart_threads.h"
#include "core/half_edges.h"
#include "atlas/cut/mesh_components.h"
#include "atlas/cut/split_chart.h"
#include "core/stretch.h"

namespace lowstretch {

namespace {

// Whether the UV triangle keeps a positive area however each coordinate moves by up to `wobble`:
// twice its area exceeds the most that moving can take (each corner's move times the opposite
// side, plus the moves' own cross product).
bool survives_rounding(const Eigen::MatrixXd& corner_uv, Eigen::Index f, double wobble) {
  const auto c = [&](int k) { return Eigen::Vector2d(corner_uv.block(f, 2 * k, 1, 2).transpose()); };
  const double sides = (c(2) - c(1)).lpNorm<1>() + (c(0) - c(2)).lpNorm<1>() + (c(1) - c(0)).lpNorm<1>();
  return 2 * corner_area(corner_uv, f) > wobble * sides + 8 * wobble * wobble;
}

// The faces of `chart` other than `taken`, in their edge-connected parts.
std::vector<std::vector<int>> connected_parts(const std::vector<int>& faces, const std::vector<char>& taken,
                                              const Eigen::MatrixXi& F) {
  std::vector<int> rest;
  for (const int f : faces)
    if (!taken[size_t(f)]) rest.push_back(f);
  Eigen::MatrixXi rest_F(Eigen::Index(rest.size()), 3);
  for (size_t j = 0; j < rest.size(); ++j) rest_F.row(Eigen::Index(j)) = F.row(rest[j]);
  int count = 0;
  const std::vector<int> component = face_components(rest_F, count);
  std::vector<std::vector<int>> parts(static_cast<size_t>(count));
  for (size_t j = 0; j < rest.size(); ++j) parts[size_t(component[j])].push_back(rest[j]);
  return parts;
}

// Each piece mapped on its own, on the thread pool, largest first.
void solve_pieces(std::vector<SolvedChart>& pieces, const ChartOptions& options) {
  const size_t faces = faces_in(pieces, 0, pieces.size());
  for_each_index(int(pieces.size()), [&](int p, int) {
    SolvedChart& piece = pieces[size_t(p)];
    // The piece's map may be replaced by its square map: marked after.
    solve_chart(piece, for_share(options.disk, piece.faces.size(), faces), 0);
    piece.kept_whole = "cut where its map was invalid";
    piece.cut_for_validity = true;
  }, largest_first(pieces, 0, pieces.size()));
}

}  // namespace

double corner_area(const Eigen::MatrixXd& corner_uv, Eigen::Index f) {
  const auto c = [&](int k) { return Eigen::Vector2d(corner_uv.block(f, 2 * k, 1, 2).transpose()); };
  return signed_uv_area(c(0), c(1), c(2));
}

std::vector<int> invalid_faces(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& corner_uv,
                               double least_area, double wobble) {
  std::vector<int> invalid;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    // A flat face may map to zero area; folded, its neighbours overlap.
    if (is_flat_face(unit_V, F, f) ? corner_area(corner_uv, f) < 0
                                   : !(corner_area(corner_uv, f) > least_area) || (wobble > 0 && !survives_rounding(corner_uv, f, wobble)))
      invalid.push_back(int(f));
  return invalid;
}

std::vector<int> without_specks(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& corner_uv,
                                const std::vector<int>& invalid) {
  if (invalid.empty()) return invalid;
  double uv_area = 0, area_3d = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    uv_area += std::abs(corner_area(corner_uv, f));
    area_3d += face_area_3d(unit_V, F, f);
  }
  const double density = area_3d > 0 ? uv_area / area_3d : 0;
  std::vector<int> kept;
  for (const int f : invalid) {
    const double area = corner_area(corner_uv, f);
    if (!(area > 0 && area >= kTuning.speck_density * density * face_area_3d(unit_V, F, f))) kept.push_back(f);
  }
  return kept;
}

int cut_invalid_charts(std::vector<SolvedChart>& charts, std::vector<int>& guests, const std::vector<int>& face_chart,
                        const std::vector<int>& invalid, const std::vector<int>& stretched,
                        const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const ChartOptions& options,
                        std::vector<int>& flat, std::vector<int>& was) {
  std::vector<char> taken(size_t(F.rows()), 0), cut(charts.size(), 0), split(charts.size(), 0);
  for (const int f : invalid) {
    if (face_chart[size_t(f)] >= int(charts.size())) continue;  // a face already left alone, on its point
    taken[size_t(f)] = 1;
    cut[size_t(face_chart[size_t(f)])] = 1;
  }
  const int invalid_charts = int(std::count(cut.begin(), cut.end(), 1));
  for (const int c : stretched) split[size_t(c)] = cut[size_t(c)] = !cut[size_t(c)];
  const std::vector<int> twin = stretched.empty() ? std::vector<int>() : opposite_half_edges(F);
  std::vector<char> is_guest(charts.size(), 0);
  for (const int g : guests) is_guest[size_t(g)] = 1;
  guests.erase(std::remove_if(guests.begin(), guests.end(), [&](int g) { return cut[size_t(g)] != 0; }), guests.end());
  std::vector<char> piece_is_guest;  // per piece
  std::vector<int> local_of(size_t(unit_V.rows()), -1);
  std::vector<SolvedChart> pieces;
  const auto add_piece = [&](std::vector<int> faces) {
    SolvedChart piece;
    piece.faces = std::move(faces);
    if (make_chart_mesh(unit_V, F, piece.faces, local_of, piece.mesh)) {  // no disk with holes: face by face
      for (const int f : piece.faces) {
        SolvedChart single;
        single.faces = {f};
        if (make_chart_mesh(unit_V, F, single.faces, local_of, single.mesh)) flat.push_back(f);  // no area to map
        else pieces.push_back(std::move(single));
      }
      return;
    }
    pieces.push_back(std::move(piece));
  };
  for (size_t c = 0; c < charts.size(); ++c) {
    if (!cut[c]) continue;
    for (const int f : charts[c].faces)
      if (taken[size_t(f)]) add_piece({f});
    for (std::vector<int>& part : split[c] ? split_chart(unit_V, F, twin, charts[c].faces) : connected_parts(charts[c].faces, taken, F))
      add_piece(std::move(part));
    piece_is_guest.resize(pieces.size(), is_guest[c]);
  }
  solve_pieces(pieces, options);
  std::vector<SolvedChart> kept;
  std::vector<int> new_index(charts.size(), -1);
  was.clear();
  for (size_t c = 0; c < charts.size(); ++c)
    if (!cut[c]) {
      new_index[c] = int(kept.size());
      was.push_back(int(c));
      kept.push_back(std::move(charts[c]));
    }
  for (int& g : guests) g = new_index[size_t(g)];
  for (size_t p = 0; p < pieces.size(); ++p) {
    if (piece_is_guest[p]) guests.push_back(int(kept.size()));
    was.push_back(-1);
    kept.push_back(std::move(pieces[p]));
  }
  charts = std::move(kept);
  return invalid_charts;
}

}  // namespace lowstretch
