/*
 * pcl_rspd: the merge phase (Sec. 3.4).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/patch_growth.h>
#include <pcl_rspd/normal_estimation.h>
#include <pcl_rspd/patch_merge.h>

#include <Eigen/Eigenvalues>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

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

namespace
{
/** Sums of positions and their outer products: a least-squares plane that merges by addition. */
struct Moments
{
  double n = 0.0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero ();

  void
  add (const Eigen::Vector3d& p)
  {
    n += 1.0;
    sum += p;
    outer += p * p.transpose ();
  }

  void
  merge (const Moments& o)
  {
    n += o.n;
    sum += o.sum;
    outer += o.outer;
  }

  bool
  plane (Eigen::Vector3d& center, Eigen::Vector3d& normal) const
  {
    if (n < 3.0)
      return false;
    center = sum / n;
    const Eigen::Matrix3d cov = outer / n - center * center.transpose ();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig (cov);
    normal = eig.eigenvectors ().col (0);
    return normal.allFinite ();
  }
};

/** M4 applied to the candidate pairs (M1-M3 met, each pair once, in any order) in a fixed order of
  * their own, see mergePatches. */
void
uniteCoplanarGroups (const PointSet& points, const std::vector<PlanarPatch>& patches,
                     std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs, double max_outlier_ratio,
                     UnionFind& sets)
{
  const auto larger = [&] (std::uint32_t p, std::uint32_t q) {
    if (patches[p].members.size () != patches[q].members.size ())
      return patches[p].members.size () > patches[q].members.size ();
    return patches[p].first_index < patches[q].first_index;
  };
  // Each pair as (larger, smaller); the pair with the larger first patch first, then the larger second.
  for (auto& pr : pairs)
    if (larger (pr.second, pr.first))
      std::swap (pr.first, pr.second);
  std::sort (pairs.begin (), pairs.end (), [&] (const auto& x, const auto& y) {
    if (x.first != y.first)
      return larger (x.first, y.first);
    return x.second != y.second && larger (x.second, y.second);
  });
  // Per union-find root: the group's representative and its member patches.
  std::vector<std::uint32_t> representative (patches.size ());
  std::vector<std::vector<std::uint32_t>> group (patches.size ());
  for (std::uint32_t p = 0; p < patches.size (); ++p)
  {
    representative[p] = p;
    group[p].assign (1, p);
  }
  // Position sums per patch, computed the first time a group's least-squares plane is asked for
  // (most merges never ask); a group's sums are those of its patches added.
  std::vector<Moments> patch_moments (patches.size ());
  std::vector<char> has_moments (patches.size (), 0);
  const auto groupMoments = [&] (std::uint32_t root) {
    Moments sum;
    for (const auto q : group[root])
    {
      if (!has_moments[q])
      {
        for (const auto m : patches[q].members)
          patch_moments[q].add (points.points[m].cast<double> ());
        has_moments[q] = 1;
      }
      sum.merge (patch_moments[q]);
    }
    return sum;
  };
  for (const auto& pr : pairs)
  {
    const std::uint32_t ra = sets.find (pr.first), rb = sets.find (pr.second);
    if (ra == rb)
      continue;
    const bool a_leads = larger (representative[ra], representative[rb]);
    const std::uint32_t lead = a_leads ? ra : rb, other = a_leads ? rb : ra;
    const PlanarPatch& plane = patches[representative[lead]];
    // The band is the wider of the two groups' (their representatives' MDP): a noisier part of the
    // same plane (farther from the scanner) or a patch of its noise tails (samples the leading plane
    // turned down, seeded again by the small-plane pass) still joins; a face bent away does not.
    const double band = std::max (plane.mdp, patches[representative[other]].mdp);
    const auto coplanar = [&] (const Eigen::Vector3d& center, const Eigen::Vector3d& normal) {
      std::size_t total = 0, inside = 0;
      for (const auto q : group[other])
        for (const auto m : patches[q].members)
        {
          ++total;
          inside += std::abs ((points.points[m].cast<double> () - center).dot (normal)) <= band;
        }
      return static_cast<double> (inside) >= (1.0 - max_outlier_ratio) * static_cast<double> (total);
    };
    // The representative's plane comes from its own samples only: its normal's error, tiny at its
    // scale, grows with the distance across a large group (a 100 m floor of 10M samples, whose
    // representative holds 40k, tilts by 1e-4 rad: 1 cm at 100 m, the noise). Where it fails, the
    // leading group's least-squares plane over all its samples is asked too.
    if (!coplanar (plane.center, plane.normal))
    {
      Eigen::Vector3d center, normal;
      if (!groupMoments (lead).plane (center, normal) || !coplanar (center, normal))
        continue;
    }
    const std::uint32_t lead_rep = representative[lead];
    std::vector<std::uint32_t> joined;
    joined.swap (group[lead]);
    joined.insert (joined.end (), group[other].begin (), group[other].end ());
    group[other].clear ();
    sets.unite (ra, rb);
    const std::uint32_t root = sets.find (ra);
    group[root].swap (joined);
    representative[root] = lead_rep;
  }
}
} // namespace

std::size_t
mergePatches (const PointSet& points, const NeighborGraph& graph, std::vector<PlanarPatch>& patches,
              std::vector<std::uint32_t>& labels, std::vector<std::uint8_t>* flags, const MergeRules& rules)
{
  if (flags && flags->size () != points.size ())
    flags->assign (points.size (), 0);
  const std::size_t num_patches = patches.size ();
  if (num_patches < 2)
    return 0;
  UnionFind sets (num_patches);
  // Pairs meeting M1-M3, each once: one boundary has many edges. Every directed edge is visited
  // once, which covers "an edge in either direction" (M1). The scan runs in parallel: each thread
  // keeps the pairs it found and those that failed M2 (a property of the two patches, so one
  // evaluation per pair and thread); the union of the pair sets does not depend on the split, and
  // uniteCoplanarGroups orders the pairs itself.
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (graph.size ());
  const int threads = resolveThreads (rules.num_threads);
  std::vector<std::vector<std::uint64_t>> found (static_cast<std::size_t> (threads));
#pragma omp parallel num_threads(threads)
  {
#ifdef _OPENMP
    std::vector<std::uint64_t>& mine = found[static_cast<std::size_t> (omp_get_thread_num ())];
#else
    std::vector<std::uint64_t>& mine = found[0];
#endif
    // Pair -> kFailsM2, kFound, or kOpen (M2 holds, no edge has passed M3 yet).
    enum : std::uint8_t { kFailsM2, kFound, kOpen };
    std::unordered_map<std::uint64_t, std::uint8_t> seen;
    // The last pair looked up: a boundary sample's neighbours across it are mostly in one patch.
    std::uint64_t last_key = ~std::uint64_t (0);
    std::uint8_t* last_state = nullptr; // references into an unordered_map survive rehashing
#pragma omp for schedule(static, 4096)
    for (std::ptrdiff_t i = 0; i < n; ++i)
    {
      const std::uint32_t a = labels[i];
      if (a == kNoPatch || (flags && ((*flags)[i] & kInterior)))
        continue;
      bool interior = true;
      graph.forEachNeighbor (static_cast<std::size_t> (i), [&] (std::uint32_t nb) {
        const std::uint32_t b = labels[nb];
        interior = interior && b == a;
        if (b == kNoPatch || b == a)
          return;
        const std::uint64_t key = (static_cast<std::uint64_t> (std::min (a, b)) << 32) | std::max (a, b);
        const PlanarPatch& pa = patches[a];
        const PlanarPatch& pb = patches[b];
        if (key != last_key)
        {
          auto it = seen.find (key);
          if (it == seen.end ())
            it = seen.emplace (key, normalsCompatible (pa, pb) ? kOpen : kFailsM2).first; // M2
          last_key = key;
          last_state = &it->second;
        }
        if (*last_state != kOpen)
          return;
        if (pb.isInlier (points.points[i], points.normals[i]) || // M3
            pa.isInlier (points.points[nb], points.normals[nb]))
        {
          *last_state = kFound;
          mine.push_back (key);
        }
      });
      if (flags && interior)
        (*flags)[i] |= kInterior | kSaturated;
    }
  }
  std::vector<std::uint64_t> pair_keys;
  for (const auto& f : found)
    pair_keys.insert (pair_keys.end (), f.begin (), f.end ());
  std::sort (pair_keys.begin (), pair_keys.end ());
  pair_keys.erase (std::unique (pair_keys.begin (), pair_keys.end ()), pair_keys.end ());
  if (!rules.coplanar)
    for (const auto key : pair_keys)
      sets.unite (static_cast<std::uint32_t> (key >> 32), static_cast<std::uint32_t> (key & 0xffffffffu));
  if (rules.coplanar)
  {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    pairs.reserve (pair_keys.size ());
    for (const auto key : pair_keys)
      pairs.emplace_back (static_cast<std::uint32_t> (key >> 32), static_cast<std::uint32_t> (key & 0xffffffffu));
    uniteCoplanarGroups (points, patches, pairs, rules.max_outlier_ratio, sets);
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
    rep.grown = false; // the absorbed members were grown from with another plane
    // A plane is judged again once grown (retested) only if every part was so seeded: a part a
    // seed admitted by the planes' own noise bound seeded vouches for it. Kept by the larger part
    // alone, a riser of the staircase (seed 12: 2,117 of its 2,500 samples) whose largest seed was
    // a flat noisy one, joined by six ordinary seeds, was judged bent by its edge bands and lost.
    rep.retested = rep.retested && patches[p].retested;
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
