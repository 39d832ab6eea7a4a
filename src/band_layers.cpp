/*
 * pcl_rspd: band layers (see band_layers.h).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/band_layers.h>
#include <pcl_rspd/bent_planes.h>      // bentAtAnEdge
#include <pcl_rspd/patch_growth.h>      // kNoPatch
#include <pcl_rspd/robust_statistics.h> // medianInPlace, kMadScale

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
                      const std::vector<std::uint32_t>& labels, const PlanarPatch& candidate)
{
  if (candidate.members.empty ())
    return false;
  std::vector<std::uint32_t> beside;
  for (const auto i : candidate.members)
    graph.forEachNeighbor (i, [&] (std::uint32_t j) {
      if (labels[j] != kNoPatch)
        beside.push_back (labels[j]);
    });
  std::sort (beside.begin (), beside.end ());
  beside.erase (std::unique (beside.begin (), beside.end ()), beside.end ());
  if (beside.empty ())
    return false;
  const double own = robustSigmaAbout (points, candidate.members, candidate.center, candidate.normal);
  for (const auto o : beside)
    if (robustSigmaAbout (points, candidate.members, patches[o].center, patches[o].normal) <= own)
      return true;
  return false;
}

} // namespace rspd
} // namespace pcl
