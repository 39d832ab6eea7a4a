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
                         std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels, bool release_strays,
                         std::size_t* strays_released)
{
  const std::size_t n = labels.size ();
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (n);
  // A part's core sample passes its plane's inlier test and has at least a third of its k neighbours
  // in the plane. Why: clutter inside a plane's band (outliers behind a facade, in the band of its
  // coplanar windows) passes the inlier test too, and where it is dense enough to percolate it joins
  // separate faces into one part. Most of a clutter sample's neighbours lie outside the plane (a
  // random facade, layout 8026 at sigma 4.25 cm: a median share of 0.34 over the outliers the
  // windows' plane held, and 1.00 over its true members, 0.94 at their 1st percentile); a face's
  // sample on a straight rim has half of its neighbours in the face, a third leaves that margin.
  // Half instead of a third split one more plane on room_scan1 and three more on cgal_building
  // (measured without the surface test below).
  // Per sample, its neighbours in its plane where it passes the plane's inlier test, else 0.
  std::vector<std::uint16_t> in_plane_share (n, 0);
  const int k = graph.k ();
  const auto core = [&] (std::uint32_t i) {
    return in_plane_share[i] > 0 && 3 * static_cast<int> (in_plane_share[i]) >= k;
  };
#pragma omp parallel for schedule(static, 4096) num_threads(resolveThreads (params.num_threads))
  for (std::ptrdiff_t i = 0; i < count; ++i)
  {
    const std::uint32_t l = labels[i];
    if (l == kNoPatch || !patches[l].isInlier (points.points[i], points.normals[i]))
      continue;
    int in_plane = 0;
    graph.forEachNeighbor (static_cast<std::size_t> (i), [&] (std::uint32_t j) { in_plane += labels[j] == l; });
    in_plane_share[i] = static_cast<std::uint16_t> (in_plane);
  }

  // Parts: union-find over the graph's edges between core samples of one plane, in parallel (the
  // partition, and each part's root, do not depend on the order the edges are seen in). With
  // release_strays, in the same pass over the rows, chains: the same over the edges between any two
  // samples of one plane.
  std::vector<std::atomic<std::uint32_t>> parent (n), links (release_strays ? n : 0);
  for (std::uint32_t i = 0; i < n; ++i)
    parent[i].store (i, std::memory_order_relaxed);
  for (std::uint32_t i = 0; i < links.size (); ++i)
    links[i].store (i, std::memory_order_relaxed);
#pragma omp parallel for schedule(dynamic, 4096) num_threads(resolveThreads (params.num_threads))
  for (std::ptrdiff_t ii = 0; ii < count; ++ii)
  {
    const std::uint32_t i = static_cast<std::uint32_t> (ii);
    const bool core_i = core (i);
    if (!core_i && !(release_strays && labels[i] != kNoPatch))
      continue;
    // The row's samples join i's set one by one: starting each search from the set's last known
    // root, not from i, saves walking i's path once per neighbour.
    std::uint32_t set = i, chained = i;
    graph.forEachNeighbor (i, [&] (std::uint32_t j) {
      if (labels[j] != labels[i])
        return;
      if (core_i && core (j))
        set = unite (parent, set, j);
      if (release_strays)
        chained = unite (links, chained, j);
    });
  }
  std::vector<std::uint32_t> root (n), chain (links.size ());
#pragma omp parallel for schedule(static, 4096) num_threads(resolveThreads (params.num_threads))
  for (std::ptrdiff_t i = 0; i < count; ++i)
  {
    root[i] = findRoot (parent, static_cast<std::uint32_t> (i));
    if (release_strays)
      chain[i] = findRoot (links, static_cast<std::uint32_t> (i));
  }
  std::vector<std::atomic<std::uint32_t>> ().swap (parent); // memory: 4 bytes a sample at 10M samples
  std::vector<std::atomic<std::uint32_t>> ().swap (links);
  std::vector<std::uint32_t> part_size (n, 0);
  for (std::uint32_t i = 0; i < n; ++i)
    if (core (i))
      ++part_size[root[i]];

  std::size_t added = 0, strays = 0;
  const std::size_t planes = patches.size ();
  // While a plane is split, root[m] of its members is read once and then holds m's part (the roots
  // of other planes' samples are untouched).
  std::vector<std::uint32_t>& part = root;
  for (std::size_t l = 0; l < planes; ++l)
  {
    // The plane's parts of at least min_patch_size core samples: (size, root), largest first.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> big;
    for (const auto m : patches[l].members)
      if (core (m) && root[m] == m && part_size[m] >= params.min_patch_size)
        big.emplace_back (part_size[m], m);
    if (big.size () < (release_strays ? 1u : 2u))
      continue;
    // The entry of big holding member m's part (kNoPatch: m is no core sample, or its part is small).
    const auto entryOf = [&] (std::uint32_t m) {
      if (core (m))
        for (std::uint32_t b = 0; b < big.size (); ++b)
          if (big[b].second == root[m])
            return b;
      return kNoPatch;
    };
    // Only pieces of surface count: a part whose median sample has at least three quarters of its
    // neighbours in the plane. Why: a plane of clutter (a layer of a slab of outliers) falls into
    // parts under the core test too, and split, its pieces were merged into the true plane as layers
    // of it (20 % outliers, seed 2: F1 0.946 -> 0.913). Measured medians (a debug print): the facade's
    // windows and walls 0.94-1.00, the slab's layer parts and a wall's clump of outliers 0.40-0.62.
    std::vector<std::vector<std::uint16_t>> shares (big.size ());
    for (const auto m : patches[l].members)
    {
      const std::uint32_t b = entryOf (m);
      if (b != kNoPatch)
        shares[b].push_back (in_plane_share[m]);
    }
    std::size_t surfaces = 0;
    for (std::size_t b = 0; b < big.size (); ++b)
    {
      auto mid = shares[b].begin () + static_cast<std::ptrdiff_t> (shares[b].size () / 2);
      std::nth_element (shares[b].begin (), mid, shares[b].end ());
      if (4 * static_cast<int> (*mid) >= 3 * k)
        big[surfaces++] = big[b];
    }
    big.resize (surfaces);
    if (big.size () < (release_strays ? 1u : 2u))
      continue;
    if (big.size () == 1)
    {
      // One piece of surface (release_strays): the members that no chain of the plane's members
      // joins to it go. Why: the passes after growth claim samples by their distance to the plane
      // wherever it reaches, and clutter inside its band joined them to it until the plane support
      // released that clutter; what it joined is left apart (boxes layout 204 among 20 % outliers: a
      // box's top held 592 samples of the sides of a box 3 m away, whose voxels kept it from matching
      // its face).
      auto& own = patches[l].members;
      const std::uint32_t piece = chain[big.front ().second];
      std::size_t kept = 0;
      for (const auto m : own)
        if (chain[m] == piece)
          own[kept++] = m;
      if (kept < own.size ())
      {
        strays += own.size () - kept;
        own.resize (kept);
        patches[l].first_index = *std::min_element (own.begin (), own.end ());
      }
      continue;
    }
    std::sort (big.begin (), big.end (), [] (const auto& x, const auto& y) {
      return x.first != y.first ? x.first > y.first : x.second < y.second;
    });
    std::vector<std::uint32_t> open;
    for (const auto m : patches[l].members)
    {
      const std::uint32_t p = entryOf (m);
      part[m] = p;
      if (p == kNoPatch)
        open.push_back (m);
    }
    // Every other member joins the part of a graph neighbour that is a core sample of it (only those
    // have a part yet; the lowest part); one hop only: a member farther from every part is released.
    // Why: members chained from neighbour to neighbour are the clutter web the core test left out,
    // which, given to the largest part, made it a plane across the others (the facade above: 0.588,
    // 1 of 10 planes).
    std::vector<std::uint32_t> choice (open.size (), kNoPatch);
    for (std::size_t t = 0; t < open.size (); ++t)
      graph.forEachNeighbor (open[t], [&] (std::uint32_t j) {
        if (labels[j] == l && part[j] != kNoPatch)
          choice[t] = std::min (choice[t], part[j]);
      });
    for (std::size_t t = 0; t < open.size (); ++t)
      part[open[t]] = choice[t];

    std::vector<std::vector<std::uint32_t>> members (big.size ());
    for (const auto m : patches[l].members)
      if (part[m] != kNoPatch)
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
  if (added > 0 || strays > 0)
    labels = labelSamples (n, patches);
  if (strays_released)
    *strays_released = strays;
  return added;
}

} // namespace rspd
} // namespace pcl
