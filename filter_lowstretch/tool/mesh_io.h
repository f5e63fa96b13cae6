// Reading meshes with the tool's own strict readers and writing them (PLY through vcglib's exporter, OBJ by obj_writer.h),
// guarded against files that would make them crash or allocate without bound.
#pragma once
#include <string>

#include "tool/tool_mesh.h"

namespace lowstretch {

// OFF (off_reader.h), PLY (ASCII or binary; ply_reader.h) or OBJ (obj_reader.h), by extension. Returns false with a one-line reason.
bool read_mesh(const std::string& path, ToolMesh& mesh, std::string& error);

// OBJ (per-corner vt and an .mtl naming `texture`) or PLY (per-wedge texcoords, per-vertex and
// per-face quality), by extension. Writes to a temporary file first, so a failure leaves no
// output behind and never changes an existing file.
bool write_mesh(const std::string& path, ToolMesh& mesh, const std::string& texture, std::string& error);

}  // namespace lowstretch
