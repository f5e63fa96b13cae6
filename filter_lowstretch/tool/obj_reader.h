// A minimal OBJ reader (v and f statements). Debian 12's vcglib (MeshLab 2020.09) cannot be
// used for OBJ: its importer makes face indices zero-based in SplitToken and then rejects index
// 0 in GoodObjIndex, so it silently drops every face that uses the file's first vertex.
#pragma once
#include <string>

#include "tool/tool_mesh.h"

namespace lowstretch {

// Polygons are split into fans. Returns false with a reason on a malformed statement or an
// index that is 0 or out of range.
bool read_obj(const std::string& path, ToolMesh& mesh, std::string& error);

}  // namespace lowstretch
