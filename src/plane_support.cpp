/*
 * pcl_rspd: plane support (departure), see plane_support.h.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/normal_estimation.h> // resolveThreads
#include <pcl_rspd/patch_growth.h>      // kNoPatch, labelSamples
#include <pcl_rspd/plane_support.h>
#include <pcl_rspd/robust_statistics.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl
{
namespace rspd
{
std::size_t
releaseUnsupportedMembers (const PointSet& points, const NeighborGraph& graph, const std::vector<double>& band,
                           int num_threads, std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels)
{
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (labels.size ());
  const int threads = resolveThreads (num_threads);
  constexpr float kNone = std::numeric_limits<float>::infinity ();

  // Pass 1: each member's in-plane gap to its plane's nearest other sample among its neighbours
  // (infinite when it has none; 0 when one coincides with it or lies on its normal line), and
  // whether it is a candidate: one-sided and within no other plane's band.
  std::vector<float> gap (labels.size (), kNone);
  std::vector<std::uint8_t> candidate (labels.size (), 0);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii)
  {
    const std::uint32_t i = static_cast<std::uint32_t> (ii);
    const std::uint32_t l = labels[i];
    if (l == kNoPatch)
      continue;
    const Eigen::Vector3d& normal = patches[l].normal;
    const Eigen::Vector3d p = points.points[i].cast<double> ();
    double nearest = HUGE_VAL;
    Eigen::Vector3d directions = Eigen::Vector3d::Zero ();
    int directed = 0;
    bool near_other = false;
    graph.forEachNeighbor (i, [&] (std::uint32_t m) {
      const std::uint32_t o = labels[m];
      if (o == kNoPatch)
        return;
      if (o != l)
      {
        near_other = near_other || std::abs ((p - patches[o].center).dot (patches[o].normal)) <= band[o];
        return;
      }
      const Eigen::Vector3d q = points.points[m].cast<double> () - p;
      const Eigen::Vector3d t = q - q.dot (normal) * normal;
      const double length = t.norm ();
      nearest = std::min (nearest, length);
      if (length > 0.0)
      {
        directions += t / length;
        ++directed;
      }
    });
    gap[i] = static_cast<float> (nearest);
    const double resultant = directed > 0 ? directions.norm () / directed : 1.0;
    candidate[i] = !near_other && resultant > kOneSidedResultant;
  }

  // Pass 2: a candidate whose gap is far beyond its neighbours' gaps, or with too few neighbours in
  // its plane to tell, is released.
  std::vector<std::uint8_t> release (labels.size (), 0);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii)
  {
    const std::uint32_t i = static_cast<std::uint32_t> (ii);
    if (!candidate[i])
      continue;
    if (std::isinf (gap[i]))
    {
      release[i] = 1; // no neighbour in its own plane
      continue;
    }
    std::vector<float> gaps;
    std::size_t neighbours = 0;
    graph.forEachNeighbor (i, [&] (std::uint32_t m) {
      ++neighbours;
      if (labels[m] == labels[i] && std::isfinite (gap[m]))
        gaps.push_back (gap[m]);
    });
    if (static_cast<double> (gaps.size ()) < kMinSupportShare * static_cast<double> (neighbours))
    {
      release[i] = 1;
      continue;
    }
    const double typical = medianInPlace (gaps);
    release[i] = typical > 0.0 && static_cast<double> (gap[i]) > kSupportGapRatio * typical;
  }

  std::size_t released = 0;
  for (auto& patch : patches)
  {
    const auto end = std::remove_if (patch.members.begin (), patch.members.end (),
                                     [&] (std::uint32_t i) { return release[i] != 0; });
    released += static_cast<std::size_t> (patch.members.end () - end);
    patch.members.erase (end, patch.members.end ());
  }
  if (released > 0)
  {
    patches.erase (std::remove_if (patches.begin (), patches.end (),
                                   [] (const PlanarPatch& p) { return p.members.empty (); }),
                   patches.end ());
    labels = labelSamples (labels.size (), patches);
  }
  return released;
}

} // namespace rspd
} // namespace pcl
