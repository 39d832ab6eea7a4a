/*
 * pcl_rspd: step split (departure), see step_split.h.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/normal_estimation.h>  // resolveThreads
#include <pcl_rspd/patch_growth.h>       // labelSamples, kNoPatch
#include <pcl_rspd/patch_merge.h>        // normalsCompatible
#include <pcl_rspd/robust_statistics.h> // robustSpread, median
#include <pcl_rspd/step_split.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace pcl
{
namespace rspd
{
namespace
{
/** A member is off the plane when the mean of its neighbourhood's distances departs from the median
  * by more than this many robust σ of the plane's distances. The mean of k = 50 distances scatters
  * by σ/7, so half a σ is far out of the noise; a door 2 cm proud of a wall at σ = 2.5 cm gives a
  * region of 1,072 samples (the door holds 1,170); at one σ the door at σ = 2 cm gave 512 (debug
  * prints). */
constexpr double kStepSmoothSigmas = 0.5;

/** Most of a region's members that may border the rest. A door of 1,100 samples has a third on its
  * border; the strips that neighbourhoods straddling an edge push off a wall are all border. */
constexpr double kStepBorderShare = 0.5;

/** How far, in half extents of the region, the two planes must meet from its centre. Doors in the
  * noisy rooms: 3.1 to 13; real scans' warped patches (room_scan1, office1, table_scene_mug): 0.4
  * to 8.6, most below 2. */
constexpr double kStepCrossReach = 2.0;

/** Least share of the planes' offset found across the region's border or, failing that, across
  * the step's midpoint (see findStep). Across the region's border: doors in the noisy rooms 0.78 to 0.94; a
  * door on a wall at σ = 1.5 cm over k = 30 neighbours (the unit tests, eight seeds): 0.69 to 0.88,
  * where the midpoint gives the same (the door is 1.3σ proud, its midpoint near the region's
  * border); a bowl 4 cm deep at σ = 1 cm: 0.37 to 0.62 (midpoint 0.50-0.59); the warped patches of
  * real scans, which bend rather than step: 0.25 to 0.66 (those above 0.6 meet their plane within
  * twice their half extent but one, cgal_building's 0.64, at 2.2). At the midpoint, two of
  * cgal_building's reach 0.70 and 0.72 (0.54-0.56 before) and one of room_scan1's, a 300-sample
  * region of a floor 4 mm off it at σ 3.5 mm, 1.13 (0.16). Windows 10 cm deep in a facade at
  * σ = 4 cm: 0.59-0.66 before, 0.81-0.88 at the midpoint (debug prints). */
constexpr double kStepJumpShare = 2.0 / 3.0;

/** A region moves when the median of its members' distances to the other plane is below that to
  * their own by this many standard errors of a median of as many samples at the plane's noise: one
  * sample, or a few along a rim, whose nearness distance alone cannot tell (the step lies within the
  * bands), stays. */
constexpr double kRegionMedianErrors = 2.0;
/** Standard error of the median of n normal samples, times √n / σ: √(π / 2). */
const double kMedianError = std::sqrt (M_PI / 2.0);

double
distanceTo (const PointSet& points, std::uint32_t i, const Eigen::Vector3d& center, const Eigen::Vector3d& normal)
{
  return (points.points[i].cast<double> () - center).dot (normal);
}

/** Robust σ of \a samples' distances to the plane (center, normal). */
double
spreadAbout (const PointSet& points, const std::vector<std::uint32_t>& samples, const PlaneEstimate& plane)
{
  std::vector<double> d;
  d.reserve (samples.size ());
  for (const auto i : samples)
    d.push_back (distanceTo (points, i, plane.center, plane.normal));
  return robustSpreadInPlace (d).mad;
}

/** A step found in one plane: the region split off and the rest, with their planes. */
struct Step
{
  std::vector<std::uint32_t> region, rest;
  PlaneEstimate region_plane, rest_plane;
};

/** Per-sample scratch shared by the planes judged in parallel: each plane writes only its own
  * members' entries, so no two threads touch one. Indexed by sample rather than by position in the
  * plane's members, a neighbour's entries are read near its own index (samples are in spatial
  * order), with no position lookup. */
struct StepScratch
{
  std::vector<double> distance;      ///< distance to the plane, less the plane's median distance
  std::vector<std::int8_t> side;     ///< +1 / -1 where the neighbourhood's mean is off the plane, else 0
  std::vector<std::int32_t> region;  ///< the region a sample joined (-1 none), within its plane
  std::vector<char> in_region;       ///< marks of the region judged
  std::vector<char> beside;          ///< marks of the rest's members beside it

  explicit StepScratch (std::size_t n) : distance (n, 0.0), side (n, 0), region (n, -1), in_region (n, 0), beside (n, 0) {}
};

/** Members of plane \a p off its plane: graph-connected regions of members whose neighbourhood's
  * mean distance (over neighbours in \a p) departs from the median by more than kStepSmoothSigmas
  * robust σ, on one side, in order of their first member; with each region's count of members that
  * border the rest (a neighbour in \a p on the other side or on none). */
struct OffRegions
{
  RobustSpread spread;                             ///< of the members' distances to the plane
  std::vector<std::vector<std::uint32_t>> regions; ///< samples
  std::vector<std::size_t> border_count;
};

/** Fills \a out for plane \a p; false where its distances do not spread (no noise, no region). The
  * scratch's distance and side entries of \a p's members are left set (distance less the median). */
bool
offPlaneRegions (const PointSet& points, const NeighborGraph& graph, const std::vector<PlanarPatch>& patches,
                 const std::vector<std::uint32_t>& labels, StepScratch& scratch, std::uint32_t p, OffRegions& out)
{
  const auto& members = patches[p].members;
  const std::size_t m = members.size ();
  std::vector<double> d (m);
  for (std::size_t k = 0; k < m; ++k)
    d[k] = distanceTo (points, members[k], patches[p].center, patches[p].normal);
  out.spread = robustSpread (d);
  out.regions.clear ();
  out.border_count.clear ();
  if (!(out.spread.mad > 0.0))
    return false;
  auto& distance = scratch.distance;
  auto& side = scratch.side;
  for (std::size_t k = 0; k < m; ++k)
    distance[members[k]] = d[k] - out.spread.median;

  // Each member's side: +1 or -1 where its neighbourhood's mean distance is off the plane, else 0.
  const double off = kStepSmoothSigmas * out.spread.mad;
  for (const auto i : members)
  {
    double sum = distance[i];
    std::size_t count = 1;
    graph.forEachNeighbor (i, [&] (std::uint32_t j) {
      if (labels[j] == p)
      {
        sum += distance[j];
        ++count;
      }
    });
    const double mean = sum / static_cast<double> (count);
    side[i] = mean > off ? 1 : (mean < -off ? -1 : 0);
  }

  // Regions: graph-connected members off the plane on one side, in order of their first member.
  auto& region_of = scratch.region;
  auto& regions = out.regions;
  // Members of each region with a neighbour in the plane on the other side or none: those border
  // the rest, as every same-side neighbour joins the region. Counted here, they turn down the
  // regions that are all border (most regions: the layers of a plane whose noise is as wide as a
  // neighbourhood, half its members) without reading their rows again (the 1M cube: the pass
  // 0.35 -> 0.19 s with the per-sample scratch, labels the same).
  auto& border_count = out.border_count;
  std::vector<std::uint32_t> stack;
  for (const auto i : members)
  {
    if (side[i] == 0 || region_of[i] >= 0)
      continue;
    const auto id = static_cast<std::int32_t> (regions.size ());
    regions.emplace_back ();
    border_count.push_back (0);
    region_of[i] = id;
    stack.assign (1, i);
    while (!stack.empty ())
    {
      const std::uint32_t q = stack.back ();
      stack.pop_back ();
      regions[id].push_back (q);
      bool borders = false;
      graph.forEachNeighbor (q, [&] (std::uint32_t j) {
        if (labels[j] != p)
          return;
        if (side[j] != side[q])
          borders = true;
        else if (region_of[j] < 0)
        {
          region_of[j] = id;
          stack.push_back (j);
        }
      });
      border_count[id] += borders;
    }
  }
  for (const auto& region : regions)
    for (const auto i : region)
      region_of[i] = -1; // the scratch is left as found
  return true;
}

/** The step of plane \a p, if any. */
bool
findStep (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
          const std::vector<PlanarPatch>& patches, const std::vector<std::uint32_t>& labels,
          StepScratch& scratch, std::uint32_t p, Step& step)
{
  const auto& members = patches[p].members;
  const std::size_t m = members.size ();
  if (m < 2 * params.min_patch_size)
    return false;
  OffRegions off;
  if (!offPlaneRegions (points, graph, patches, labels, scratch, p, off))
    return false;
  const auto& regions = off.regions;
  const auto& border_count = off.border_count;
  std::vector<std::uint32_t> order (regions.size ());
  for (std::uint32_t r = 0; r < order.size (); ++r)
    order[r] = r;
  std::stable_sort (order.begin (), order.end (),
                    [&] (std::uint32_t a, std::uint32_t b) { return regions[a].size () > regions[b].size (); });

  // Marks of the region judged, then of its part past the step's midpoint and of the members beside
  // that, cleared after each use (only the entries set), so that judging many regions does not sweep
  // the whole plane each time.
  auto& in_region = scratch.in_region;
  auto& is_beside = scratch.beside;
  std::vector<std::uint32_t> upper, beside;
  std::vector<double> inner, outer;
  for (const auto r : order)
  {
    const auto& region = regions[r];
    if (region.size () < params.min_patch_size)
      break; // the rest are smaller still
    if (m - region.size () < params.min_patch_size ||
        static_cast<double> (border_count[r]) > kStepBorderShare * static_cast<double> (region.size ()))
      continue;
    for (const auto q : region)
      in_region[q] = 1;
    Step s;
    for (const auto i : members)
      (in_region[i] ? s.region : s.rest).push_back (i);
    for (const auto q : region)
      in_region[q] = 0;
    if (!estimatePlane (points, s.region, params, s.region_plane) || !estimatePlane (points, s.rest, params, s.rest_plane))
      continue;
    const PlaneEstimate& a = s.region_plane;
    const PlaneEstimate& b = s.rest_plane;
    const double angle = std::acos (std::min (1.0, std::abs (a.normal.dot (b.normal))));
    if (angle > std::min (a.mnd (), b.mnd ()))
      continue;
    const double offset = (a.center - b.center).dot (b.normal);
    const double half_extent = 0.5 * std::max (a.width, a.length);
    // The planes meet at offset / sin(angle) from the region's centre (never, when parallel).
    if (!(std::abs (offset) > 0.0) || std::abs (offset) < kStepCrossReach * half_extent * std::sin (angle))
      continue;

    // The jump is read across the region's border and, if that falls short, where the step is half
    // made: across the border of the region's members whose neighbourhood's mean distance to the
    // rest's plane is past half the offset. The region ends where the mean departs by
    // kStepSmoothSigmas σ; where the offset is several σ (a window 10 cm deep in a facade at σ =
    // 4 cm) that is where a fifth of a neighbourhood lies across the step, and its border members can
    // be mostly the rest's samples (debug prints: 0.61-0.66 of the offset at the border, 0.81-0.88 at
    // the midpoint); elsewhere the border reads the step better (windows 8 cm deep at σ = 3.7 cm:
    // 0.68-0.75 at the border, 0.38-0.67 at the midpoint). Across a smooth bend, the distances on
    // either side of either border differ by one neighbourhood's slope only.
    const auto meanDistance = [&] (std::uint32_t q) {
      double sum = distanceTo (points, q, b.center, b.normal);
      std::size_t count = 1;
      graph.forEachNeighbor (q, [&] (std::uint32_t j) {
        if (labels[j] == p)
        {
          sum += distanceTo (points, j, b.center, b.normal);
          ++count;
        }
      });
      return sum / static_cast<double> (count);
    };
    // Whether the distances (to the rest's plane) of the members of \a part with a neighbour in the
    // plane outside it and those of these neighbours differ, on the offset's side, by kStepJumpShare
    // of the offset (medians).
    const auto jumpsAt = [&] (const std::vector<std::uint32_t>& part) {
      for (const auto q : part)
        in_region[q] = 1;
      inner.clear ();
      outer.clear ();
      beside.clear ();
      for (const auto q : part)
      {
        bool borders = false;
        graph.forEachNeighbor (q, [&] (std::uint32_t j) {
          if (labels[j] == p && !in_region[j])
          {
            borders = true;
            if (!is_beside[j])
            {
              is_beside[j] = 1;
              beside.push_back (j);
              outer.push_back (distanceTo (points, j, b.center, b.normal));
            }
          }
        });
        if (borders)
          inner.push_back (distanceTo (points, q, b.center, b.normal));
      }
      for (const auto q : part)
        in_region[q] = 0;
      for (const auto q : beside)
        is_beside[q] = 0;
      if (inner.empty () || outer.empty ())
        return false;
      const double jump = medianInPlace (inner) - medianInPlace (outer);
      return jump * offset > 0.0 && std::abs (jump) >= kStepJumpShare * std::abs (offset);
    };
    if (!jumpsAt (s.region))
    {
      upper.clear ();
      for (const auto q : s.region)
        if (meanDistance (q) / offset >= 0.5)
          upper.push_back (q);
      if (upper.size () == s.region.size () || !jumpsAt (upper))
        continue;
    }
    if (std::abs (offset) < std::max (spreadAbout (points, s.region, a), spreadAbout (points, s.rest, b)))
      continue;
    step = std::move (s);
    return true;
  }
  return false;
}
} // namespace

std::size_t
splitSteps (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
            std::vector<PlanarPatch>& patches)
{
  const std::vector<std::uint32_t> labels = labelSamples (points.size (), patches);
  StepScratch scratch (points.size ());

  const std::size_t count = patches.size ();
  std::vector<Step> steps (count);
  std::vector<char> found (count, 0);
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolveThreads (params.num_threads))
  for (std::ptrdiff_t p = 0; p < static_cast<std::ptrdiff_t> (count); ++p)
    found[p] = findStep (points, graph, params, patches, labels, scratch, static_cast<std::uint32_t> (p), steps[p]);

  std::size_t split = 0;
  for (std::size_t p = 0; p < count; ++p)
  {
    if (!found[p])
      continue;
    Step& s = steps[p];
    // The rest stays the plane it was (its flags kept); it has lost members, so it is not grown.
    PlanarPatch& rest = patches[p];
    rest.members = std::move (s.rest);
    rest.first_index = *std::min_element (rest.members.begin (), rest.members.end ());
    rest.setEstimate (s.rest_plane);
    rest.grown = false;
    PlanarPatch region;
    region.members = std::move (s.region);
    region.first_index = *std::min_element (region.members.begin (), region.members.end ());
    region.setEstimate (s.region_plane);
    patches.push_back (std::move (region));
    ++split;
  }
  return split;
}

std::size_t
settleStepRegions (const PointSet& points, const NeighborGraph& graph, const std::vector<double>& band, int num_threads,
                   std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels)
{
  const std::size_t count = patches.size ();
  // Each plane's partners, sorted: parallel (normals within either's MND) and offset within the
  // wider band, where the step sides move no sample.
  std::vector<std::vector<std::uint32_t>> partners (count);
  bool any = false;
  for (std::uint32_t a = 0; a < count; ++a)
    for (std::uint32_t b = 0; b < count; ++b)
      if (b != a && !patches[a].members.empty () && !patches[b].members.empty () &&
          normalsCompatible (patches[a], patches[b]) &&
          std::abs ((patches[b].center - patches[a].center).dot (patches[a].normal)) <= std::max (band[a], band[b]))
      {
        partners[a].push_back (b);
        any = true;
      }
  if (!any)
    return 0; // most scenes: no per-sample scratch to allocate, no labels to copy
  std::vector<std::uint32_t> next (labels);
  StepScratch scratch (points.size ());
#pragma omp parallel num_threads(resolveThreads (num_threads))
  {
    OffRegions off;
    std::vector<std::pair<std::uint32_t, std::size_t>> contacts; // (plane, neighbours in it)
    std::vector<double> own, other;
#pragma omp for schedule(dynamic, 1)
    for (std::ptrdiff_t aa = 0; aa < static_cast<std::ptrdiff_t> (count); ++aa)
    {
      const auto a = static_cast<std::uint32_t> (aa);
      const PlanarPatch& plane = patches[a];
      if (partners[a].empty () || !offPlaneRegions (points, graph, patches, labels, scratch, a, off))
        continue;
      for (const auto& region : off.regions)
      {
        // The partner beside the region on its side that holds most of its members' neighbours.
        const int side = scratch.side[region.front ()];
        contacts.clear ();
        for (const auto q : region)
          graph.forEachNeighbor (q, [&] (std::uint32_t j) {
            const std::uint32_t b = labels[j];
            if (b == a || b == kNoPatch || !std::binary_search (partners[a].begin (), partners[a].end (), b))
              return;
            const auto it = std::find_if (contacts.begin (), contacts.end (), [b] (const auto& c) { return c.first == b; });
            if (it == contacts.end ())
              contacts.emplace_back (b, 1);
            else
              ++it->second;
          });
        std::uint32_t to = kNoPatch;
        std::size_t most = 0;
        for (const auto& [b, c] : contacts)
        {
          const double level = (patches[b].center - plane.center).dot (plane.normal) - off.spread.median;
          if (level * side > 0.0 && (c > most || (c == most && b < to)))
          {
            to = b;
            most = c;
          }
        }
        if (to == kNoPatch)
          continue;
        // The region goes where its members lie nearer, by the median of their distances.
        own.clear ();
        other.clear ();
        for (const auto q : region)
        {
          own.push_back (std::abs (distanceTo (points, q, plane.center, plane.normal)));
          other.push_back (std::abs (distanceTo (points, q, patches[to].center, patches[to].normal)));
        }
        const double mo = medianInPlace (other), mw = medianInPlace (own);
        const double margin = kRegionMedianErrors * kMedianError * off.spread.mad / std::sqrt (static_cast<double> (region.size ()));
        if (mw - mo > margin)
          for (const auto q : region)
            next[q] = to;
      }
    }
  }
  return adoptLabels (next, labels, patches);
}

std::size_t
dropPlanesAcrossSteps (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                       std::vector<PlanarPatch>& patches)
{
  if (patches.size () < 3)
    return 0;
  const std::vector<std::uint32_t> labels = labelSamples (points.size (), patches);
  std::vector<char> drop (patches.size (), 0);
#pragma omp parallel num_threads(resolveThreads (params.num_threads))
  {
    std::vector<std::uint32_t> beside;
    std::vector<double> own, between;
#pragma omp for schedule(dynamic, 1)
    for (std::ptrdiff_t l = 0; l < static_cast<std::ptrdiff_t> (patches.size ()); ++l)
    {
      const PlanarPatch& plane = patches[l];
      beside.clear ();
      for (const auto i : plane.members)
        graph.forEachNeighbor (i, [&] (std::uint32_t j) {
          if (labels[j] != kNoPatch && labels[j] != static_cast<std::uint32_t> (l))
            beside.push_back (labels[j]);
        });
      std::sort (beside.begin (), beside.end ());
      beside.erase (std::unique (beside.begin (), beside.end ()), beside.end ());
      // The pairs that could explain the plane: parallel to each other, neither to the plane.
      std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
      for (std::size_t x = 0; x < beside.size (); ++x)
      {
        const PlanarPatch& a = patches[beside[x]];
        if (normalsCompatible (plane, a))
          continue;
        for (std::size_t y = x + 1; y < beside.size (); ++y)
        {
          const PlanarPatch& b = patches[beside[y]];
          if (normalsCompatible (a, b) && !normalsCompatible (plane, b))
            pairs.emplace_back (beside[x], beside[y]);
        }
      }
      if (pairs.empty ())
        continue;
      own.clear ();
      for (const auto i : plane.members)
        own.push_back (std::abs (distanceTo (points, i, plane.center, plane.normal)));
      const double own_sigma = kMadScale * medianInPlace (own);
      for (const auto& [ia, ib] : pairs)
      {
        const PlanarPatch& a = patches[ia];
        const PlanarPatch& b = patches[ib];
        between.clear ();
        for (const auto i : plane.members)
          between.push_back (std::min (std::abs (distanceTo (points, i, a.center, a.normal)),
                                       std::abs (distanceTo (points, i, b.center, b.normal))));
        if (kMadScale * medianInPlace (between) <= own_sigma)
        {
          drop[l] = 1;
          break;
        }
      }
    }
  }
  std::size_t kept = 0;
  for (std::size_t l = 0; l < patches.size (); ++l)
    if (!drop[l])
    {
      if (kept != l)
        patches[kept] = std::move (patches[l]);
      ++kept;
    }
  const std::size_t dropped = patches.size () - kept;
  patches.resize (kept);
  return dropped;
}

} // namespace rspd
} // namespace pcl
