#include "tool/mesh_io.h"

#include "tool/obj_reader.h"
#include "tool/obj_writer.h"
#include "tool/off_reader.h"
#include "tool/ply_reader.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <new>
#include <sstream>

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

bool write_mesh(const std::string& path, ToolMesh& mesh, const std::string& texture, std::string& error) {
  const std::string ext = extension_of(path);
  if (ext == "obj") return write_obj(path, mesh, texture, error);
  if (ext != "ply") {
    error = "unknown output type '." + ext + "': use .obj or .ply";
    return false;
  }
  namespace io = vcg::tri::io;
  mesh.textures.assign(1, texture);
  const std::string temporary = path.substr(0, path.find_last_of('.')) + ".partial.ply";
  // No per-vertex texcoords: vcglib 2020.09 writes them as doubles under a float header for a
  // double mesh. The per-wedge texcoords (float) carry the same values.
  const int code = io::ExporterPLY<ToolMesh>::Save(
      mesh, temporary.c_str(), io::Mask::IOM_WEDGTEXCOORD | io::Mask::IOM_VERTQUALITY | io::Mask::IOM_FACEQUALITY);
  if (code != 0 || std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    error = "cannot write " + path + (code != 0 ? " (vcglib exporter error " + std::to_string(code) + ")" : "");
    return false;
  }
  return true;
}

}  // namespace lowstretch
