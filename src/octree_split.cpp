/*
 * pcl_rspd: the split phase (Sec. 3.1, Algorithm 1).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/normal_estimation.h>
#include <pcl_rspd/octree_split.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <iterator>
#include <numeric>

namespace pcl
{
namespace rspd
{
namespace
{
class OctreeSplitter
{
public:
  OctreeSplitter (const PointSet& points, const DetectorParameters& params, const std::vector<std::uint32_t>* subset,
                  bool retest_rim_cells)
    : points_ (points), params_ (params), retest_rim_cells_ (retest_rim_cells)
  {
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
  detect (std::size_t begin, std::size_t end, const Eigen::Vector3d& lo, double size, int depth,
          std::vector<PlanarPatch>& out)
  {
    if (end - begin < params_.min_patch_size)
      return false;

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
        std::array<std::vector<PlanarPatch>, 8> child_out;
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
          std::move (child_out[c].begin (), child_out[c].end (), std::back_inserter (out));
        }
      }
      else
        for (int c = 0; c < 8; ++c)
          if (detect (bounds[c], bounds[c + 1], child_lo (c), 0.5 * size, depth + 1, out))
            has_planar_patch = true;
    }
    if (has_planar_patch)
      return true;

    // No child became a patch: test the cell itself (every level, the root included).
    const std::vector<std::uint32_t> samples (order_.begin () + begin, order_.begin () + end);
    PlanarityResult r = robustPlanarityTest (points_, samples, params_);
    cells_tested_.fetch_add (1, std::memory_order_relaxed);
    if (r.verdict == PlanarityVerdict::TooManyOutliers && retest_rim_cells_)
    {
      // The inliers of the cell's own estimate (the test drops them when it fails), tested again.
      const std::vector<std::uint32_t> inliers = intervalInliers (points_, samples, r.estimate);
      if (inliers.size () >= params_.min_patch_size)
      {
        r = robustPlanarityTest (points_, inliers, params_);
        if (r.verdict == PlanarityVerdict::Planar)
          rim_seeds_.fetch_add (1, std::memory_order_relaxed);
      }
    }
    if (r.verdict != PlanarityVerdict::Planar)
      return false;
    PlanarPatch patch;
    patch.members = std::move (r.inliers);
    std::sort (patch.members.begin (), patch.members.end ());
    patch.first_index = patch.members.front ();
    patch.setEstimate (r.estimate);
    out.push_back (std::move (patch));
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
  const bool retest_rim_cells_;
  std::vector<std::uint32_t> order_;
};
} // namespace

std::vector<PlanarPatch>
splitPhase (const PointSet& points, const DetectorParameters& params, DetectorStatistics* stats,
            const std::vector<std::uint32_t>* subset, bool retest_rim_cells, std::size_t* rim_seeds)
{
  std::vector<PlanarPatch> patches;
  OctreeSplitter splitter (points, params, subset, retest_rim_cells);
  if (splitter.size () == 0)
    return patches;
  Eigen::Vector3d lo;
  double size;
  splitter.rootCell (lo, size);
#pragma omp parallel num_threads(resolveThreads (params.num_threads))
#pragma omp single
  splitter.detect (0, splitter.size (), lo, size, 0, patches);
  if (stats)
  {
    stats->cells_tested += splitter.cells_tested_;
    stats->seed_patches += patches.size ();
  }
  if (rim_seeds)
    *rim_seeds = splitter.rim_seeds_;
  return patches;
}

} // namespace rspd
} // namespace pcl
