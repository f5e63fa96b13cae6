// What every atlas layout must satisfy, checked from the texture coordinates alone: shared by the
// chart and atlas tests.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "atlas/charts.h"

namespace lowstretch {

Eigen::Vector2d corner(const ChartsResult& r, Eigen::Index f, int k);
double signed_area(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

// Each chart's texel density: its UV area over its 3D area.
std::vector<double> texel_densities(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartsResult& r);

// Pixel centres of a 1024 x 1024 raster strictly inside two triangles (of one chart or of two):
// any overlap of the layout that covers a pixel centre.
int overlapping_pixels(const ChartsResult& r);

// The least distance between two triangles: 0 where their sides cross, else from a corner of one
// to a side of the other (one inside the other without crossing is not looked for).
double triangle_distance(const Eigen::Vector2d a[3], const Eigen::Vector2d b[3]);
// The least distance between triangles of different charts, in UV (all pairs: small meshes only).
double least_distance_between_charts(const Eigen::MatrixXi& F, const ChartsResult& r);

// Every face mapped, inside the default gutter, no flipped or zero-area triangle, no overlap,
// finite stretch, every face in one of the charts. With V, a face of zero 3D area may have zero
// UV area (never a negative one).
void expect_valid_layout(const Eigen::MatrixXi& F, const ChartsResult& r, const Eigen::MatrixXd* V = nullptr);

}  // namespace lowstretch
