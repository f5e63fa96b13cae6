// The prepare stage: the input made ready for the charts, once, up front. The defects of a scan
// that charts get past are fixed on a copy, one step after another, each step kept so that the
// atlas of the copy can be given back for the input: duplicate vertices welded, a manifold copy (cut
// open along bad edges, split at bad vertices), parts of zero 3D area left out. The input mesh
// itself is never changed.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "atlas/base/atlas_types.h"
#include "atlas/cut/split_vertex_fans.h"
#include "atlas/cut/weld_duplicates.h"
#include "core/parameterize.h"

namespace lowstretch {

struct PrepareStep {
  enum class Kind { Weld, ManifoldCopy, LeaveOutZeroArea };
  Kind kind = Kind::Weld;
  WeldedFaces welded;                   // Weld
  SplitFans split;                      // ManifoldCopy
  int vertices = 0;                     // rows of the V the step was taken on
  Eigen::MatrixXd V;                    // LeaveOutZeroArea: the mesh the step was taken on
  Eigen::MatrixXi F;
  std::vector<int> mapped, zero_area;   // LeaveOutZeroArea: the rows of F kept, and those left out
};

struct PreparedInput {
  Eigen::MatrixXd V;               // the mesh to chart
  Eigen::MatrixXi F;
  Result whole;                    // parameterize's map of V, F as one disk, or why it is not one
  std::vector<PrepareStep> steps;  // in the order taken
  Error error;                     // a defect that no step gets past
};

// The steps options.non_disk allows, each taken while parameterize's error is one it fixes (none
// for a disk or with NonDisk::Reject). `may_weld` false: no welding (the way out when the welded
// copy's charts fail).
PreparedInput prepare_input(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options, bool may_weld);

// The charts of prepared.V, F given back for the input, from the last step to the first, with a
// note per step saying what it did; an error is given back as it is.
ChartsResult give_back(const PreparedInput& prepared, ChartsResult charted, const ChartOptions& options);

// The errors of the disk check that a manifold copy of the mesh gets past.
bool manifold_copy_helps(ErrorCode code);

// Whether making charts gets past this error of the disk check (a cut into disks or a manifold copy
// fixes it): the caller then adds how its user asks for charts.
bool charts_would_help(ErrorCode code);

}  // namespace lowstretch
