// A strict PLY reader (ASCII, binary little- and big-endian): vertex x, y, z and the face list
// vertex_indices (or vertex_index), every other element and property skipped by its type.
// Debian 12's vcglib (MeshLab 2020.09) ImporterPLY / plylib trusts the file: atoi(NULL) on an
// element line without a count, strcmp(NULL) on an empty header line, a face list longer than its
// fixed int[512] (stack overflow), polygon indices checked against the wrong entry, no byte swap
// for big-endian doubles; tests/fuzz/ found these within seconds.
#pragma once
#include <string>

#include "tool/tool_mesh.h"

namespace lowstretch {

// Returns false with a reason: bad header, counts the file cannot hold, a malformed or missing
// value, an index out of range, a face of fewer than 3 vertices, a file cut short.
bool read_ply(const std::string& path, long long file_size, ToolMesh& mesh, std::string& error);

}  // namespace lowstretch
