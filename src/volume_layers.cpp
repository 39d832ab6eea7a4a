/*
 * pcl_rspd: volume layers (see volume_layers.h).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/normal_estimation.h>  // resolveThreads
#include <pcl_rspd/robust_statistics.h> // medianInPlace
#include <pcl_rspd/volume_layers.h>

#include <Eigen/Geometry> // cross, unitOrthogonal

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
/** A noisy seed's plane is a volume layer when the layer beside its band holds more than this many
  * times its samples. Samples of one volume, of which the plane holds a share s of its band's (those
  * whose cut neighbourhoods turn their normals across the end), give 1 / (2 s): the facade's slabs of
  * outliers 2.5-6.0 (four planes, three seeds with 25 % outliers at 100,000 points). A layer of one
  * noisy face gives about 1 wherever it lies in the face's noise: the boxes at σ 1 cm, faces at 10
  * and 15 cm held by planes with bands of 9-21 cm, 0.73-1.25 (at 1, one of them was dropped). */
constexpr double kVolumeLayerRatio = 2.0;

/** The footprint's cell is the median neighbourhood radius of at most about this many members, evenly
  * strided: a median of thousands is as good as one of all, and reading every member's row cost 0.1 s
  * on the 1M cube once every final plane is judged (DetectorParameters::final_volume_layer_check). */
constexpr std::size_t kRadiusSamples = 4096;
} // namespace

std::size_t
samplesBesideBand (const PointSet& points, const NeighborGraph& graph, const PlanarPatch& plane, double band)
{
  if (plane.members.empty () || !(band > 0.0) || !std::isfinite (band))
    return 0;
  // The footprint's cell: the members' median neighbourhood radius, so that a cell holds a few of
  // them wherever the plane is sampled, however sparsely (a scale of the cloud's own).
  const std::size_t stride = (plane.members.size () + kRadiusSamples - 1) / kRadiusSamples;
  std::vector<double> radii;
  radii.reserve (plane.members.size () / stride + 1);
  for (std::size_t m = 0; m < plane.members.size (); m += stride)
  {
    const std::uint32_t i = plane.members[m];
    const Eigen::Vector3d pi = points.points[i].cast<double> ();
    double r = 0.0;
    graph.forEachNeighbor (i, [&] (std::uint32_t j) { r = std::max (r, (points.points[j].cast<double> () - pi).norm ()); });
    radii.push_back (r);
  }
  const double cell = medianInPlace (radii);
  if (!(cell > 0.0) || !std::isfinite (cell))
    return 0;

  const Eigen::Vector3d u = plane.normal.unitOrthogonal ();
  const Eigen::Vector3d v = plane.normal.cross (u);
  using Cell = std::pair<std::int64_t, std::int64_t>;
  std::vector<Cell> footprint;
  footprint.reserve (plane.members.size ());
  double lo_u = HUGE_VAL, hi_u = -HUGE_VAL, lo_v = HUGE_VAL, hi_v = -HUGE_VAL;
  for (const auto i : plane.members)
  {
    const Eigen::Vector3d q = points.points[i].cast<double> () - plane.center;
    const double a = q.dot (u) / cell, b = q.dot (v) / cell;
    lo_u = std::min (lo_u, a);
    hi_u = std::max (hi_u, a);
    lo_v = std::min (lo_v, b);
    hi_v = std::max (hi_v, b);
    footprint.emplace_back (static_cast<std::int64_t> (std::floor (a)), static_cast<std::int64_t> (std::floor (b)));
  }
  std::sort (footprint.begin (), footprint.end ());
  footprint.erase (std::unique (footprint.begin (), footprint.end ()), footprint.end ());

  std::size_t above = 0, below = 0;
  for (std::size_t i = 0; i < points.size (); ++i)
  {
    const Eigen::Vector3d q = points.points[i].cast<double> () - plane.center;
    const double d = q.dot (plane.normal);
    if (!(std::abs (d) > band && std::abs (d) <= 2.0 * band))
      continue;
    const double a = q.dot (u) / cell, b = q.dot (v) / cell;
    if (!(a >= lo_u && a <= hi_u && b >= lo_v && b <= hi_v)) // outside the members' extent (and no overflow below)
      continue;
    const Cell c (static_cast<std::int64_t> (std::floor (a)), static_cast<std::int64_t> (std::floor (b)));
    if (std::binary_search (footprint.begin (), footprint.end (), c))
      ++(d > 0.0 ? above : below);
  }
  return std::max (above, below);
}

std::size_t
dropVolumeLayers (const PointSet& points, const NeighborGraph& graph, const std::vector<double>& band,
                  int num_threads, std::vector<PlanarPatch>& patches, bool every_plane)
{
  const std::size_t count = patches.size ();
  std::vector<char> drop (count, 0);
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolveThreads (num_threads))
  for (std::ptrdiff_t p = 0; p < static_cast<std::ptrdiff_t> (count); ++p)
  {
    const PlanarPatch& plane = patches[p];
    if (every_plane || plane.retested || plane.joined)
      drop[p] = static_cast<double> (samplesBesideBand (points, graph, plane, band[p])) >
                kVolumeLayerRatio * static_cast<double> (plane.members.size ());
  }
  std::size_t kept = 0;
  for (std::size_t p = 0; p < count; ++p)
  {
    if (drop[p])
      continue;
    if (kept != p)
      patches[kept] = std::move (patches[p]);
    ++kept;
  }
  patches.resize (kept);
  return count - kept;
}

} // namespace rspd
} // namespace pcl
