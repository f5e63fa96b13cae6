// The pack stage alone: an atlas packed again (another texture size or gutter) without cutting or
// mapping its charts again. Its charts are read from its texture coordinates: faces joined by an
// edge whose two corners have the same UV on both sides. Each chart keeps its UV shape (scaled to
// the one texel density of the new layout, turned by quarter turns; one stored mirrored is mirrored
// back, since its faces would count as flipped) and all are
// packed by their outlines, then stored and made valid as parameterize_charts's atlas is. Where the
// layout as given, its charts' bounding square scaled onto the texture, keeps the new gutter and
// uses the texture at least as well (a tiling, whose rectangles a packing would leave gaps
// between), it is kept instead.
#pragma once
#include <Eigen/Core>

#include "atlas/base/atlas_types.h"

namespace lowstretch {

// corner_uv: #F x 6, (u, v) of corners 0, 1, 2 of every face, as the atlas to pack again stores
// them. A chart of no 3D area is put on a point; a chart with no UV area, or whose UV overlaps
// itself, is charted again as the atlas charts a mesh; a face whose UV folds or collapses is cut
// out and mapped again, as the atlas's are. Errors: options out of range, bad indices, non-finite
// coordinates, NoTextureCoordinates (UV missing or not finite, or no chart with UV area: no atlas
// to pack again), ChartsNotPacked.
ChartsResult repack_atlas(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& corner_uv,
                          const ChartOptions& options);

}  // namespace lowstretch
