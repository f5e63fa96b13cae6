// Convex-combination weights of an interior vertex in terms of its one-ring (the initial
// weights w0_ij of the method).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "core/disk_mesh.h"
#include "core/method_types.h"

namespace lowstretch {

// Floater's shape-preserving weights of the point p among its ring p_1..p_d (counter-clockwise,
// closed): geodesic polar map, then barycentric coordinates of p in the triangles that the
// rays through p cut out (Floater 1997, section 6). Positive and summing to 1 when the ring is
// not degenerate; returns false (weights untouched) when it is.
bool floater_weights(const Eigen::RowVector3d& p, const std::vector<Eigen::RowVector3d>& ring,
                     std::vector<double>& weights);
// Floater's mean value coordinates: (tan(a_{k-1}/2) + tan(a_k/2)) / |p_k - p|, normalized.
bool mean_value_weights(const Eigen::RowVector3d& p, const std::vector<Eigen::RowVector3d>& ring,
                        std::vector<double>& weights);
// Cotangent weights (cot of the two angles opposite each edge) / 2, normalized by their sum
// when it is positive; can be negative.
bool harmonic_weights(const Eigen::RowVector3d& p, const std::vector<Eigen::RowVector3d>& ring,
                      std::vector<double>& weights);

// Weights of every interior vertex of the disk, aligned with disk.ring (boundary slots are 0).
// Where a ring is degenerate (zero-length edges, zero-area corners) the uniform weights 1/d are
// used so that every weight stays positive; `uniform_fallbacks` counts those vertices.
std::vector<double> initial_weights(const DiskMesh& disk, InitialWeights kind, int& uniform_fallbacks);

// One stretch pass: w_ij <- w_ij / sigma_j^exponent for every interior vertex i, with sigma the
// per-vertex stretch of the previous pass; each row is then rescaled to sum 1.
void reweight(const DiskMesh& disk, const Eigen::VectorXd& sigma, double exponent, std::vector<double>& weights);

}  // namespace lowstretch
