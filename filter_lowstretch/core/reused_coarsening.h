// A coarsening policy for amgcl::amg (amgcl 1.0.0 takes the coarsening as a template policy) that
// builds every level's transfer operators P and R once and hands them back on later builds: a
// values-only rebuild. The passes change the weights, never the mesh, so every pass has the same
// sparsity; a later pass recomputes only the Galerkin products R A P (and amg its smoothers), not
// the aggregation and the smoothing of P.
// It also keeps the Galerkin products of the last build, so that a twin hierarchy of the same
// matrix (one per thread: a hierarchy holds its cycle's work vectors) shares them instead of
// computing them again.
#pragma once
#include <amgcl/coarsening/smoothed_aggregation.hpp>
#include <boost/shared_ptr.hpp>
#include <boost/tuple/tuple.hpp>
#include <cstddef>
#include <vector>

namespace lowstretch {

// The operators of one hierarchy, level by level. Before each build, set `level` to 0 and `twin`
// to whether the matrix is the one of the last build.
template <class Matrix>
struct TransferRecord {
  std::vector<boost::shared_ptr<Matrix>> P, R, coarse;
  size_t level = 0;
  bool twin = false;
};

template <class Matrix, class Base = amgcl::coarsening::smoothed_aggregation>
struct ReusedCoarsening {
  struct params : Base::params {
    TransferRecord<Matrix>* record = nullptr;  // none: Base alone
    params() = default;
    explicit params(const boost::property_tree::ptree& p) : Base::params(p) {}
  };

  static boost::tuple<boost::shared_ptr<Matrix>, boost::shared_ptr<Matrix>> transfer_operators(const Matrix& A,
                                                                                               params& prm) {
    TransferRecord<Matrix>* r = prm.record;
    if (!r) return Base::transfer_operators(A, prm);
    const size_t l = r->level++;
    // A level whose size differs (never with one sparsity) is built afresh, and so are those below.
    if (l < r->P.size() && amgcl::backend::rows(*r->P[l]) == amgcl::backend::rows(A))
      return boost::make_tuple(r->P[l], r->R[l]);
    r->P.resize(l);
    r->R.resize(l);
    r->twin = false;
    const auto fresh = Base::transfer_operators(A, prm);
    r->P.push_back(boost::get<0>(fresh));
    r->R.push_back(boost::get<1>(fresh));
    return fresh;
  }

  static boost::shared_ptr<Matrix> coarse_operator(const Matrix& A, const Matrix& P, const Matrix& R,
                                                   const params& prm) {
    TransferRecord<Matrix>* r = prm.record;
    if (!r) return Base::coarse_operator(A, P, R, prm);
    const size_t l = r->level - 1;  // transfer_operators has just counted this level
    if (r->twin && l < r->coarse.size()) return r->coarse[l];
    r->coarse.resize(l);
    r->coarse.push_back(Base::coarse_operator(A, P, R, prm));
    return r->coarse.back();
  }
};

}  // namespace lowstretch
