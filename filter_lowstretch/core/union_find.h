// Disjoint sets over 0..n-1 (path halving): which faces, corners or vertices end up joined.
#pragma once
#include <numeric>
#include <vector>

namespace lowstretch {

class UnionFind {
 public:
  explicit UnionFind(int n) : parent_(static_cast<size_t>(n)) { std::iota(parent_.begin(), parent_.end(), 0); }
  // The representative of x's set.
  int find(int x) {
    while (parent_[size_t(x)] != x) x = parent_[size_t(x)] = parent_[size_t(parent_[size_t(x)])];
    return x;
  }
  // Joins the sets of a and b; returns false if they were one set already.
  bool unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[size_t(a)] = b;
    return true;
  }

 private:
  std::vector<int> parent_;
};

}  // namespace lowstretch
