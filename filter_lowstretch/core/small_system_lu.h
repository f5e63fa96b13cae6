// The direct solve of a small pass system: KLU (SuiteSparse), made for many small sparse systems
// with one pattern. Its ordering is found once; a later pass refactors with the first pass's
// pivots, falling back to a fresh factorization where that fails. The matrix is given by rows:
// read as columns that is its transpose, which KLU factors and solves transposed, so no copy is made.
#pragma once
#include <Eigen/Core>
#include <Eigen/Sparse>
#include <memory>
#include <mutex>

namespace lowstretch {

// KLU's ordering of one pattern (its symbolic analysis), found by the first factorization among
// the SmallSystemLu that share it, from any thread. With AMD's ordering (KLU's default, kept here)
// its factorizations and solves only read it (after COLAMD, klu_factor would write its own fill
// estimate into it), so the maps of one mesh (an atlas maps a chart onto many rectangles) order
// its system once.
class LuOrdering {
 public:
  LuOrdering();
  ~LuOrdering();
  LuOrdering(const LuOrdering&) = delete;
  LuOrdering& operator=(const LuOrdering&) = delete;

 private:
  friend class SmallSystemLu;
  struct Analysis;  // klu_symbolic (klu.h stays out of this header)
  std::once_flag once_;
  std::unique_ptr<Analysis> analysis_;
};

class SmallSystemLu {
 public:
  // With `shared`, the ordering is that one's (every matrix factored must have its pattern);
  // without, one of its own.
  explicit SmallSystemLu(LuOrdering* shared = nullptr);
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
  std::unique_ptr<LuOrdering> own_ordering_;
  LuOrdering* ordering_;
};

}  // namespace lowstretch
