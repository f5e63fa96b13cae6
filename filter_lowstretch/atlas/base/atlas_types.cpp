#include "atlas/base/atlas_types.h"

namespace lowstretch {

const char* to_string(NonDisk non_disk) {
  switch (non_disk) {
    case NonDisk::Reject: return "reject";
    case NonDisk::Charts: return "charts";
    case NonDisk::Atlas: return "atlas";
  }
  return "?";
}

}  // namespace lowstretch
