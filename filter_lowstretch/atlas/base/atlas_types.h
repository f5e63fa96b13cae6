// The atlas's vocabulary, shared by its stages and its callers: what to do with a mesh that is
// not a disk, the options, and the result (every chart, every pass over all charts, the layout).
#pragma once
#include <Eigen/Core>
#include <chrono>
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
  // is cut in two, until max_charts (small charts may stay whole: AtlasTuning::smallest_chart).
  double max_stretch = 1.2;            // at least 1
  int max_charts = 100000;             // at least 1
  // A chart far above the bound has its largest part cut again before any part is mapped, once
  // per doubling of its L2 stretch over max_stretch, at most this often (0: every part is mapped
  // before it is cut, which is slower and gives the same atlas).
  int most_cuts_ahead = 4;             // 0 to 16
  // Then neighbouring charts are merged for shorter seams while the atlas keeps this texture
  // efficiency (coverage / L2^2); 1 merges none. 0: AtlasTuning::merge_floor and merge_keeps of the
  // unmerged atlas's, by default or with fewer_seams.
  double min_efficiency = 0;           // 0 to 1
  bool fewer_seams = false;
  // Keep the atlas the mesh has (its per-corner texture coordinates) and pack its charts again for
  // texture_size and gutter (repack.h); the options above are not used.
  bool repack = false;
};

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

// The wall-clock seconds one stage of the atlas took.
struct StageSeconds {
  std::string stage;
  double seconds = 0;
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
  double l2_of_valid = 0;                 // the layout's L2 stretch over the faces neither flipped nor zero-area
  std::vector<LayoutPass> passes;         // L2 stretch and flips of every pass, whole mesh
  double seam_length = 0;                 // sum over the charts
  double coverage = 0;                    // fraction of [0,1]^2 covered by the UV triangles
  // In texels: the least distance from a chart to another or to the texture's border, as stored
  // (measure/least_gutter.h; distances between charts above twice the gutter are not looked for).
  double least_gutter = 0;
  double seconds_total = 0;
  // Where seconds_total went, stage by stage in the order they ran: "input and whole map" (the
  // mesh's shape, its repairs, the whole mesh's map, and any atlas not kept), the kept atlas's
  // stages, "valid as stored".
  std::vector<StageSeconds> stage_seconds;
  // A disk input is one chart: parameterize's map of the whole mesh, in the fields above (the
  // faces it folded or collapsed as stored cut out, if any: valid_as_stored.h). How its passes
  // went (empty for charts, whose passes are per chart and summed up in `passes`):
  bool input_is_disk = false;
  std::vector<PassMetrics> disk_passes;   // every pass computed, including a rejected last one
  int chosen_pass = 0;                    // index into disk_passes of the kept pass (= layout)
  StopReason stop_reason = StopReason::MaxPasses;
  std::vector<std::string> notes;
};

const char* to_string(NonDisk non_disk);

// Texture efficiency (Sander et al. 2001): coverage / L2^2, the share of the texture used per unit
// of stretch; -1 for a failed result. Where float rounding alone folds or collapses triangles, L2
// is taken over the others: the last step (valid_as_stored.h) makes each such triangle a chart of
// its own, and on a large scan a few of them would make every candidate's efficiency 0.
double texture_efficiency(const ChartsResult& result);
// The highest L2 stretch of any one chart (0 for a failed result).
double largest_chart_stretch(const ChartsResult& result);

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace lowstretch
