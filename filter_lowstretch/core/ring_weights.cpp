#include "core/ring_weights.h"

#include <Eigen/Geometry>
#include <cmath>

namespace lowstretch {

namespace {

const double kPi = 3.14159265358979323846;
// A ring angle this close to pi makes the ring degenerate: the vertex sits on the line between
// two neighbours (a scan's T-junction, a sliver's tip), where Floater's and the mean value weights
// give the other neighbours next to nothing and the faces beside that line collapse in UV.
const double kStraightAngle = kPi - 1e-8;

// Angle between two vectors, robust near 0 and pi.
double angle(const Eigen::RowVector3d& a, const Eigen::RowVector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

bool normalize(std::vector<double>& w) {
  double sum = 0;
  for (double x : w) sum += x;
  if (!(sum > 0) || !std::isfinite(sum)) return false;
  for (double& x : w) x /= sum;
  return true;
}

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

bool floater_weights(const Eigen::RowVector3d& p, const std::vector<Eigen::RowVector3d>& ring,
                     std::vector<double>& weights) {
  const int d = int(ring.size());
  if (d < 3) return false;
  std::vector<double> length(static_cast<size_t>(d)), phi(size_t(d) + 1, 0.0);
  for (int k = 0; k < d; ++k) {
    length[size_t(k)] = (ring[size_t(k)] - p).norm();
    if (!(length[size_t(k)] > 0)) return false;
    phi[size_t(k) + 1] = phi[size_t(k)] + angle(ring[size_t(k)] - p, ring[size_t((k + 1) % d)] - p);
  }
  const double total = phi[size_t(d)];
  if (!(total > 0)) return false;
  std::vector<Eigen::Vector2d> q(static_cast<size_t>(d));
  for (int k = 0; k < d; ++k) {
    phi[size_t(k)] *= 2 * kPi / total;
    if (k > 0 && phi[size_t(k)] - phi[size_t(k) - 1] >= kStraightAngle) return false;  // p not inside the flat ring
    q[size_t(k)] = length[size_t(k)] * Eigen::Vector2d(std::cos(phi[size_t(k)]), std::sin(phi[size_t(k)]));
  }
  if (2 * kPi - phi[size_t(d) - 1] >= kStraightAngle) return false;

  std::vector<double> lambda(size_t(d), 0.0);
  for (int k = 0; k < d; ++k) {
    // The ray from q_k through the origin leaves the ring through the segment [q_r, q_r+1]
    // with phi_r <= phi_k + pi < phi_r+1.
    const double target = std::fmod(phi[size_t(k)] + kPi, 2 * kPi);
    int r = d - 1;
    for (int j = 0; j + 1 < d; ++j)
      if (phi[size_t(j)] <= target && target < phi[size_t(j) + 1]) r = j;
    if (r == k) r = (k + d - 1) % d;  // the ray hit q_k's own segment: only when degenerate
    const int s = (r + 1) % d;
    const Eigen::Vector2d a = q[size_t(k)], b = q[size_t(r)], c = q[size_t(s)];
    const double area = cross2(b - a, c - a);
    if (!(std::abs(area) > 0)) return false;
    // Barycentric coordinates of the origin in (a, b, c); clamp rounding below zero.
    const double la = std::max(0.0, cross2(b, c) / area);
    const double lb = std::max(0.0, cross2(c, a) / area);
    const double lc = std::max(0.0, cross2(a, b) / area);
    lambda[size_t(k)] += la;
    lambda[size_t(r)] += lb;
    lambda[size_t(s)] += lc;
  }
  if (!normalize(lambda)) return false;
  weights = lambda;
  return true;
}

bool mean_value_weights(const Eigen::RowVector3d& p, const std::vector<Eigen::RowVector3d>& ring,
                        std::vector<double>& weights) {
  const int d = int(ring.size());
  if (d < 3) return false;
  std::vector<double> half_tan(static_cast<size_t>(d)), w(static_cast<size_t>(d));
  for (int k = 0; k < d; ++k) {
    const double a = angle(ring[size_t(k)] - p, ring[size_t((k + 1) % d)] - p);
    if (!(a > 0 && a < kStraightAngle)) return false;
    half_tan[size_t(k)] = std::tan(a / 2);
  }
  for (int k = 0; k < d; ++k) {
    const double r = (ring[size_t(k)] - p).norm();
    if (!(r > 0)) return false;
    w[size_t(k)] = (half_tan[size_t((k + d - 1) % d)] + half_tan[size_t(k)]) / r;
  }
  if (!normalize(w)) return false;
  weights = w;
  return true;
}

bool harmonic_weights(const Eigen::RowVector3d& p, const std::vector<Eigen::RowVector3d>& ring,
                      std::vector<double>& weights) {
  const int d = int(ring.size());
  if (d < 3) return false;
  std::vector<double> w(static_cast<size_t>(d));
  auto cot_at = [&](const Eigen::RowVector3d& apex, const Eigen::RowVector3d& a, const Eigen::RowVector3d& b) {
    const Eigen::RowVector3d u = a - apex, v = b - apex;
    return u.dot(v) / u.cross(v).norm();
  };
  double sum = 0;
  for (int k = 0; k < d; ++k) {
    const Eigen::RowVector3d& prev = ring[size_t((k + d - 1) % d)];
    const Eigen::RowVector3d& next = ring[size_t((k + 1) % d)];
    w[size_t(k)] = 0.5 * (cot_at(prev, p, ring[size_t(k)]) + cot_at(next, p, ring[size_t(k)]));
    if (!std::isfinite(w[size_t(k)])) return false;
    sum += w[size_t(k)];
  }
  if (sum > 0)
    for (double& x : w) x /= sum;
  weights = w;
  return true;
}

std::vector<double> initial_weights(const DiskMesh& disk, InitialWeights kind, int& uniform_fallbacks) {
  std::vector<double> all(disk.ring.size(), 0.0), w;
  std::vector<Eigen::RowVector3d> ring;
  uniform_fallbacks = 0;
  const int n = int(disk.V.rows());
  for (int i = 0; i < n; ++i) {
    if (disk.is_boundary[size_t(i)]) continue;
    const int b = disk.ring_start[size_t(i)], e = disk.ring_start[size_t(i) + 1];
    ring.clear();
    for (int s = b; s < e; ++s) ring.push_back(disk.V.row(disk.ring[size_t(s)]));
    const Eigen::RowVector3d p = disk.V.row(i);
    bool ok = false;
    switch (kind) {
      case InitialWeights::Floater: ok = floater_weights(p, ring, w); break;
      case InitialWeights::MeanValue: ok = mean_value_weights(p, ring, w); break;
      case InitialWeights::Harmonic: ok = harmonic_weights(p, ring, w); break;
    }
    if (!ok) {
      w.assign(size_t(e - b), 1.0 / (e - b));
      ++uniform_fallbacks;
    }
    for (int s = b; s < e; ++s) all[size_t(s)] = w[size_t(s - b)];
  }
  return all;
}

// w_ij <- w_ij / sigma_j^eta, then each row rescaled to sum 1 (a row's scale does not change its
// equation; this keeps the values near 1).
void reweight(const DiskMesh& disk, const Eigen::VectorXd& sigma, double exponent, std::vector<double>& weights) {
  for (int i = 0; i < int(disk.V.rows()); ++i) {
    if (disk.is_boundary[size_t(i)]) continue;
    const int begin = disk.ring_start[size_t(i)], end = disk.ring_start[size_t(i) + 1];
    double sum = 0;
    for (int s = begin; s < end; ++s) {
      weights[size_t(s)] /= std::pow(sigma(disk.ring[size_t(s)]), exponent);
      sum += weights[size_t(s)];
    }
    if (sum > 0)
      for (int s = begin; s < end; ++s) weights[size_t(s)] /= sum;
  }
}

}  // namespace lowstretch
