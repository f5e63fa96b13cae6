#include "atlas/charts.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <string>
#include <utility>

#include "atlas/base/used_vertices.h"
#include "atlas/bound/cut_invalid_charts.h"
#include "atlas/cut/split_vertex_fans.h"
#include "atlas/cut/weld_duplicates.h"
#include "atlas/cut/zero_area_parts.h"
#include "atlas/measure/atlas_result.h"
#include "atlas/measure/least_gutter.h"
#include "atlas/measure/valid_as_stored.h"
#include "atlas/search/make_atlas.h"
#include "core/disk_mesh.h"

namespace lowstretch {

Error check_chart_options(const ChartOptions& o) {
  if (!(o.max_stretch >= 1 && o.max_stretch < 1e6))
    return {ErrorCode::InvalidOption, 0, "must be at least 1, got " + number_text(o.max_stretch), "max_stretch"};
  if (o.most_cuts_ahead < 0 || o.most_cuts_ahead > 16)
    return {ErrorCode::InvalidOption, 0, "must be from 0 to 16, got " + std::to_string(o.most_cuts_ahead), "most_cuts_ahead"};
  if (!(o.min_efficiency >= 0 && o.min_efficiency <= 1))
    return {ErrorCode::InvalidOption, 0, "must be from 0 to 1, got " + number_text(o.min_efficiency), "min_efficiency"};
  if (o.max_charts < 1) return {ErrorCode::InvalidOption, 0, "must be at least 1, got " + std::to_string(o.max_charts), "max_charts"};
  if (o.texture_size < 8 || o.texture_size > 65536)
    return {ErrorCode::InvalidOption, 0, "must be from 8 to 65536, got " + std::to_string(o.texture_size), "texture_size"};
  if (!(o.gutter >= 0.5 && o.gutter <= o.texture_size / 8.0))
    return {ErrorCode::InvalidOption, 0, "must be from 0.5 to an eighth of the texture size (" +
                                             number_text(o.texture_size / 8.0) + "), got " + number_text(o.gutter),
            "gutter"};
  return {};
}

namespace {

// A disk as one chart: parameterize's map and pass history; measured later, like a layout.
ChartsResult from_disk(const Eigen::MatrixXi& F, Result disk) {
  ChartsResult result;
  result.input_is_disk = true;
  result.corner_uv.resize(F.rows(), 6);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) result.corner_uv.block(f, 2 * k, 1, 2) = disk.uv.row(F(f, k));
  result.face_chart.assign(size_t(F.rows()), 0);
  for (const PassMetrics& p : disk.passes) result.passes.push_back({p.pass, p.l2_stretch, p.flipped, p.degenerate});
  Chart chart;
  chart.faces = int(F.rows());
  chart.chosen_pass = disk.chosen_pass;
  chart.passes = int(disk.passes.size());
  result.charts.push_back(chart);
  result.seconds_total = disk.seconds_total;
  result.notes = std::move(disk.notes);
  result.disk_passes = std::move(disk.passes);
  result.chosen_pass = disk.chosen_pass;
  result.stop_reason = disk.stop_reason;
  return result;
}

// The errors that a manifold copy of the mesh gets past (several components: when parts touch
// at a vertex, that is found after the components).
bool manifold_copy_helps(ErrorCode code) {
  return code == ErrorCode::NonManifoldVertices || code == ErrorCode::SeveralComponents ||
         code == ErrorCode::NonManifoldEdges || code == ErrorCode::InconsistentOrientation ||
         code == ErrorCode::RepeatedVertexInFace;
}

std::string count_text(int count, const char* one, const char* many) {
  return std::to_string(count) + " " + (count == 1 ? one : many);
}


// A triangle soup (each face with vertices of its own, as STL stores them): half or more of the
// used vertices sit on another. Welding it, not cutting it, is the way out (as parameterize says).
bool is_unwelded(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  const Eigen::MatrixXd used = used_rows(V, F);
  return used.allFinite() && 2 * vertices_on_others(used) >= used.rows();  // NaN: refused later
}

// What the manifold copy changed, one note per kind of defect.
std::vector<std::string> split_notes(const SplitFans& split) {
  struct Defect {
    int count;
    const char *one, *many, *done;
  };
  const Defect defects[] = {
      {split.non_manifold_edges, "non-manifold edge", "non-manifold edges", " (shared by more than two faces) cut open"},
      {split.misoriented_edges, "edge", "edges", " between faces of opposite orientation cut open"},
      {split.repeated_vertex_faces, "face names", "faces name", " a vertex twice (zero area): given corners of their own"},
      {split.split_vertices, "non-manifold vertex", "non-manifold vertices",
       " (where parts, holes or cut edges touch) split per fan of faces"}};
  std::vector<std::string> notes;
  for (const Defect& d : defects)
    if (d.count > 0) notes.push_back(count_text(d.count, d.one, d.many) + d.done + " for the charts; the mesh is unchanged");
  return notes;
}

// parameterize_charts; `own_copies`: V holds copies of vertices made for a manifold copy, which
// are no sign of an unwelded mesh.
ChartsResult disk_or_atlas(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options, bool own_copies);


// parameterize's map of a disk as one chart, stored and measured as MeshLab holds it.
ChartsResult disk_result(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options, Result whole,
                         const Eigen::MatrixXd& unit_V, Clock::time_point start) {
  ChartsResult result = from_disk(F, std::move(whole));
  std::vector<int> all(static_cast<size_t>(F.rows()));
  for (Eigen::Index f = 0; f < F.rows(); ++f) all[size_t(f)] = int(f);
  store(unit_V, F, int(V.rows()), {all}, options, result);
  // The layout is the kept pass, as stored: its number, timings and solver stay.
  const PassMetrics measured = result.layout;
  result.layout = result.disk_passes.at(size_t(result.chosen_pass));
  copy_measures(measured, result.layout);
  result.seconds_total = seconds_since(start);
  return result;
}

// A mesh that is not manifold or not consistently oriented: the charts are made on a manifold
// copy (split_vertex_fans.h), cut open along its bad edges and split at its bad vertices.
ChartsResult on_manifold_copy(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options,
                              const SplitFans& split, Clock::time_point start) {
  if (is_unwelded(V, F)) return failed_result({ErrorCode::UnweldedVertices, vertices_on_others(used_rows(V, F)), ""});
  ChartsResult result = disk_or_atlas(split.V, split.F, options, true);
  if (result.error) return result;
  result.vertex_stretch = join_vertex_values(split, result.vertex_stretch, int(V.rows()));
  const std::vector<std::string> notes = split_notes(split);
  result.notes.insert(result.notes.begin(), notes.begin(), notes.end());
  result.seconds_total = seconds_since(start);
  return result;
}

// Parts of zero 3D area have nothing to map: the atlas is made of the other parts.
ChartsResult without_zero_area_parts(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options,
                                     bool own_copies, const std::vector<int>& zero_area, Clock::time_point start) {
  std::vector<int> mapped;
  for (Eigen::Index f = 0, z = 0; f < F.rows(); ++f)
    if (size_t(z) < zero_area.size() && zero_area[size_t(z)] == f) ++z;
    else mapped.push_back(int(f));
  Eigen::MatrixXi mapped_F(Eigen::Index(mapped.size()), 3);
  for (size_t j = 0; j < mapped.size(); ++j) mapped_F.row(Eigen::Index(j)) = F.row(mapped[j]);
  ChartsResult result = disk_or_atlas(V, mapped_F, options, own_copies);
  if (result.error) return result;
  result = with_zero_area_faces(std::move(result), V, F, mapped, zero_area, options);
  result.seconds_total = seconds_since(start);
  return result;
}

// A disk keeps the paper's single chart, unless it has flipped or zero-area triangles as stored
// (or, for Atlas, stretches more than the bound) and an atlas uses the texture better; a valid
// map wins over an invalid one, whatever their efficiency. Any other mesh gets the atlas.
ChartsResult disk_or_atlas_of_whole(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options,
                                    Result whole, Clock::time_point start) {
  const bool is_disk = !whole.error;
  if (!is_disk && (options.non_disk == NonDisk::Reject || !cutting_into_disks_fixes(whole.error.code)))
    return failed_result(whole.error);
  ChartsResult disk;
  double unit = 1;
  const Eigen::MatrixXd unit_V = is_disk ? unit_box_of_used(V, F, unit) : Eigen::MatrixXd();
  // Specks are left to the last step, valid_as_stored.
  const auto valid = [&](const ChartsResult& r) {
    return !r.error && without_specks(unit_V, F, r.corner_uv, invalid_faces(unit_V, F, r.corner_uv)).empty();
  };
  bool disk_valid = false;
  if (is_disk) {
    disk = disk_result(V, F, options, std::move(whole), unit_V, start);
    disk_valid = valid(disk);
    const bool try_atlas = options.non_disk == NonDisk::Atlas
                               ? !disk_valid || needs_split(as_chart_pass(disk.disk_passes.at(size_t(disk.chosen_pass))), options.max_stretch)
                               : options.non_disk == NonDisk::Charts && !disk_valid;
    if (!try_atlas) return disk;
  }
  ChartsResult atlas = make_atlas(V, F, options);
  const bool atlas_valid = is_disk && valid(atlas);
  if (is_disk && (atlas.error || (disk_valid != atlas_valid ? disk_valid : !more_efficient(atlas, disk)))) {
    if (!atlas.error)
      disk.notes.push_back("the disk stays one chart: cut into " + std::to_string(atlas.charts.size()) +
                           " charts it had efficiency " + number_text(texture_efficiency(atlas)) + " (coverage / L2^2) against " +
                           number_text(texture_efficiency(disk)));
    return disk;
  }
  atlas.seconds_total = seconds_since(start);
  atlas.layout.seconds = atlas.seconds_total;
  return atlas;
}

// A mesh with duplicate vertices: the charts made with them welded (weld_duplicates.h), each
// duplicate taking the stretch of the vertex it was welded onto; an error if that fails.
ChartsResult on_welded_copy(const Eigen::MatrixXd& V, const ChartOptions& options, const WeldedFaces& welded,
                            Clock::time_point start) {
  ChartsResult result = disk_or_atlas(V, welded.F, options, true);
  if (result.error) return result;
  for (size_t v = 0; v < welded.onto.size(); ++v)
    if (welded.onto[v] != int(v) && Eigen::Index(v) < result.vertex_stretch.size())
      result.vertex_stretch(Eigen::Index(v)) = result.vertex_stretch(welded.onto[v]);
  result.notes.insert(result.notes.begin(), count_text(welded.welded, "duplicate vertex", "duplicate vertices") +
                                                " (on another vertex's position) welded for the charts; the mesh is unchanged");
  result.seconds_total = seconds_since(start);
  return result;
}

ChartsResult disk_or_atlas(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options, bool own_copies) {
  const Clock::time_point start = Clock::now();
  Result whole = parameterize(V, F, options.disk);
  if (own_copies && whole.error.code == ErrorCode::UnweldedVertices) whole.error = {ErrorCode::SeveralComponents, 0, ""};
  // Not a disk: duplicates welded first (a disk keeps its seams; a soup is refused below, as the
  // manifold copy cannot help it). Copies the manifold copy made are not duplicates.
  if (!own_copies && options.non_disk != NonDisk::Reject && whole.error && charts_would_help(whole.error.code) &&
      !is_unwelded(V, F)) {
    const WeldedFaces welded = weld_duplicate_vertices(V, F);
    // Not where welding joins more faces on an edge than two, or two running it the same way: those
    // are parts that touch, or the two sides of a double-sided sheet, each better charted alone.
    const auto bad_edges = [&](const Eigen::MatrixXi& faces) {
      const SplitFans split = split_vertex_fans(V, faces);
      return split.non_manifold_edges + split.misoriented_edges;
    };
    if (welded.welded > 0 && bad_edges(welded.F) <= bad_edges(F)) {
      ChartsResult result = on_welded_copy(V, options, welded, start);
      if (!result.error) return result;
    }
  }
  if (options.non_disk != NonDisk::Reject && manifold_copy_helps(whole.error.code)) {
    const SplitFans split = split_vertex_fans(V, F);
    if (split.new_vertices > 0) return on_manifold_copy(V, F, options, split, start);
  }
  if (options.non_disk != NonDisk::Reject && whole.error.code == ErrorCode::SeveralComponents) {
    double unit = 1;
    const std::vector<int> zero_area = faces_of_zero_area_parts(unit_box_of_used(V, F, unit), F);
    if (!zero_area.empty() && Eigen::Index(zero_area.size()) < F.rows())
      return without_zero_area_parts(V, F, options, own_copies, zero_area, start);
  }
  return disk_or_atlas_of_whole(V, F, options, std::move(whole), start);
}

}  // namespace

void measure_gutter(const ChartOptions& options, ChartsResult& result) {
  if (result.error) return;
  const double texel = 1.0 / options.texture_size;
  result.least_gutter = least_gutter(result.corner_uv, result.face_chart, 2 * options.gutter * texel) / texel;
}

bool charts_would_help(ErrorCode code) { return cutting_into_disks_fixes(code) || manifold_copy_helps(code); }

ChartsResult parameterize_charts(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options) {
  if (Error e = check_chart_options(options)) return failed_result(e);
  ChartsResult result = disk_or_atlas(V, F, options, false);
  if (result.error) return result;
  double unit = 1;
  const Eigen::MatrixXd unit_V = unit_box_of_used(V, F, unit);
  double in_stages = 0;
  for (const StageSeconds& stage : result.stage_seconds) in_stages += stage.seconds;
  result.stage_seconds.insert(result.stage_seconds.begin(), {"input and whole map", std::max(0.0, result.seconds_total - in_stages)});
  const Clock::time_point start = Clock::now();
  result = valid_as_stored(unit_V, F, unit, int(V.rows()), options, std::move(result));
  measure_gutter(options, result);
  result.stage_seconds.push_back({"valid as stored", seconds_since(start)});
  result.seconds_total += result.stage_seconds.back().seconds;
  return result;
}

}  // namespace lowstretch
