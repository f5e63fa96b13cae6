// libFuzzer target: binary PLY through the tool's reader (header check, then vcglib's
// ImporterPLY / plylib) and the core.
// An input that starts with "ply" is taken as a whole file. Any other input is a header recipe
// plus a body, so that the fuzzer spends its time on binary bodies rather than header text:
//   byte 0: bit 0 big-endian, bit 1 double coordinates, bit 2 vertex colours (uchar r g b),
//           bit 3 per-face float quality, bit 4 int list count (else uchar), bit 5 uint indices
//           (else int), bit 6 faces before vertices, bit 7 an extra "edge" element first
//   byte 1, 2: vertex and face counts; byte 3: its low 7 bits count the extra element's
//           items, its top bit names the list "vertex_index" instead of "vertex_indices"
//   bytes 4..: the binary body, as it is (short bodies test files cut short).
#include "fuzz_reader.h"

#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size >= 3 && data[0] == 'p' && data[1] == 'l' && data[2] == 'y') {
    lowstretch_fuzz::read_and_parameterize("ply", data, size);
    return 0;
  }
  if (size < 4) return 0;
  const unsigned flags = data[0], vertices = data[1], faces = data[2], extra = data[3] & 0x7f;
  const char* list_name = (data[3] & 0x80) ? "vertex_index" : "vertex_indices";
  std::string vertex_element = "element vertex " + std::to_string(vertices) + "\n";
  const char* coordinate = (flags & 2) ? "double" : "float";
  for (const char* axis : {"x", "y", "z"}) vertex_element += std::string("property ") + coordinate + " " + axis + "\n";
  if (flags & 4) vertex_element += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  std::string face_element = "element face " + std::to_string(faces) + "\nproperty list " +
                             ((flags & 16) ? "int " : "uchar ") + ((flags & 32) ? "uint " : "int ") + list_name + "\n";
  if (flags & 8) face_element += "property float quality\n";
  std::string header = std::string("ply\nformat ") + ((flags & 1) ? "binary_big_endian" : "binary_little_endian") + " 1.0\n";
  if (flags & 128) header += "element edge " + std::to_string(extra) + "\nproperty int vertex1\nproperty int vertex2\n";
  header += (flags & 64) ? face_element + vertex_element : vertex_element + face_element;
  header += "end_header\n";
  std::vector<uint8_t> file(header.begin(), header.end());
  file.insert(file.end(), data + 4, data + size);
  lowstretch_fuzz::read_and_parameterize("ply", file.data(), file.size());
  return 0;
}
