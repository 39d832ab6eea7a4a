/*
 * pcl_rspd: PCA normals over the growth graph's k-neighbourhoods.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/normal_estimation.h>

#include <pcl/common/eigen.h>

#include <omp.h>

#include <cmath>

namespace pcl
{
namespace rspd
{
int
resolveThreads (int requested)
{
  return requested > 0 ? requested : std::max (1, omp_get_max_threads ());
}

void
estimateNormals (const std::vector<Eigen::Vector3f>& points, const NeighborGraph& graph, int num_threads,
                 std::vector<Eigen::Vector3f>& normals)
{
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (points.size ());
  normals.assign (points.size (), Eigen::Vector3f::UnitZ ());
  const int k = graph.k ();
#pragma omp parallel for schedule(static, 4096) num_threads(resolveThreads (num_threads))
  for (std::ptrdiff_t i = 0; i < n; ++i)
  {
    // Covariance about the neighbourhood's mean, relative to the sample to keep precision.
    // The six distinct sums of the symmetric matrix as scalars: a full 3x3 update costs half again.
    const double ox = points[i].x (), oy = points[i].y (), oz = points[i].z ();
    double sx = 0.0, sy = 0.0, sz = 0.0, sxx = 0.0, sxy = 0.0, sxz = 0.0, syy = 0.0, syz = 0.0, szz = 0.0;
    graph.forEachNeighbor (static_cast<std::size_t> (i), [&] (std::uint32_t j) {
      const double dx = static_cast<double> (points[j].x ()) - ox;
      const double dy = static_cast<double> (points[j].y ()) - oy;
      const double dz = static_cast<double> (points[j].z ()) - oz;
      sx += dx;
      sy += dy;
      sz += dz;
      sxx += dx * dx;
      sxy += dx * dy;
      sxz += dx * dz;
      syy += dy * dy;
      syz += dy * dz;
      szz += dz * dz;
    });
    const double m = static_cast<double> (k + 1); // the sample itself contributes d = 0
    const Eigen::Vector3d mean (sx / m, sy / m, sz / m);
    Eigen::Matrix3d cov;
    cov << sxx / m, sxy / m, sxz / m, sxy / m, syy / m, syz / m, sxz / m, syz / m, szz / m;
    cov -= mean * mean.transpose ();
    if (!(cov.cwiseAbs ().maxCoeff () > 0.0))
      continue; // all coincide
    double eigen_value;
    Eigen::Vector3d eigen_vector;
    pcl::eigen33 (cov, eigen_value, eigen_vector);
    const double norm = eigen_vector.norm ();
    if (norm > 0.0 && std::isfinite (norm))
      normals[i] = (eigen_vector / norm).cast<float> ();
  }
}

} // namespace rspd
} // namespace pcl
