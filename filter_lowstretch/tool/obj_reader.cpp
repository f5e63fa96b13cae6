#include "tool/obj_reader.h"

#include "tool/mesh_counts.h"

#include <cstdlib>
#include <limits>
#include <fstream>
#include <sstream>
#include <vector>

namespace lowstretch {

namespace {

// An OBJ index (1-based; negative: relative to the last of `count`) as zero-based, -1 if out of range.
long zero_based(long index, long count) {
  const long i = index > 0 ? index - 1 : count + index;
  return index != 0 && i >= 0 && i < count ? i : -1;
}

}  // namespace

bool read_obj(const std::string& path, ToolMesh& mesh, std::string& error) {
  std::ifstream in(path);
  if (!in) { error = "cannot open the file"; return false; }
  std::vector<vcg::Point3d> points;
  std::vector<vcg::Point2f> uvs, corner_uv;  // the vt lines; the corners' (NaN where a face gives none)
  std::vector<int> corners;  // three per triangle, zero-based
  std::string line, word;
  std::vector<int> polygon, polygon_uv;
  const float none = std::numeric_limits<float>::quiet_NaN();
  for (long long number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    if (!(words >> word)) continue;
    const std::string where = "line " + std::to_string(number) + ": ";
    if (word == "v") {
      // strtod, not >>: "nan" and "inf" are read as such (the core names them if a face uses them).
      double xyz[3];
      for (double& c : xyz) {
        char* end = nullptr;
        if (!(words >> word) || (c = std::strtod(word.c_str(), &end), *end != '\0')) {
          error = where + "a vertex needs three numbers";
          return false;
        }
      }
      points.emplace_back(xyz[0], xyz[1], xyz[2]);
    } else if (word == "vt") {
      float uv[2] = {none, none};  // a malformed vt is no texture coordinate (repacking names it)
      for (float& c : uv)
        if (words >> word) c = std::strtof(word.c_str(), nullptr);
      uvs.emplace_back(uv[0], uv[1]);
    } else if (word == "f") {
      polygon.clear();
      polygon_uv.clear();
      while (words >> word) {
        char* end = nullptr;
        const long index = std::strtol(word.c_str(), &end, 10);  // "i", "i/t", "i//n", "i/t/n"
        if (end == word.c_str() || (*end != '\0' && *end != '/')) { error = where + "malformed face index '" + word + "'"; return false; }
        const long t = *end == '/' ? std::strtol(end + 1, nullptr, 10) : 0;  // 0: none
        polygon_uv.push_back(int(zero_based(t, long(uvs.size()))));
        const long count = long(points.size()), vertex = zero_based(index, count);
        if (vertex < 0) {
          error = where + "face index " + std::to_string(index) + " is out of range (1.." + std::to_string(count) + ")";
          return false;
        }
        polygon.push_back(int(vertex));
      }
      if (polygon.size() < 3) { error = where + "a face needs at least three vertices"; return false; }
      for (size_t k = 1; k + 1 < polygon.size(); ++k) {
        corners.insert(corners.end(), {polygon[0], polygon[k], polygon[k + 1]});
        for (const size_t j : {size_t(0), k, k + 1})
          corner_uv.push_back(polygon_uv[j] < 0 ? vcg::Point2f(none, none) : uvs[size_t(polygon_uv[j])]);
      }
    }
  }
  if (points.empty()) { error = "no vertices"; return false; }
  fill_tool_mesh(points, corners, mesh, uvs.empty() ? std::vector<vcg::Point2f>() : corner_uv);
  return true;
}

}  // namespace lowstretch
