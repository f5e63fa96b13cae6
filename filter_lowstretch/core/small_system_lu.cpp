#include "core/small_system_lu.h"

#include <klu.h>

namespace lowstretch {

struct LuOrdering::Analysis {
  klu_symbolic* symbolic = nullptr;
};

LuOrdering::LuOrdering() : analysis_(std::make_unique<Analysis>()) {}

LuOrdering::~LuOrdering() {
  if (!analysis_->symbolic) return;
  klu_common common;
  klu_defaults(&common);
  klu_free_symbolic(&analysis_->symbolic, &common);
}

struct SmallSystemLu::Klu {
  klu_common common;
  klu_numeric* numeric = nullptr;
  int rows = 0;
};

SmallSystemLu::SmallSystemLu(LuOrdering* shared)
    : klu_(std::make_unique<Klu>()), own_ordering_(shared ? nullptr : std::make_unique<LuOrdering>()),
      ordering_(shared ? shared : own_ordering_.get()) {
  klu_defaults(&klu_->common);
  klu_->common.btf = 0;  // a chart's system is one block: the search for more only costs time
  klu_->common.ordering = 0;  // AMD: a shared ordering stays read-only (small_system_lu.h)
}

SmallSystemLu::~SmallSystemLu() {
  if (klu_->numeric) klu_free_numeric(&klu_->numeric, &klu_->common);
}

bool SmallSystemLu::factorize(Eigen::SparseMatrix<double, Eigen::RowMajor, int>& A, bool fresh) {
  A.makeCompressed();
  int* starts = A.outerIndexPtr();
  int* indices = A.innerIndexPtr();
  double* values = A.valuePtr();
  klu_->rows = int(A.rows());
  std::call_once(ordering_->once_, [&] { ordering_->analysis_->symbolic = klu_analyze(klu_->rows, starts, indices, &klu_->common); });
  klu_symbolic* symbolic = ordering_->analysis_->symbolic;
  if (!symbolic || symbolic->n != klu_->rows || symbolic->nz != starts[klu_->rows]) return false;
  if (!fresh && klu_->numeric && klu_refactor(starts, indices, values, symbolic, klu_->numeric, &klu_->common) &&
      klu_->common.status == KLU_OK)
    return true;
  if (klu_->numeric) klu_free_numeric(&klu_->numeric, &klu_->common);
  klu_->numeric = klu_factor(starts, indices, values, symbolic, &klu_->common);
  return klu_->numeric != nullptr && klu_->common.status == KLU_OK;
}

bool SmallSystemLu::solve(const Eigen::MatrixXd& b, Eigen::MatrixXd& x) {
  x = b;
  if (!klu_->numeric || x.rows() != klu_->rows) return false;
  return klu_tsolve(ordering_->analysis_->symbolic, klu_->numeric, int(x.rows()), int(x.cols()), x.data(), &klu_->common) &&
         klu_->common.status == KLU_OK;
}

}  // namespace lowstretch
