/*
 * pcl_rspd tests: small builders shared by the unit tests.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/neighbor_graph.h>
#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/plane_detector.h>
#include <pcl_rspd/point_set.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace rspd_test
{
/** Exact k-NN graph by brute force (reference for small sets; ties by index). */
inline pcl::rspd::NeighborGraph
bruteForceGraph (const std::vector<Eigen::Vector3f>& pts, int k)
{
  pcl::rspd::NeighborTable g (pts.size (), k);
  std::vector<std::pair<float, std::uint32_t>> d (pts.size ());
  for (std::size_t i = 0; i < pts.size (); ++i)
  {
    for (std::size_t j = 0; j < pts.size (); ++j)
      d[j] = {j == i ? INFINITY : (pts[i] - pts[j]).squaredNorm (), static_cast<std::uint32_t> (j)};
    std::partial_sort (d.begin (), d.begin () + k, d.end ());
    for (int j = 0; j < k; ++j)
      g.row (i)[j] = d[j].second;
  }
  return pcl::rspd::NeighborGraph::fromTable (g);
}

/** Append a grid-sampled rectangle to \a set: origin o, edge vectors a and b, nu x nv samples,
  * exact normal a x b, optional Gaussian noise along the normal. Returns the indices added. */
inline std::vector<std::uint32_t>
addRectangle (pcl::rspd::PointSet& set, const Eigen::Vector3f& o, const Eigen::Vector3f& a, const Eigen::Vector3f& b,
              int nu, int nv, float noise = 0.0f, std::uint32_t seed = 1)
{
  std::mt19937 rng (seed);
  std::normal_distribution<float> g (0.0f, 1.0f);
  const Eigen::Vector3f n = a.cross (b).normalized ();
  std::vector<std::uint32_t> added;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
    {
      const float s = (i + 0.5f) / nu, t = (j + 0.5f) / nv;
      added.push_back (static_cast<std::uint32_t> (set.points.size ()));
      set.points.push_back (o + s * a + t * b + (noise > 0 ? noise * g (rng) : 0.0f) * n);
      set.normals.push_back (n);
      set.input_indices.push_back (static_cast<pcl::index_t> (set.input_indices.size ()));
    }
  return added;
}
/** A patch with the given members, plane (c, n) and interval half-widths (MDP and MND around a
  * zero median). */
inline pcl::rspd::PlanarPatch
makePatch (const std::vector<std::uint32_t>& members, const Eigen::Vector3d& c, const Eigen::Vector3d& n,
           double mdp, double mnd)
{
  pcl::rspd::PlanarPatch p;
  p.members = members;
  p.first_index = *std::min_element (members.begin (), members.end ());
  pcl::rspd::PlaneEstimate e;
  e.center = c;
  e.normal = n;
  e.distance_halfwidth = mdp;
  e.angle_halfwidth = mnd;
  p.setEstimate (e);
  return p;
}

/** Detector parameters of the phase tests: ε = 50 samples, \a threads OpenMP threads. */
inline pcl::rspd::DetectorParameters
unitParameters (int threads = 1)
{
  pcl::rspd::DetectorParameters p;
  p.min_patch_size = 50;
  p.num_threads = threads;
  return p;
}

/** One patch holding samples 0..n-1: plane z = 0 through the origin, MDP \a mdp, MND \a mnd. */
inline std::vector<pcl::rspd::PlanarPatch>
onePatchOfAll (std::size_t n, double mdp, double mnd)
{
  std::vector<std::uint32_t> all (n);
  for (std::uint32_t i = 0; i < n; ++i)
    all[i] = i;
  return {makePatch (all, {0, 0, 0}, {0, 0, 1}, mdp, mnd)};
}
} // namespace rspd_test
