// Hostile input found by the fuzz targets (tests/fuzz/) or around what they found: files that
// crash, read freed memory, invent faces or read garbage in the tool's readers (lowstretch::
// read_mesh over vcglib 2020.09's ImporterOFF and ImporterPLY), and arrays that the core turns
// into NaN texture coordinates or refuses with a wrong reason.
// Each reader case runs in a child process, so a crash fails that test only (and the report
// says which signal) instead of ending the whole suite.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/parameterize.h"
#include "generated_meshes.h"
#include "tool/mesh_io.h"
#include "vcg_arrays/mesh_arrays.h"

using namespace lowstretch;

namespace {

// What read_mesh did with a file, as seen from outside the child that ran it.
struct Outcome {
  int signal = 0;     // the child died of this signal (a crash)
  int exit_code = 0;  // the child exited with this code without reporting (a sanitizer report: 86 or 1)
  bool reported = false;
  bool ok = false;
  std::string error;
  long long vertices = 0, faces = 0;
  bool faces_in_range = true;  // every face refers to a vertex of the mesh
  std::vector<double> coordinates;  // x, y, z of the first vertices (up to 9)
  double cpu_seconds = 0;
};

std::string describe(const Outcome& o) {
  std::ostringstream s;
  if (o.signal) s << "the reader crashed with signal " << o.signal << " (" << strsignal(o.signal) << ")";
  else if (!o.reported) s << "the reader's process ended with exit code " << o.exit_code << " before reporting";
  else s << "ok=" << o.ok << " error='" << o.error << "' vertices=" << o.vertices << " faces=" << o.faces
         << " faces_in_range=" << o.faces_in_range << " cpu=" << o.cpu_seconds << "s";
  return s.str();
}

std::string write_file(const std::string& name, const std::string& bytes) {
  const std::string path = ::testing::TempDir() + "hostile_" + std::to_string(getpid()) + "_" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// read_mesh in a child process; the child sends its findings back through a pipe.
Outcome read_isolated(const std::string& name, const std::string& bytes) {
  const std::string path = write_file(name, bytes);
  int fds[2];
  Outcome o;
  if (pipe(fds) != 0) { o.error = "pipe failed"; return o; }
  std::fflush(nullptr);
  const pid_t child = fork();
  if (child == 0) {
    close(fds[0]);
    const std::clock_t start = std::clock();
    ToolMesh mesh;
    std::string error;
    const bool ok = read_mesh(path, mesh, error);
    std::ostringstream out;
    out.precision(17);
    int in_range = 1;
    for (const auto& f : mesh.face)
      for (int k = 0; k < 3; ++k)
        if (mesh.vert.empty() || f.cV(k) < &mesh.vert.front() || f.cV(k) > &mesh.vert.back()) in_range = 0;
    out << double(std::clock() - start) / CLOCKS_PER_SEC << "\n" << ok << "\n" << mesh.vert.size() << "\n"
        << mesh.face.size() << "\n" << in_range << "\n";
    for (size_t i = 0; i < mesh.vert.size() && i < 3; ++i)
      out << mesh.vert[i].cP()[0] << " " << mesh.vert[i].cP()[1] << " " << mesh.vert[i].cP()[2] << " ";
    out << "\n" << error;
    const std::string text = out.str();
    size_t written = 0;
    while (written < text.size()) {
      const ssize_t w = write(fds[1], text.data() + written, text.size() - written);
      if (w <= 0) break;
      written += size_t(w);
    }
    close(fds[1]);
    _exit(0);
  }
  close(fds[1]);
  std::string text;
  char buffer[4096];
  for (ssize_t r; (r = read(fds[0], buffer, sizeof buffer)) > 0;) text.append(buffer, size_t(r));
  close(fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  std::remove(path.c_str());
  if (WIFSIGNALED(status)) { o.signal = WTERMSIG(status); return o; }
  o.exit_code = WEXITSTATUS(status);
  if (o.exit_code != 0 || text.empty()) return o;
  std::istringstream in(text);
  int ok = 0, in_range = 0;
  in >> o.cpu_seconds >> ok >> o.vertices >> o.faces >> in_range;
  o.ok = ok != 0;
  o.faces_in_range = in_range != 0;
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  std::istringstream values(line);
  for (double v; values >> v;) o.coordinates.push_back(v);
  std::getline(in, o.error, '\0');
  o.reported = true;
  return o;
}

// Refused, with a message that holds `words`; no crash.
void expect_refused(const Outcome& o, const std::string& words) {
  ASSERT_TRUE(o.reported) << describe(o);
  EXPECT_FALSE(o.ok) << describe(o);
  EXPECT_NE(o.error.find(words), std::string::npos) << "expected '" << words << "' in: " << describe(o);
}

// Read, with exactly these counts, every face referring to one of the mesh's vertices.
void expect_read(const Outcome& o, long long vertices, long long faces) {
  ASSERT_TRUE(o.reported) << describe(o);
  EXPECT_TRUE(o.ok) << describe(o);
  EXPECT_EQ(o.vertices, vertices) << describe(o);
  EXPECT_EQ(o.faces, faces) << describe(o);
  EXPECT_TRUE(o.faces_in_range) << describe(o);
}

const char* kSquareOff =
    "OFF\n"
    "4 2 0\n"
    "0 0 0\n"
    "1 0 0\n"
    "1 1 0\n"
    "0 1 0\n";

const char* kTrianglePlyHeader =
    "ply\n"
    "format ascii 1.0\n"
    "element vertex 4\n"
    "property float x\n"
    "property float y\n"
    "property float z\n";

const char* kSquarePlyBody =
    "0 0 0\n"
    "1 0 0\n"
    "1 1 0\n"
    "0 1 0\n";

}  // namespace

// --- OFF (vcglib ImporterOFF) ----------------------------------------------------------------

// The header declares 2 faces, the file has 1. ImporterOFF reads tokens[0] of the empty token
// list of the missing line: a destroyed string, which still says "3 0 1 2", so the tool loaded a
// second face that is not in the file (ASan: heap-use-after-free; a fuzz find).
TEST(HostileOff, FaceListCutShortIsRefusedNotInvented) {
  const Outcome o = read_isolated("cut.off", std::string(kSquareOff) + "3 0 1 2\n");
  ASSERT_TRUE(o.reported) << describe(o);
  EXPECT_FALSE(o.ok) << describe(o);
  EXPECT_FALSE(o.error.empty());
}

// A quad with a vertex index past the end: ImporterOFF reads mesh.vert[99] (heap overflow) and
// stores a pointer past the vertex array in the face.
TEST(HostileOff, OutOfRangeIndexInAQuadIsRefused) {
  const Outcome o = read_isolated("quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 99\n");
  expect_refused(o, "line 7: face index 99 is out of range (0..3)");
}

// Triangles with indices past the end or negative: &mesh.vert[i] out of the array (undefined
// behaviour; UBSan: pointer overflow for -15). The core would name them, but the pointer must
// not be made.
TEST(HostileOff, OutOfRangeIndexInATriangleIsRefused) {
  const std::pair<const char*, const char*> cases[] = {{"3 0 1 7\n", "face index 7 is out of range (0..2)"},
                                                       {"3 -15 1 2\n", "face index -15 is out of range (0..2)"}};
  for (const auto& c : cases) {
    const Outcome o = read_isolated("tri.off", std::string("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n") + c.first);
    SCOPED_TRACE(c.first);
    expect_refused(o, c.second);
  }
}

// A face colour given as one colour-map index: ImporterOFF reads its 148-entry colour map at any
// index (global buffer overflow; 10^8 segfaults). The geometry is read; the colour is not needed.
TEST(HostileOff, ColourMapIndexOutOfRangeIsReadWithoutCrashing) {
  for (const char* index : {" 100000000\n", " -100000000\n"}) {
    const Outcome o = read_isolated("colour.off", std::string(kSquareOff) + "3 0 1 2" + index + "3 0 2 3\n");
    SCOPED_TRACE(index);
    expect_read(o, 4, 2);
  }
  // The same for a vertex colour of a COFF file.
  const Outcome v = read_isolated("vcolour.off", "COFF\n3 1 0\n0 0 0 100000000\n1 0 0 1\n0 1 0 1\n3 0 1 2\n");
  expect_read(v, 3, 1);
}

// Float colours outside [0, 1]: (unsigned char)(-5227.5f) is undefined behaviour (UBSan).
TEST(HostileOff, FloatColourOutOfRangeIsNotUndefinedBehaviour) {
  const Outcome o = read_isolated("fcolour.off", std::string(kSquareOff) + "3 0 1 2 -20.5 3.5 1e30\n3 0 2 3\n");
  expect_read(o, 4, 2);
}

// A polygon that claims 2^31 - 1 vertices on a 60-byte file: ImporterOFF allocates that many
// faces first (bad_alloc, reported as "out of memory"; under ASan an allocation-size abort). It
// must be refused for what it is, at once.
TEST(HostileOff, HugePolygonCountIsRefusedWithoutAllocating) {
  const Outcome o = read_isolated("polygon.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2147483647 0 1 2\n");
  ASSERT_TRUE(o.reported) << describe(o);
  EXPECT_FALSE(o.ok) << describe(o);
  EXPECT_EQ(o.error.find("memory"), std::string::npos) << describe(o);
}

// --- PLY (vcglib ImporterPLY and plylib) -----------------------------------------------------

// An element line whose count plylib cannot see: after a vertical tab (a space to the header
// check, not to plylib) or after a NUL byte. plylib calls atoi(NULL): segfault. The vertical
// tab is read as the space it is; the NUL byte is refused by name.
TEST(HostilePly, ElementCountPlylibCannotSeeIsReadOrRefused) {
  for (const std::string& line : {std::string("element vertex\v4\n"), std::string("element vertex\0 4\n", 18)}) {
    std::string file = kTrianglePlyHeader;
    file.replace(file.find("element vertex 4\n"), 17, line);
    file += "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    file += kSquarePlyBody;
    file += "3 0 1 2\n";
    const Outcome o = read_isolated("count.ply", file);
    if (line.find('\v') != std::string::npos) expect_read(o, 4, 1);
    else expect_refused(o, "line 3: a NUL byte in the PLY header");
  }
}

// An empty line after a comment, before the format line: plylib calls strcmp(NULL, "comment").
TEST(HostilePly, EmptyHeaderLineAfterACommentIsSkipped) {
  std::string file = kTrianglePlyHeader;
  file.replace(0, 4, "ply\ncomment made by hand\n\n");
  file += "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  file += std::string(kSquarePlyBody) + "3 0 1 2\n";
  const Outcome o = read_isolated("empty.ply", file);
  expect_read(o, 4, 1);
}

// A polygon of 1000 vertices with an int list count: ImporterPLY reads the list into its fixed
// int v[512] (stack overflow) and keeps the count in an unsigned char (1000 -> 232), so it loads
// 230 triangles instead of the 998 of the polygon's fan.
TEST(HostilePly, LongFaceListIsReadWhole) {
  const int n = 1000;
  const double pi = 3.14159265358979323846;
  std::ostringstream file;
  file << "ply\nformat ascii 1.0\nelement vertex " << n
       << "\nproperty double x\nproperty double y\nproperty double z\nelement face 1\n"
          "property list int int vertex_indices\nend_header\n";
  file.precision(17);
  for (int i = 0; i < n; ++i) file << std::cos(2 * pi * i / n) << " " << std::sin(2 * pi * i / n) << " 0\n";
  file << n;
  for (int i = 0; i < n; ++i) file << " " << i;
  file << "\n";
  const Outcome o = read_isolated("long.ply", file.str());
  expect_read(o, n, n - 2);
}

// A quad whose last index is out of range: ImporterPLY checks fa.v[2 + qq] but uses
// fa.v[1 + qq + k], so index[99] is read past the end (heap overflow) and stored in a face.
TEST(HostilePly, OutOfRangeIndexInAPolygonIsRefused) {
  std::string file = std::string(kTrianglePlyHeader) + "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  file += std::string(kSquarePlyBody) + "4 0 1 2 99\n";
  const Outcome o = read_isolated("quad.ply", file);
  expect_refused(o, "vertex index 99.000000 is out of range (0..3)");
}

// Two vertex elements: ImporterPLY adds both but keeps only the second one's index table, so
// face indices below the total pass its check and are read past that table.
TEST(HostilePly, DuplicateVertexElementIsRefused) {
  std::string file =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n5 5 5\n3 0 1 2\n";
  const Outcome o = read_isolated("twovertex.ply", file);
  expect_refused(o, "line 7 of the PLY header: element 'vertex' is declared twice");
}

// Stanford triangle strips: ImporterPLY checks strip entry k but uses k + 1 and k + 2. Our
// reader does not read strips at all: the vertices load, no face does (the core then names the
// missing faces).
TEST(HostilePly, TriangleStripIndexOutOfRangeIsNotRead) {
  std::string file = std::string(kTrianglePlyHeader) + "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
  file += std::string(kSquarePlyBody) + "5 0 1 2 99 3\n";
  const Outcome o = read_isolated("strip.ply", file);
  expect_read(o, 4, 0);
}

// A binary list property the importer does not read (here 200 doubles per face): plylib skips it
// through a 512-byte stack buffer, fread(skip_buf, 8, 200): a stack buffer overflow with the
// file's bytes (a fuzz find). It also reads every skipped list's count as one byte, whatever type
// the header gives it.
TEST(HostilePly, LongSkippedBinaryListDoesNotOverflowTheStack) {
  std::string file =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nproperty list uchar double junk\nend_header\n";
  const float points[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  file.append(reinterpret_cast<const char*>(points), sizeof points);  // little-endian machines only
  const int32_t face[3] = {0, 1, 2};
  file += char(3);
  file.append(reinterpret_cast<const char*>(face), sizeof face);
  file += char(200);
  file += std::string(200 * 8, '\x41');  // 200 doubles of 0x4141414141414141
  const Outcome o = read_isolated("skip.ply", file);
  expect_read(o, 3, 1);
}

// Binary big-endian doubles: plylib's SwapDouble is an empty function (with assert(0)), so the
// coordinates are read byte-reversed: garbage, silently (a debug build aborts).
TEST(HostilePly, BigEndianDoublesAreReadRight) {
  const double points[4][3] = {{0, 0, 0}, {1, 0, 0.25}, {1, 1, 0}, {0, 1, -0.5}};
  std::string file =
      "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  auto big_endian = [&file](const void* value, size_t bytes) {
    const unsigned char* b = static_cast<const unsigned char*>(value);
    for (size_t i = bytes; i-- > 0;) file += char(b[i]);
  };
  for (const auto& p : points)
    for (double c : p) big_endian(&c, 8);
  const int32_t faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (const auto& f : faces) {
    file += char(3);
    for (int32_t i : f) big_endian(&i, 4);
  }
  const Outcome o = read_isolated("bigendian.ply", file);
  ASSERT_TRUE(o.reported) << describe(o);
  if (!o.ok) {  // refusing the format is fine; reading garbage is not
    EXPECT_FALSE(o.error.empty());
    return;
  }
  ASSERT_EQ(o.coordinates.size(), 9u) << describe(o);
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(o.coordinates[size_t(3 * i + c)], points[i][c]) << "vertex " << i << " axis " << c;
}

// An element of two billion items with no properties: vcglib reads it item by item, seconds of
// work for a 300-byte file. It must be refused (or skipped) at once.
TEST(HostilePly, HugeElementWithoutPropertiesIsNotReadItemByItem) {
  std::string file = std::string(kTrianglePlyHeader) + "element junk 2000000000\nelement face 1\n"
                     "property list uchar int vertex_indices\nend_header\n";
  file += std::string(kSquarePlyBody) + "3 0 1 2\n";
  const Outcome o = read_isolated("junk.ply", file);
  expect_refused(o, "line 7 of the PLY header: element 'junk' has a malformed count or one larger than the file");
}

// --- The core on arrays (lowstretch::parameterize) -------------------------------------------

// A fuzz find (fuzz_parameterize): a disk with one finite but huge coordinate (-DBL_MAX) and one
// tiny one. The boundary's arc length overflows and the circle map is NaN, yet parameterize
// reported success with NaN texture coordinates.
TEST(HostileArrays, HugeFiniteCoordinateIsRefusedNotMappedToNaN) {
  Eigen::MatrixXd V(10, 3);
  const double huge = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::min();
  V << 0.75, 0, 0, 0.5, 0, 0, 1, 0, 0, 0, 0.5, 0, 0.5, -huge, 0, 1, 0.5, 0, 0, 1, 0, 0.5, 1, 0, 1, 1, 0, 0, tiny, tiny;
  Eigen::MatrixXi F(8, 3);
  F << 0, 1, 4, 0, 4, 3, 1, 2, 4, 2, 5, 4, 4, 7, 6, 4, 5, 8, 4, 8, 7, 0, 3, 9;
  Options options;
  options.boundary = BoundaryShape::Circle;
  options.weights = InitialWeights::MeanValue;
  options.max_passes = 2;
  const Result r = parameterize(V, F, options);
  // Next to a coordinate of -1.8e308 every other vertex is the same point: no face has an area
  // at the mesh's own scale, and the mesh is refused as such (no NaN map).
  EXPECT_EQ(r.error.code, ErrorCode::ZeroAreaMesh) << message(r.error);
  EXPECT_EQ(r.uv.size(), 0);
}

// Every measure the core takes is scale-invariant, so a disk scaled by 1e150 or 1e-150 (finite
// coordinates) must give the same map. Now: areas underflow or overflow, and the mesh is refused
// as "all faces have zero area" (false) or the solve fails.
TEST(HostileArrays, ExtremeScaleGivesTheSameMap) {
  const testmesh::Mesh m = testmesh::grid(4, [](double x, double y) { return 0.2 * std::sin(3 * x) * std::cos(2 * y); });
  for (BoundaryShape shape : {BoundaryShape::Square, BoundaryShape::Circle, BoundaryShape::Natural}) {
    Options options;
    options.boundary = shape;
    options.max_passes = 2;
    const Result reference = parameterize(m.V, m.F, options);
    ASSERT_FALSE(reference.error) << message(reference.error);
    for (double scale : {1e150, 1e-150, 1e300, 1e-300}) {
      SCOPED_TRACE(std::string(to_string(shape)) + " scale " + std::to_string(std::log10(scale)));
      const Result r = parameterize(m.V * scale, m.F, options);
      ASSERT_FALSE(r.error) << message(r.error);
      EXPECT_TRUE(r.uv.isApprox(reference.uv, 1e-9));
    }
  }
}

// The cases the issue lists, on the core directly: each is named, none crashes.
TEST(HostileArrays, DegenerateArraysAreNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  Eigen::MatrixXd triangle(3, 3);
  triangle << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  Eigen::MatrixXi one(1, 3);
  one << 0, 1, 2;
  for (BoundaryShape shape : {BoundaryShape::Square, BoundaryShape::Circle, BoundaryShape::Natural}) {
    Options options;
    options.boundary = shape;
    options.max_passes = 2;
    SCOPED_TRACE(to_string(shape));
    // One triangle: a disk with no interior vertex.
    const Result single = parameterize(triangle, one, options);
    ASSERT_FALSE(single.error) << message(single.error);
    EXPECT_TRUE(single.uv.allFinite());
    // Zero faces.
    EXPECT_EQ(parameterize(triangle, Eigen::MatrixXi(0, 3), options).error.code, ErrorCode::NoFaces);
    // No vertices at all, and faces naming them.
    EXPECT_EQ(parameterize(Eigen::MatrixXd(0, 3), one, options).error.code, ErrorCode::IndexOutOfRange);
    // Extreme indices.
    Eigen::MatrixXi bad = one;
    bad(0, 2) = std::numeric_limits<int>::min();
    EXPECT_EQ(parameterize(triangle, bad, options).error.code, ErrorCode::IndexOutOfRange);
    bad(0, 2) = std::numeric_limits<int>::max();
    EXPECT_EQ(parameterize(triangle, bad, options).error.code, ErrorCode::IndexOutOfRange);
    // Repeated index.
    bad = one;
    bad(0, 2) = 0;
    EXPECT_EQ(parameterize(triangle, bad, options).error.code, ErrorCode::RepeatedVertexInFace);
    // NaN and infinite coordinates of a used vertex.
    for (double v : {nan, inf, -inf}) {
      Eigen::MatrixXd V = triangle;
      V(1, 1) = v;
      EXPECT_EQ(parameterize(V, one, options).error.code, ErrorCode::NonFiniteCoordinates);
    }
    // The same face twice: the same orientation, then the opposite one.
    Eigen::MatrixXi twice(2, 3);
    twice << 0, 1, 2, 0, 1, 2;
    EXPECT_EQ(parameterize(triangle, twice, options).error.code, ErrorCode::InconsistentOrientation);
    twice << 0, 1, 2, 0, 2, 1;
    EXPECT_EQ(parameterize(triangle, twice, options).error.code, ErrorCode::Closed);
    // Wrong column counts.
    EXPECT_TRUE(parameterize(triangle, Eigen::MatrixXi::Zero(1, 2), options).error);
    EXPECT_TRUE(parameterize(Eigen::MatrixXd::Zero(3, 2), one, options).error);
  }
}
