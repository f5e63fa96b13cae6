#include "core/errors.h"

#include <sstream>

namespace lowstretch {

namespace {
std::string n(long long v) { return std::to_string(v); }
std::string plural(long long v, const char* one, const char* many) { return n(v) + " " + (v == 1 ? one : many); }
// The way out for the topology problems that charts solve (charts.h); the caller names the
// option its user knows (charts_would_help in atlas/prepare/prepare_input.h).
const char* const kChartsHint = "parameterize it as charts";
}  // namespace

std::string message(const Error& e) {
  switch (e.code) {
    case ErrorCode::None: return "no error";
    case ErrorCode::NoFaces:
      return "the mesh has no faces (" + plural(e.count, "vertex", "vertices") +
             "): a parameterization needs a triangle mesh, not a point cloud";
    case ErrorCode::IndexOutOfRange:
      return plural(e.count, "face refers", "faces refer") + " to a vertex that does not exist: the file is corrupt";
    case ErrorCode::RepeatedVertexInFace:
      return plural(e.count, "face names", "faces name") +
             " the same vertex twice: remove duplicate vertices in faces (Cleaning and Repairing) first, or " + kChartsHint;
    case ErrorCode::NonFiniteCoordinates:
      return plural(e.count, "vertex has", "vertices have") +
             " NaN or infinite coordinates: remove or repair those vertices first";
    case ErrorCode::NonManifoldEdges:
      return plural(e.count, "non-manifold edge", "non-manifold edges") +
             " (shared by more than two faces): repair non-manifold edges first, or " + kChartsHint;
    case ErrorCode::InconsistentOrientation:
      return plural(e.count, "edge joins faces", "edges join faces") +
             " of opposite orientation: the mesh is not consistently oriented (or not orientable); re-orient the faces "
             "coherently first, or " + kChartsHint;
    case ErrorCode::NonManifoldVertices:
      return plural(e.count, "non-manifold vertex", "non-manifold vertices") +
             " (several fans of faces meet there): split non-manifold vertices first, or " + kChartsHint;
    case ErrorCode::SeveralComponents:
      return "the mesh has " + n(e.count) + " connected components; a disk has exactly 1: keep one component, or " +
             kChartsHint;
    case ErrorCode::UnweldedVertices:
      return plural(e.count, "vertex sits", "vertices sit") +
             " exactly on another vertex, so the faces do not share them: the mesh is not welded (a triangle soup, as "
             "STL files are); merge them first (MeshLab: Cleaning and Repairing > Remove Duplicate Vertices) and try again";
    case ErrorCode::Closed: return std::string("the mesh is closed (no boundary): cut it open into a disk, or ") + kChartsHint;
    case ErrorCode::SeveralBoundaryLoops:
      return "the mesh has " + n(e.count) + " boundary loops; a disk has exactly 1: close the holes or cut the mesh, or " +
             kChartsHint;
    case ErrorCode::NotGenusZero:
      return "the mesh has genus " + n(e.count) + " with one boundary loop; a disk has genus 0: cut the handles open, or " +
             kChartsHint;
    case ErrorCode::ZeroAreaMesh:
      return "all " + plural(e.count, "face has", "faces have") + " zero area: there is no surface to parameterize";
    case ErrorCode::InvalidOption: return "invalid option: " + (e.option.empty() ? "" : e.option + " ") + e.detail;
    case ErrorCode::SolverFailed:
      return "the linear solve failed in pass " + n(e.count) + " (" + e.detail +
             "): try the circle boundary or Floater weights";
    case ErrorCode::ChartsNotPacked:
      return "the packer could not place the " + n(e.count) +
             " charts in the unit square: remove tiny parts (MeshLab: Remove Isolated pieces), or choose a larger "
             "texture or a narrower gutter, and try again";
    case ErrorCode::NoTextureCoordinates:
      return "there is no atlas to pack again: " + plural(e.count, "face has", "faces have") +
             " no usable per-corner texture coordinates (missing, NaN or infinite, or a chart with no texture area); "
             "parameterize the mesh first, then pack it again";
    case ErrorCode::Cancelled: return "cancelled";
  }
  return "unknown error";
}

std::string message(const Error& e, const std::function<std::string(const std::string&)>& name_of) {
  if (e.code != ErrorCode::InvalidOption || e.option.empty()) return message(e);
  return name_of(e.option) + " " + e.detail;
}

std::string number_text(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

const char* code_name(ErrorCode code) {
  switch (code) {
    case ErrorCode::None: return "none";
    case ErrorCode::NoFaces: return "no_faces";
    case ErrorCode::IndexOutOfRange: return "index_out_of_range";
    case ErrorCode::RepeatedVertexInFace: return "repeated_vertex_in_face";
    case ErrorCode::NonFiniteCoordinates: return "non_finite_coordinates";
    case ErrorCode::NonManifoldEdges: return "non_manifold_edges";
    case ErrorCode::InconsistentOrientation: return "inconsistent_orientation";
    case ErrorCode::NonManifoldVertices: return "non_manifold_vertices";
    case ErrorCode::SeveralComponents: return "several_components";
    case ErrorCode::UnweldedVertices: return "unwelded_vertices";
    case ErrorCode::Closed: return "closed";
    case ErrorCode::SeveralBoundaryLoops: return "several_boundary_loops";
    case ErrorCode::NotGenusZero: return "not_genus_zero";
    case ErrorCode::ZeroAreaMesh: return "zero_area_mesh";
    case ErrorCode::InvalidOption: return "invalid_option";
    case ErrorCode::SolverFailed: return "solver_failed";
    case ErrorCode::ChartsNotPacked: return "charts_not_packed";
    case ErrorCode::NoTextureCoordinates: return "no_texture_coordinates";
    case ErrorCode::Cancelled: return "cancelled";
  }
  return "unknown";
}

}  // namespace lowstretch
