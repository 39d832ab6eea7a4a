/*
 * pcl_rspd: the frame the method works in, found from the normals.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/dominant_frame.h>
#include <pcl_rspd/normal_estimation.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pcl
{
namespace rspd
{
namespace
{
/** Normals within this angle of a direction vote for it and move it in the mean shift: wide
  * enough to gather a noisy wall's normals, narrow enough to keep perpendicular walls apart. */
const double kCos = std::cos (15.0 * M_PI / 180.0);
const double kSin = std::sin (15.0 * M_PI / 180.0);
constexpr std::size_t kVoters = 16384;
constexpr std::size_t kCandidates = 256;

/** Mean shift of \a axis over all normals within 15° of it (signs aligned to it), kept
  * perpendicular to \a ortho when given. */
Eigen::Vector3d
shiftToMode (const std::vector<Eigen::Vector3f>& normals, Eigen::Vector3d axis, const Eigen::Vector3d* ortho)
{
  for (int iteration = 0; iteration < 8; ++iteration)
  {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
    for (const auto& nf : normals)
    {
      const Eigen::Vector3d n = nf.cast<double> ();
      const double c = n.dot (axis);
      if (std::abs (c) >= kCos)
        sum += c < 0 ? -n : n;
    }
    if (ortho)
      sum -= sum.dot (*ortho) * *ortho;
    if (!(sum.norm () > 0))
      break;
    const Eigen::Vector3d next = sum.normalized ();
    const bool settled = next.dot (axis) > 1.0 - 1e-14;
    axis = next;
    if (settled)
      break;
  }
  return axis;
}
} // namespace

Eigen::Matrix3d
dominantFrame (const PointSet& points)
{
  const std::size_t n = points.size ();
  if (n == 0)
    return Eigen::Matrix3d::Identity ();
  const auto strided = [&] (std::size_t count) {
    std::vector<Eigen::Vector3d> out;
    const std::size_t step = std::max<std::size_t> (1, n / count);
    for (std::size_t i = 0; i < n && out.size () < count; i += step)
      out.push_back (points.normals[i].cast<double> ());
    return out;
  };
  const std::vector<Eigen::Vector3d> voters = strided (kVoters);
  const std::vector<Eigen::Vector3d> candidates = strided (kCandidates);
  // The candidate with most votes (the first on ties) among those admit() accepts.
  const auto best = [&] (auto admit, Eigen::Vector3d& out) {
    std::size_t best_votes = 0;
    for (const auto& c : candidates)
    {
      if (!admit (c))
        continue;
      std::size_t votes = 0;
      for (const auto& v : voters)
        votes += std::abs (v.dot (c)) >= kCos;
      if (votes > best_votes)
      {
        best_votes = votes;
        out = c;
      }
    }
    return best_votes > 0;
  };

  Eigen::Vector3d first = Eigen::Vector3d::UnitZ ();
  best ([] (const Eigen::Vector3d&) { return true; }, first);
  first = shiftToMode (points.normals, first.normalized (), nullptr);

  Eigen::Vector3d second;
  if (best ([&] (const Eigen::Vector3d& c) { return std::abs (c.dot (first)) <= kSin; }, second))
    second = shiftToMode (points.normals, (second - second.dot (first) * first).normalized (), &first);
  else
  {
    // No normal is perpendicular to the first axis (one plane family, or curved surfaces only):
    // the points' main direction in the plane perpendicular to it.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
    for (const auto& p : points.points)
      mean += p.cast<double> ();
    mean /= static_cast<double> (n);
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero ();
    for (const auto& p : points.points)
    {
      Eigen::Vector3d d = p.cast<double> () - mean;
      d -= d.dot (first) * first;
      cov += d * d.transpose ();
    }
    second = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (cov).eigenvectors ().col (2);
    second -= second.dot (first) * first;
    second = second.norm () > 1e-9 ? second.normalized () : first.unitOrthogonal ();
  }
  Eigen::Matrix3d rotation;
  rotation.row (0) = first.transpose ();
  rotation.row (1) = second.transpose ();
  rotation.row (2) = first.cross (second).normalized ().transpose ();
  return rotation;
}

void
rotateSamples (PointSet& points, const Eigen::Matrix3d& rotation, int num_threads)
{
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (points.size ());
  const bool with_normals = points.normals.size () == points.points.size ();
#pragma omp parallel for num_threads(resolveThreads (num_threads))
  for (std::ptrdiff_t i = 0; i < n; ++i)
  {
    points.points[i] = (rotation * points.points[i].cast<double> ()).cast<float> ();
    if (with_normals)
      points.normals[i] = (rotation * points.normals[i].cast<double> ()).normalized ().cast<float> ();
  }
}

} // namespace rspd
} // namespace pcl
