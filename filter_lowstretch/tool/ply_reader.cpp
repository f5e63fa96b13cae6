#include "tool/ply_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include "tool/mesh_counts.h"

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

// One header line after "ply": format, element, property, comment. Returns false with the
// reason in error; sets done at end_header.
bool read_header_line(const std::string& line, int number, long long file_size, Format& format, bool& has_format,
                      std::vector<Element>& elements, bool& done, std::string& error) {
  if (line.find('\0') != std::string::npos) { error = "line " + std::to_string(number) + ": a NUL byte in the PLY header"; return false; }
  std::istringstream words(line);
  std::string keyword, a, b, c, d;
  words >> keyword;
  const std::string where = "line " + std::to_string(number) + " of the PLY header: ";
  if (keyword == "end_header") { done = true; return true; }
  if (keyword.empty() || keyword == "comment" || keyword == "obj_info") return true;
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
  return true;
}

// The header, up to end_header: the body's format and its elements.
bool read_header(std::istream& in, long long file_size, Format& format, std::vector<Element>& elements, std::string& error) {
  std::string line;
  if (!std::getline(in, line) || line.compare(0, 3, "ply") != 0 || line.find_first_not_of(" \t\r", 3) != std::string::npos) {
    error = "not a PLY file (no ply header)";
    return false;
  }
  bool has_format = false, done = false;
  for (int number = 2; !done; ++number) {
    if (!std::getline(in, line)) { error = "the PLY header never ends (no end_header)"; return false; }
    if (number > 10000 || line.size() > 10000) { error = "the PLY header is too long"; return false; }
    if (!read_header_line(line, number, file_size, format, has_format, elements, done, error)) return false;
  }
  if (!has_format) { error = "the PLY header has no format line"; return false; }
  return true;
}

// What the tool reads: the vertex element's x, y, z and the face element's vertex list.
struct Layout {
  const Element* vertex = nullptr;
  const Element* face = nullptr;
  int axis_of[3] = {-1, -1, -1};  // property index of x, y, z in the vertex element
  int list_of = -1;               // property index of the vertex list in the face element
  int texcoord_of = -1;           // ... of its texture coordinates (u, v per corner), if any
};

// Finds the layout and checks the counts against the file.
bool find_layout(const std::vector<Element>& elements, long long file_size, Layout& l, std::string& error) {
  long long all_items = 0;
  for (const Element& e : elements) {
    if (e.name == "vertex") l.vertex = &e;
    if (e.name == "face") l.face = &e;
    if (e.properties.empty() && e.count > 0) { error = "PLY element '" + e.name + "' has items but no properties"; return false; }
    all_items += e.count;
  }
  if (!l.vertex) { error = "the PLY file has no vertex element"; return false; }
  if (!counts_fit(l.vertex->count, l.face ? l.face->count : 0, file_size, error) || all_items > file_size) {
    if (error.empty()) error = "the PLY header declares more items than the file can hold: the file is corrupt or cut short";
    return false;
  }
  for (size_t k = 0; k < l.vertex->properties.size(); ++k)
    for (int c = 0; c < 3; ++c)
      if (l.vertex->properties[k].name == std::string(1, char('x' + c)) && !l.vertex->properties[k].list) l.axis_of[c] = int(k);
  if (l.axis_of[0] < 0 || l.axis_of[1] < 0 || l.axis_of[2] < 0) { error = "the PLY vertex element has no x, y and z"; return false; }
  if (l.face) {
    for (size_t k = 0; k < l.face->properties.size(); ++k) {
      const Property& p = l.face->properties[k];
      if (p.list && p.type > 0 && (p.name == "vertex_indices" || (p.name == "vertex_index" && l.list_of < 0))) l.list_of = int(k);
      if (p.list && p.name == "texcoord") l.texcoord_of = int(k);
    }
    if (l.list_of < 0 && l.face->count > 0) { error = "the PLY face element has no integer list vertex_indices"; return false; }
  }
  return true;
}

// One list property of one item: its values, kept in polygon when they are the face's vertices,
// in values if given.
bool read_list(Body& body, const Property& p, bool indices, long long vertex_count, const std::string& what,
               std::vector<int>& polygon, std::string& error, std::vector<float>* values = nullptr) {
  double count = 0, v = 0;
  if (!body.value(p.count_type, p.count_signed, count)) { error = what + "missing or malformed list count"; return false; }
  if (count < 0) { error = what + "negative list count"; return false; }
  if (indices && count < 3) { error = what + "a face needs at least three vertices"; return false; }
  for (double j = 0; j < count; ++j) {  // bounded by the file: each value is read, none reserved
    if (!body.value(p.type, p.is_signed, v)) { error = what + "the list is cut short"; return false; }
    if (values) values->push_back(float(v));
    if (!indices) continue;
    if (!(v >= 0 && v < double(vertex_count)) || v != std::floor(v)) {
      error = what + "vertex index " + std::to_string(v) + " is out of range (0.." + std::to_string(vertex_count - 1) + ")";
      return false;
    }
    polygon.push_back(int(v));
  }
  return true;
}

// The body, element by element: vertex positions and faces (polygons as fans of triangles).
bool read_body(Body& body, const std::vector<Element>& elements, const Layout& l, std::vector<vcg::Point3d>& points,
               std::vector<int>& corners, std::vector<vcg::Point2f>& corner_uv, std::string& error) {
  std::vector<int> polygon;
  std::vector<float> uv;  // the face's texcoord list
  const float none = std::numeric_limits<float>::quiet_NaN();
  points.reserve(size_t(l.vertex->count));
  for (const Element& e : elements)
    for (long long item = 0; item < e.count; ++item) {
      vcg::Point3d point(0, 0, 0);
      polygon.clear();
      uv.clear();
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        const std::string what = "PLY " + e.name + " " + std::to_string(item) + ", property " + p.name + ": ";
        if (p.list) {
          const bool texcoord = &e == l.face && int(k) == l.texcoord_of;
          if (!read_list(body, p, &e == l.face && int(k) == l.list_of, l.vertex->count, what, polygon, error, texcoord ? &uv : nullptr))
            return false;
          continue;
        }
        double v = 0;
        if (!body.value(p.type, p.is_signed, v)) { error = what + "missing or malformed value: the file is cut short or corrupt"; return false; }
        if (&e == l.vertex)
          for (int c = 0; c < 3; ++c)
            if (int(k) == l.axis_of[c]) point[c] = v;
      }
      if (&e == l.vertex) points.push_back(point);
      for (size_t k = 1; k + 1 < polygon.size(); ++k) {
        corners.insert(corners.end(), {polygon[0], polygon[k], polygon[k + 1]});
        if (l.texcoord_of < 0) continue;
        for (const size_t j : {size_t(0), k, k + 1})  // a list of another length gives none
          corner_uv.push_back(uv.size() == 2 * polygon.size() ? vcg::Point2f(uv[2 * j], uv[2 * j + 1]) : vcg::Point2f(none, none));
      }
    }
  return true;
}

}  // namespace

bool read_ply(const std::string& path, long long file_size, ToolMesh& mesh, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) { error = "cannot open the file"; return false; }
  Format format = Format::Ascii;
  std::vector<Element> elements;
  Layout layout;
  if (!read_header(in, file_size, format, elements, error) || !find_layout(elements, file_size, layout, error)) return false;
  Body body(in, format);
  std::vector<vcg::Point3d> points;
  std::vector<int> corners;
  std::vector<vcg::Point2f> corner_uv;
  if (!read_body(body, elements, layout, points, corners, corner_uv, error)) return false;
  fill_tool_mesh(points, corners, mesh, corner_uv);
  return true;
}

}  // namespace lowstretch
