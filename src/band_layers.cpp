/*
 * pcl_rspd: band layers (see band_layers.h).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/band_layers.h>
#include <pcl_rspd/bent_planes.h>      // bentAtAnEdge
#include <pcl_rspd/normal_estimation.h> // resolveThreads
#include <pcl_rspd/patch_growth.h>      // kNoPatch
#include <pcl_rspd/patch_merge.h>       // normalsCompatible
#include <pcl_rspd/plane_refit.h>       // leastSquaresPlane
#include <pcl_rspd/robust_statistics.h> // medianInPlace, kMadScale
#include <pcl_rspd/volume_layers.h>     // countLayerSamples, isInBandLayer

#include <Eigen/Geometry> // cross, AlignedBox

#include <algorithm>
#include <cmath>

namespace pcl
{
namespace rspd
{
namespace
{
/** Robust σ (kMadScale median |d|) of the distances of \a samples to the plane (center, normal). */
double
robustSigmaAbout (const PointSet& points, const std::vector<std::uint32_t>& samples, const Eigen::Vector3d& center,
                  const Eigen::Vector3d& normal)
{
  std::vector<double> d;
  d.reserve (samples.size ());
  for (const auto i : samples)
    d.push_back (std::abs ((points.points[i].cast<double> () - center).dot (normal)));
  return kMadScale * medianInPlace (d);
}

/** A plane is a step off the plane it would join, not a layer of its band, when the surface under its
  * members lies off their joint plane by more than this many robust σ of that plane's distances (at
  * the median member). The step split's measure and bound (step_split.cpp): a neighbourhood's mean
  * distance scatters by σ/√k, and two interleaved layers of one face average to the face. */
constexpr double kLayerStepSigmas = 0.5;

/** Whether plane \a a (members \a pa) lies a step off plane \a b (\a pb) rather than among its
  * samples as a layer of one face: each of A's members is given the mean signed distance, to the
  * least-squares plane of A's and B's members together, of its graph neighbours held by A or B
  * (itself with them); the median of those means is compared with the joint plane's robust σ.
  *
  * Two layers of one noisy face hold its samples between them, interleaved: a neighbourhood of
  * either averages to the face, and the face is their joint plane. A recessed window whose band
  * overlaps its wall's (a facade at σ = 4 cm, windows 10 cm deep: the wall holds 5-15 % of each
  * window's samples, so every window member has a neighbour held by the wall) has neighbourhoods of
  * window samples, which average to the window, about 2 robust σ off the joint plane, most of which
  * is wall (1.9-2.2 on that facade; 0.57-0.66 for a door 2 cm proud of its wall at σ 2.5 cm). */
bool
isStepOff (const PointSet& points, const NeighborGraph& graph, const std::vector<std::uint32_t>& labels,
           std::uint32_t a, const PlanarPatch& pa, std::uint32_t b, const PlanarPatch& pb)
{
  std::vector<std::uint32_t> both;
  both.reserve (pa.members.size () + pb.members.size ());
  both.insert (both.end (), pa.members.begin (), pa.members.end ());
  both.insert (both.end (), pb.members.begin (), pb.members.end ());
  Eigen::Vector3d center, normal;
  if (!leastSquaresPlane (points, both, {}, pb.center, center, normal))
    return false;
  const double sigma = robustSigmaAbout (points, both, center, normal);
  const auto offset = [&] (std::uint32_t i) { return (points.points[i].cast<double> () - center).dot (normal); };
  std::vector<double> d;
  d.reserve (pa.members.size ());
  for (const auto i : pa.members)
  {
    double sum = offset (i);
    std::size_t count = 1;
    graph.forEachNeighbor (i, [&] (std::uint32_t j) {
      if (labels[j] == a || labels[j] == b)
      {
        sum += offset (j);
        ++count;
      }
    });
    d.push_back (sum / static_cast<double> (count));
  }
  return std::abs (medianInPlace (d)) > kLayerStepSigmas * sigma;
}
} // namespace

bool
isBandLayer (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
             const std::vector<PlanarPatch>& patches, const std::vector<double>& band,
             const std::vector<std::uint32_t>& labels, const PlanarPatch& seed, bool* beside)
{
  if (beside)
    *beside = false;
  if (seed.members.empty ())
    return false;
  // Per plane, whether the seed is a face beside it (see the header); judged once, and only for a
  // plane whose band holds a member (-1: not judged yet).
  std::vector<signed char> beside_plane (patches.size (), -1);
  double own_sigma = -1.0;
  const auto faceBeside = [&] (std::uint32_t o) {
    if (beside_plane[o] < 0)
    {
      const PlanarPatch& plane = patches[o];
      const double angle = std::acos (std::min (1.0, std::abs (plane.normal.dot (seed.normal))));
      beside_plane[o] = 0;
      if (angle > 0.5 * M_PI - params.min_distance_angle)
      {
        if (own_sigma < 0.0)
          own_sigma = robustSigmaAbout (points, seed.members, seed.center, seed.normal);
        const bool bends_away =
            own_sigma <= params.bent_sigma_ratio * robustSigmaAbout (points, seed.members, plane.center, plane.normal);
        beside_plane[o] = bends_away && bentAtAnEdge (points, plane.members, params);
      }
    }
    return beside_plane[o] != 0;
  };
  std::size_t inside = 0, inside_any = 0; // in the band of a plane the seed is no face beside; of any
  for (const auto i : seed.members)
  {
    const Eigen::Vector3d p = points.points[i].cast<double> ();
    bool in = false, in_any = false;
    graph.forEachNeighbor (i, [&] (std::uint32_t m) {
      const std::uint32_t o = labels[m];
      if (in || o == kNoPatch || std::abs ((p - patches[o].center).dot (patches[o].normal)) > band[o])
        return;
      in_any = true;
      in = !faceBeside (o);
    });
    inside += in;
    inside_any += in_any;
  }
  const bool layer = 2 * inside > seed.members.size ();
  if (beside)
    *beside = !layer && 2 * inside_any > seed.members.size ();
  return layer;
}

bool
liesOnNeighbourPlane (const PointSet& points, const NeighborGraph& graph, const std::vector<PlanarPatch>& patches,
                      const std::vector<std::uint32_t>& labels, const PlanarPatch& candidate, std::uint32_t* on)
{
  if (candidate.members.empty ())
    return false;
  std::vector<std::uint32_t> beside;
  for (const auto i : candidate.members)
    graph.forEachNeighbor (i, [&] (std::uint32_t j) {
      if (labels[j] != kNoPatch)
        beside.push_back (labels[j]);
    });
  if (beside.empty ())
  {
    // No member has a neighbour a plane holds: the candidate is closed under the graph, each
    // member's neighbourhood within the members (a scanner's rings below or above its head,
    // thousands of samples within centimetres whose nearest neighbours are each other). The samples
    // around it still count members among their nearest: the edges into it are read instead, from
    // the labelled samples within its bounding box widened by the box's own size on each side (a
    // scan of the cloud's coordinates; a closed candidate is rare, read only then).
    Eigen::AlignedBox3f box;
    for (const auto i : candidate.members)
      box.extend (points.points[i]);
    const Eigen::Vector3f reach = box.sizes ();
    box.min () -= reach;
    box.max () += reach;
    std::vector<std::uint32_t> sorted (candidate.members);
    std::sort (sorted.begin (), sorted.end ());
    for (std::size_t j = 0; j < points.size (); ++j)
      if (labels[j] != kNoPatch && box.contains (points.points[j]))
      {
        bool into = false;
        graph.forEachNeighbor (j, [&] (std::uint32_t m) {
          into = into || std::binary_search (sorted.begin (), sorted.end (), m);
        });
        if (into)
          beside.push_back (labels[j]);
      }
  }
  std::sort (beside.begin (), beside.end ());
  beside.erase (std::unique (beside.begin (), beside.end ()), beside.end ());
  if (beside.empty ())
    return false;
  // Within twice the standard error of the members' own robust σ.
  const double own = robustSigmaBound (robustSigmaAbout (points, candidate.members, candidate.center, candidate.normal),
                                       candidate.members.size (), 2.0);
  for (const auto o : beside)
    if (robustSigmaAbout (points, candidate.members, patches[o].center, patches[o].normal) <= own)
    {
      if (on)
        *on = o;
      return true;
    }
  return false;
}

std::size_t
mergeBandLayers (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                 const std::vector<double>& band, std::vector<PlanarPatch>& patches,
                 const std::vector<std::uint32_t>& labels)
{
  const std::size_t count = patches.size ();
  if (count < 2)
    return 0;
  const auto larger = [&] (std::size_t b, std::size_t a) {
    const std::size_t nb = patches[b].members.size (), na = patches[a].members.size ();
    return nb > na || (nb == na && patches[b].first_index < patches[a].first_index);
  };
  // Per plane, the larger plane it is a layer of (kNoPatch: none); each plane reads only the labels
  // and planes as they were, so the result does not depend on the thread count.
  std::vector<std::uint32_t> into (count, kNoPatch);
#pragma omp parallel num_threads(resolveThreads (params.num_threads))
  {
    std::vector<std::uint32_t> touching (count, 0), last (count, kNoPatch), seen, candidates;
    std::vector<char> candidate (count, 0);
    std::vector<double> d;
#pragma omp for schedule(dynamic, 1)
    for (std::ptrdiff_t ai = 0; ai < static_cast<std::ptrdiff_t> (count); ++ai)
    {
      const auto a = static_cast<std::size_t> (ai);
      const PlanarPatch& pa = patches[a];
      if (pa.members.empty ())
        continue;
      // The planes A may be a layer of: larger, with compatible normals. Touches of the others are
      // not counted (the largest plane, and faces at an angle, read no row at all: the 1M cube
      // 0.12 -> 0.03 s a pass, labels the same).
      candidates.clear ();
      for (std::size_t b = 0; b < count; ++b)
        if (b != a && !patches[b].members.empty () && larger (b, a) && normalsCompatible (pa, patches[b]))
        {
          candidate[b] = 1;
          candidates.push_back (static_cast<std::uint32_t> (b));
        }
      if (candidates.empty ())
        continue;
      // How many of A's members have a neighbour in each candidate (each member counted once); the
      // count stops once more than half of A has touched none, as no plane can then hold half of it.
      seen.clear ();
      const std::size_t m = pa.members.size ();
      std::size_t untouched = 0;
      for (const auto i : pa.members)
      {
        bool touches = false;
        graph.forEachNeighbor (i, [&] (std::uint32_t j) {
          const std::uint32_t l = labels[j];
          if (l == kNoPatch || !candidate[l])
            return;
          touches = true;
          if (last[l] == i)
            return;
          if (touching[l]++ == 0)
            seen.push_back (l);
          last[l] = i;
        });
        untouched += !touches;
        if (2 * untouched > m)
          break;
      }
      for (const auto b : candidates)
        candidate[b] = 0;
      if (2 * untouched > m)
      {
        for (const auto b : seen)
        {
          touching[b] = 0;
          last[b] = kNoPatch;
        }
        continue;
      }
      std::sort (seen.begin (), seen.end ());
      double best_share = 0.0;
      for (const auto b : seen)
      {
        const double share = static_cast<double> (touching[b]) / static_cast<double> (pa.members.size ());
        touching[b] = 0;
        last[b] = kNoPatch;
        const PlanarPatch& pb = patches[b];
        if (!(2.0 * share >= 1.0) || share <= best_share || !larger (b, a) || !normalsCompatible (pa, pb))
          continue;
        d.clear ();
        double reach = 0.0;
        for (const auto i : pa.members)
        {
          const Eigen::Vector3d p = points.points[i].cast<double> ();
          d.push_back (std::abs ((p - pb.center).dot (pb.normal)));
          const Eigen::Vector3d v = p - pa.center;
          reach = std::max (reach, (v - v.dot (pb.normal) * pb.normal).norm ());
        }
        const double tilt = pa.normal.cross (pb.normal).norm () * reach;
        if (medianInPlace (d) <= band[b] && tilt <= band[b] &&
            !(params.layer_steps && isStepOff (points, graph, labels, static_cast<std::uint32_t> (a), pa, b, pb)))
        {
          into[a] = b;
          best_share = share;
        }
      }
      // A layer inside a denser plane's band is a share of the clutter or noise around it: joined,
      // it would widen that plane's band into the clutter (DetectorParameters::in_band_layer_check).
      if (into[a] != kNoPatch && params.final_volume_layer_check && params.in_band_layer_check &&
          isInBandLayer (countLayerSamples (points, graph, pa, band[a], &labels, static_cast<std::uint32_t> (a)),
                         patches, band, a))
        into[a] = kNoPatch;
    }
  }
  std::size_t merged = 0;
  std::vector<char> grew (count, 0);
  for (std::size_t a = 0; a < count; ++a)
  {
    const std::uint32_t b = into[a];
    if (b == kNoPatch || into[b] != kNoPatch) // B is a layer itself: next pass
      continue;
    PlanarPatch& pb = patches[b];
    pb.members.insert (pb.members.end (), patches[a].members.begin (), patches[a].members.end ());
    patches[a].members.clear ();
    grew[b] = 1;
    ++merged;
  }
  for (std::size_t b = 0; b < count; ++b)
    if (grew[b])
    {
      PlanarPatch& pb = patches[b];
      std::sort (pb.members.begin (), pb.members.end ());
      pb.first_index = pb.members.front ();
      pb.grown = false;
      PlaneEstimate e;
      if (estimatePlane (points, pb.members, params, e))
        pb.setEstimate (e);
    }
  patches.erase (std::remove_if (patches.begin (), patches.end (), [] (const PlanarPatch& p) { return p.members.empty (); }),
                 patches.end ());
  return merged;
}

} // namespace rspd
} // namespace pcl
