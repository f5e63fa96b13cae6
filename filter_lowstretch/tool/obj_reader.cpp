#include "tool/obj_reader.h"

#include "tool/mesh_counts.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

namespace lowstretch {

bool read_obj(const std::string& path, ToolMesh& mesh, std::string& error) {
  std::ifstream in(path);
  if (!in) { error = "cannot open the file"; return false; }
  std::vector<vcg::Point3d> points;
  std::vector<int> corners;  // three per triangle, zero-based
  std::string line, word;
  std::vector<int> polygon;
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
    } else if (word == "f") {
      polygon.clear();
      while (words >> word) {
        char* end = nullptr;
        const long index = std::strtol(word.c_str(), &end, 10);  // "i", "i/t", "i//n", "i/t/n"
        if (end == word.c_str() || (*end != '\0' && *end != '/')) { error = where + "malformed face index '" + word + "'"; return false; }
        const long count = long(points.size());
        const long zero_based = index > 0 ? index - 1 : count + index;  // negative: relative
        if (index == 0 || zero_based < 0 || zero_based >= count) {
          error = where + "face index " + std::to_string(index) + " is out of range (1.." + std::to_string(count) + ")";
          return false;
        }
        polygon.push_back(int(zero_based));
      }
      if (polygon.size() < 3) { error = where + "a face needs at least three vertices"; return false; }
      for (size_t k = 1; k + 1 < polygon.size(); ++k) corners.insert(corners.end(), {polygon[0], polygon[k], polygon[k + 1]});
    }
  }
  if (points.empty()) { error = "no vertices"; return false; }
  fill_tool_mesh(points, corners, mesh);
  return true;
}

}  // namespace lowstretch
