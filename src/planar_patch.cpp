/*
 * pcl_rspd: robust plane estimate and planarity test (Sec. 3.2, Eqs. 3-9).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/robust_statistics.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace pcl
{
namespace rspd
{
namespace
{
/** Component-wise median of a set of 3D vectors (Eqs. 3 and 4), using one scratch buffer. */
Eigen::Vector3d
componentMedian (const std::vector<Eigen::Vector3f>& vectors, const std::vector<std::uint32_t>& samples,
                 const std::vector<float>* signs, std::vector<float>& scratch)
{
  Eigen::Vector3d m;
  scratch.resize (samples.size ());
  for (int c = 0; c < 3; ++c)
  {
    for (std::size_t i = 0; i < samples.size (); ++i)
      scratch[i] = vectors[samples[i]][c] * (signs ? (*signs)[i] : 1.0f);
    m[c] = medianInPlace (scratch);
  }
  return m;
}

/** Extents of the samples along the two principal axes of their projection on the plane (w, l).
  * A 2D PCA in the plane rather than an axis-aligned box, so T1 does not depend on orientation. */
void
inPlaneExtent (const PointSet& points, const std::vector<std::uint32_t>& samples,
               const Eigen::Vector3d& center, const Eigen::Vector3d& normal, double& width, double& length)
{
  const Eigen::Vector3d u = normal.unitOrthogonal ();
  const Eigen::Vector3d v = normal.cross (u);
  Eigen::Vector2d mean = Eigen::Vector2d::Zero ();
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero ();
  for (const auto s : samples)
  {
    const Eigen::Vector3d p = points.points[s].cast<double> () - center;
    const Eigen::Vector2d q (p.dot (u), p.dot (v));
    mean += q;
    scatter += q * q.transpose ();
  }
  const double n = static_cast<double> (samples.size ());
  mean /= n;
  scatter = scatter / n - mean * mean.transpose ();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver (scatter);
  const Eigen::Vector2d a1 = solver.eigenvectors ().col (1);
  const Eigen::Vector2d a2 = solver.eigenvectors ().col (0);
  double lo1 = HUGE_VAL, hi1 = -HUGE_VAL, lo2 = HUGE_VAL, hi2 = -HUGE_VAL;
  for (const auto s : samples)
  {
    const Eigen::Vector3d p = points.points[s].cast<double> () - center;
    const Eigen::Vector2d q (p.dot (u), p.dot (v));
    const double t1 = q.dot (a1), t2 = q.dot (a2);
    lo1 = std::min (lo1, t1); hi1 = std::max (hi1, t1);
    lo2 = std::min (lo2, t2); hi2 = std::max (hi2, t2);
  }
  width = hi1 - lo1;
  length = hi2 - lo2;
}
} // namespace

void
PlanarPatch::setEstimate (const PlaneEstimate& estimate)
{
  center = estimate.center;
  normal = estimate.normal;
  mdp = estimate.mdp ();
  mnd = estimate.mnd ();
  cos_mnd = std::cos (std::min (mnd, M_PI / 2.0));
  estimate_size = members.size ();
  grown = false;
}

bool
estimatePlane (const PointSet& points, const std::vector<std::uint32_t>& samples,
               const DetectorParameters& params, PlaneEstimate& estimate)
{
  if (samples.empty ())
    return false;
  std::vector<float> scratch;
  estimate.center = componentMedian (points.points, samples, nullptr, scratch);

  // Eq. 4 on unoriented normals: a split of signs drags each component's median towards zero.
  // Flip every normal into the hemisphere of the dominant direction (principal eigenvector of
  // Σ nᵢnᵢᵀ, which is the same whatever the normals' signs or the frame) first.
  std::vector<float> signs;
  if (params.align_normals)
  {
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero ();
    for (const auto s : samples)
    {
      const Eigen::Vector3d n = points.normals[s].cast<double> ();
      scatter += n * n.transpose ();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (scatter);
    const Eigen::Vector3d dominant = solver.eigenvectors ().col (2);
    signs.resize (samples.size ());
    for (std::size_t i = 0; i < samples.size (); ++i)
      signs[i] = points.normals[samples[i]].cast<double> ().dot (dominant) < 0.0 ? -1.0f : 1.0f;
  }
  Eigen::Vector3d n = componentMedian (points.normals, samples, params.align_normals ? &signs : nullptr, scratch);
  const double norm = n.norm ();
  if (!(norm > 0.0) || !std::isfinite (norm))
    return false;
  estimate.normal = n / norm;

  inPlaneExtent (points, samples, estimate.center, estimate.normal, estimate.width, estimate.length);

  // D (Eq. 5) and Φ (Eq. 8), then median and MAD of each (Eqs. 6 and 9).
  std::vector<double> obs (samples.size ());
  for (std::size_t i = 0; i < samples.size (); ++i)
    obs[i] = std::abs ((points.points[samples[i]].cast<double> () - estimate.center).dot (estimate.normal));
  RobustSpread spread = robustSpreadInPlace (obs);
  estimate.distance_median = spread.median;
  // Zero spread (a noise-free plane has MAD = 0): the half-width has a floor relative to the
  // patch's extent, so exact samples stay inliers; 0 restores the paper's letter.
  const double extent = std::max (estimate.width, estimate.length);
  estimate.distance_halfwidth = std::max (params.alpha * spread.mad, params.distance_floor_ratio * extent);

  for (std::size_t i = 0; i < samples.size (); ++i)
  {
    const double c = std::abs (points.normals[samples[i]].cast<double> ().dot (estimate.normal));
    obs[i] = std::acos (std::min (1.0, c));
  }
  spread = robustSpreadInPlace (obs);
  estimate.angle_median = spread.median;
  estimate.angle_halfwidth = std::max (params.alpha * spread.mad, params.normal_deviation_floor);
  return true;
}

std::vector<std::uint32_t>
intervalInliers (const PointSet& points, const std::vector<std::uint32_t>& samples, const PlaneEstimate& e)
{
  // T3: a sample is an outlier when outside either two-sided interval (Eqs. 6 and 9).
  const double d_lo = e.distance_median - e.distance_halfwidth, d_hi = e.mdp ();
  const double a_lo = e.angle_median - e.angle_halfwidth, a_hi = e.mnd ();
  std::vector<std::uint32_t> inliers;
  inliers.reserve (samples.size ());
  for (const auto s : samples)
  {
    const double d = std::abs ((points.points[s].cast<double> () - e.center).dot (e.normal));
    const double a = std::acos (std::min (1.0, std::abs (points.normals[s].cast<double> ().dot (e.normal))));
    if (d >= d_lo && d <= d_hi && a >= a_lo && a <= a_hi)
      inliers.push_back (s);
  }
  return inliers;
}

PlanarityResult
robustPlanarityTest (const PointSet& points, const std::vector<std::uint32_t>& samples,
                     const DetectorParameters& params)
{
  PlanarityResult result;
  if (samples.size () < 3 || !estimatePlane (points, samples, params, result.estimate))
  {
    result.verdict = PlanarityVerdict::Degenerate;
    return result;
  }
  const PlaneEstimate& e = result.estimate;

  // T1: F = 0.5·max(w, l)·U + MDP·N with U ⟂ N, so angle(F, N) = atan2(0.5·max(w, l), MDP).
  result.distance_angle = std::atan2 (0.5 * std::max (e.width, e.length), e.mdp ());

  result.inliers = intervalInliers (points, samples, e);
  result.outlier_ratio = 1.0 - static_cast<double> (result.inliers.size ()) / static_cast<double> (samples.size ());

  if (!(result.distance_angle > params.min_distance_angle))
    result.verdict = PlanarityVerdict::FailedDistance;
  else if (!(e.mnd () < params.max_normal_deviation))
    result.verdict = PlanarityVerdict::FailedNormal;
  else if (!(result.outlier_ratio < params.max_outlier_ratio))
    result.verdict = PlanarityVerdict::TooManyOutliers;
  else if (result.inliers.size () < params.min_patch_size)
    result.verdict = PlanarityVerdict::TooSmall;
  else
    result.verdict = PlanarityVerdict::Planar;
  if (result.verdict != PlanarityVerdict::Planar)
    result.inliers.clear ();
  return result;
}

bool
setsShareAPlane (const PointSet& points, const DetectorParameters& params, const std::vector<std::uint32_t>& a,
                 const Eigen::Vector3d& a_center, const Eigen::Vector3d& a_normal, double a_mdp, double a_mnd,
                 const std::vector<std::uint32_t>& b, const Eigen::Vector3d& b_center, const Eigen::Vector3d& b_normal,
                 double b_mdp, double b_mnd)
{
  const auto within = [&] (const std::vector<std::uint32_t>& samples, const Eigen::Vector3d& center,
                           const Eigen::Vector3d& normal, double mdp) {
    std::size_t in = 0;
    for (const auto i : samples)
      in += std::abs ((points.points[i].cast<double> () - center).dot (normal)) <= mdp;
    return static_cast<double> (in) >= (1.0 - params.max_outlier_ratio) * static_cast<double> (samples.size ());
  };
  return std::abs (a_normal.dot (b_normal)) >= std::cos (std::max (a_mnd, b_mnd)) && within (a, b_center, b_normal, b_mdp) &&
         within (b, a_center, a_normal, a_mdp);
}

} // namespace rspd
} // namespace pcl
