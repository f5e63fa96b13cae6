#include "tool/obj_writer.h"

#include <cstdio>
#include <cstring>
#include <map>
#include <utility>
#include <vector>

namespace lowstretch {

namespace {

std::string base_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

// Writes `text` to `path` through `path`.partial; false if any step fails.
bool write_file(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".partial";
  std::FILE* f = std::fopen(temporary.c_str(), "wb");
  if (f == nullptr) return false;
  const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !written || std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    return false;
  }
  return true;
}

// One printf-formatted line appended to text.
template <class... Values>
void append(std::string& text, const char* format, Values... values) {
  char line[128];
  std::snprintf(line, sizeof line, format, values...);
  text += line;
}

}  // namespace

bool write_obj(const std::string& path, const ToolMesh& mesh, const std::string& texture, std::string& error) {
  const std::string mtl = path + ".mtl";
  std::string text = "# lowstretch: per-corner texture coordinates\nmtllib " + base_name(mtl) + "\n";
  std::vector<int> index(mesh.vert.size(), 0);
  int next = 1;
  for (size_t i = 0; i < mesh.vert.size(); ++i) {
    if (mesh.vert[i].IsD()) continue;
    index[i] = next++;
    const auto& p = mesh.vert[i].cP();
    append(text, "v %.17g %.17g %.17g\n", double(p[0]), double(p[1]), double(p[2]));
  }
  // One vt per distinct (u, v): the corners of a vertex inside a chart share theirs.
  std::map<std::pair<float, float>, int> vt_of;
  std::string faces = "usemtl material_0\n";
  for (const ToolFace& f : mesh.face) {
    if (f.IsD()) continue;
    faces += "f";
    for (int k = 0; k < 3; ++k) {
      const std::pair<float, float> uv(f.cWT(k).U(), f.cWT(k).V());
      auto found = vt_of.find(uv);
      if (found == vt_of.end()) {
        found = vt_of.emplace(uv, int(vt_of.size()) + 1).first;
        append(text, "vt %.17g %.17g\n", double(uv.first), double(uv.second));
      }
      faces += " " + std::to_string(index[size_t(f.cV(k) - &mesh.vert[0])]) + "/" + std::to_string(found->second);
    }
    faces += "\n";
  }
  text += faces;
  const std::string material = "newmtl material_0\nKa 0.2 0.2 0.2\nKd 1 1 1\nmap_Kd " + texture + "\n";
  if (!write_file(mtl, material) || !write_file(path, text)) {
    error = "cannot write " + path + " or " + mtl;
    return false;
  }
  return true;
}

}  // namespace lowstretch
