/*
 * pcl_rspd: the growth phase (Sec. 3.3, Algorithm 2) and re-estimation after growth (Sec. 3.5).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/patch_growth.h>
#include <pcl_rspd/normal_estimation.h> // resolveThreads

#include <algorithm>
#include <numeric>

namespace pcl
{
namespace rspd
{
std::vector<std::uint32_t>
labelSamples (std::size_t num_samples, const std::vector<PlanarPatch>& patches)
{
  std::vector<std::uint32_t> labels (num_samples, kNoPatch);
  for (std::size_t p = 0; p < patches.size (); ++p)
    for (const auto s : patches[p].members)
      labels[s] = static_cast<std::uint32_t> (p);
  return labels;
}

void
membersFromLabels (const std::vector<std::uint32_t>& labels, std::vector<PlanarPatch>& patches)
{
  for (auto& patch : patches)
    patch.members.clear ();
  for (std::uint32_t i = 0; i < labels.size (); ++i)
    if (labels[i] != kNoPatch)
      patches[labels[i]].members.push_back (i);
  for (auto& patch : patches)
    if (!patch.members.empty ())
      patch.first_index = patch.members.front ();
}

std::size_t
adoptLabels (std::vector<std::uint32_t>& next, std::vector<std::uint32_t>& labels, std::vector<PlanarPatch>& patches)
{
  std::size_t changed = 0;
  for (std::size_t i = 0; i < labels.size (); ++i)
    changed += next[i] != labels[i];
  if (changed > 0)
  {
    labels.swap (next);
    membersFromLabels (labels, patches);
  }
  return changed;
}

std::size_t
growPatches (const PointSet& points, const NeighborGraph& graph, std::vector<PlanarPatch>& patches,
             std::vector<std::uint32_t>& labels, std::vector<std::uint8_t>* flags, const PointSet* trimmed)
{
  if (flags && flags->size () != points.size ())
    flags->assign (points.size (), 0);
  std::vector<std::size_t> order (patches.size ());
  std::iota (order.begin (), order.end (), 0);
  std::sort (order.begin (), order.end (), [&] (std::size_t a, std::size_t b) {
    if (patches[a].mnd != patches[b].mnd)
      return patches[a].mnd < patches[b].mnd;
    return patches[a].first_index < patches[b].first_index;
  });

  // The per-patch "outliers" set of Algorithm 2 as a stamp per sample: a sample rejected by the
  // patch grown in turn t carries stamp t + 1, so no set needs clearing between patches.
  std::vector<std::uint32_t> rejected_by (points.size (), 0);
  std::size_t added = 0;
  std::uint32_t stamp = 0;
  for (const auto p : order)
  {
    PlanarPatch& patch = patches[p];
    if (flags && patch.grown)
      continue;
    ++stamp;
    const auto& normals = (patch.trimmed && trimmed) ? trimmed->normals : points.normals;
    // The queue is the member list itself: members are popped in order and new ones appended.
    for (std::size_t head = 0; head < patch.members.size (); ++head)
    {
      const std::uint32_t m = patch.members[head];
      if (flags && ((*flags)[m] & kSaturated))
        continue;
      bool open = false; // a neighbour is still in no patch
      graph.forEachNeighbor (m, [&] (std::uint32_t n) {
        if (labels[n] != kNoPatch)
          return;
        if (rejected_by[n] == stamp)
        {
          open = true;
          return;
        }
        if (patch.isInlier (points.points[n], normals[n]))
        {
          labels[n] = static_cast<std::uint32_t> (p);
          patch.members.push_back (n);
          patch.first_index = std::min (patch.first_index, n);
          ++added;
        }
        else
        {
          rejected_by[n] = stamp;
          open = true;
        }
      });
      if (flags && !open)
        (*flags)[m] |= kSaturated;
    }
    patch.grown = flags != nullptr;
  }
  return added;
}

std::size_t
reestimateGrownPatches (const PointSet& points, const DetectorParameters& params, std::vector<PlanarPatch>& patches,
                        std::size_t* kept, const PointSet* trimmed)
{
  std::size_t updated = 0, refused = 0;
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (patches.size ());
  // Patches are independent: one per task (the big ones dominate, hence dynamic scheduling).
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : updated, refused) num_threads(resolveThreads (params.num_threads))
  for (std::ptrdiff_t p = 0; p < count; ++p)
  {
    PlanarPatch& patch = patches[p];
    const double limit = (1.0 + params.update_growth_ratio) * static_cast<double> (patch.estimate_size);
    if (!(static_cast<double> (patch.members.size ()) > limit))
      continue;
    ++updated;
    PlaneEstimate estimate;
    if (!estimatePlane ((patch.trimmed && trimmed) ? *trimmed : points, patch.members, params, estimate))
    {
      patch.estimate_size = patch.members.size (); // keep the old plane; do not retry forever
      continue;
    }
    // A plane whose new MND fails T2 has run onto the faces around it (see
    // DetectorParameters::bounded_reestimation); one past T2 already has no estimate within it to keep.
    if (params.bounded_reestimation && patch.mnd < params.max_normal_deviation &&
        estimate.mnd () >= params.max_normal_deviation)
    {
      ++refused;
      patch.estimate_size = patch.members.size ();
      continue;
    }
    patch.setEstimate (estimate);
  }
  if (kept)
    *kept = refused;
  return updated;
}

} // namespace rspd
} // namespace pcl
