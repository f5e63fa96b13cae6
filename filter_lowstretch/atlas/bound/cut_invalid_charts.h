// The kept atlas is always valid. A chart whose map, as stored in float, still has a flipped or
// zero-area triangle on a face with 3D area (a sliver a solve or float rounding folds, a spike's
// tip), or a flipped flat face, is cut: its invalid faces become charts of their own, the rest its
// connected parts, and the charts are laid out again, a few rounds; what is still invalid then is
// left to the last step (valid_as_stored.h), which never takes a whole chart apart face by face.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "atlas/base/atlas_types.h"
#include "atlas/base/tuning.h"
#include "atlas/chart_map/solved_chart.h"

namespace lowstretch {

// The signed UV area of face f's corners (corner_uv: #F x 6).
double corner_area(const Eigen::MatrixXd& corner_uv, Eigen::Index f);

// The faces whose UV triangle (corner_uv, as laid out) is flipped or has (next to) zero area,
// under `least_area` of the texture or, if `wobble` > 0, flipped or collapsed when each coordinate
// moves by up to `wobble` (kTuning.written_uv_rounding: as MeshLab's ASCII writers round), though
// the face is not flat (is_flat_face; unit_V in the unit box), and the flat faces whose UV triangle
// is flipped (their neighbours overlap there). The charts are cut for the first kind only: a needle
// that rounding could collapse stays one in any chart, and the last step moves it alone.
std::vector<int> invalid_faces(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& corner_uv,
                               double least_area = kTuning.least_uv_area, double wobble = 0);

// `invalid` less its specks: faces so small in 3D (a merged scan's caps) that, mapped as densely
// as the rest, their UV triangle is under the least area though not flipped. Cutting their charts
// does not help them; the last step (valid_as_stored.h) moves them alone.
std::vector<int> without_specks(const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& corner_uv,
                                const std::vector<int>& invalid);

// Cuts the charts (face_chart: the chart of each face) that hold `invalid` faces, each into its
// invalid faces one by one and the connected parts of the rest, and the `stretched` charts (such
// pieces far above the bound) in two where the stretch splits charts. Maps the new charts. The
// pieces of a guest are guests (a layout by outline stays one). A flat face left alone has
// nothing to map: it goes to `flat`. was: each chart's index before, -1 for a piece.
// Returns how many charts held invalid faces.
int cut_invalid_charts(std::vector<SolvedChart>& charts, std::vector<int>& guests, const std::vector<int>& face_chart,
                        const std::vector<int>& invalid, const std::vector<int>& stretched,
                        const Eigen::MatrixXd& unit_V, const Eigen::MatrixXi& F, const ChartOptions& options,
                        std::vector<int>& flat, std::vector<int>& was);

}  // namespace lowstretch
