#include "atlas/prepare/prepare_input.h"

#include <string>
#include <utility>

#include "atlas/base/used_vertices.h"
#include "atlas/chart_map/solved_chart.h"
#include "atlas/cut/zero_area_parts.h"
#include "core/disk_mesh.h"

namespace lowstretch {

bool manifold_copy_helps(ErrorCode code) {
  // Several components: when parts touch at a vertex, that is found after the components.
  return code == ErrorCode::NonManifoldVertices || code == ErrorCode::SeveralComponents ||
         code == ErrorCode::NonManifoldEdges || code == ErrorCode::InconsistentOrientation ||
         code == ErrorCode::RepeatedVertexInFace;
}

bool charts_would_help(ErrorCode code) { return cutting_into_disks_fixes(code) || manifold_copy_helps(code); }

namespace {

std::string count_text(int count, const char* one, const char* many) {
  return std::to_string(count) + " " + (count == 1 ? one : many);
}

// A triangle soup (each face with vertices of its own, as STL stores them): half or more of the
// used vertices sit on another. Welding it, not cutting it, is the way out (as parameterize says).
bool is_unwelded(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  const Eigen::MatrixXd used = used_rows(V, F);
  return used.allFinite() && 2 * vertices_on_others(used) >= used.rows();  // NaN: refused later
}

// Edges shared by more than two faces, or by two running them the same way.
int bad_edges(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  const SplitFans split = split_vertex_fans(V, F);
  return split.non_manifold_edges + split.misoriented_edges;
}

// Duplicates are welded where that does not join more faces on an edge than two, or two running it
// the same way: those are parts that touch, or the two sides of a double-sided sheet, each better
// charted alone. A disk keeps its seams; a soup is left to the manifold copy's refusal.
bool weld(PreparedInput& p) {
  if (!charts_would_help(p.whole.error.code) || is_unwelded(p.V, p.F)) return false;
  PrepareStep step;
  step.kind = PrepareStep::Kind::Weld;
  step.welded = weld_duplicate_vertices(p.V, p.F);
  if (step.welded.welded == 0 || bad_edges(p.V, step.welded.F) > bad_edges(p.V, p.F)) return false;
  p.F = step.welded.F;
  p.steps.push_back(std::move(step));
  return true;
}

// A mesh that is not manifold or not consistently oriented is charted as a manifold copy
// (split_vertex_fans.h), cut open along its bad edges and split at its bad vertices.
bool make_manifold_copy(PreparedInput& p) {
  if (!manifold_copy_helps(p.whole.error.code)) return false;
  PrepareStep step;
  step.kind = PrepareStep::Kind::ManifoldCopy;
  step.split = split_vertex_fans(p.V, p.F);
  if (step.split.new_vertices == 0) return false;
  if (is_unwelded(p.V, p.F)) {
    p.error = {ErrorCode::UnweldedVertices, vertices_on_others(used_rows(p.V, p.F)), ""};
    return false;
  }
  step.vertices = int(p.V.rows());
  p.V = step.split.V;
  p.F = step.split.F;
  p.steps.push_back(std::move(step));
  return true;
}

// Parts of zero 3D area have nothing to map: the atlas is made of the other parts.
bool leave_out_zero_area_parts(PreparedInput& p) {
  if (p.whole.error.code != ErrorCode::SeveralComponents) return false;
  double unit = 1;
  PrepareStep step;
  step.kind = PrepareStep::Kind::LeaveOutZeroArea;
  step.zero_area = faces_of_zero_area_parts(unit_box_of_used(p.V, p.F, unit), p.F);
  if (step.zero_area.empty() || Eigen::Index(step.zero_area.size()) == p.F.rows()) return false;
  for (Eigen::Index f = 0, z = 0; f < p.F.rows(); ++f)
    if (size_t(z) < step.zero_area.size() && step.zero_area[size_t(z)] == f) ++z;
    else step.mapped.push_back(int(f));
  Eigen::MatrixXi mapped_F(Eigen::Index(step.mapped.size()), 3);
  for (size_t j = 0; j < step.mapped.size(); ++j) mapped_F.row(Eigen::Index(j)) = p.F.row(step.mapped[j]);
  step.V = p.V;
  step.F = std::move(p.F);
  p.F = std::move(mapped_F);
  p.steps.push_back(std::move(step));
  return true;
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

// One step undone: each duplicate takes the stretch of the vertex it was welded onto; each vertex of
// the manifold copy's copies gives its stretch to its input vertex; the zero-area faces come back.
ChartsResult undo(const PrepareStep& step, ChartsResult result, const ChartOptions& options) {
  std::vector<std::string> notes;
  if (step.kind == PrepareStep::Kind::Weld) {
    for (size_t v = 0; v < step.welded.onto.size(); ++v)
      if (step.welded.onto[v] != int(v) && Eigen::Index(v) < result.vertex_stretch.size())
        result.vertex_stretch(Eigen::Index(v)) = result.vertex_stretch(step.welded.onto[v]);
    notes.push_back(count_text(step.welded.welded, "duplicate vertex", "duplicate vertices") +
                    " (on another vertex's position) welded for the charts; the mesh is unchanged");
  } else if (step.kind == PrepareStep::Kind::ManifoldCopy) {
    result.vertex_stretch = join_vertex_values(step.split, result.vertex_stretch, step.vertices);
    notes = split_notes(step.split);
  } else {
    result = with_zero_area_faces(std::move(result), step.V, step.F, step.mapped, step.zero_area, options);
  }
  result.notes.insert(result.notes.begin(), notes.begin(), notes.end());
  return result;
}

}  // namespace

PreparedInput prepare_input(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ChartOptions& options, bool may_weld) {
  PreparedInput p;
  p.V = V;
  p.F = F;
  for (;;) {
    p.whole = parameterize(p.V, p.F, options.disk);
    // Copies a step made (welded, or the manifold copy's) are not duplicates.
    bool own_copies = false;
    for (const PrepareStep& step : p.steps) own_copies = own_copies || step.kind != PrepareStep::Kind::LeaveOutZeroArea;
    if (own_copies && p.whole.error.code == ErrorCode::UnweldedVertices) p.whole.error = {ErrorCode::SeveralComponents, 0, ""};
    if (options.non_disk == NonDisk::Reject || !p.whole.error) return p;
    const bool stepped = (may_weld && !own_copies && weld(p)) || make_manifold_copy(p) || (!p.error && leave_out_zero_area_parts(p));
    if (!stepped) return p;
  }
}

ChartsResult give_back(const PreparedInput& prepared, ChartsResult charted, const ChartOptions& options) {
  for (size_t s = prepared.steps.size(); s-- > 0 && !charted.error;) {
    charted = undo(prepared.steps[s], std::move(charted), options);
  }
  return charted;
}

}  // namespace lowstretch
