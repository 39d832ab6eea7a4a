/*
 * pcl_rspd: small-plane completion (see plane_completion.h).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/band_layers.h>
#include <pcl_rspd/normal_estimation.h> // resolveThreads
#include <pcl_rspd/patch_growth.h>      // labelSamples, membersFromLabels, kNoPatch
#include <pcl_rspd/plane_completion.h>
#include <pcl_rspd/plane_refit.h>       // refitPlanes
#include <pcl_rspd/robust_statistics.h> // kMadScale, medianInPlace

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace pcl
{
namespace rspd
{
namespace
{
/** The noise band in robust σ, as the passes after growth take it (a Gaussian keeps 99.7 % within). */
constexpr double kCompletionBandSigmas = 3.0;

/** A candidate whose band is under this share of its sample spacing (the median distance from a
  * member to its nearest neighbour) is flat to the float rounding of its coordinates: a level of a
  * depth camera, whose samples at one quantized depth make terraces on every slanted surface, not a
  * noisy face. Measured: office1's 31 candidates, all such terraces, 2e-6 to 4e-5 of their spacing
  * (without this floor 12 of them were completed, 9 planes more); synpeb_pc01's four faces 0.3-0.9,
  * room_scan1's candidates 0.2 and more. */
constexpr double kExactFlatShare = 0.01;

/** A small plane the pass may complete: short of ε, at least half of it, seeded by a clean seed. */
bool
isCandidate (const PlanarPatch& patch, std::size_t epsilon)
{
  return patch.members.size () < epsilon && 2 * patch.members.size () >= epsilon && !patch.retested;
}
} // namespace

std::size_t
completeSmallPlanes (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                     std::vector<PlanarPatch>& patches)
{
  const std::size_t epsilon = params.min_patch_size;
  if (std::none_of (patches.begin (), patches.end (), [&] (const PlanarPatch& p) { return isCandidate (p, epsilon); }))
    return 0;

  // Every plane's least-squares plane and band: the candidates' own, and those of the planes they
  // may take samples from (the paper's estimate of a small face is what stopped its growth).
  std::vector<PlanarPatch> fitted = patches;
  refitPlanes (points, params.num_threads, fitted);
  std::vector<double> band (fitted.size (), 0.0), flat_floor (fitted.size (), 0.0);
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolveThreads (params.num_threads))
  for (std::ptrdiff_t l = 0; l < static_cast<std::ptrdiff_t> (fitted.size ()); ++l)
  {
    const PlanarPatch& plane = fitted[l];
    if (plane.members.empty ())
      continue;
    std::vector<double> d (plane.members.size ());
    for (std::size_t t = 0; t < d.size (); ++t)
      d[t] = std::abs ((points.points[plane.members[t]].cast<double> () - plane.center).dot (plane.normal));
    band[l] = kCompletionBandSigmas * kMadScale * medianInPlace (d);
    if (!isCandidate (patches[l], epsilon))
      continue;
    // The candidate's sample spacing: the median over its members of the nearest graph neighbour.
    std::vector<double> gap;
    gap.reserve (plane.members.size ());
    for (const auto i : plane.members)
    {
      double nearest = HUGE_VAL;
      graph.forEachNeighbor (i, [&] (std::uint32_t j) {
        const double g = (points.points[j] - points.points[i]).norm ();
        if (g > 0.0)
          nearest = std::min (nearest, g);
      });
      if (std::isfinite (nearest))
        gap.push_back (nearest);
    }
    flat_floor[l] = gap.empty () ? HUGE_VAL : kExactFlatShare * medianInPlace (gap);
  }
  const auto relative = [&] (std::uint32_t s, std::uint32_t l) {
    return std::abs ((points.points[s].cast<double> () - fitted[l].center).dot (fitted[l].normal)) / band[l];
  };

  std::vector<std::uint32_t> labels = labelSamples (points.size (), patches);
  // Visit stamps, one per candidate, so the walk needs no clearing between candidates.
  std::vector<std::uint32_t> visited (points.size (), 0);
  std::uint32_t stamp = 0;
  std::size_t completed = 0;
  std::vector<std::uint32_t> walk, taken;
  for (std::uint32_t c = 0; c < patches.size (); ++c)
  {
    if (!isCandidate (patches[c], epsilon) || !(band[c] > flat_floor[c]))
      continue;
    // A sample joins when it lies within c's band, and no plane holds it or a plane holds it that is
    // noisier than c, turned from it beyond its MND, and relatively farther from it.
    const auto joins = [&] (std::uint32_t s) {
      const double r = relative (s, c);
      if (!(r <= 1.0))
        return false;
      const std::uint32_t l = labels[s];
      if (l == kNoPatch)
        return true;
      // (c's own members are visited before the walk: l is another plane)
      return band[c] < band[l] && std::abs (fitted[c].normal.dot (fitted[l].normal)) < patches[c].cos_mnd &&
             r < relative (s, l);
    };
    walk.assign (patches[c].members.begin (), patches[c].members.end ());
    ++stamp;
    for (const auto m : walk)
      visited[m] = stamp;
    taken.clear ();
    for (std::size_t q = 0; q < walk.size (); ++q)
      graph.forEachNeighbor (walk[q], [&] (std::uint32_t s) {
        if (visited[s] == stamp)
          return;
        visited[s] = stamp;
        if (!joins (s))
          return;
        taken.push_back (s);
        walk.push_back (s);
      });
    if (patches[c].members.size () + taken.size () < epsilon)
      continue;
    // Completed, it must be no layer of a plane found, as the pass's seeds must not be (isBandLayer,
    // on the least-squares bands): samples taken by position along a real room's edges are one
    // (room_scan1: without this test, 12 completions and 11 more planes; cgal_building 4; measured).
    PlanarPatch grown = fitted[c];
    grown.members.insert (grown.members.end (), taken.begin (), taken.end ());
    std::sort (grown.members.begin (), grown.members.end ());
    if (isBandLayer (points, graph, params, patches, band, labels, grown))
      continue;
    for (const auto s : taken)
      labels[s] = c;
    patches[c].retested = true; // completed by position: judged flat once grown, as noisy seeds' planes
    ++completed;
  }
  if (completed > 0)
    membersFromLabels (labels, patches);
  return completed;
}

} // namespace rspd
} // namespace pcl
