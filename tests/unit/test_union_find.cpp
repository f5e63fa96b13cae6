// Disjoint sets (core/union_find.h).
#include <gtest/gtest.h>

#include "core/union_find.h"

using namespace lowstretch;

TEST(UnionFind, UniteJoinsSetsOnceAndFindNamesTheirRepresentative) {
  UnionFind sets(6);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(sets.find(i), i);
  EXPECT_TRUE(sets.unite(0, 1));
  EXPECT_TRUE(sets.unite(2, 3));
  EXPECT_TRUE(sets.unite(1, 3));
  EXPECT_FALSE(sets.unite(0, 2)) << "already one set";
  for (const int i : {1, 2, 3}) EXPECT_EQ(sets.find(i), sets.find(0));
  EXPECT_NE(sets.find(4), sets.find(0));
  EXPECT_NE(sets.find(4), sets.find(5));
  EXPECT_EQ(sets.find(5), 5);
}
