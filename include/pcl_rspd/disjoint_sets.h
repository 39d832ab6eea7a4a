/*
 * pcl_rspd: disjoint sets — the serial union-find that joins thick cells and noisy seeds into groups.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <algorithm>
#include <cstddef>
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
    return groups (1, [] (std::uint32_t) { return true; });
  }

  /** \brief The sets of at least \a min_size elements that \a keep (a predicate on an element)
    * admits, counted over those elements alone; each ascending, in order of their smallest element.
    * A cloud's samples are mostly sets of one that the caller does not want: counting first
    * allocates only the sets returned (at 10M samples a vector per sample cost ~0.7 GB). */
  template <typename Keep> std::vector<std::vector<std::uint32_t>>
  groups (std::size_t min_size, Keep keep)
  {
    const auto n = static_cast<std::uint32_t> (parent_.size ());
    // Per root, its kept elements' count, then the index of its group among those returned.
    constexpr std::uint32_t kNone = ~0u;
    std::vector<std::uint32_t> slot (n, 0);
    for (std::uint32_t a = 0; a < n; ++a)
      if (keep (a))
        ++slot[find (a)];
    std::vector<std::vector<std::uint32_t>> out;
    for (std::uint32_t a = 0; a < n; ++a)
    {
      if (parent_[a] != a)
        continue; // a root is its own parent
      if (slot[a] >= std::max<std::size_t> (min_size, 1))
      {
        out.emplace_back ();
        out.back ().reserve (slot[a]);
        slot[a] = static_cast<std::uint32_t> (out.size () - 1);
      }
      else
        slot[a] = kNone;
    }
    for (std::uint32_t a = 0; a < n; ++a)
      if (keep (a))
      {
        const std::uint32_t g = slot[find (a)];
        if (g != kNone)
          out[g].push_back (a);
      }
    return out;
  }

private:
  std::vector<std::uint32_t> parent_;
};

} // namespace rspd
} // namespace pcl
