// libFuzzer target: arbitrary bytes as a .obj file through the tool's own OBJ reader and the core.
#include "fuzz_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lowstretch_fuzz::read_and_parameterize("obj", data, size);
  return 0;
}
