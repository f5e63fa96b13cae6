// Stretch of a parameterization (Sander et al. 2001; METHOD.md section 2) and the
// paper's distortion metrics.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/method_types.h"

namespace lowstretch {

struct FaceStretch {
  Eigen::VectorXd area_3d;  // per face
  Eigen::VectorXd area_uv;  // signed parameter area, positive = counter-clockwise
  // L2 stretch sqrt((a + c) / 2) and Linf stretch (largest singular value) per face, computed
  // with |A_U| bounded away from zero so that they stay finite; `valid` marks A_U > tolerance,
  // or a flat face (is_flat_face) whose A_U is zero too (sigma = gamma = 0: nothing to stretch).
  Eigen::VectorXd sigma, gamma;
  Eigen::Matrix<bool, Eigen::Dynamic, 1> valid;
  // sqrt(sum |A_U| / sum A_3D): multiplying by it makes an isometry up to scale read 1.
  double normalization = 1;
  int flipped = 0, degenerate = 0;
};

// Area of face f of the mesh (V, F) in 3D.
inline double face_area_3d(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, Eigen::Index f) {
  const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
  return 0.5 * (b - a).cross(c - a).norm();
}

// Whether face f of a mesh in a unit box (make_disk_mesh's) has no 3D area up to the rounding
// of its coordinates (its corners on one line or point, as a scan's zero-area faces are): its
// height over its longest edge is at most 1e-14, where moving the mesh into the box leaves about
// 1e-16.
inline bool is_flat_face(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, Eigen::Index f) {
  const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
  const double longest = std::sqrt(std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()}));
  return (b - a).cross(c - a).norm() <= 1e-14 * longest;
}

// Signed area of the UV triangle abc, positive when counter-clockwise.
inline double signed_uv_area(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return 0.5 * ((b - a).x() * (c - a).y() - (c - a).x() * (b - a).y());
}

// V: #V x 3, F: #F x 3, UV: #V x 2.
FaceStretch face_stretch(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV);

// sigma_i = sqrt(sum_T A(T) sigma(T)^2 / sum_T A(T)) over the faces T around each vertex, from
// the finite per-face values (so usable for reweighting); normalized. A vertex whose faces all
// have zero 3D area gets the global L2 stretch.
Eigen::VectorXd vertex_stretch(const Eigen::MatrixXi& F, int vertex_count, const FaceStretch& s);

// The normalized L2 stretch of every face: sqrt(sum |A_U| / sum A) * sqrt(sum A sigma^2 / sum A)
// (METHOD.md section 2). Infinite if a face is flipped or zero-area, unless skip_invalid: then
// the sums of sigma run over the valid faces alone (to rank passes that have some).
double l2_stretch(const FaceStretch& s, bool skip_invalid = false);
// The same over some of the faces.
double l2_stretch(const FaceStretch& s, const std::vector<int>& faces);

// The 3D side of the edge and angle metrics. It is the same in every pass, so the pass loop
// computes it once.
struct SurfaceReference {
  Eigen::VectorXd edge_length;  // per row of disk.edges
  double total_edge_length = 0;
  Eigen::MatrixXd corner_angle;  // F x 3: the angle at corner k of face f
};
// V, F: the surface; edges: its undirected edges (#E x 2), each once.
SurfaceReference surface_reference(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXi& edges);

// The stretch metrics and the flipped and zero-area counts alone (the distortions left 0);
// stretch is infinite when a parameter triangle is flipped or degenerate.
PassMetrics measure_stretch(const FaceStretch& s);

// The paper's metrics: measure_stretch's and the edge, angle and area distortions.
// F, edges as for surface_reference; UV: #V x 2; s: face_stretch of the same map.
PassMetrics measure(const Eigen::MatrixXi& F, const Eigen::MatrixXi& edges, const Eigen::MatrixXd& UV, const FaceStretch& s,
                    const SurfaceReference& reference);
PassMetrics measure(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXi& edges,
                    const Eigen::MatrixXd& UV, const FaceStretch& s);  // computes the reference

}  // namespace lowstretch
