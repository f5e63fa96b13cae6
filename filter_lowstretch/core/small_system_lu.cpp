#include "core/small_system_lu.h"

#include <klu.h>

namespace lowstretch {

struct SmallSystemLu::Klu {
  klu_common common;
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
  int rows = 0;
};

SmallSystemLu::SmallSystemLu() : klu_(std::make_unique<Klu>()) {
  klu_defaults(&klu_->common);
  klu_->common.btf = 0;  // a chart's system is one block: the search for more only costs time
}

SmallSystemLu::~SmallSystemLu() {
  if (klu_->numeric) klu_free_numeric(&klu_->numeric, &klu_->common);
  if (klu_->symbolic) klu_free_symbolic(&klu_->symbolic, &klu_->common);
}

bool SmallSystemLu::factorize(Eigen::SparseMatrix<double, Eigen::RowMajor, int>& A, bool fresh) {
  A.makeCompressed();
  int* starts = A.outerIndexPtr();
  int* indices = A.innerIndexPtr();
  double* values = A.valuePtr();
  klu_->rows = int(A.rows());
  if (!klu_->symbolic) {
    klu_->symbolic = klu_analyze(klu_->rows, starts, indices, &klu_->common);
    if (!klu_->symbolic) return false;
  }
  if (!fresh && klu_->numeric && klu_refactor(starts, indices, values, klu_->symbolic, klu_->numeric, &klu_->common) &&
      klu_->common.status == KLU_OK)
    return true;
  if (klu_->numeric) klu_free_numeric(&klu_->numeric, &klu_->common);
  klu_->numeric = klu_factor(starts, indices, values, klu_->symbolic, &klu_->common);
  return klu_->numeric != nullptr && klu_->common.status == KLU_OK;
}

bool SmallSystemLu::solve(const Eigen::MatrixXd& b, Eigen::MatrixXd& x) {
  x = b;
  if (!klu_->numeric || x.rows() != klu_->rows) return false;
  return klu_tsolve(klu_->symbolic, klu_->numeric, int(x.rows()), int(x.cols()), x.data(), &klu_->common) &&
         klu_->common.status == KLU_OK;
}

}  // namespace lowstretch
