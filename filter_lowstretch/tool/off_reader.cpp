#include "tool/off_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "tool/mesh_counts.h"

namespace lowstretch {

namespace {

// Lines with something on them other than a comment.
bool next_line(std::istream& in, std::string& line, long long& number) {
  while (std::getline(in, line)) {
    ++number;
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r\f\v") != std::string::npos) return true;
  }
  return false;
}

bool to_integer(const std::string& token, long long& value) {
  if (token.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(token.c_str(), &end, 10);
  return errno == 0 && *end == '\0';
}

bool to_double(const std::string& token, double& value) {
  if (token.empty()) return false;
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);  // overflow gives +-inf, which the core reports
  return *end == '\0';
}

// The OFF header: "[ST][C][N]OFF", then the vertex and face counts, on that line or the next;
// the counts are checked against the file's size. `number` is the line read last.
bool read_off_header(std::istream& in, long long file_size, long long& number, long long& vertices, long long& faces,
                     std::string& error) {
  std::string line, token;
  if (!next_line(in, line, number)) { error = "not an OFF file (no OFF header)"; return false; }
  std::istringstream words(line);
  words >> token;
  // [ST][C][N][4][n]OFF: the prefixes only add values to each vertex line, which are skipped.
  const size_t off = token.rfind("OFF");
  if (off == std::string::npos || off + 3 != token.size() || token.find_first_not_of("STCN", 0) < off) {
    error = token.find_first_of("4n") < off ? "homogeneous or n-dimensional OFF files are not supported"
                                            : "not an OFF file (no OFF header)";
    return false;
  }
  // The counts may follow on the same line ("OFF 8 6 0").
  std::vector<std::string> counts;
  while (words >> token) counts.push_back(token);
  if (counts.empty()) {
    if (!next_line(in, line, number)) { error = "the OFF header has no vertex and face counts"; return false; }
    std::istringstream more(line);
    while (more >> token) counts.push_back(token);
  }
  if (counts.size() < 2 || !to_integer(counts[0], vertices) || !to_integer(counts[1], faces)) {
    error = "line " + std::to_string(number) + ": the OFF header needs vertex and face counts";
    return false;
  }
  return counts_fit(vertices, faces, file_size, error);
}

}  // namespace

bool read_off(const std::string& path, long long file_size, ToolMesh& mesh, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) { error = "cannot open the file"; return false; }
  std::string line, token;
  long long number = 0, vertices = 0, faces = 0;
  if (!read_off_header(in, file_size, number, vertices, faces, error)) return false;

  std::vector<vcg::Point3d> points(static_cast<size_t>(vertices));
  for (long long i = 0; i < vertices; ++i) {
    if (!next_line(in, line, number)) {
      error = "the file ends after " + std::to_string(i) + " of " + std::to_string(vertices) + " vertices: it is cut short";
      return false;
    }
    std::istringstream values(line);
    for (int c = 0; c < 3; ++c)
      if (!(values >> token) || !to_double(token, points[size_t(i)][c])) {
        error = "line " + std::to_string(number) + ": a vertex needs three coordinates";
        return false;
      }
  }
  std::vector<int> corners, polygon;  // three per triangle
  corners.reserve(size_t(faces) * 3);
  for (long long f = 0; f < faces; ++f) {
    if (!next_line(in, line, number)) {
      error = "the file ends after " + std::to_string(f) + " of " + std::to_string(faces) + " faces: it is cut short";
      return false;
    }
    const std::string where = "line " + std::to_string(number) + ": ";
    std::istringstream values(line);
    long long n = 0;
    if (!(values >> token) || !to_integer(token, n)) { error = where + "a face starts with its vertex count"; return false; }
    if (n < 3) { error = where + "a face needs at least three vertices, not " + std::to_string(n); return false; }
    polygon.clear();
    for (long long k = 0; k < n; ++k) {  // bounded by the tokens on the line, not by n
      long long index = 0;
      if (!(values >> token)) { error = where + "the face has fewer than the " + std::to_string(n) + " indices it declares"; return false; }
      if (!to_integer(token, index)) { error = where + "malformed face index '" + token + "'"; return false; }
      if (index < 0 || index >= vertices) {
        error = where + "face index " + std::to_string(index) + " is out of range (0.." + std::to_string(vertices - 1) + ")";
        return false;
      }
      polygon.push_back(int(index));
    }
    for (size_t k = 1; k + 1 < polygon.size(); ++k) corners.insert(corners.end(), {polygon[0], polygon[k], polygon[k + 1]});
  }
  fill_tool_mesh(points, corners, mesh);
  return true;
}

}  // namespace lowstretch
