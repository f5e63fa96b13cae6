// libFuzzer target: lowstretch::parameterize, then lowstretch::parameterize_charts (non-disk
// input as charts, packed by vcglib) on small (V, F) arrays decoded from the bytes:
// out-of-range and repeated indices, NaN, infinite, huge and tiny coordinates, duplicate and
// flipped faces, zero faces, one triangle, flaps, coincident vertices, every option.
//
// byte 0: bits 0-1 boundary (square, circle, natural, square), bits 2-3 weights (floater,
//         mean value, harmonic, floater), bit 4 exponent from byte 1 (else 1), bit 5 raw arrays
//         (else an edited grid or hemisphere), bit 6 cancel at the k-th progress call (k = byte 1
//         % 8), bit 7 run every pass (stop_when_stretch_rises = false)
// raw:  byte 2 = #V (% 25), byte 3 = #F (% 25), then 3 bytes per coordinate and index (see
//       coordinate() and index()); missing bytes read as 0
// grid: byte 2 picks grid(2..7) or hemisphere, then edits of 4 bytes (op, a, b, c), see below
// With LOWSTRETCH_FUZZ_PRINT set in the environment, each input's options, V and F are printed
// (to turn a crashing input into a unit test: fuzz_parameterize crash-...).
#include <cmath>
#include <cstdio>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

#include "atlas/charts.h"
#include "core/disk_mesh.h"
#include "core/parameterize.h"
#include "core/stretch.h"
#include "generated_meshes.h"

namespace {

struct Bytes {
  const uint8_t* data;
  size_t size, at = 0;
  uint8_t next() { return at < size ? data[at++] : 0; }
  bool empty() const { return at >= size; }
};

// Mostly small values on a coarse lattice (degenerate and coincident points are likely), with
// the special values a scan or a broken filter can leave.
double coordinate(uint8_t b) {
  const double inf = std::numeric_limits<double>::infinity();
  static const double special[16] = {std::numeric_limits<double>::quiet_NaN(), inf, -inf, 1e308, -1e308,
                                     std::numeric_limits<double>::denorm_min(), 1e-310, 1e154, -1e154, 1e-160,
                                     std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
                                     -0.0, 1e20, 1e-20, std::numeric_limits<double>::min()};
  if (b >= 0xf0) return special[b - 0xf0];
  return double(int8_t(b)) / 8.0;
}

// Mostly in range; sometimes -1, #V, huge or negative.
int index(uint8_t b, int nv) {
  switch (b) {
    case 0xff: return -1;
    case 0xfe: return nv;
    case 0xfd: return std::numeric_limits<int>::max();
    case 0xfc: return std::numeric_limits<int>::min();
    case 0xfb: return nv + 1000;
    default: return nv > 0 ? b % nv : b % 4;
  }
}

void raw_arrays(Bytes& in, Eigen::MatrixXd& V, Eigen::MatrixXi& F) {
  const int nv = in.next() % 25, nf = in.next() % 25;
  V.resize(nv, 3);
  F.resize(nf, 3);
  for (int i = 0; i < nv; ++i)
    for (int c = 0; c < 3; ++c) V(i, c) = coordinate(in.next());
  for (int f = 0; f < nf; ++f)
    for (int c = 0; c < 3; ++c) F(f, c) = index(in.next(), nv);
}

template <class Matrix>
void remove_row(Matrix& M, Eigen::Index row) {
  if (row + 1 < M.rows()) M.block(row, 0, M.rows() - row - 1, M.cols()) = M.bottomRows(M.rows() - row - 1).eval();
  M.conservativeResize(M.rows() - 1, M.cols());
}

void edited_mesh(Bytes& in, Eigen::MatrixXd& V, Eigen::MatrixXi& F) {
  const uint8_t shape = in.next();
  const testmesh::Mesh base = shape % 7 == 6 ? testmesh::hemisphere(2 + shape / 7 % 3, 4 + shape / 21 % 5)
                                             : testmesh::grid(2 + shape % 6, [shape](double x, double y) {
                                                 return (shape & 0x80) ? 0.3 * std::sin(7 * x) * std::cos(5 * y) : 0.0;
                                               });
  V = base.V;
  F = base.F;
  for (int edits = 0; !in.empty() && edits < 64; ++edits) {
    const uint8_t op = in.next(), a = in.next(), b = in.next(), c = in.next();
    const int nv = int(V.rows()), nf = int(F.rows());
    switch (op % 9) {
      case 0:  // one coordinate
        if (nv) V(a % nv, b % 3) = coordinate(c);
        break;
      case 1:  // one index
        if (nf) F(a % nf, b % 3) = index(c, nv);
        break;
      case 2:  // duplicate a face (same or opposite orientation)
        if (nf) {
          F.conservativeResize(nf + 1, 3);
          F.row(nf) = F.row(a % nf);
          if (b & 1) std::swap(F(nf, 1), F(nf, 2));
        }
        break;
      case 3:  // remove a face (holes, zero faces, one triangle left)
        if (nf) remove_row(F, a % nf);
        break;
      case 4:  // flip a face
        if (nf) std::swap(F(a % nf, 1), F(a % nf, 2));
        break;
      case 5:  // a flap: a new vertex and a face on two existing ones
        if (nv) {
          V.conservativeResize(nv + 1, 3);
          V.row(nv) << coordinate(a), coordinate(b), coordinate(c);
          F.conservativeResize(nf + 1, 3);
          F.row(nf) << a % nv, b % nv, nv;
        }
        break;
      case 6:  // a vertex moved onto another (zero-length edges, zero-area faces)
        if (nv) V.row(a % nv) = V.row(b % nv).eval();
        break;
      case 7:  // everything scaled by 10^((a - 128) / 4): overflow and underflow of areas
        V *= std::pow(10.0, (int(a) - 128) / 4.0);
        break;
      case 8:  // an unreferenced vertex (any coordinates) or a vertex removed from the end
        if (b & 1) {
          V.conservativeResize(nv + 1, 3);
          V.row(nv) << coordinate(a), coordinate(b), coordinate(c);
        } else if (nv) {
          V.conservativeResize(nv - 1, 3);
        }
        break;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Bytes in{data, size};
  const uint8_t mode = in.next(), parameter = in.next();
  lowstretch::Options options;
  options.max_passes = 2;
  static const lowstretch::BoundaryShape shapes[4] = {lowstretch::BoundaryShape::Square, lowstretch::BoundaryShape::Circle,
                                                      lowstretch::BoundaryShape::Natural, lowstretch::BoundaryShape::Square};
  static const lowstretch::InitialWeights weights[4] = {lowstretch::InitialWeights::Floater, lowstretch::InitialWeights::MeanValue,
                                                        lowstretch::InitialWeights::Harmonic, lowstretch::InitialWeights::Floater};
  options.boundary = shapes[mode & 3];
  options.weights = weights[(mode >> 2) & 3];
  if (mode & 16) options.exponent = parameter / 200.0;  // 0 and > 1 are invalid options
  int calls = 0;
  if (mode & 64) {
    const int cancel_at = parameter % 8;
    options.progress = [&calls, cancel_at](double fraction, const char* stage) {
      if (!(fraction >= 0 && fraction <= 1) || stage == nullptr) std::abort();
      return calls++ != cancel_at;
    };
  }
  options.stop_when_stretch_rises = !(mode & 128);

  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  if (mode & 32) raw_arrays(in, V, F);
  else edited_mesh(in, V, F);

  if (std::getenv("LOWSTRETCH_FUZZ_PRINT")) {
    std::printf("boundary %d weights %d exponent %.17g cancel_at %d stop_when_stretch_rises %d\nV (%d rows)\n",
                mode & 3, (mode >> 2) & 3, options.exponent, (mode & 64) ? parameter % 8 : -1,
                int(options.stop_when_stretch_rises), int(V.rows()));
    for (Eigen::Index i = 0; i < V.rows(); ++i) std::printf("  %.17g, %.17g, %.17g,\n", V(i, 0), V(i, 1), V(i, 2));
    std::printf("F (%d rows)\n", int(F.rows()));
    for (Eigen::Index f = 0; f < F.rows(); ++f) std::printf("  %d, %d, %d,\n", F(f, 0), F(f, 1), F(f, 2));
    std::fflush(stdout);
  }
  const lowstretch::Result r = lowstretch::parameterize(V, F, options);
  // Charts of the same arrays (a disk gives the same as above, anything else its own layout).
  calls = 0;
  lowstretch::ChartOptions chart_options;
  chart_options.disk = options;
  chart_options.non_disk = lowstretch::NonDisk::Charts;
  chart_options.texture_size = 256;  // as fuzz_reader.h says why
  const lowstretch::ChartsResult c = lowstretch::parameterize_charts(V, F, chart_options);
  if (std::getenv("LOWSTRETCH_FUZZ_PRINT")) {
    std::printf("charts: error %s (%s), input is a disk %d, %d charts, uv in [%.17g, %.17g]\n", lowstretch::code_name(c.error.code),
                c.error ? lowstretch::message(c.error).c_str() : "", int(c.input_is_disk), int(c.charts.size()),
                c.error ? 0.0 : c.corner_uv.minCoeff(), c.error ? 0.0 : c.corner_uv.maxCoeff());
    std::fflush(stdout);
  }
  if (c.error) {
    if (lowstretch::message(c.error).empty()) std::abort();
  } else if (c.corner_uv.rows() != F.rows() || c.corner_uv.cols() != 6 || !c.corner_uv.allFinite() ||
             c.corner_uv.minCoeff() < 0 || c.corner_uv.maxCoeff() > 1 ||
             c.face_stretch.size() != F.rows() ||
             c.vertex_stretch.size() != V.rows() || c.face_chart.size() != size_t(F.rows()) || c.charts.empty()) {
    std::abort();
  }
  if (!r.error && c.error) std::abort();  // a disk always gets a map (its own, or charts)
  // Charts never come with a flipped or zero-area triangle on a face that has 3D area (as stored
  // in float), whatever the input: non-manifold, misoriented, slivers, duplicate vertices.
  if (!c.error) {
    // The atlas's unit box: of the vertices that faces use.
    std::vector<Eigen::RowVector3d> used;
    for (Eigen::Index f = 0; f < F.rows(); ++f)
      for (int k = 0; k < 3; ++k) used.push_back(V.row(F(f, k)));
    Eigen::MatrixXd used_V(Eigen::Index(used.size()), 3);
    for (size_t i = 0; i < used.size(); ++i) used_V.row(Eigen::Index(i)) = used[i];
    const lowstretch::UnitBox box = lowstretch::unit_box(used_V);
    Eigen::MatrixXd unit_V = V;
    for (Eigen::Index i = 0; i < V.rows(); ++i) unit_V.row(i) = box.map(V.row(i));
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
      const auto corner = [&](int k) { return Eigen::Vector2d(c.corner_uv(f, 2 * k), c.corner_uv(f, 2 * k + 1)); };
      if (!(lowstretch::signed_uv_area(corner(0), corner(1), corner(2)) > 0) && !lowstretch::is_flat_face(unit_V, F, f))
        std::abort();
    }
  }
  if (std::getenv("LOWSTRETCH_FUZZ_PRINT")) {
    std::printf("error %s (%s)\n", lowstretch::code_name(r.error.code), r.error ? lowstretch::message(r.error).c_str() : "");
    if (!r.error) std::printf("uv finite %d, passes %d, chosen %d\n", int(r.uv.allFinite()), int(r.passes.size()), r.chosen_pass);
    std::fflush(stdout);
  }
  if (r.error) {
    if (lowstretch::message(r.error).empty()) std::abort();
    return 0;
  }
  // What the tool and the plugin rely on when there is no error.
  if (r.uv.rows() != V.rows() || r.uv.cols() != 2 || r.vertex_stretch.size() != V.rows() ||
      r.face_stretch.size() != F.rows() || r.passes.empty() || r.chosen_pass < 0 ||
      r.chosen_pass >= int(r.passes.size()) || int(r.passes.size()) > options.max_passes + 1)
    std::abort();
  if (!r.uv.allFinite() || r.uv.minCoeff() < 0 || r.uv.maxCoeff() > 1) std::abort();  // usable texture coordinates
  return 0;
}
