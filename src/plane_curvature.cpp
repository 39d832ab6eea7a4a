/*
 * pcl_rspd: plane curvature (see plane_curvature.h).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/plane_curvature.h>

#include <boost/math/distributions/beta.hpp>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace pcl
{
namespace rspd
{
PlaneCurvature
measureCurvature (const PointSet& points, const std::vector<std::uint32_t>& members)
{
  PlaneCurvature c;
  if (members.size () < 12)
    return c;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
  for (const auto m : members)
    mean += points.points[m].cast<double> ();
  mean /= static_cast<double> (members.size ());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero ();
  for (const auto m : members)
  {
    const Eigen::Vector3d q = points.points[m].cast<double> () - mean;
    scatter += q * q.transpose ();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (scatter);
  const Eigen::Vector3d n = solver.eigenvectors ().col (0);
  const Eigen::Vector3d u = solver.eigenvectors ().col (2);
  const Eigen::Vector3d v = solver.eigenvectors ().col (1);
  // In-plane coordinates scaled to about unit range, so the normal equations are well conditioned.
  const double scale = std::sqrt (std::max (solver.eigenvalues () (2) / static_cast<double> (members.size ()), 1e-300));
  Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero ();
  Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero ();
  double rss_plane = 0.0;
  for (const auto m : members)
  {
    const Eigen::Vector3d q = points.points[m].cast<double> () - mean;
    const double x = q.dot (u) / scale, y = q.dot (v) / scale, w = q.dot (n);
    Eigen::Matrix<double, 6, 1> f;
    f << x * x, x * y, y * y, x, y, 1.0;
    a.selfadjointView<Eigen::Lower> ().rankUpdate (f);
    b += f * w;
    rss_plane += w * w;
  }
  if (!(rss_plane > 0.0))
    return c;
  a.triangularView<Eigen::StrictlyUpper> () = a.transpose ();
  // Rank-revealing: samples on a few scan lines leave the quadric terms undetermined.
  const Eigen::Matrix<double, 6, 1> coef = a.completeOrthogonalDecomposition ().solve (b);
  const double explained = coef.dot (b);
  if (!std::isfinite (explained))
    return c;
  c.share = std::min (1.0, std::max (0.0, explained / rss_plane));
  c.samples = members.size ();
  // Hessian of w(u, v) in the data's units: its largest curvature times the half extent along that
  // direction is the slope, hence the turn of the normal, from the middle of the patch to its rim.
  Eigen::Matrix2d h;
  h << 2.0 * coef (0), coef (1), coef (1), 2.0 * coef (2);
  h /= scale * scale;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> bend (h);
  const int k = std::abs (bend.eigenvalues () (0)) > std::abs (bend.eigenvalues () (1)) ? 0 : 1;
  const double kappa = std::abs (bend.eigenvalues () (k));
  const Eigen::Vector3d along = bend.eigenvectors () (0, k) * u + bend.eigenvectors () (1, k) * v;
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  std::vector<double> minor;
  minor.reserve (members.size ());
  for (const auto m : members)
  {
    const Eigen::Vector3d q = points.points[m].cast<double> () - mean;
    const double t = q.dot (along);
    lo = std::min (lo, t);
    hi = std::max (hi, t);
    minor.push_back (q.dot (v));
  }
  // The narrow side: its range, or the inner 95 % of the samples scaled back to a uniform strip's
  // full width (95 % of it lies within) where that is less. Why: a plane's band reaches beyond a
  // tube's end into the surface there; a pipe 15 cm across standing on the ground, 429 samples, held
  // 6 of the ground's, which stretched its narrow side's range from 0.15 to 0.39 m, and it passed as
  // no tube (isTube). Never more than the range: a tube's samples crowd at its sides, where the
  // scaled inner share would widen it by 5 %.
  const auto range = std::minmax_element (minor.begin (), minor.end ());
  const double full = *range.second - *range.first;
  const std::size_t last = minor.size () - 1;
  const auto at = [&] (std::size_t i) {
    std::nth_element (minor.begin (), minor.begin () + static_cast<std::ptrdiff_t> (i), minor.end ());
    return minor[i];
  };
  const double minor_lo = at (static_cast<std::size_t> (std::floor (0.025 * static_cast<double> (last))));
  const double minor_hi = at (static_cast<std::size_t> (std::ceil (0.975 * static_cast<double> (last))));
  c.minor_extent = std::min (full, (minor_hi - minor_lo) / 0.95);
  c.normal = n;
  c.along = along;
  // Slope of the quadric at the rim, half the extent away along its most curved direction.
  c.half_bend = std::isfinite (kappa) ? std::atan (0.5 * kappa * (hi - lo)) : 0.0;
  return c;
}

double
chanceBendShare (std::size_t samples, double confidence)
{
  if (!(confidence > 0.0))
    return 0.0;
  if (samples <= 6 || !(confidence < 1.0))
    return 1.0;
  const boost::math::beta_distribution<double> share (1.5, 0.5 * (static_cast<double> (samples) - 6.0));
  return boost::math::quantile (share, confidence);
}

bool
isTube (const PlaneCurvature& c, double mdp)
{
  return c.samples > 0 && !(0.5 * c.minor_extent > mdp);
}

bool
isFlatPatch (const PointSet& points, const DetectorParameters& params, const PlanarPatch& patch, bool grown)
{
  return isFlatPatch (measureCurvature (points, patch.members), params, patch, grown);
}

bool
isFlatPatch (const PlaneCurvature& c, const DetectorParameters& params, const PlanarPatch& patch, bool grown)
{
  const bool calibrated = params.bend_confidence > 0.0;
  if (calibrated && grown && isTube (c, patch.mdp))
    return false; // a tube: its noise band is as wide as half its narrow side
  if (calibrated && c.share < chanceBendShare (c.samples, params.bend_confidence))
    return true;  // noise explains the bend
  return c.share < params.min_curvature_share && (!grown || c.half_bend < 0.5 * patch.mnd);
}

bool
isCurvedPatch (const PlaneCurvature& c, double mnd, const DetectorParameters& params)
{
  return c.share >= params.min_curvature_share && c.share >= chanceBendShare (c.samples, params.bend_confidence) &&
         c.share <= 0.999 && c.half_bend >= 0.5 * mnd;
}

bool
isCurvedByNormals (const PlaneCurvature& c, double turn_across, double mnd, const DetectorParameters& params)
{
  return c.samples > 0 && c.share >= chanceBendShare (c.samples, params.curved_turn_confidence) && c.share <= 0.999 &&
         std::isfinite (turn_across) && turn_across >= 0.5 * mnd;
}

namespace
{
/** Each member's (position along the curved direction, signed angle of its normal towards it), both
  * about the first member: only differences matter, and the offsets stay small wherever the cloud
  * lies. Empty when the turn cannot be measured (fewer than 12 members, no curved direction). */
std::vector<std::pair<double, double>>
normalTurnSamples (const PointSet& points, const std::vector<std::uint32_t>& members, const PlaneCurvature& c)
{
  std::vector<std::pair<double, double>> turn;
  if (members.size () < 12 || c.samples == 0 || !(c.along.squaredNorm () > 0.0))
    return turn;
  const Eigen::Vector3d origin = points.points[members.front ()].cast<double> ();
  turn.reserve (members.size ());
  for (const auto m : members)
  {
    Eigen::Vector3d normal = points.normals[m].cast<double> ();
    if (normal.dot (c.normal) < 0.0)
      normal = -normal; // unoriented normals: the angle is taken on the plane's side
    turn.emplace_back ((points.points[m].cast<double> () - origin).dot (c.along),
                       std::atan2 (normal.dot (c.along), normal.dot (c.normal)));
  }
  return turn;
}
/** Centred sums of the (position, angle) pairs: the variance of the positions and of the angles and
  * their covariance, each times the count. */
struct TurnMoments
{
  double count = 0.0, var_t = 0.0, var_a = 0.0, cov = 0.0;
};

TurnMoments
turnMoments (const std::vector<std::pair<double, double>>& turn)
{
  double st = 0.0, sa = 0.0, stt = 0.0, sta = 0.0, saa = 0.0;
  for (const auto& q : turn)
  {
    st += q.first;
    sa += q.second;
    stt += q.first * q.first;
    sta += q.first * q.second;
    saa += q.second * q.second;
  }
  TurnMoments m;
  m.count = static_cast<double> (turn.size ());
  m.var_t = stt - st * st / m.count;
  m.var_a = saa - sa * sa / m.count;
  m.cov = sta - st * sa / m.count;
  return m;
}
} // namespace

double
normalTurnRatio (const PointSet& points, const std::vector<std::uint32_t>& members, const PlaneCurvature& c)
{
  std::vector<std::pair<double, double>> turn = normalTurnSamples (points, members, c);
  const std::size_t n = turn.size ();
  if (n == 0)
    return HUGE_VAL;
  std::sort (turn.begin (), turn.end ());
  const TurnMoments m = turnMoments (turn);
  const double line = std::max (0.0, m.var_a - (m.var_t > 0.0 ? m.cov * m.cov / m.var_t : 0.0));
  // Best single step by prefix sums over the sorted positions.
  double sa = 0.0, saa = 0.0;
  for (const auto& q : turn)
  {
    sa += q.second;
    saa += q.second * q.second;
  }
  const double count = m.count;
  const std::size_t min_side = std::max<std::size_t> (n / 20, 3);
  double step = HUGE_VAL, left = 0.0, left_sq = 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k)
  {
    left += turn[k].second;
    left_sq += turn[k].second * turn[k].second;
    const double nl = static_cast<double> (k + 1), nr = count - nl;
    if (k + 1 < min_side || n - (k + 1) < min_side)
      continue;
    const double right = sa - left, right_sq = saa - left_sq;
    step = std::min (step, (left_sq - left * left / nl) + (right_sq - right * right / nr));
  }
  if (!(step > 0.0))
    return HUGE_VAL; // the normals take two values exactly: a fold, not a turn
  return line / step;
}

double
normalTurnAcross (const PointSet& points, const std::vector<std::uint32_t>& members, const PlaneCurvature& c)
{
  const std::vector<std::pair<double, double>> turn = normalTurnSamples (points, members, c);
  if (turn.empty ())
    return HUGE_VAL;
  const TurnMoments m = turnMoments (turn);
  if (!(m.var_t > 0.0))
    return HUGE_VAL;
  return std::abs (m.cov / m.var_t) * std::sqrt (12.0 * m.var_t / m.count);
}
} // namespace rspd
} // namespace pcl
