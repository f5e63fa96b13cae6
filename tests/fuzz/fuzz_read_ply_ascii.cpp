// libFuzzer target: arbitrary bytes as a .ply file (seeded with ASCII PLY) through the tool's
// reader (header check, then vcglib's ImporterPLY / plylib) and the core. The bytes are taken as
// they are, so the header itself is fuzzed too (format line, elements, property types, lists).
#include "fuzz_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lowstretch_fuzz::read_and_parameterize("ply", data, size);
  return 0;
}
