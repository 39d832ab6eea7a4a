/*
 * pcl_rspd: final refit (departure), see plane_refit.h.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/normal_estimation.h> // resolveThreads
#include <pcl_rspd/plane_refit.h>
#include <pcl_rspd/robust_statistics.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstddef>

namespace pcl
{
namespace rspd
{
bool
leastSquaresPlane (const PointSet& points, const std::vector<std::uint32_t>& members, const std::vector<char>& use,
                   const Eigen::Vector3d& origin, Eigen::Vector3d& center, Eigen::Vector3d& normal)
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
  std::size_t count = 0;
  for (std::size_t t = 0; t < members.size (); ++t)
    if (use.empty () || use[t])
    {
      sum += points.points[members[t]].cast<double> () - origin;
      ++count;
    }
  if (count < 3)
    return false;
  const Eigen::Vector3d mean = sum / static_cast<double> (count);
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero ();
  for (std::size_t t = 0; t < members.size (); ++t)
    if (use.empty () || use[t])
    {
      const Eigen::Vector3d d = points.points[members[t]].cast<double> () - origin - mean;
      scatter += d * d.transpose ();
    }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (scatter);
  if (solver.info () != Eigen::Success || !(solver.eigenvalues ()[1] > 0.0))
    return false; // coincident or collinear members span no plane
  center = origin + mean;
  normal = solver.eigenvectors ().col (0).normalized ();
  return true;
}

void
refitPlanes (const PointSet& points, int num_threads, std::vector<PlanarPatch>& patches)
{
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (patches.size ());
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolveThreads (num_threads))
  for (std::ptrdiff_t p = 0; p < count; ++p)
  {
    PlanarPatch& patch = patches[p];
    const std::vector<std::uint32_t>& members = patch.members;
    Eigen::Vector3d center, normal;
    if (!leastSquaresPlane (points, members, {}, patch.center, center, normal))
      continue;
    std::vector<char> use (members.size ());
    std::vector<double> distance (members.size ());
    for (int round = 0; round < kRefitRounds; ++round)
    {
      for (std::size_t t = 0; t < members.size (); ++t)
        distance[t] = std::abs ((points.points[members[t]].cast<double> () - center).dot (normal));
      std::vector<double> scratch = distance;
      const double bound = kRefitTrimSigmas * kMadScale * medianInPlace (scratch);
      for (std::size_t t = 0; t < members.size (); ++t)
        use[t] = distance[t] <= bound;
      Eigen::Vector3d c, n;
      if (!leastSquaresPlane (points, members, use, center, c, n))
        break;
      center = c;
      normal = n;
    }
    patch.center = center;
    patch.normal = normal.dot (patch.normal) < 0.0 ? Eigen::Vector3d (-normal) : normal;
  }
}

} // namespace rspd
} // namespace pcl
