// Initial weights: positive, summing to 1, and reproducing a planar one-ring exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/ring_weights.h"

using namespace lowstretch;

namespace {

// A ring around p with random radii, and angles jittered so that every gap stays below pi
// (p in the kernel of the flattened ring).
std::vector<Eigen::RowVector3d> random_ring(std::mt19937& rng, const Eigen::RowVector3d& p, int d, double z_noise) {
  std::uniform_real_distribution<double> radius(0.3, 2.0), jitter(-0.2, 0.2), z(-z_noise, z_noise);
  std::vector<Eigen::RowVector3d> ring;
  for (int k = 0; k < d; ++k) {
    const double a = 2 * 3.14159265358979 * (k + 0.5 + jitter(rng)) / d;
    const double r = radius(rng);
    ring.push_back(p + Eigen::RowVector3d(r * std::cos(a), r * std::sin(a), z(rng)));
  }
  return ring;
}

using WeightFunction = bool (*)(const Eigen::RowVector3d&, const std::vector<Eigen::RowVector3d>&, std::vector<double>&);

void expect_convex_and_linear_precision(WeightFunction weights, bool positive) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::RowVector3d p(0.3, -0.2, 0.0);
    const auto ring = random_ring(rng, p, 3 + trial % 8, 0.0);
    std::vector<double> w;
    ASSERT_TRUE(weights(p, ring, w));
    double sum = 0;
    Eigen::RowVector3d combination = Eigen::RowVector3d::Zero();
    for (size_t k = 0; k < ring.size(); ++k) {
      if (positive) EXPECT_GT(w[k], 0.0);
      sum += w[k];
      combination += w[k] * ring[k];
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_LT((combination - p).norm(), 1e-12) << "trial " << trial;  // linear precision
  }
}

}  // namespace

TEST(RingWeights, FloaterIsConvexWithLinearPrecision) { expect_convex_and_linear_precision(floater_weights, true); }
TEST(RingWeights, MeanValueIsConvexWithLinearPrecision) { expect_convex_and_linear_precision(mean_value_weights, true); }
TEST(RingWeights, HarmonicHasLinearPrecision) { expect_convex_and_linear_precision(harmonic_weights, false); }

TEST(RingWeights, FloaterStaysPositiveOnCurvedRings) {
  std::mt19937 rng(11);
  int refused = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const auto ring = random_ring(rng, Eigen::RowVector3d::Zero(), 4 + trial % 6, 0.8);
    std::vector<double> w;
    if (!floater_weights(Eigen::RowVector3d::Zero(), ring, w)) {  // p outside its flattened ring
      ++refused;
      continue;
    }
    double sum = 0;
    for (double x : w) {
      EXPECT_GT(x, 0.0);
      sum += x;
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
  }
  // The curved rings are star-shaped around p once flattened far more often than not: a
  // function that refused them all would test nothing here.
  EXPECT_LE(refused, 10) << refused << " of 200 rings refused";
}

TEST(RingWeights, RegularRingGetsUniformWeights) {
  std::vector<Eigen::RowVector3d> ring;
  for (int k = 0; k < 6; ++k) ring.emplace_back(std::cos(k * 3.14159265358979 / 3), std::sin(k * 3.14159265358979 / 3), 0);
  std::vector<double> w;
  for (WeightFunction f : {floater_weights, mean_value_weights, harmonic_weights}) {
    ASSERT_TRUE(f(Eigen::RowVector3d::Zero(), ring, w));
    for (double x : w) EXPECT_NEAR(x, 1.0 / 6, 1e-12);
  }
}

TEST(RingWeights, DegenerateRingIsRefused) {
  const std::vector<Eigen::RowVector3d> ring{{1, 0, 0}, {0, 0, 0}, {-1, 1, 0}, {-1, -1, 0}};  // a zero-length edge
  std::vector<double> w;
  EXPECT_FALSE(floater_weights(Eigen::RowVector3d::Zero(), ring, w));
  EXPECT_FALSE(mean_value_weights(Eigen::RowVector3d::Zero(), ring, w));
}

TEST(RingWeights, AVertexOnTheLineBetweenTwoNeighboursHasADegenerateRing) {
  // A T-junction: p at the midpoint of a-b (up to rounding), c on one side. Floater's and the mean
  // value weights would give c next to nothing and collapse the face (a, b, p) in UV; the ring is
  // called degenerate (the caller then uses uniform weights). Slightly off the line it is not.
  const Eigen::RowVector3d a(0, 0, 0), b(1, 0, 0), c(0.5, 0.7, 0);
  std::vector<double> w;
  for (const double off : {0.0, 1e-13})
    for (const WeightFunction f : {WeightFunction(floater_weights), WeightFunction(mean_value_weights)})
      EXPECT_FALSE(f(Eigen::RowVector3d(0.5, -off, 0), {a, b, c}, w)) << off;
  for (const WeightFunction f : {WeightFunction(floater_weights), WeightFunction(mean_value_weights)}) {
    ASSERT_TRUE(f(Eigen::RowVector3d(0.5, 0.01, 0), {a, b, c}, w));
    EXPECT_GT(w[2], 0.005);
  }
}
