#include "ply_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "mesh_counts.h"

namespace lowstretch {

namespace {

enum class Format { Ascii, Little, Big };

struct Property {
  std::string name;
  int type = 0;        // bytes of a value: 1, 2, 4, 8; negative for float/double (-4, -8)
  bool is_signed = false;
  bool list = false;
  int count_type = 0;  // for a list: bytes of its count (an integer type)
  bool count_signed = false;
};

struct Element {
  std::string name;
  long long count = 0;
  std::vector<Property> properties;
};

// char/int8 ... double/float64 -> bytes (negative: floating point) and signedness.
bool parse_type(const std::string& name, int& bytes, bool& is_signed) {
  static const struct { const char* a; const char* b; int bytes; bool is_signed; } types[] = {
      {"char", "int8", 1, true},    {"uchar", "uint8", 1, false},   {"short", "int16", 2, true},
      {"ushort", "uint16", 2, false}, {"int", "int32", 4, true},    {"uint", "uint32", 4, false},
      {"float", "float32", -4, true}, {"double", "float64", -8, true}};
  for (const auto& t : types)
    if (name == t.a || name == t.b) {
      bytes = t.bytes;
      is_signed = t.is_signed;
      return true;
    }
  return false;
}

// Reads values one at a time from the body; false at the end of the file or on a malformed value.
class Body {
 public:
  Body(std::istream& in, Format format) : in_(in), format_(format) {}

  bool value(int type, bool is_signed, double& out) {
    if (format_ == Format::Ascii) {
      if (!(in_ >> token_)) return false;
      char* end = nullptr;
      if (type < 0) {
        out = std::strtod(token_.c_str(), &end);  // overflow: +-inf, which the core reports
      } else {
        errno = 0;
        const long long v = std::strtoll(token_.c_str(), &end, 10);
        if (errno != 0) return false;
        out = double(v);
      }
      return end != token_.c_str() && *end == '\0';
    }
    const int bytes = type < 0 ? -type : type;
    unsigned char b[8];
    if (!in_.read(reinterpret_cast<char*>(b), bytes)) return false;
    if (format_ == Format::Big)
      for (int i = 0; i < bytes / 2; ++i) std::swap(b[i], b[bytes - 1 - i]);
    if (type == -4) { float f; std::memcpy(&f, b, 4); out = f; return true; }
    if (type == -8) { double d; std::memcpy(&d, b, 8); out = d; return true; }
    uint64_t u = 0;
    for (int i = bytes - 1; i >= 0; --i) u = u << 8 | b[i];
    if (is_signed && (u >> (8 * bytes - 1)) & 1) out = double(int64_t(u) - (int64_t(1) << (8 * bytes)));
    else out = double(u);
    return true;
  }

 private:
  std::istream& in_;
  Format format_;
  std::string token_;
};

}  // namespace

bool read_ply(const std::string& path, long long file_size, ToolMesh& mesh, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) { error = "cannot open the file"; return false; }
  std::string line;
  if (!std::getline(in, line) || line.compare(0, 3, "ply") != 0 || line.find_first_not_of(" \t\r", 3) != std::string::npos) {
    error = "not a PLY file (no ply header)";
    return false;
  }
  Format format = Format::Ascii;
  bool has_format = false;
  std::vector<Element> elements;
  for (int number = 2;; ++number) {
    if (!std::getline(in, line)) { error = "the PLY header never ends (no end_header)"; return false; }
    if (number > 10000 || line.size() > 10000) { error = "the PLY header is too long"; return false; }
    if (line.find('\0') != std::string::npos) { error = "line " + std::to_string(number) + ": a NUL byte in the PLY header"; return false; }
    std::istringstream words(line);
    std::string keyword, a, b, c, d;
    words >> keyword;
    const std::string where = "line " + std::to_string(number) + " of the PLY header: ";
    if (keyword == "end_header") break;
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "format") {
      words >> a >> b;
      if (a == "ascii") format = Format::Ascii;
      else if (a == "binary_little_endian") format = Format::Little;
      else if (a == "binary_big_endian") format = Format::Big;
      else { error = where + "unknown format '" + a + "'"; return false; }
      has_format = true;
    } else if (keyword == "element") {
      Element e;
      char* end = nullptr;
      if (!(words >> e.name >> a)) { error = where + "an element needs a name and a count"; return false; }
      errno = 0;
      e.count = std::strtoll(a.c_str(), &end, 10);
      if (errno != 0 || *end != '\0' || e.count < 0 || e.count > file_size) {
        error = where + "element '" + e.name + "' has a malformed count or one larger than the file";
        return false;
      }
      for (const Element& other : elements)
        if (other.name == e.name) { error = where + "element '" + e.name + "' is declared twice"; return false; }
      elements.push_back(e);
    } else if (keyword == "property") {
      if (elements.empty()) { error = where + "a property before any element"; return false; }
      Property p;
      words >> a;
      if (a == "list") {
        p.list = true;
        if (!(words >> b >> c >> d) || !parse_type(b, p.count_type, p.count_signed) || p.count_type < 0 ||
            !parse_type(c, p.type, p.is_signed)) {
          error = where + "a list property needs an integer count type, a value type and a name";
          return false;
        }
        p.name = d;
      } else if (!parse_type(a, p.type, p.is_signed) || !(words >> p.name)) {
        error = where + "a property needs a known type and a name";
        return false;
      }
      elements.back().properties.push_back(p);
    } else {
      error = where + "unknown keyword '" + keyword + "'";
      return false;
    }
  }
  if (!has_format) { error = "the PLY header has no format line"; return false; }

  // What the tool reads: vertex x, y, z and the face's vertex list; counts checked against the file.
  const Element* vertex = nullptr;
  const Element* face = nullptr;
  long long all_items = 0;
  for (const Element& e : elements) {
    if (e.name == "vertex") vertex = &e;
    if (e.name == "face") face = &e;
    if (e.properties.empty() && e.count > 0) { error = "PLY element '" + e.name + "' has items but no properties"; return false; }
    all_items += e.count;
  }
  if (!vertex) { error = "the PLY file has no vertex element"; return false; }
  if (!counts_fit(vertex->count, face ? face->count : 0, file_size, error) || all_items > file_size) {
    if (error.empty()) error = "the PLY header declares more items than the file can hold: the file is corrupt or cut short";
    return false;
  }
  int axis_of[3] = {-1, -1, -1}, list_of = -1;
  for (size_t k = 0; k < vertex->properties.size(); ++k)
    for (int c = 0; c < 3; ++c)
      if (vertex->properties[k].name == std::string(1, char('x' + c)) && !vertex->properties[k].list) axis_of[c] = int(k);
  if (axis_of[0] < 0 || axis_of[1] < 0 || axis_of[2] < 0) { error = "the PLY vertex element has no x, y and z"; return false; }
  if (face) {
    for (size_t k = 0; k < face->properties.size(); ++k) {
      const Property& p = face->properties[k];
      if (p.list && p.type > 0 && (p.name == "vertex_indices" || (p.name == "vertex_index" && list_of < 0))) list_of = int(k);
    }
    if (list_of < 0 && face->count > 0) { error = "the PLY face element has no integer list vertex_indices"; return false; }
  }

  Body body(in, format);
  std::vector<vcg::Point3d> points;
  std::vector<int> corners, polygon;
  points.reserve(size_t(vertex->count));
  for (const Element& e : elements) {
    for (long long item = 0; item < e.count; ++item) {
      vcg::Point3d point(0, 0, 0);
      polygon.clear();
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        double v = 0;
        const std::string what = "PLY " + e.name + " " + std::to_string(item) + ", property " + p.name + ": ";
        if (!p.list) {
          if (!body.value(p.type, p.is_signed, v)) { error = what + "missing or malformed value: the file is cut short or corrupt"; return false; }
          if (&e == vertex)
            for (int c = 0; c < 3; ++c)
              if (int(k) == axis_of[c]) point[c] = v;
          continue;
        }
        double count = 0;
        if (!body.value(p.count_type, p.count_signed, count)) { error = what + "missing or malformed list count"; return false; }
        if (count < 0) { error = what + "negative list count"; return false; }
        const bool indices = &e == face && int(k) == list_of;
        if (indices && count < 3) { error = what + "a face needs at least three vertices"; return false; }
        for (double j = 0; j < count; ++j) {  // bounded by the file: each value is read, none reserved
          if (!body.value(p.type, p.is_signed, v)) { error = what + "the list is cut short"; return false; }
          if (!indices) continue;
          if (!(v >= 0 && v < double(vertex->count)) || v != std::floor(v)) {
            error = what + "vertex index " + std::to_string(v) + " is out of range (0.." + std::to_string(vertex->count - 1) + ")";
            return false;
          }
          polygon.push_back(int(v));
        }
      }
      if (&e == vertex) points.push_back(point);
      for (size_t k = 1; k + 1 < polygon.size(); ++k) corners.insert(corners.end(), {polygon[0], polygon[k], polygon[k + 1]});
    }
  }
  fill_tool_mesh(points, corners, mesh);
  return true;
}

}  // namespace lowstretch
