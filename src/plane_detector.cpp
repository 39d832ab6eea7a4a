/*
 * pcl_rspd: the pipeline of Sec. 3 — split, then grow and merge until every patch is stable.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/normal_estimation.h>
#include <pcl_rspd/octree_split.h>
#include <pcl_rspd/patch_growth.h>
#include <pcl_rspd/patch_merge.h>
#include <pcl_rspd/plane_detector.h>
#include <pcl_rspd/robust_statistics.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>

namespace pcl
{
namespace rspd
{
namespace
{
/** Sec. 3.5: re-estimate C, N, MDP and MND of every patch that grew by more than the update ratio
  * since its last estimate. Members are kept; T1-T3 are not re-run. \return patches updated */
std::size_t
reestimateGrownPatches (const PointSet& points, const DetectorParameters& params, std::vector<PlanarPatch>& patches)
{
  std::size_t updated = 0;
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (patches.size ());
  // Patches are independent: one per task (the big ones dominate, hence dynamic scheduling).
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : updated) num_threads(resolveThreads (params.num_threads))
  for (std::ptrdiff_t p = 0; p < count; ++p)
  {
    PlanarPatch& patch = patches[p];
    const double limit = (1.0 + params.update_growth_ratio) * static_cast<double> (patch.estimate_size);
    if (!(static_cast<double> (patch.members.size ()) > limit))
      continue;
    PlaneEstimate estimate;
    if (estimatePlane (points, patch.members, params, estimate))
      patch.setEstimate (estimate);
    else
      patch.estimate_size = patch.members.size (); // keep the old plane; do not retry forever
    ++updated;
  }
  return updated;
}
/** Sec. 3.5: grow, merge and re-estimate until no patch needs an update (or the cap). */
void
growMergeUntilStable (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                      std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels,
                      std::vector<std::uint8_t>& flags, DetectorStatistics& st)
{
  for (;;)
  {
    if (st.iterations >= params.max_iterations)
    {
      st.hit_iteration_cap = true;
      PCL_WARN ("[pcl::rspd::detectPlanes] stopped after %d grow-merge iterations with patches still "
                "unstable\n", st.iterations);
      return;
    }
    ++st.iterations;
    growPatches (points, graph, patches, labels, &flags);
    st.merges += mergePatches (points, graph, patches, labels, &flags);
    const std::size_t updated = reestimateGrownPatches (points, params, patches);
    st.reestimations += updated;
    if (updated == 0)
      return;
  }
}
} // namespace

void
detectPlanes (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
              std::vector<DetectedPatch>& result, DetectorStatistics* stats)
{
  result.clear ();
  DetectorStatistics local;
  DetectorStatistics& st = stats ? *stats : local;
  // The caller's stages (before detection) are kept; the rest is this run's.
  DetectorStatistics before = st;
  st = DetectorStatistics ();
  st.prepare_seconds = before.prepare_seconds;
  st.graph_seconds = before.graph_seconds;
  st.graph_bytes = before.graph_bytes;
  st.normals_seconds = before.normals_seconds;
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now ();

  // Split (Sec. 3.1).
  std::vector<PlanarPatch> patches = splitPhase (points, params, &st);
  std::vector<std::uint32_t> labels = labelSamples (points.size (), patches);
  const auto t1 = Clock::now ();
  st.split_seconds = std::chrono::duration<double> (t1 - t0).count ();

  // Grow and merge until no patch needs an update (Sec. 3.3-3.5).
  std::vector<std::uint8_t> flags (points.size (), 0); // see SampleFlag
  growMergeUntilStable (points, graph, params, patches, labels, flags, st);

  if (params.small_cell_size > 0 && params.small_cell_size < params.min_patch_size && !patches.empty ())
  {
    // Small-cell pass (departure, see DetectorParameters::small_cell_size).
    std::vector<double> mnds;
    for (const auto& p : patches)
      mnds.push_back (p.mnd);
    const double max_mnd = medianInPlace (mnds);
    std::vector<std::uint32_t> left;
    for (std::uint32_t i = 0; i < labels.size (); ++i)
      if (labels[i] == kNoPatch)
        left.push_back (i);
    DetectorParameters small = params;
    small.min_patch_size = params.small_cell_size;
    std::vector<PlanarPatch> seeds = splitPhase (points, small, &st, &left);
    for (auto& seed : seeds)
    {
      if (seed.mnd > max_mnd)
        continue; // noisier than every plane found: an edge band of bent normals, not a plane
      for (const auto i : seed.members)
        labels[i] = static_cast<std::uint32_t> (patches.size ());
      patches.push_back (std::move (seed));
      ++st.small_seeds;
    }
    if (st.small_seeds > 0)
    {
      growMergeUntilStable (points, graph, params, patches, labels, flags, st);
      patches.erase (std::remove_if (patches.begin (), patches.end (),
                                     [&] (const PlanarPatch& p) { return p.members.size () < params.min_patch_size; }),
                     patches.end ());
    }
  }

  st.grow_merge_seconds = std::chrono::duration<double> (Clock::now () - t1).count ();

  // Largest first, ties by lowest member index.
  std::sort (patches.begin (), patches.end (), [] (const PlanarPatch& a, const PlanarPatch& b) {
    if (a.members.size () != b.members.size ())
      return a.members.size () > b.members.size ();
    return a.first_index < b.first_index;
  });
  result.reserve (patches.size ());
  for (auto& p : patches)
  {
    DetectedPatch d;
    d.members = std::move (p.members);
    std::sort (d.members.begin (), d.members.end ());
    d.center = p.center;
    d.normal = p.normal;
    d.mdp = p.mdp;
    d.mnd = p.mnd;
    result.push_back (std::move (d));
  }
}

} // namespace rspd
} // namespace pcl
