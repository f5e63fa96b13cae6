#include "layout_checks.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lowstretch {

Eigen::Vector2d corner(const ChartsResult& r, Eigen::Index f, int k) { return r.corner_uv.block<1, 2>(f, 2 * k).transpose(); }

double signed_area(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return 0.5 * ((b - a).x() * (c - a).y() - (c - a).x() * (b - a).y());
}

std::vector<double> texel_densities(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartsResult& r) {
  std::vector<double> uv(r.charts.size(), 0.0), area(r.charts.size(), 0.0);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const size_t c = size_t(r.face_chart[size_t(f)]);
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), d = V.row(F(f, 2));
    area[c] += 0.5 * (b - a).cross(d - a).norm();
    uv[c] += signed_area(corner(r, f, 0), corner(r, f, 1), corner(r, f, 2));
  }
  std::vector<double> density;
  for (size_t c = 0; c < r.charts.size(); ++c) density.push_back(uv[c] / area[c]);
  return density;
}

int overlapping_pixels(const ChartsResult& r) {
  const int n = 1024;
  std::vector<int> owner(size_t(n) * n, -1);
  int overlaps = 0;
  for (Eigen::Index f = 0; f < r.corner_uv.rows(); ++f) {
    const Eigen::Vector2d a = corner(r, f, 0) * n, b = corner(r, f, 1) * n, c = corner(r, f, 2) * n;
    const double area = signed_area(a, b, c);
    if (!(area > 0)) continue;  // counted as flipped or degenerate elsewhere
    const int x0 = std::max(0, int(std::floor(std::min({a.x(), b.x(), c.x()})))),
              x1 = std::min(n - 1, int(std::ceil(std::max({a.x(), b.x(), c.x()}))));
    const int y0 = std::max(0, int(std::floor(std::min({a.y(), b.y(), c.y()})))),
              y1 = std::min(n - 1, int(std::ceil(std::max({a.y(), b.y(), c.y()}))));
    const double eps = 1e-9 * area;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Eigen::Vector2d p(x + 0.5, y + 0.5);
        if (signed_area(a, b, p) > eps && signed_area(b, c, p) > eps && signed_area(c, a, p) > eps) {
          int& o = owner[size_t(y) * n + size_t(x)];
          if (o >= 0) ++overlaps;
          o = int(f);
        }
      }
  }
  return overlaps;
}

void expect_valid_layout(const Eigen::MatrixXi& F, const ChartsResult& r, const Eigen::MatrixXd* V) {
  ASSERT_FALSE(r.error) << message(r.error);
  ASSERT_EQ(r.corner_uv.rows(), F.rows());
  ASSERT_EQ(r.corner_uv.cols(), 6);
  ASSERT_TRUE(r.corner_uv.allFinite());
  const double gutter = ChartOptions().gutter / ChartOptions().texture_size;  // 2 texels of 1024
  EXPECT_GE(r.corner_uv.minCoeff(), gutter - 1e-15);
  EXPECT_LE(r.corner_uv.maxCoeff(), 1 - gutter + 1e-15);
  int not_positive = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const double area = signed_area(corner(r, f, 0), corner(r, f, 1), corner(r, f, 2));
    const auto p = [&](int k) { return Eigen::Vector3d(V->row(F(f, k)).transpose()); };
    const bool no_surface = V && (p(1) - p(0)).cross(p(2) - p(0)).norm() == 0;
    not_positive += no_surface ? area < 0 : !(area > 0);
  }
  EXPECT_EQ(not_positive, 0);
  EXPECT_EQ(r.layout.flipped, 0);
  EXPECT_EQ(r.layout.degenerate, 0);
  EXPECT_TRUE(std::isfinite(r.layout.l2_stretch));
  EXPECT_EQ(overlapping_pixels(r), 0);
  EXPECT_GT(r.coverage, 0.0);
  EXPECT_LE(r.coverage, 1.0 + 1e-12);
  ASSERT_EQ(r.face_chart.size(), size_t(F.rows()));
  for (int c : r.face_chart) {
    EXPECT_GE(c, 0);
    EXPECT_LT(c, int(r.charts.size()));
  }
}

double triangle_distance(const Eigen::Vector2d a[3], const Eigen::Vector2d b[3]) {
  for (int i = 0; i < 3; ++i)  // sides that cross: 0
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d &p = a[i], &q = a[(i + 1) % 3], &s = b[k], &t = b[(k + 1) % 3];
      if (signed_area(p, q, s) * signed_area(p, q, t) < 0 && signed_area(s, t, p) * signed_area(s, t, q) < 0) return 0;
    }
  const auto to_side = [](const Eigen::Vector2d& p, const Eigen::Vector2d& s, const Eigen::Vector2d& t) {
    const double along = std::min(1.0, std::max(0.0, (p - s).dot(t - s) / (t - s).squaredNorm()));
    return (p - (s + along * (t - s))).norm();
  };
  double least = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      least = std::min(least, to_side(a[i], b[k], b[(k + 1) % 3]));
      least = std::min(least, to_side(b[i], a[k], a[(k + 1) % 3]));
    }
  return least;
}

double least_distance_between_charts(const Eigen::MatrixXi& F, const ChartsResult& r) {
  double least = std::numeric_limits<double>::infinity();
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (Eigen::Index g = f + 1; g < F.rows(); ++g) {
      if (r.face_chart[size_t(f)] == r.face_chart[size_t(g)]) continue;
      const Eigen::Vector2d a[3] = {corner(r, f, 0), corner(r, f, 1), corner(r, f, 2)};
      const Eigen::Vector2d b[3] = {corner(r, g, 0), corner(r, g, 1), corner(r, g, 2)};
      least = std::min(least, triangle_distance(a, b));
    }
  return least;
}

}  // namespace lowstretch
