// The direct solve of a small pass system: KLU (SuiteSparse), made for many small sparse systems
// with one pattern. Its ordering is found once; a later pass refactors with the first pass's
// pivots, falling back to a fresh factorization where that fails. The matrix is given by rows:
// read as columns that is its transpose, which KLU factors and solves transposed, so no copy is made.
#pragma once
#include <Eigen/Core>
#include <Eigen/Sparse>
#include <memory>

namespace lowstretch {

class SmallSystemLu {
 public:
  SmallSystemLu();
  ~SmallSystemLu();
  SmallSystemLu(const SmallSystemLu&) = delete;
  SmallSystemLu& operator=(const SmallSystemLu&) = delete;

  // Factors A (same pattern on every call), with the last factorization's pivots unless `fresh`;
  // false if it is singular.
  bool factorize(Eigen::SparseMatrix<double, Eigen::RowMajor, int>& A, bool fresh);
  // x = A^-1 b for each column of b; false if the solve failed.
  bool solve(const Eigen::MatrixXd& b, Eigen::MatrixXd& x);

 private:
  struct Klu;  // KLU's objects (klu.h stays out of this header)
  std::unique_ptr<Klu> klu_;
};

}  // namespace lowstretch
