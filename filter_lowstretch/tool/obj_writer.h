// The tool's OBJ output: vcglib 2020.09's OBJ exporter writes texture coordinates with 6 decimals
// (printf "%f"), which moves a float texcoord by up to 5e-7 and can flip a tiny UV triangle. This
// writer prints 17 significant digits of the float texture coordinates and of the double
// positions: read as double, they are exactly the values measured; read as float (MeshLab), the
// same floats.
#pragma once
#include <string>

#include "tool/tool_mesh.h"

namespace lowstretch {

// Writes `path` (v, per-corner vt, f v/vt) and `path`.mtl naming `texture`, each through a
// temporary file renamed at the end. Returns false with a one-line reason.
bool write_obj(const std::string& path, const ToolMesh& mesh, const std::string& texture, std::string& error);

}  // namespace lowstretch
