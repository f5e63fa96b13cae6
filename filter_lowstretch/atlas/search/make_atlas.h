// The search over candidate atlases of a mesh that the entry point (charts.h) has prepared: each
// candidate segmentation is mapped, laid out and measured, and the best kept (make_atlas.cpp);
// the layouts each candidate gets (layouts.cpp); merging for shorter seams (merge_for_seams.cpp).
#pragma once
#include <Eigen/Core>

#include "atlas/base/atlas_types.h"

namespace lowstretch {

// Any mesh as charts: the best of the candidate atlases, with its notes and stage seconds.
ChartsResult make_atlas(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& given);

// Whether atlas a uses the texture better than b, or as well with fewer flipped and zero-area triangles.
bool more_efficient(const ChartsResult& a, const ChartsResult& b);

}  // namespace lowstretch
