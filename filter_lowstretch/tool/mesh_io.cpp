#include "mesh_io.h"

#include "obj_reader.h"
#include "off_reader.h"
#include "ply_reader.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <new>
#include <sstream>

#include <wrap/io_trimesh/export_obj.h>
#include <wrap/io_trimesh/export_ply.h>

namespace lowstretch {

namespace {

std::string extension_of(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

long long file_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  return in ? (long long)in.tellg() : -1;
}

}  // namespace

bool read_mesh(const std::string& path, ToolMesh& mesh, std::string& error) {
  const long long size = file_size(path);
  if (size < 0) { error = "cannot open " + path; return false; }
  if (size == 0) { error = path + " is empty"; return false; }
  const std::string ext = extension_of(path);
  bool ok = false;
  try {
    if (ext == "off") {
      ok = read_off(path, size, mesh, error);
    } else if (ext == "ply") {
      ok = read_ply(path, size, mesh, error);
    } else if (ext == "obj") {
      ok = read_obj(path, mesh, error);
    } else {
      error = "unknown file type '." + ext + "': use OFF, OBJ or PLY";
    }
  } catch (const std::bad_alloc&) {
    error = "out of memory while reading: the file declares more than this machine can hold";
    ok = false;
  } catch (const std::exception& e) {
    error = std::string("the reader failed: ") + e.what();
    ok = false;
  }
  if (!ok) error = "cannot read " + path + ": " + error;
  return ok;
}

namespace {
template <class Exporter>
int run_exporter(ToolMesh& mesh, const std::string& path, int mask) {
  return Exporter::Save(mesh, path.c_str(), mask);
}
}  // namespace

bool write_mesh(const std::string& path, ToolMesh& mesh, const std::string& texture, std::string& error) {
  const std::string ext = extension_of(path);
  namespace io = vcg::tri::io;
  mesh.textures.assign(1, texture);
  // The temporary keeps the extension: the OBJ exporter names its .mtl after the file.
  const size_t dot = path.find_last_of('.');
  const std::string temporary = path.substr(0, dot) + ".partial." + ext;
  int code = 0;
  if (ext == "obj") {
    code = run_exporter<io::ExporterOBJ<ToolMesh>>(mesh, temporary, io::Mask::IOM_WEDGTEXCOORD);
  } else if (ext == "ply") {
    // No per-vertex texcoords: vcglib 2020.09 writes them as doubles under a float header for a
    // double mesh. The per-wedge texcoords carry the same values.
    code = run_exporter<io::ExporterPLY<ToolMesh>>(
        mesh, temporary, io::Mask::IOM_WEDGTEXCOORD | io::Mask::IOM_VERTQUALITY | io::Mask::IOM_FACEQUALITY);
  } else {
    error = "unknown output type '." + ext + "': use .obj or .ply";
    return false;
  }
  if (code != 0) {
    std::remove(temporary.c_str());
    error = "cannot write " + path + " (vcglib exporter error " + std::to_string(code) + ")";
    return false;
  }
  if (ext == "obj") {  // the exporter wrote <temporary>.mtl and named it in the OBJ: rename both
    const std::string tmp_mtl = temporary + ".mtl", mtl = path + ".mtl";
    std::ifstream obj_in(temporary);
    std::stringstream body;
    body << obj_in.rdbuf();
    obj_in.close();
    std::string text = body.str();
    const std::string old_name = temporary.substr(temporary.find_last_of('/') + 1) + ".mtl";
    const std::string new_name = path.substr(path.find_last_of('/') + 1) + ".mtl";
    const size_t at = text.find(old_name);
    if (at != std::string::npos) text.replace(at, old_name.size(), new_name);
    std::ofstream obj_out(temporary, std::ios::trunc);
    obj_out << text;
    obj_out.close();
    if (!obj_out || std::rename(tmp_mtl.c_str(), mtl.c_str()) != 0) {
      std::remove(temporary.c_str());
      std::remove(tmp_mtl.c_str());
      error = "cannot write " + mtl;
      return false;
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    error = "cannot write " + path;
    return false;
  }
  return true;
}

}  // namespace lowstretch
