/*
 * pcl_rspd: the merge phase (Sec. 3.4).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/patch_growth.h>
#include <pcl_rspd/patch_merge.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pcl
{
namespace rspd
{
UnionFind::UnionFind (std::size_t n) : parent_ (n)
{
  std::iota (parent_.begin (), parent_.end (), 0u);
}

std::uint32_t
UnionFind::find (std::uint32_t x)
{
  while (parent_[x] != x)
  {
    parent_[x] = parent_[parent_[x]];
    x = parent_[x];
  }
  return x;
}

bool
UnionFind::unite (std::uint32_t a, std::uint32_t b)
{
  a = find (a);
  b = find (b);
  if (a == b)
    return false;
  // Lower position becomes the root: the result does not depend on the order of unions.
  if (b < a)
    std::swap (a, b);
  parent_[b] = a;
  return true;
}

bool
normalsCompatible (const PlanarPatch& a, const PlanarPatch& b)
{
  const double angle = std::acos (std::min (1.0, std::abs (a.normal.dot (b.normal))));
  return angle < std::max (a.mnd, b.mnd);
}

std::size_t
mergePatches (const PointSet& points, const NeighborGraph& graph, std::vector<PlanarPatch>& patches,
              std::vector<std::uint32_t>& labels, std::vector<std::uint8_t>* flags)
{
  if (flags && flags->size () != points.size ())
    flags->assign (points.size (), 0);
  const std::size_t num_patches = patches.size ();
  if (num_patches < 2)
    return 0;
  UnionFind sets (num_patches);
  // Every directed edge is visited once, which covers "an edge in either direction" (M1).
  for (std::size_t i = 0; i < graph.size (); ++i)
  {
    const std::uint32_t a = labels[i];
    if (a == kNoPatch || (flags && ((*flags)[i] & kInterior)))
      continue;
    bool interior = true;
    graph.forEachNeighbor (i, [&] (std::uint32_t n) {
      const std::uint32_t b = labels[n];
      interior = interior && b == a;
      if (b == kNoPatch || b == a || sets.find (a) == sets.find (b))
        return;
      const PlanarPatch& pa = patches[a];
      const PlanarPatch& pb = patches[b];
      if (!normalsCompatible (pa, pb))                                        // M2
        return;
      if (pb.isInlier (points.points[i], points.normals[i]) ||                // M3
          pa.isInlier (points.points[n], points.normals[n]))
        sets.unite (a, b);
    });
    if (flags && interior)
      (*flags)[i] |= kInterior | kSaturated;
  }

  // Representative of each group: the largest patch, ties by lowest member index.
  std::vector<std::uint32_t> representative (num_patches, kNoPatch);
  for (std::uint32_t p = 0; p < num_patches; ++p)
  {
    const std::uint32_t root = sets.find (p);
    std::uint32_t& r = representative[root];
    if (r == kNoPatch || patches[p].members.size () > patches[r].members.size () ||
        (patches[p].members.size () == patches[r].members.size () && patches[p].first_index < patches[r].first_index))
      r = p;
  }
  std::size_t absorbed = 0;
  for (std::uint32_t p = 0; p < num_patches; ++p)
  {
    const std::uint32_t r = representative[sets.find (p)];
    if (r == p)
      continue;
    PlanarPatch& rep = patches[r];
    rep.members.insert (rep.members.end (), patches[p].members.begin (), patches[p].members.end ());
    rep.first_index = std::min (rep.first_index, patches[p].first_index);
    patches[p].members.clear ();
    ++absorbed;
  }
  if (absorbed == 0)
    return 0;
  patches.erase (std::remove_if (patches.begin (), patches.end (),
                                 [] (const PlanarPatch& p) { return p.members.empty (); }),
                 patches.end ());
  labels = labelSamples (points.size (), patches);
  return absorbed;
}

} // namespace rspd
} // namespace pcl
