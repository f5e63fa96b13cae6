// KLU on a pass's system as the solver holds it (by rows): it solves A x = b, not its transpose,
// keeps doing so when the values change, says when A is singular, and shares an ordering.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <thread>
#include <vector>

#include "core/small_system_lu.h"

using namespace lowstretch;

namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// A non-symmetric, diagonally dominant matrix with a path and a few far entries: `scale` changes
// its values, never its pattern.
RowMatrix lopsided(int n, double scale) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 6.0 + scale * i);
    if (i + 1 < n) entries.emplace_back(i, i + 1, -1.0 - scale);
    if (i > 0) entries.emplace_back(i, i - 1, -2.0);
    if (i + 3 < n) entries.emplace_back(i, i + 3, -0.5 * scale);
  }
  RowMatrix A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  return A;
}

Eigen::MatrixXd right_sides(int n) {
  Eigen::MatrixXd b(n, 2);
  for (int i = 0; i < n; ++i) b.row(i) << 1.0 + i, (i % 3) - 1.0;
  return b;
}

}  // namespace

TEST(SmallSystemLu, SolvesTheMatrixNotItsTranspose) {
  RowMatrix A = lopsided(12, 0.7);
  const Eigen::MatrixXd dense = Eigen::MatrixXd(A);
  ASSERT_GT((dense - dense.transpose()).norm(), 1.0);
  const Eigen::MatrixXd b = right_sides(12);
  SmallSystemLu lu;
  ASSERT_TRUE(lu.factorize(A, false));
  Eigen::MatrixXd x;
  ASSERT_TRUE(lu.solve(b, x));
  EXPECT_LT((dense * x - b).norm(), 1e-12 * b.norm());
  EXPECT_LT((x - dense.partialPivLu().solve(b)).norm(), 1e-12 * x.norm());
}

TEST(SmallSystemLu, NewValuesOnTheSamePatternAreSolvedWithTheFirstPivotsOrAfresh) {
  SmallSystemLu lu;
  RowMatrix first = lopsided(30, 0.2);
  ASSERT_TRUE(lu.factorize(first, false));
  const Eigen::MatrixXd b = right_sides(30);
  for (const bool fresh : {false, true}) {
    RowMatrix A = lopsided(30, fresh ? 3.0 : 1.5);
    ASSERT_TRUE(lu.factorize(A, fresh));
    Eigen::MatrixXd x;
    ASSERT_TRUE(lu.solve(b, x));
    EXPECT_LT((Eigen::MatrixXd(A) * x - b).norm(), 1e-12 * b.norm()) << "fresh " << fresh;
  }
}

TEST(SmallSystemLu, ASingularMatrixIsNotFactored) {
  RowMatrix A = lopsided(8, 0.5);
  for (int k = A.outerIndexPtr()[4]; k < A.outerIndexPtr()[5]; ++k) A.valuePtr()[k] = 0;  // row 4 all zero
  SmallSystemLu lu;
  EXPECT_FALSE(lu.factorize(A, true));
  Eigen::MatrixXd x;
  EXPECT_FALSE(lu.solve(right_sides(8), x));
}

TEST(SmallSystemLu, SolversSharingAnOrderingFromTwoThreadsSolveAsAloneAndRefuseAnotherPattern) {
  const Eigen::MatrixXd b = right_sides(40);
  Eigen::MatrixXd alone[2];
  for (int k = 0; k < 2; ++k) {
    SmallSystemLu lu;
    RowMatrix A = lopsided(40, 0.3 + k);
    ASSERT_TRUE(lu.factorize(A, false));
    ASSERT_TRUE(lu.solve(b, alone[k]));
  }
  LuOrdering ordering;
  Eigen::MatrixXd shared[2];
  bool solved[2] = {false, false};
  std::vector<std::thread> threads;
  for (int k = 0; k < 2; ++k)
    threads.emplace_back([&, k] {
      SmallSystemLu lu(&ordering);
      RowMatrix A = lopsided(40, 0.3 + k);
      solved[k] = lu.factorize(A, false) && lu.solve(b, shared[k]);
    });
  for (std::thread& t : threads) t.join();
  for (int k = 0; k < 2; ++k) {
    ASSERT_TRUE(solved[k]) << k;
    EXPECT_EQ(shared[k], alone[k]) << k;  // the same ordering, so the same factors, bit for bit
  }
  SmallSystemLu other(&ordering);
  RowMatrix smaller = lopsided(39, 0.3);
  EXPECT_FALSE(other.factorize(smaller, false));
}
