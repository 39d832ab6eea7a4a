/*
 * pcl_rspd: connected parts (departure), see connected_parts.h.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/connected_parts.h>
#include <pcl_rspd/normal_estimation.h> // resolveThreads
#include <pcl_rspd/patch_growth.h>      // kNoPatch, labelSamples

#include <algorithm>
#include <atomic>
#include <utility>

namespace pcl
{
namespace rspd
{
namespace
{
/** Root of \a x with path halving. Roots are linked smaller index over larger, so a set's root is its
  * lowest sample, whatever order the links are made in. Lock-free: a halving step only ever points a
  * sample that is no root at an ancestor, and a link is a compare-and-swap on a root. */
std::uint32_t
findRoot (std::vector<std::atomic<std::uint32_t>>& parent, std::uint32_t x)
{
  for (;;)
  {
    const std::uint32_t p = parent[x].load (std::memory_order_relaxed);
    if (p == x)
      return x;
    const std::uint32_t g = parent[p].load (std::memory_order_relaxed);
    if (g != p)
      parent[x].store (g, std::memory_order_relaxed); // x is no root: only halving writes its link
    x = g;
  }
}

/** Links the sets of \a a and \a b. \return the root of the joined set, as seen at the time. */
std::uint32_t
unite (std::vector<std::atomic<std::uint32_t>>& parent, std::uint32_t a, std::uint32_t b)
{
  for (;;)
  {
    a = findRoot (parent, a);
    b = findRoot (parent, b);
    if (a == b)
      return a;
    if (a > b)
      std::swap (a, b);
    std::uint32_t expected = b;
    if (parent[b].compare_exchange_strong (expected, a, std::memory_order_relaxed))
      return a;
  }
}
} // namespace

std::size_t
splitDisconnectedPlanes (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                         std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels)
{
  const std::size_t n = labels.size ();
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (n);
  std::vector<std::uint8_t> core (n, 0);
#pragma omp parallel for schedule(static, 4096) num_threads(resolveThreads (params.num_threads))
  for (std::ptrdiff_t i = 0; i < count; ++i)
    core[i] = labels[i] != kNoPatch && patches[labels[i]].isInlier (points.points[i], points.normals[i]);

  // Parts: union-find over the graph's edges between core samples of one plane, in parallel (the
  // partition, and each part's root, do not depend on the order the edges are seen in).
  std::vector<std::atomic<std::uint32_t>> parent (n);
  for (std::uint32_t i = 0; i < n; ++i)
    parent[i].store (i, std::memory_order_relaxed);
#pragma omp parallel for schedule(dynamic, 4096) num_threads(resolveThreads (params.num_threads))
  for (std::ptrdiff_t ii = 0; ii < count; ++ii)
  {
    const std::uint32_t i = static_cast<std::uint32_t> (ii);
    if (!core[i])
      continue;
    // The row's samples join i's set one by one: starting each search from the set's last known
    // root, not from i, saves walking i's path once per neighbour.
    std::uint32_t set = i;
    graph.forEachNeighbor (i, [&] (std::uint32_t j) {
      if (core[j] && labels[j] == labels[i])
        set = unite (parent, set, j);
    });
  }
  std::vector<std::uint32_t> root (n);
#pragma omp parallel for schedule(static, 4096) num_threads(resolveThreads (params.num_threads))
  for (std::ptrdiff_t i = 0; i < count; ++i)
    root[i] = findRoot (parent, static_cast<std::uint32_t> (i));
  std::vector<std::atomic<std::uint32_t>> ().swap (parent); // memory: 4 bytes a sample at 10M samples
  std::vector<std::uint32_t> part_size (n, 0);
  for (std::uint32_t i = 0; i < n; ++i)
    if (core[i])
      ++part_size[root[i]];

  std::size_t added = 0;
  const std::size_t planes = patches.size ();
  // While a plane is split, root[m] of its members is read once and then holds m's part (the roots
  // of other planes' samples are untouched).
  std::vector<std::uint32_t>& part = root;
  for (std::size_t l = 0; l < planes; ++l)
  {
    // The plane's parts of at least min_patch_size core samples: (size, root), largest first.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> big;
    for (const auto m : patches[l].members)
      if (core[m] && root[m] == m && part_size[m] >= params.min_patch_size)
        big.emplace_back (part_size[m], m);
    if (big.size () < 2)
      continue;
    std::sort (big.begin (), big.end (), [] (const auto& x, const auto& y) {
      return x.first != y.first ? x.first > y.first : x.second < y.second;
    });
    std::vector<std::uint32_t> open;
    for (const auto m : patches[l].members)
    {
      std::uint32_t p = kNoPatch;
      for (std::uint32_t b = 0; core[m] && b < big.size (); ++b)
        if (big[b].second == root[m])
          p = b;
      part[m] = p;
      if (p == kNoPatch)
        open.push_back (m);
    }
    std::vector<std::uint32_t> choice (open.size ());
    for (;;)
    {
      for (std::size_t t = 0; t < open.size (); ++t)
      {
        choice[t] = kNoPatch;
        graph.forEachNeighbor (open[t], [&] (std::uint32_t j) {
          if (labels[j] == l && part[j] != kNoPatch)
            choice[t] = std::min (choice[t], part[j]);
        });
      }
      std::size_t kept = 0;
      for (std::size_t t = 0; t < open.size (); ++t)
      {
        if (choice[t] == kNoPatch)
          open[kept++] = open[t];
        else
          part[open[t]] = choice[t];
      }
      if (kept == open.size ())
        break;
      open.resize (kept);
    }
    for (const auto m : open)
      part[m] = 0;

    std::vector<std::vector<std::uint32_t>> members (big.size ());
    for (const auto m : patches[l].members)
      members[part[m]].push_back (m);
    for (std::size_t b = 0; b < big.size (); ++b)
    {
      std::sort (members[b].begin (), members[b].end ());
      PlanarPatch piece = patches[l];
      piece.members = std::move (members[b]);
      piece.first_index = piece.members.front ();
      PlaneEstimate estimate;
      if (estimatePlane (points, piece.members, params, estimate))
        piece.setEstimate (estimate);
      if (b == 0)
        patches[l] = std::move (piece);
      else
      {
        patches.push_back (std::move (piece));
        ++added;
      }
    }
  }
  if (added > 0)
    labels = labelSamples (n, patches);
  return added;
}

} // namespace rspd
} // namespace pcl
