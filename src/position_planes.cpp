/*
 * pcl_rspd: position planes (see position_planes.h).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/position_planes.h>
#include <pcl_rspd/band_layers.h>       // isBandLayer, liesOnNeighbourPlane
#include <pcl_rspd/disjoint_sets.h>
#include <pcl_rspd/patch_growth.h>      // kNoPatch
#include <pcl_rspd/plane_curvature.h>   // measureCurvature, chanceBendShare, isTube
#include <pcl_rspd/plane_refit.h>       // leastSquaresPlane, kRefitTrimSigmas
#include <pcl_rspd/robust_statistics.h> // robustSpreadInPlace, kMadScale, robustSigmaBound

#include <algorithm>
#include <cmath>
#include <iterator>

namespace pcl
{
namespace rspd
{
namespace
{
/** Starts tried per part at least: enough that one lies inside each face of a part a few faces share. */
constexpr std::size_t kStarts = 32;
/** Starts tried per ε samples of a part at least: where outliers join a scene's free samples into
  * one large part, a face of ε samples there still holds a few starts (4 if its samples are
  * consecutive in index order, as a scanner writes them; if they are spread at random, it holds none
  * with a chance of e^-4, 2 %). */
constexpr std::size_t kStartsPerEpsilon = 4;
/** Rounds of fit-and-collect per start; the members settle in two or three. */
constexpr int kFitRounds = 8;
/** A member lies within this many \a noise of its plane (the noise band of the passes after growth). */
constexpr double kPositionBandSigmas = 3.0;
/** A plane may be noisier than the noisiest plane found by this many standard errors of its own σ:
  * as noisy a face is as likely to measure a little above as below. The boxes' roughest box at
  * 80,000 points (layout 9): a face of 380 samples measured σ 3.17 cm against its sibling faces' 3.14
  * (debug prints) and was turned down. Every plane the pass keeps is also flat within chance, no
  * layer and no strip of a neighbour. */
constexpr double kNoiseBoundErrors = 2.0;

/** A sample lies on a surface if half of its neighbourhood lies within this share of the
  * neighbourhood's radius of its plane (and within the pass's reach): of a uniform volume of
  * outliers, half lies within 0.35 of the radius of any plane through the middle of a ball. */
constexpr double kSurfaceRadiusShare = 0.25;
/** A member of a plane searched again must have its neighbourhood's plane nearer parallel to it than
  * perpendicular (|cos| >= cos 45°): the strip of a face across an edge, within reach of the plane,
  * is not. */
constexpr double kSameFaceCos = 0.70710678118654752;

struct Plane
{
  Eigen::Vector3d center = Eigen::Vector3d::Zero ();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero ();
};

/** |d| of sample \a i from the plane through \a center with unit \a normal. */
double
distance (const PointSet& points, std::uint32_t i, const Eigen::Vector3d& center, const Eigen::Vector3d& normal)
{
  return std::abs ((points.points[i].cast<double> () - center).dot (normal));
}

/** Least-squares plane of \a samples (leastSquaresPlane; the centred positions need no origin).
  * false: fewer than three or collinear. */
bool
fitPlane (const PointSet& points, const std::vector<std::uint32_t>& samples, Plane& plane)
{
  return leastSquaresPlane (points, samples, {}, Eigen::Vector3d::Zero (), plane.center, plane.normal);
}

/** The surface around one sample: its neighbourhood's plane and how thin the neighbourhood is about it. */
struct LocalSurface
{
  Eigen::Vector3d normal = Eigen::Vector3d::Zero (); ///< unit normal of the plane (zero: none)
  double median = HUGE_VAL;                          ///< median |d| of the neighbourhood from it
  double radius = 0.0;                               ///< distance to the farthest neighbour
};

/** The samples of the part (stamp[i] == part) connected to \a start through samples within \a band
  * of \a plane (and, given \a local, whose neighbourhood's plane is nearer parallel to it than
  * perpendicular), in ascending order. */
std::vector<std::uint32_t>
collect (const PointSet& points, const NeighborGraph& graph, const std::vector<std::uint32_t>& stamp,
         std::uint32_t part, std::uint32_t start, const Plane& plane, double band, std::vector<std::uint32_t>& seen,
         std::uint32_t& visit, const std::vector<LocalSurface>* local = nullptr)
{
  const auto near = [&] (std::uint32_t i) {
    return distance (points, i, plane.center, plane.normal) <= band &&
           (local == nullptr || std::abs ((*local)[i].normal.dot (plane.normal)) >= kSameFaceCos);
  };
  std::vector<std::uint32_t> out;
  if (!near (start))
    return out;
  ++visit;
  seen[start] = visit;
  out.push_back (start);
  for (std::size_t head = 0; head < out.size (); ++head)
    graph.forEachNeighbor (out[head], [&] (std::uint32_t n) {
      if (stamp[n] == part && seen[n] != visit && near (n))
      {
        seen[n] = visit;
        out.push_back (n);
      }
    });
  std::sort (out.begin (), out.end ());
  return out;
}

/** The parts of ε samples or more that the k-NN graph joins among the samples \a in marks. */
std::vector<std::vector<std::uint32_t>>
partsOf (const NeighborGraph& graph, const std::vector<char>& in, std::size_t eps)
{
  DisjointSets sets (in.size ());
  for (std::uint32_t i = 0; i < in.size (); ++i)
    if (in[i])
      graph.forEachNeighbor (i, [&] (std::uint32_t j) {
        if (in[j])
          sets.join (i, j);
      });
  return sets.groups (eps, [&] (std::uint32_t i) { return in[i] != 0; });
}

/** Whether \a members (ascending) lie inside a surface: their median member has at least half of
  * its k neighbours among them, or of the members but itself where they are fewer than k (a sample
  * on a straight rim has half). A layer that a plane's band cuts from a volume of outliers has its
  * neighbours all around it: medians 0.10-0.32 of k (debug prints, boxes with 10-20 % outliers),
  * against 0.74-0.81 for the rough faces found there. */
bool
insideASurface (const NeighborGraph& graph, const std::vector<std::uint32_t>& members)
{
  std::vector<int> among;
  among.reserve (members.size ());
  for (const auto i : members)
  {
    int in = 0;
    graph.forEachNeighbor (i, [&] (std::uint32_t j) { in += std::binary_search (members.begin (), members.end (), j); });
    among.push_back (in);
  }
  auto mid = among.begin () + static_cast<std::ptrdiff_t> (among.size () / 2);
  std::nth_element (among.begin (), mid, among.end ());
  // Of as many as it could have: a plane of fewer than k + 1 members cannot give any member half of k.
  const int possible = static_cast<int> (std::min<std::size_t> (graph.k (), members.size () - 1));
  return 2 * *mid >= possible;
}

/** Buffers localSurface reuses from one sample to the next. */
struct LocalScratch
{
  std::vector<std::uint32_t> hood, nearest;
  std::vector<std::pair<double, std::uint32_t>> by_distance;
  std::vector<double> d;
};

/** The plane of sample \a i's neighbourhood (it and its k neighbours): fitted by least squares, then
  * again to the half of them nearest to that fit, so that outliers among the neighbours (up to half)
  * do not tilt it. */
LocalSurface
localSurface (const PointSet& points, const NeighborGraph& graph, std::uint32_t i, LocalScratch& scratch)
{
  LocalSurface out;
  auto& hood = scratch.hood;
  auto& by_distance = scratch.by_distance;
  hood.assign (1, i);
  graph.forEachNeighbor (i, [&] (std::uint32_t j) { hood.push_back (j); });
  Plane plane;
  if (!fitPlane (points, hood, plane))
    return out;
  by_distance.clear ();
  for (const auto j : hood)
  {
    by_distance.emplace_back (distance (points, j, plane.center, plane.normal), j);
    out.radius = std::max (out.radius, (points.points[j] - points.points[i]).cast<double> ().norm ());
  }
  const auto half = by_distance.begin () + static_cast<std::ptrdiff_t> ((by_distance.size () + 1) / 2);
  std::nth_element (by_distance.begin (), half, by_distance.end ());
  scratch.nearest.clear ();
  for (auto it = by_distance.begin (); it != half; ++it)
    scratch.nearest.push_back (it->second);
  if (!fitPlane (points, scratch.nearest, plane))
    return out;
  scratch.d.clear ();
  for (const auto j : hood)
    scratch.d.push_back (distance (points, j, plane.center, plane.normal));
  out.median = medianInPlace (scratch.d);
  out.normal = plane.normal;
  return out;
}
} // namespace

std::size_t
seedPositionPlanes (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params, double noise,
                    std::vector<double> band, std::vector<PlanarPatch>& patches,
                    std::vector<std::uint32_t>& labels)
{
  const std::size_t n = points.points.size ();
  const std::size_t eps = std::max<std::size_t> (params.min_patch_size, 3);
  if (!(noise > 0.0) || !std::isfinite (noise) || n == 0)
    return 0;
  double reach = kPositionBandSigmas * noise;
  double level = noise; // the noise the search allows (a ladder step may raise it)
  double noisiest_kept = 0.0;
  // The least noisy plane a ladder step turned down for its noise alone (position_ladder_rungs).
  double quietest_noise_reject = HUGE_VAL;
  std::vector<LocalSurface> local; // per sample searched again (surface parts), its neighbourhood's plane

  // Open: no plane holds the sample, and it lies in the noise band of no plane a neighbour holds
  // (a plane's tail beside its rim would curl a face's quadric there).
  std::vector<char> free (n, 0);
  for (std::uint32_t i = 0; i < n; ++i)
  {
    if (labels[i] != kNoPatch)
      continue;
    bool in_band = false;
    const Eigen::Vector3d pi = points.points[i].cast<double> ();
    graph.forEachNeighbor (i, [&] (std::uint32_t j) {
      const std::uint32_t l = labels[j];
      if (l != kNoPatch && !in_band)
        in_band = std::abs ((pi - patches[l].center).dot (patches[l].normal)) <= band[l];
    });
    free[i] = !in_band;
  }
  // The parts of what is open, joined along the k-NN graph.
  const std::vector<std::vector<std::uint32_t>> parts = partsOf (graph, free, eps);
  if (parts.empty ())
    return 0;

  // stamp[i]: the part (1-based) sample i is still open in, 0 for none.
  std::vector<std::uint32_t> stamp (n, 0), seen (n, 0), covered (n, 0);
  std::uint32_t visit = 0, search = 0, part = 0;
  const std::size_t before = patches.size ();
  // Searches one part. Returns the samples still open where a plane was turned down there (the part
  // is left at it; \a go_on: it leaves the part instead, and the search goes on among the rest but
  // where a surface bends), none where the part ran out of planes of ε.
  const auto searchPart = [&] (std::vector<std::uint32_t> open, bool go_on) {
    ++part;
    for (const auto i : open)
      stamp[i] = part;
    bool turned_down = false;
    while (open.size () >= eps)
    {
      std::vector<std::uint32_t> best;
      Plane best_plane;
      const std::size_t stride =
        std::max<std::size_t> (1, std::min (open.size () / kStarts, eps / kStartsPerEpsilon));
      ++search;
      for (std::size_t s = 0; s < open.size (); s += stride)
      {
        const std::uint32_t start = open[s];
        if (covered[start] == search)
          continue; // inside a plane an earlier start of this search settled on: it would settle there too
        std::vector<std::uint32_t> members {start};
        graph.forEachNeighbor (start, [&] (std::uint32_t j) {
          if (stamp[j] == part)
            members.push_back (j);
        });
        Plane plane;
        if (!fitPlane (points, members, plane))
          continue;
        for (int round = 0; round < kFitRounds; ++round)
        {
          std::vector<std::uint32_t> next = collect (points, graph, stamp, part, start, plane, reach, seen, visit,
                                                     go_on && params.position_surface_normals ? &local : nullptr);
          const bool settled = next == members;
          members = std::move (next);
          if (settled || !fitPlane (points, members, plane))
            break;
        }
        for (const auto i : members)
          covered[i] = search;
        // Most members wins; ties keep the earlier start (the result does not depend on threads).
        if (members.size () > best.size ())
        {
          best = std::move (members);
          best_plane = plane;
        }
      }
      if (best.size () < eps)
        break;
      {
        // Trimmed to kRefitTrimSigmas of their own robust σ: samples of a neighbouring face inside
        // the reach, all on one side of the plane at its rim, would curl its quadric.
        std::vector<double> d;
        for (const auto i : best)
          d.push_back (distance (points, i, best_plane.center, best_plane.normal));
        std::vector<double> scratch = d;
        const double bound = kRefitTrimSigmas * kMadScale * medianInPlace (scratch);
        std::vector<std::uint32_t> kept;
        for (std::size_t t = 0; t < best.size (); ++t)
          if (d[t] <= bound)
            kept.push_back (best[t]);
        Plane core;
        if (!fitPlane (points, kept, core))
          break; // fewer than three, or collinear: no plane
        // ε is asked of the plane's support, not of its trimmed core: a 2.5 σ trim takes 1.2 % of a
        // plane's Gaussian noise, which the last assignment gives back. Asked of the core, a face of
        // ε to 1.02 ε samples was never kept (room layout 6: the cabinet's top, 208 samples, ε = 200,
        // 205 open of which 6 trimmed). The support: the members within kPositionBandSigmas of the
        // core's own robust σ of its plane.
        std::vector<double> dc;
        dc.reserve (kept.size ());
        for (const auto i : kept)
          dc.push_back (distance (points, i, core.center, core.normal));
        const double core_band = kPositionBandSigmas * kMadScale * medianInPlace (dc);
        std::size_t support = 0;
        for (const auto i : best)
          if (distance (points, i, core.center, core.normal) <= core_band)
            ++support;
        best = std::move (kept);
        best_plane = core;
        if (support < eps)
          break;
      }

      PlanarPatch plane;
      plane.members = best;
      plane.first_index = best.front ();
      plane.center = best_plane.center;
      plane.normal = best_plane.normal;
      std::vector<double> d, phi;
      d.reserve (best.size ());
      phi.reserve (best.size ());
      for (const auto i : best)
      {
        d.push_back (distance (points, i, plane.center, plane.normal));
        phi.push_back (std::acos (std::min (1.0, std::abs (points.normals[i].cast<double> ().dot (plane.normal)))));
      }
      const RobustSpread ds = robustSpreadInPlace (d);
      const RobustSpread ps = robustSpreadInPlace (phi);
      plane.mdp = ds.median + params.alpha * ds.mad;
      plane.mnd = ps.median + std::max (params.alpha * ps.mad, params.normal_deviation_floor);
      plane.cos_mnd = std::cos (plane.mnd);
      plane.estimate_size = best.size ();
      plane.grown = true;

      // No noisier than the noisiest plane found (within the error of its own σ), flat within
      // chance, no tube, no layer of a plane found and no strip that lies on a neighbouring plane.
      const double sigma = kMadScale * ds.median;
      const double bound = robustSigmaBound (level, best.size (), kNoiseBoundErrors);
      const PlaneCurvature c = measureCurvature (points, best);
      const auto withinChance = [&] (const PlaneCurvature& q) {
        return q.samples == 0 || q.share < chanceBendShare (q.samples, params.curved_turn_confidence);
      };
      bool flat = withinChance (c);
      if (!flat && params.position_bend_band)
      {
        // Band samples (DetectorParameters::position_bend_band): judged again with the samples
        // beside the members, within the trimmed band and facing the plane, that no plane holds
        // but the pass left out as lying in a neighbouring plane's band.
        ++visit; // seen[i] == visit: i is in the set judged
        std::vector<std::uint32_t> wide = best;
        for (const auto i : best)
          seen[i] = visit;
        const double trim = kRefitTrimSigmas * kMadScale * ds.median;
        for (const auto i : best)
          graph.forEachNeighbor (i, [&] (std::uint32_t j) {
            if (seen[j] == visit || labels[j] != kNoPatch || free[j] ||
                distance (points, j, plane.center, plane.normal) > trim ||
                std::abs (points.normals[j].cast<double> ().dot (plane.normal)) < kSameFaceCos)
              return;
            seen[j] = visit;
            wide.push_back (j);
          });
        flat = withinChance (measureCurvature (points, wide));
      }
      if (!flat && params.position_bend_slabs)
      {
        // Neighbours' slabs (DetectorParameters::position_bend_slabs): judged again without the
        // members in the band of a plane found beside them that crosses the face. There, which of
        // a rough face's rim samples the pass left out depended on their offsets from the face (one
        // below it, nearer that plane's members, has one among its neighbours more often), so the
        // rim members kept stand out of the face; outside the slabs, no offset decided. A parallel
        // plane's slab would hold the face itself: not used.
        ++visit; // seen[j] == visit: a left-out sample whose neighbours' planes were noted
        std::vector<std::uint32_t> beside;
        const auto note = [&] (std::uint32_t l) {
          if (l != kNoPatch && std::find (beside.begin (), beside.end (), l) == beside.end () &&
              std::abs (patches[l].normal.dot (plane.normal)) < kSameFaceCos)
            beside.push_back (l);
        };
        for (const auto i : best)
          graph.forEachNeighbor (i, [&] (std::uint32_t j) {
            note (labels[j]);
            if (labels[j] == kNoPatch && !free[j] && seen[j] != visit)
            {
              seen[j] = visit; // left out: in the band of a plane one of its neighbours holds
              graph.forEachNeighbor (j, [&] (std::uint32_t m) { note (labels[m]); });
            }
          });
        std::vector<std::uint32_t> outside;
        for (const auto i : best)
          if (std::none_of (beside.begin (), beside.end (), [&] (std::uint32_t l) {
                return distance (points, i, patches[l].center, patches[l].normal) <= band[l];
              }))
            outside.push_back (i);
        if (outside.size () < best.size ())
          flat = withinChance (measureCurvature (points, outside));
      }
      const bool bent = !flat || (c.samples > 0 && isTube (c, plane.mdp));
      // On a ladder's step, a plane holds more than k samples: with fewer, no member's neighbourhood
      // lies in it, and the rough surface it claims to be is read from neighbourhoods of others (the
      // box corner in the paper's assignment mode: 24 samples of the bands along its edges, tilted
      // 20° from both faces, as noisy as a step above the planes found allows).
      const bool too_small_for_step = level > noise && best.size () <= static_cast<std::size_t> (graph.k ());
      const bool quiet = sigma <= bound;
      std::uint32_t on = kNoPatch; // the plane beside it that it lies on, if that turned it down
      // The other tests, read once, and for a noisy plane only where a rung may climb to it.
      const bool sound = (quiet || (params.position_ladder_rungs && go_on)) && !bent && !too_small_for_step &&
                         (!go_on || insideASurface (graph, best)) &&
                         !isBandLayer (points, graph, params, patches, band, labels, plane) &&
                         !liesOnNeighbourPlane (points, graph, patches, labels, plane, &on);
      if (!quiet && sound)
        quietest_noise_reject = std::min (quietest_noise_reject, sigma); // turned down for its noise alone
      if (!quiet || !sound)
      {
        turned_down = true;
        if (on != kNoPatch && params.position_join_beside)
        {
          // It lies on that plane: those of its members within that plane's band are its samples,
          // which no graph path from its members reached (a disc of a scanner's rings below its
          // head is the floor's, under the sensor, not a hole in it).
          for (const auto i : best)
            if (distance (points, i, patches[on].center, patches[on].normal) <= band[on])
            {
              labels[i] = on;
              patches[on].members.push_back (i);
            }
        }
        // A surface that bends is a curved one: the planes cut from it next would be its facets.
        if (!go_on || bent)
          break;
        for (const auto i : best)
          stamp[i] = 0;
      }
      else
      {
        const auto label = static_cast<std::uint32_t> (patches.size ());
        for (const auto i : best)
        {
          labels[i] = label;
          stamp[i] = 0;
        }
        noisiest_kept = std::max (noisiest_kept, sigma);
        band.push_back (plane.mdp);
        patches.push_back (std::move (plane));
      }
      std::vector<std::uint32_t> rest;
      rest.reserve (open.size () - best.size ());
      std::set_difference (open.begin (), open.end (), best.begin (), best.end (), std::back_inserter (rest));
      open = std::move (rest);
    }
    for (const auto i : open)
      stamp[i] = 0;
    if (!turned_down)
      open.clear ();
    return open;
  };
  std::vector<std::uint32_t> left;
  for (const auto& p : parts)
  {
    std::vector<std::uint32_t> rest = searchPart (p, false);
    left.insert (left.end (), rest.begin (), rest.end ());
  }
  if (!params.position_surface_parts || left.empty ())
    return patches.size () - before;
  // What the parts left at a plane turned down still hold on a surface, searched again: outliers
  // join a scene's free samples into one part, whose best plane is a slab of them.
  local.resize (n);
  {
    LocalScratch scratch;
    for (const auto i : left)
      local[i] = localSurface (points, graph, i, scratch);
  }
  double base = noise; // the noise the ladder's next step doubles
  for (int step = 0;; ++step)
  {
    if (step > 0)
    {
      // A step of the noise ladder (as the small-plane pass's noisy seeds climb theirs): planes up
      // to noisy_group_ratio times the noisiest plane kept, among what is still left.
      base = std::max (base, noisiest_kept);
      level = params.noisy_group_ratio * base;
      reach = kPositionBandSigmas * level;
    }
    noisiest_kept = 0.0;
    quietest_noise_reject = HUGE_VAL;
    std::vector<char> surface (n, 0);
    for (const auto i : left)
      surface[i] = labels[i] == kNoPatch && local[i].median <= std::min (reach, kSurfaceRadiusShare * local[i].radius);
    for (const auto& p : partsOf (graph, surface, eps))
      searchPart (p, true);
    // The first step is always tried; the next only once a step kept a plane noisier than the last,
    // or (position_ladder_rungs) turned one down for its noise alone within the next step: a rough
    // face that no plane found anchors, which that step then keeps.
    const bool rung = params.position_ladder_rungs && step > 0 && !(noisiest_kept > base) &&
                      quietest_noise_reject <= params.noisy_group_ratio * level;
    if (!params.position_surface_ladder || (step > 0 && !(noisiest_kept > base) && !rung))
      break;
    if (rung)
      base = level;
  }
  return patches.size () - before;
}

} // namespace rspd
} // namespace pcl
