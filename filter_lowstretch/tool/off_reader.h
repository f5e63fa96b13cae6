// A strict OFF reader (positions and polygons; normals, colours and texture coordinates are
// skipped). Debian 12's vcglib (MeshLab 2020.09) ImporterOFF trusts the file: it indexes the
// vertex array with unchecked face indices (heap overflow for polygons), reads the first token of
// a missing face line, indexes its 148-entry colour map with any integer and sizes polygons by
// their declared vertex count; tests/fuzz/ found all of these within seconds.
#pragma once
#include <string>

#include "tool/tool_mesh.h"

namespace lowstretch {

// One vertex per line (x y z first; the rest of the line is ignored), one face per line ("n i1 ..
// in", polygons split into fans). Returns false with a reason: bad header, counts the file cannot
// hold, a malformed number, an index out of range, a face of fewer than 3 vertices, a file cut short.
bool read_off(const std::string& path, long long file_size, ToolMesh& mesh, std::string& error);

}  // namespace lowstretch
