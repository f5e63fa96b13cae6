// What can go wrong (core/errors.h): one message and one stable name per code.
#include <gtest/gtest.h>

#include "core/errors.h"

using namespace lowstretch;

TEST(Errors, EveryCodeHasItsOwnMessageAndName) {
  for (int c = 1; c <= int(ErrorCode::Cancelled); ++c)
    for (int d = c + 1; d <= int(ErrorCode::Cancelled); ++d) {
      EXPECT_NE(message({ErrorCode(c), 3, "x"}), message({ErrorCode(d), 3, "x"}));
      EXPECT_STRNE(code_name(ErrorCode(c)), code_name(ErrorCode(d)));
    }
}
