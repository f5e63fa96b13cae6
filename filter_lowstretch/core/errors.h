// What can go wrong with an input mesh or a run, as one enum with one message per code.
#pragma once
#include <functional>
#include <string>
#include <utility>

namespace lowstretch {

enum class ErrorCode {
  None = 0,
  NoFaces,                  // count: vertices
  IndexOutOfRange,          // count: faces with a bad vertex index
  RepeatedVertexInFace,     // count: faces that name one vertex twice
  NonFiniteCoordinates,     // count: referenced vertices with NaN or infinite coordinates
  NonManifoldEdges,         // count: edges shared by more than two faces
  InconsistentOrientation,  // count: edges whose two faces disagree on orientation
  NonManifoldVertices,      // count: vertices whose faces form several fans
  SeveralComponents,        // count: connected components
  UnweldedVertices,         // count: vertices at exactly the position of another (half or more of them)
  Closed,                   // count: unused
  SeveralBoundaryLoops,     // count: boundary loops
  NotGenusZero,             // count: genus
  ZeroAreaMesh,             // count: faces (all of them have zero 3D area)
  InvalidOption,            // count: unused; detail names the option
  SolverFailed,             // count: pass number
  ChartsNotPacked,          // count: charts
  NoTextureCoordinates,     // count: faces without usable texture coordinates (packing an atlas again)
  Cancelled,                // count: unused
};

struct Error {
  Error(ErrorCode code = ErrorCode::None, long long count = 0, std::string detail = "", std::string option = "")
      : code(code), count(count), detail(std::move(detail)), option(std::move(option)) {}
  ErrorCode code;
  long long count;
  std::string detail;  // extra words for InvalidOption and SolverFailed
  std::string option;  // InvalidOption: the Options field at fault, as the core names it ("exponent")
  explicit operator bool() const { return code != ErrorCode::None; }
};

// One line for a person: what was found and what to do about it.
std::string message(const Error& error);
// The same, with the option at fault (InvalidOption) named as the caller's user knows it: a flag
// of the tool, a parameter label of the filter. `name_of` maps the core's name to that.
std::string message(const Error& error, const std::function<std::string(const std::string&)>& name_of);
// A number as a person writes it in a message: 2, 0.5, 1e+30.
std::string number_text(double value);
// A stable short name for scripts and JSON ("several_boundary_loops").
const char* code_name(ErrorCode code);

}  // namespace lowstretch
