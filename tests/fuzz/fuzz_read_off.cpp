// libFuzzer target: arbitrary bytes as a .off file through the tool's reader (header check, then
// vcglib's ImporterOFF) and the core.
#include "fuzz_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  lowstretch_fuzz::read_and_parameterize("off", data, size);
  return 0;
}
