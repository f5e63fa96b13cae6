// A low-stretch atlas of any manifold mesh: every connected component becomes a disk chart
// (holes closed virtually, closed or higher-genus parts cut open along short seams;
// solved_chart.h), each chart gets the paper's low-stretch map onto a rectangle, a chart that
// stretches more than a bound is cut in two (split_until_bounded.h; also one whose closed holes
// leave too much of its rectangle empty) and mapped again (a chart no rectangle fits keeps its own
// shape: free_charts.h), and the charts' rectangles tile the unit square (lay_out_charts.h); the
// layout is measured as MeshLab stores it (atlas_result.h). A model made of faces (a CAD part) is
// also cut along its sharp edges first (sharp_patches.h; at 80 degrees, and at 30 while its atlas
// uses the texture poorly); the atlas that uses the texture best is kept, and laid out again
// with small charts in the texels its tiling leaves empty (empty_texels.h) if that is better.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <string>
#include <vector>

#include "core/parameterize.h"

namespace lowstretch {

// What to do with a mesh: Reject a mesh that is not a disk (disk-only); make an atlas of a mesh
// that is not a disk (Charts, the default: a disk keeps the paper's single chart while that map
// has no flipped or zero-area triangle); make an atlas of any mesh (Atlas: a disk whose map meets
// max_stretch stays that one chart).
enum class NonDisk { Reject, Charts, Atlas };

struct ChartOptions {
  Options disk;                        // the method, for the whole disk or for each chart
  NonDisk non_disk = NonDisk::Charts;  // Reject: a non-disk mesh is an error, as parameterize
  // The texture the map is made for: every UV stays `gutter` texels or more away from the border
  // of [0,1]^2, so that baking, mipmaps and rasterizers never address a texel outside the image
  // (UV exactly 0 or 1 would give texel -1 or `texture_size`).
  int texture_size = 1024;             // texels per side, 8 to 65536
  double gutter = 2;                   // in texels, from 0.5 to an eighth of texture_size
                                       // (between charts too)
  // A chart whose L2 stretch is above max_stretch, or that has a flipped or zero-area triangle,
  // is cut in two, until max_charts; charts of fewer than 2 x kSmallestChart faces stay whole
  // unless they stretch more than kSmallCutAbove times the bound and have kSmallestCutChart faces.
  double max_stretch = 1.2;            // at least 1
  int max_charts = 100000;             // at least 1
  // A chart far above the bound has its largest part cut again before any part is mapped, once
  // per doubling of its L2 stretch over max_stretch, at most this often (0: every part is mapped
  // before it is cut, which is slower and gives the same atlas).
  int most_cuts_ahead = 4;             // 0 to 16
};
// Smaller charts cut coarse models better, at the cost of more seams and gutters.
constexpr int kSmallestChart = 15;
// A smaller chart is cut after all when it stretches more than kSmallCutAbove times the bound and
// has kSmallestCutChart faces or more: a spike's tip or a crease left in a small part can stretch
// so much that it raises the L2 stretch of the whole atlas. Cutting smaller charts too would split
// a finely meshed CAD part into more charts than a tiling can hold.
constexpr double kSmallCutAbove = 2;
constexpr int kSmallestCutChart = 8;  // faces

struct Chart {
  int faces = 0;
  int closed_holes = 0;     // holes filled virtually for the solve
  double seam_length = 0;   // 3D length of the seams cut in this chart, in the input's units
  double l2_stretch = 0;    // normalized L2 stretch of this chart alone in the final layout
  double linf_stretch = 0;  // its largest triangle stretch, normalized the same way
  bool above_bound = false; // l2_stretch > max_stretch or invalid triangles
  std::string kept_whole;   // why such a chart was not cut further (the notes sum them up)
  int chosen_pass = 0, passes = 0;
};

// Pass k over the whole mesh: every chart at its pass k, or at its kept pass once it has
// stopped, laid out at one texel density (as the final layout is).
struct LayoutPass {
  int pass = 0;
  double l2_stretch = 0;  // normalized; infinite if a triangle is flipped or has zero area
  int flipped = 0, degenerate = 0;
};

struct ChartsResult {
  Error error;  // error.code != None: nothing below is filled
  // #F x 6: (u, v) of corners 0, 1, 2 of every face, in [g, 1 - g]^2, g = gutter / texture_size,
  // rounded to float as MeshLab stores them: `layout`, face_stretch, vertex_stretch, coverage and
  // the charts' L2 stretch are measured on these, so they describe the map a user reads back.
  Eigen::MatrixXd corner_uv;
  std::vector<int> face_chart;            // chart of each face
  Eigen::VectorXd face_stretch;           // normalized over the whole layout, inf if flipped
  Eigen::VectorXd vertex_stretch;         // per input vertex (0 if unused)
  std::vector<Chart> charts;
  PassMetrics layout;                     // the paper's metrics of corner_uv (a disk: its kept pass's
                                          // number and timings, measured after rounding)
  int subtexel_triangles = 0;             // UV triangles smaller than one texel of a 4096^2 texture
  int float_collapsed = 0;                // of them, positive in double, flipped or zero in float
  std::vector<LayoutPass> passes;         // L2 stretch and flips of every pass, whole mesh
  double seam_length = 0;                 // sum over the charts
  double coverage = 0;                    // fraction of [0,1]^2 covered by the UV triangles
  double seconds_total = 0;
  // A disk input is one chart: parameterize's map of the whole mesh, in the fields above. How
  // its passes went (empty for charts, whose passes are per chart and summed up in `passes`):
  bool input_is_disk = false;
  std::vector<PassMetrics> disk_passes;   // every pass computed, including a rejected last one
  int chosen_pass = 0;                    // index into disk_passes of the kept pass (= layout)
  StopReason stop_reason = StopReason::MaxPasses;
  std::vector<std::string> notes;
};

// A disk gives parameterize's result (one chart, the same UV), and with NonDisk::Atlas too
// when it meets max_stretch. Any other mesh gives parameterize's error unless options.non_disk
// makes charts and the only problems are several components, holes, no boundary or genus;
// non-manifold or non-orientable input stays an error.
ChartsResult parameterize_charts(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options);

// Texture efficiency (Sander et al. 2001): coverage / L2^2, the share of the texture used per unit
// of stretch; -1 for a failed result.
double texture_efficiency(const ChartsResult& result);
// The highest L2 stretch of any one chart (0 for a failed result).
double largest_chart_stretch(const ChartsResult& result);

// Whether making charts gets past this error of the disk check (a cut into disks or a manifold copy
// fixes it): the caller then adds how its user asks for charts.
bool charts_would_help(ErrorCode code);

const char* to_string(NonDisk non_disk);

}  // namespace lowstretch
