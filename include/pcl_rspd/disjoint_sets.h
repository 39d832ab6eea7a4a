/*
 * pcl_rspd: disjoint sets — the serial union-find that joins thick cells and noisy seeds into groups.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Union-find over 0..n-1 whose roots are each set's smallest element, so the groups do not
  * depend on the order in which pairs are joined (connected_parts.h has the lock-free one that
  * labels a whole cloud's graph in parallel). */
class DisjointSets
{
public:
  explicit DisjointSets (std::size_t n) : parent_ (n) { std::iota (parent_.begin (), parent_.end (), 0u); }

  /** \brief The smallest element of x's set (path halving). */
  std::uint32_t
  find (std::uint32_t x)
  {
    while (parent_[x] != x)
      x = parent_[x] = parent_[parent_[x]];
    return x;
  }

  /** \brief Join the sets of a and b. */
  void
  join (std::uint32_t a, std::uint32_t b)
  {
    const std::uint32_t ra = find (a), rb = find (b);
    if (ra != rb)
      parent_[std::max (ra, rb)] = std::min (ra, rb);
  }

  /** \brief The sets, each ascending, in order of their smallest element (sets of one included). */
  std::vector<std::vector<std::uint32_t>>
  groups ()
  {
    std::vector<std::vector<std::uint32_t>> by_root (parent_.size ());
    for (std::uint32_t a = 0; a < parent_.size (); ++a)
      by_root[find (a)].push_back (a);
    std::vector<std::vector<std::uint32_t>> out;
    for (auto& g : by_root)
      if (!g.empty ())
        out.push_back (std::move (g));
    return out;
  }

private:
  std::vector<std::uint32_t> parent_;
};

} // namespace rspd
} // namespace pcl
