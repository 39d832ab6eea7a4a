/*
 * pcl_rspd: the split phase (Sec. 3.1, Algorithm 1).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/bent_planes.h>
#include <pcl_rspd/disjoint_sets.h>
#include <pcl_rspd/normal_estimation.h>
#include <pcl_rspd/octree_split.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <iterator>
#include <numeric>

namespace pcl
{
namespace rspd
{
namespace
{
/** A cell that fails T1 alone (too thick for its extent; T2 and T3 pass, ε inliers) and whose parent
  * does not: the largest such cells, disjoint (thick-cell join). */
struct ThickCell
{
  Eigen::Vector3d lo;
  double size;
  std::vector<std::uint32_t> samples;
  PlaneEstimate estimate;
};

/** What one subtree of the split found. */
struct SplitOutput
{
  std::vector<PlanarPatch> patches;
  std::vector<ThickCell> thick;
};

class OctreeSplitter
{
public:
  OctreeSplitter (const PointSet& points, const DetectorParameters& params, const std::vector<std::uint32_t>* subset,
                  bool retest_rim_cells, bool keep_thick_cells, double thick_max_mnd)
    : points_ (points), params_ (params), retest_params_ (params), retest_rim_cells_ (retest_rim_cells),
      keep_thick_cells_ (keep_thick_cells), thick_max_mnd_ (thick_max_mnd), subset_ (subset != nullptr)
  {
    if (params.rim_retest_min_size > 0)
      retest_params_.min_patch_size = std::min (params.min_patch_size, params.rim_retest_min_size);
    if (subset)
      order_ = *subset;
    else
    {
      order_.resize (points.size ());
      std::iota (order_.begin (), order_.end (), 0u);
    }
  }

  std::size_t
  size () const { return order_.size (); }

  /** Algorithm 1 on the slice [begin, end) of order_, cell of corner lo and edge size.
    * Patches found are appended to out in depth-first order. */
  bool
  detect (std::size_t begin, std::size_t end, const Eigen::Vector3d& lo, double size, int depth, SplitOutput& out)
  {
    if (end - begin < params_.min_patch_size)
      return false;
    const std::size_t thick_before = out.thick.size ();

    bool has_planar_patch = false;
    if (depth < params_.max_octree_depth && !allCoincide (begin, end))
    {
      const Eigen::Vector3d mid = lo + Eigen::Vector3d::Constant (0.5 * size);
      std::array<std::size_t, 9> bounds;
      partition (begin, end, mid, bounds);
      const auto child_lo = [&] (int c) {
        return Eigen::Vector3d (c & 1 ? mid.x () : lo.x (), c & 2 ? mid.y () : lo.y (), c & 4 ? mid.z () : lo.z ());
      };
      if (end - begin >= kTaskSamples)
      {
        // Large cells: the children's subtrees are independent (disjoint ranges of order_), so they
        // run as tasks, each into its own list; joining the lists in child order gives exactly the
        // serial result whatever the thread count.
        std::array<SplitOutput, 8> child_out;
        std::array<char, 8> child_planar{};
        for (int c = 0; c < 8; ++c)
        {
#pragma omp task default(shared) firstprivate(c)
          child_planar[c] = detect (bounds[c], bounds[c + 1], child_lo (c), 0.5 * size, depth + 1, child_out[c]);
        }
#pragma omp taskwait
        for (int c = 0; c < 8; ++c)
        {
          has_planar_patch = has_planar_patch || child_planar[c];
          std::move (child_out[c].patches.begin (), child_out[c].patches.end (), std::back_inserter (out.patches));
          std::move (child_out[c].thick.begin (), child_out[c].thick.end (), std::back_inserter (out.thick));
        }
      }
      else
        for (int c = 0; c < 8; ++c)
          if (detect (bounds[c], bounds[c + 1], child_lo (c), 0.5 * size, depth + 1, out))
            has_planar_patch = true;
    }
    if (has_planar_patch)
      return true;

    // No child became a patch: test the cell itself (every level, the root included); a cell below
    // the coarse size only at an edge where normals were narrowed to their face (DetectorParameters::
    // coarse_cell_size). Elsewhere its normals are k-neighbourhoods' that it is narrower than.
    if (end - begin < params_.coarse_cell_size && points_.narrowed.size () == points_.size () &&
        std::none_of (order_.begin () + static_cast<std::ptrdiff_t> (begin), order_.begin () + static_cast<std::ptrdiff_t> (end),
                      [&] (std::uint32_t i) { return points_.narrowed[i] != 0; }))
      return false;
    const std::vector<std::uint32_t> samples (order_.begin () + begin, order_.begin () + end);
    PlanarityResult r = robustPlanarityTest (points_, samples, params_);
    cells_tested_.fetch_add (1, std::memory_order_relaxed);
    if (r.verdict == PlanarityVerdict::TooManyOutliers && retest_rim_cells_)
    {
      // The inliers of the cell's own estimate (the test drops them when it fails), tested again.
      // Until stable (DetectorParameters::rim_retest_until_stable): each estimate on cleaner
      // inliers is tighter, so the rim's bent normals fall out a step at a time.
      // Down to rim_retest_min_size inliers on the left samples' own normals (DetectorParameters::left_rim_retest).
      std::vector<std::uint32_t> inliers = intervalInliers (points_, samples, r.estimate);
      while (inliers.size () >= retest_params_.min_patch_size)
      {
        r = robustPlanarityTest (points_, inliers, retest_params_);
        if (r.verdict == PlanarityVerdict::Planar)
          rim_seeds_.fetch_add (1, std::memory_order_relaxed);
        if (r.verdict != PlanarityVerdict::TooManyOutliers || !params_.rim_retest_until_stable)
          break;
        std::vector<std::uint32_t> next = intervalInliers (points_, inliers, r.estimate);
        if (next.size () == inliers.size ())
          break;
        inliers.swap (next);
      }
    }
    bool thick = keep_thick_cells_ && r.verdict == PlanarityVerdict::FailedDistance &&
                 r.estimate.mnd () < params_.max_normal_deviation && r.estimate.mnd () <= thick_max_mnd_ &&
                 r.outlier_ratio < params_.max_outlier_ratio &&
                 (1.0 - r.outlier_ratio) * static_cast<double> (samples.size ()) >= static_cast<double> (params_.min_patch_size);
    // On a subset (the small-plane pass), a thick cell that two planes meeting at an edge explain
    // does not replace the thick cells below it: at 10,000 points a riser's thick cells gave way to
    // their parents, riser and tread, whose groups are bent and seed nothing (measured). Measured
    // in the small-plane pass only; the first split keeps its largest thick cells.
    if (thick && subset_ && out.thick.size () > thick_before && bentAtAnEdge (points_, samples, params_))
      thick = false;
    if (thick || r.verdict == PlanarityVerdict::Planar)
      out.thick.erase (out.thick.begin () + thick_before, out.thick.end ()); // the cell holds its subtree's
    if (thick)
      out.thick.push_back ({lo, size, samples, r.estimate}); // T2 and T3 pass: planar but for its width
    if (r.verdict != PlanarityVerdict::Planar)
      return false;
    PlanarPatch patch;
    patch.members = std::move (r.inliers);
    std::sort (patch.members.begin (), patch.members.end ());
    patch.first_index = patch.members.front ();
    patch.setEstimate (r.estimate);
    out.patches.push_back (std::move (patch));
    return true;
  }

  /** Bounding cube of all samples: corner and edge. */
  void
  rootCell (Eigen::Vector3d& lo, double& size) const
  {
    Eigen::Vector3d mn = Eigen::Vector3d::Constant (HUGE_VAL), mx = Eigen::Vector3d::Constant (-HUGE_VAL);
    for (const auto i : order_)
    {
      mn = mn.cwiseMin (points_.points[i].cast<double> ());
      mx = mx.cwiseMax (points_.points[i].cast<double> ());
    }
    size = (mx - mn).maxCoeff ();
    // A cube (octree cells stay cubes), centred on the box.
    lo = 0.5 * (mn + mx) - Eigen::Vector3d::Constant (0.5 * size);
  }

  std::atomic<std::size_t> cells_tested_{0};
  std::atomic<std::size_t> rim_seeds_{0};

private:
  /** \brief Cells with at least this many samples split into tasks (a few hundred tasks for a
    * million samples; smaller subtrees are not worth a task). */
  static constexpr std::size_t kTaskSamples = 16384;

  bool
  allCoincide (std::size_t begin, std::size_t end) const
  {
    const Eigen::Vector3f& first = points_.points[order_[begin]];
    for (std::size_t i = begin + 1; i < end; ++i)
      if (points_.points[order_[i]] != first)
        return false;
    return true;
  }

  /** Partition [begin, end) into the eight children of a cell split at mid; child c holds the
    * samples with (x >= mid.x) == bit 0, (y >= mid.y) == bit 1, (z >= mid.z) == bit 2. */
  void
  partition (std::size_t begin, std::size_t end, const Eigen::Vector3d& mid, std::array<std::size_t, 9>& bounds)
  {
    auto split = [this] (std::size_t b, std::size_t e, int axis, double value) {
      auto it = std::partition (order_.begin () + b, order_.begin () + e, [&] (std::uint32_t i) {
        return static_cast<double> (points_.points[i][axis]) < value;
      });
      return static_cast<std::size_t> (it - order_.begin ());
    };
    bounds[0] = begin;
    bounds[8] = end;
    bounds[4] = split (begin, end, 2, mid.z ());
    bounds[2] = split (begin, bounds[4], 1, mid.y ());
    bounds[6] = split (bounds[4], end, 1, mid.y ());
    for (int c = 0; c < 8; c += 2)
      bounds[c + 1] = split (bounds[c], bounds[c + 2], 0, mid.x ());
  }

  const PointSet& points_;
  const DetectorParameters& params_;
  DetectorParameters retest_params_; ///< params_ with min_patch_size lowered for a rim cell's inliers
  const bool retest_rim_cells_;
  const bool keep_thick_cells_;
  const double thick_max_mnd_;
  const bool subset_;
  std::vector<std::uint32_t> order_;
};
/** Thick-cell join (departure, DetectorParameters::join_thick_cells): thick cells whose cubes touch
  * and whose planes agree (normals within either's MND, at least 1 - T3's share of each one's
  * samples within the other's MDP) are joined, and each group of two or more that passes T1-T3 as a
  * whole and is not bentAtAnEdge becomes a seed. Where noise is thick against the cells that hold
  * one plane alone (a cube's faces at σ = 3 % of the edge: every cell that holds one face fails T1,
  * every cell wide enough holds three), no cell seeds; a group of such cells is as wide as the face.
  * Groups in order of their first cell (deterministic). */
std::vector<PlanarPatch>
joinThickCells (const PointSet& points, const DetectorParameters& params, const std::vector<ThickCell>& thick)
{
  const std::size_t count = thick.size ();
  const auto touch = [&] (const ThickCell& a, const ThickCell& b) {
    const double tol = 1e-9 * std::max (a.size, b.size);
    for (int d = 0; d < 3; ++d)
      if (a.lo[d] > b.lo[d] + b.size + tol || b.lo[d] > a.lo[d] + a.size + tol)
        return false;
    return true;
  };
  const auto agree = [&] (const ThickCell& a, const ThickCell& b) {
    return setsShareAPlane (points, params, a.samples, a.estimate.center, a.estimate.normal, a.estimate.mdp (),
                            a.estimate.mnd (), b.samples, b.estimate.center, b.estimate.normal, b.estimate.mdp (),
                            b.estimate.mnd ());
  };
  DisjointSets sets (count);
  for (std::uint32_t a = 0; a < count; ++a)
    for (std::uint32_t b = a + 1; b < count; ++b)
      if (touch (thick[a], thick[b]) && agree (thick[a], thick[b]))
        sets.join (a, b);
  // Groups are judged in parallel (a 1M cube's 15 groups of 6,000-50,000 samples took 0.12 s in
  // turn, most of it the hinge fit) and kept in their order.
  const std::vector<std::vector<std::uint32_t>> groups = sets.groups ();
  std::vector<PlanarPatch> judged (groups.size ());
  std::vector<char> kept (groups.size (), 0);
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolveThreads (params.num_threads))
  for (std::ptrdiff_t g = 0; g < static_cast<std::ptrdiff_t> (groups.size ()); ++g)
  {
    const auto& group = groups[g];
    if (group.size () < 2)
      continue;
    std::vector<std::uint32_t> samples;
    for (const auto c : group)
      samples.insert (samples.end (), thick[c].samples.begin (), thick[c].samples.end ());
    std::sort (samples.begin (), samples.end ());
    PlanarityResult r = robustPlanarityTest (points, samples, params);
    if (r.verdict != PlanarityVerdict::Planar || bentAtAnEdge (points, r.inliers, params))
      continue;
    PlanarPatch& patch = judged[g];
    patch.members = std::move (r.inliers);
    patch.first_index = patch.members.front ();
    patch.setEstimate (r.estimate);
    kept[g] = 1;
  }
  std::vector<PlanarPatch> patches;
  for (std::size_t g = 0; g < groups.size (); ++g)
    if (kept[g])
      patches.push_back (std::move (judged[g]));
  return patches;
}
} // namespace

std::vector<PlanarPatch>
splitPhase (const PointSet& points, const DetectorParameters& params, DetectorStatistics* stats,
            const std::vector<std::uint32_t>* subset, bool retest_rim_cells, std::size_t* rim_seeds,
            std::vector<PlanarPatch>* joined_out, double thick_max_mnd, bool shifted_grid)
{
  const bool join = params.join_thick_cells && (subset == nullptr || joined_out != nullptr);
  DetectorParameters grid = params;
  if (shifted_grid)
    ++grid.max_octree_depth; // the doubled root's level l + 1 is the bounding cube's level l
  OctreeSplitter splitter (points, grid, subset, retest_rim_cells, join, thick_max_mnd);
  if (splitter.size () == 0)
    return {};
  Eigen::Vector3d lo;
  double size;
  splitter.rootCell (lo, size);
  if (shifted_grid)
  {
    lo -= Eigen::Vector3d::Constant (kShiftedGridOffset * size);
    size *= 2.0;
  }
  SplitOutput out;
#pragma omp parallel num_threads(resolveThreads (params.num_threads))
#pragma omp single
  splitter.detect (0, splitter.size (), lo, size, 0, out);
  std::vector<PlanarPatch> patches = std::move (out.patches);
  std::size_t joined = 0;
  if (join && out.thick.size () >= 2)
  {
    std::vector<PlanarPatch> extra = joinThickCells (points, params, out.thick);
    joined = extra.size ();
    std::move (extra.begin (), extra.end (), std::back_inserter (joined_out ? *joined_out : patches));
  }
  if (stats)
  {
    stats->cells_tested += splitter.cells_tested_;
    stats->seed_patches += patches.size ();
    if (!joined_out)
      stats->joined_seeds += joined;
  }
  if (rim_seeds)
    *rim_seeds = splitter.rim_seeds_;
  return patches;
}

} // namespace rspd
} // namespace pcl
