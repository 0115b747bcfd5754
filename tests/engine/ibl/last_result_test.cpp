#include "engine/ibl/last_result.h"

#include <gtest/gtest.h>

#include <string>

namespace facet::ibl {
namespace {

TEST(LastResult, ComputesOncePerKeyInARowAndAgainForAnother) {
  LastResult<std::string, int> last;
  int computed = 0;
  const auto length = [&](const std::string& key) {
    return last.get(key, [&] {
      ++computed;
      return int(key.size());
    });
  };
  EXPECT_EQ(length("studio"), 6);
  EXPECT_EQ(length("studio"), 6);
  EXPECT_EQ(computed, 1) << "the same key asked twice in a row";
  EXPECT_EQ(length("courtyard"), 9);
  EXPECT_EQ(computed, 2);
  EXPECT_EQ(length("studio"), 6);
  EXPECT_EQ(computed, 3) << "one entry: the last key only";
}

}  // namespace
}  // namespace facet::ibl
