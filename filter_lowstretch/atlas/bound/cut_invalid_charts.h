// The kept atlas is always valid. A chart whose map, as stored in float, still has a flipped or
// zero-area triangle on a face with 3D area (a sliver a solve or float rounding folds, a spike's
// tip), or a flipped flat face, is cut: its invalid faces become charts of their own, the rest its connected parts, and
// the charts are laid out again; a chart that stays invalid is cut into single faces, which every
// map keeps valid.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "atlas/base/atlas_types.h"
#include "atlas/chart_map/solved_chart.h"

namespace lowstretch {

// The faces whose UV triangle (corner_uv, as laid out) is flipped or has (next to) zero area,
// under 1e-11 of the texture, though the face is not flat (is_flat_face; unit_V in the unit box),
// and the flat faces whose UV triangle is flipped (their neighbours overlap there).
std::vector<int> invalid_faces(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& corner_uv);

// Cuts the charts (face_chart: the chart of each face) that hold `invalid` faces, each into its
// invalid faces one by one and the connected parts of the rest, and the `stretched` charts (such
// pieces far above the bound) in two where the stretch splits charts; into single faces if
// `into_faces`. Maps the new charts. A cut chart is no longer a guest. A flat face left alone has
// nothing to map: it goes to `flat`. Returns how many charts held invalid faces.
int cut_invalid_charts(std::vector<SolvedChart>& charts, std::vector<int>& guests, const std::vector<int>& face_chart,
                        const std::vector<int>& invalid, const std::vector<int>& stretched, bool into_faces,
                        const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const ChartOptions& options,
                        std::vector<int>& flat);

}  // namespace lowstretch
