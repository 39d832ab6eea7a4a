/*
 * pcl_rspd: least-trimmed-squares normals (see robust_normals.h).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/normal_estimation.h>
#include <pcl_rspd/robust_normals.h>

#include <pcl/common/eigen.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace pcl
{
namespace rspd
{
namespace
{
/** Reweighting bound on squared residuals in σ²: χ²₁ at 97.5 %. */
constexpr double kReweightChi2 = 5.0239;
/** Concentration steps per start; they converge in two or three. */
constexpr int kMaxSteps = 10;

/** E[r² | |r| <= q] / σ² for a Gaussian r, q the two-sided quantile of \a coverage: divides the mean
  * of the h smallest squared residuals to estimate σ². */
double
trimmedVarianceFactor (double coverage)
{
  double lo = 0.0, hi = 10.0;
  for (int it = 0; it < 100; ++it)
  {
    const double mid = 0.5 * (lo + hi);
    (std::erf (mid / std::sqrt (2.0)) < coverage ? lo : hi) = mid;
  }
  const double q = 0.5 * (lo + hi);
  return 1.0 - 2.0 * q * std::exp (-0.5 * q * q) / std::sqrt (2.0 * M_PI) / coverage;
}

/** Unit eigenvector of the smallest eigenvalue (PCL's closed-form 3x3 solver, as its normals). */
Eigen::Vector3d
smallestEigenvector (const Eigen::Matrix3d& cov)
{
  double value;
  Eigen::Vector3d vector;
  pcl::eigen33 (cov, value, vector);
  return vector.normalized ();
}

/** Eigenvalues in ascending order. */
Eigen::Vector3d
eigenvalues (const Eigen::Matrix3d& cov)
{
  Eigen::Vector3d values;
  pcl::eigen33 (cov, values);
  return values;
}

/** Centroid and covariance of the samples \a ids[0..count) of \a q. */
void
moments (const std::vector<Eigen::Vector3d>& q, const std::vector<int>& ids, std::size_t count, Eigen::Vector3d& c,
         Eigen::Matrix3d& cov)
{
  c.setZero ();
  for (std::size_t j = 0; j < count; ++j)
    c += q[ids[j]];
  c /= static_cast<double> (count);
  cov.setZero ();
  for (std::size_t j = 0; j < count; ++j)
  {
    const Eigen::Vector3d d = q[ids[j]] - c;
    cov += d * d.transpose ();
  }
}

/** Per-thread work space and the fit of one neighbourhood. */
class TrimmedFit
{
public:
  TrimmedFit (std::size_t m, std::size_t h) : m_ (m), h_ (h), ids_ (m), key_ (m), packed_ (m), chosen_ (m), fitted_ (m) {}

  /** Concentration steps from the plane (c, n); returns the trimmed sum, updates c and n. */
  double
  concentrate (const std::vector<Eigen::Vector3d>& q, Eigen::Vector3d& c, Eigen::Vector3d& n)
  {
    double objective = HUGE_VAL;
    for (int step = 0; step < kMaxSteps; ++step)
    {
      for (std::size_t j = 0; j < m_; ++j)
      {
        const double r = (q[j] - c).dot (n);
        key_[j] = r * r;
      }
      const double sum = selectSmallest ();
      // The plane (c, n) was fitted to the subset just selected: converged. (The sum never rises;
      // the second test only guards against a cycle through rounding.)
      if (step > 0 && chosen_ == fitted_)
      {
        objective = std::min (objective, sum);
        break;
      }
      if (!(sum < objective))
        break;
      objective = sum;
      fitted_ = chosen_;
      Eigen::Matrix3d cov;
      moments (q, ids_, h_, c, cov);
      n = smallestEigenvector (cov);
    }
    return objective;
  }

  /** Whether the sample itself (position 0) is among the h samples last selected. */
  bool
  holdsSample () const
  {
    return chosen_[0] != 0;
  }

  /** The h samples nearest the plane (c, n). */
  void
  nearestToPlane (const std::vector<Eigen::Vector3d>& q, const Eigen::Vector3d& c, const Eigen::Vector3d& n)
  {
    for (std::size_t j = 0; j < m_; ++j)
    {
      const double r = (q[j] - c).dot (n);
      key_[j] = r * r;
    }
    selectSmallest ();
  }

  /** The h samples nearest the sample itself (q[0] is the sample, at the origin). */
  void
  nearestHalf (const std::vector<Eigen::Vector3d>& q)
  {
    for (std::size_t j = 0; j < m_; ++j)
      key_[j] = q[j].squaredNorm ();
    selectSmallest ();
  }

  std::vector<int>&
  ids () { return ids_; }

private:
  /** Puts the h smallest keys first in ids_ (ties by position, so the result is deterministic),
    * marks them in chosen_ and returns their sum. */
  double
  selectSmallest ()
  {
    // One selection on (key, position) packed in 64 bits: a non-negative float's bits order as the
    // float does, and the position below them breaks ties. Keys are compared in single precision.
    for (std::size_t j = 0; j < m_; ++j)
    {
      const float f = static_cast<float> (key_[j]);
      std::uint32_t bits;
      std::memcpy (&bits, &f, sizeof bits);
      packed_[j] = (static_cast<std::uint64_t> (bits) << 32) | static_cast<std::uint64_t> (j);
    }
    std::nth_element (packed_.begin (), packed_.begin () + static_cast<std::ptrdiff_t> (h_ - 1), packed_.end ());
    std::fill (chosen_.begin (), chosen_.end (), 0);
    double sum = 0.0;
    for (std::size_t t = 0; t < h_; ++t)
    {
      const auto j = static_cast<std::uint32_t> (packed_[t] & 0xffffffffu);
      ids_[t] = static_cast<int> (j);
      chosen_[j] = 1;
      sum += key_[j];
    }
    return sum;
  }

  std::size_t m_, h_;
  std::vector<int> ids_;
  std::vector<double> key_;
  std::vector<std::uint64_t> packed_;
  std::vector<std::uint8_t> chosen_, fitted_; ///< the subset last selected / last fitted
};
} // namespace

void
refineNormalsTrimmed (const std::vector<Eigen::Vector3f>& points, const NeighborGraph& graph, int num_threads,
                      std::vector<Eigen::Vector3f>& normals, TrimmedNormalStatistics* stats,
                      const std::vector<std::uint32_t>* subset)
{
  TrimmedNormalStatistics local;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (subset ? subset->size () : points.size ());
  const int k = graph.k ();
  const std::size_t m = static_cast<std::size_t> (std::max (k, 0)) + 1;
  const std::size_t h = (m + 4) / 2;
  if (k < 3 || normals.size () != points.size ())
  {
    if (stats)
      *stats = local;
    return;
  }
  const double variance_factor = trimmedVarianceFactor (static_cast<double> (h) / static_cast<double> (m));
  const double isotropic = isotropicEigenRatioQuantile (k, 0.05);
  std::size_t refined = 0, unresolved = 0, collinear = 0;
#pragma omp parallel num_threads(resolveThreads (num_threads)) reduction(+ : refined, unresolved, collinear)
  {
    std::vector<Eigen::Vector3d> q;
    q.reserve (m);
    TrimmedFit fit (m, h);
    std::vector<int> kept;
    kept.reserve (m);
#pragma omp for schedule(static, 4096)
    for (std::ptrdiff_t t = 0; t < n; ++t)
    {
      const std::ptrdiff_t i = subset ? static_cast<std::ptrdiff_t> ((*subset)[static_cast<std::size_t> (t)]) : t;
      // Offsets from the sample itself, for precision wherever the scene lies.
      q.clear ();
      const Eigen::Vector3d self = points[i].cast<double> ();
      q.push_back (Eigen::Vector3d::Zero ());
      graph.forEachNeighbor (static_cast<std::size_t> (i),
                             [&] (std::uint32_t j) { q.push_back (points[j].cast<double> () - self); });
      if (q.size () != m)
        continue;

      std::vector<int>& ids = fit.ids ();
      for (std::size_t j = 0; j < m; ++j)
        ids[j] = static_cast<int> (j);
      Eigen::Vector3d c_all;
      Eigen::Matrix3d cov_all;
      moments (q, ids, m, c_all, cov_all);
      const Eigen::Vector3d ev = eigenvalues (cov_all);
      if (!(ev[1] > 0.0) || ev[0] / ev[1] >= isotropic)
      {
        ++unresolved;
        continue;
      }

      // Two starts: the PCA plane of all, and that of the h samples nearest the sample.
      Eigen::Vector3d c1 = c_all, n1 = smallestEigenvector (cov_all);

      // The sample's own surface is wanted: the trimmed plane from the whole neighbourhood is kept
      // if the sample is among its h samples; otherwise (the sample may lie on the smaller of two
      // faces) the start from its nearest half replaces it if that plane's h samples include the
      // sample or its trimmed sum is lower. On a flat neighbourhood both starts reach the same
      // plane, so the second is only run where it can matter.
      const double s1 = fit.concentrate (q, c1, n1);
      double trimmed = s1;
      Eigen::Vector3d c = c1, normal = n1;
      if (!fit.holdsSample ())
      {
        fit.nearestHalf (q);
        Eigen::Vector3d c2;
        Eigen::Matrix3d cov2;
        moments (q, fit.ids (), h, c2, cov2);
        Eigen::Vector3d n2 = smallestEigenvector (cov2);
        const double s2 = fit.concentrate (q, c2, n2);
        if (fit.holdsSample () || s2 < s1)
        {
          trimmed = s2;
          c = c2;
          normal = n2;
        }
      }

      // Reweighting.
      const double sigma2 = trimmed / static_cast<double> (h) / variance_factor;
      kept.clear ();
      for (std::size_t j = 0; j < m; ++j)
      {
        const double r = (q[j] - c).dot (normal);
        if (r * r <= kReweightChi2 * sigma2)
          kept.push_back (static_cast<int> (j));
      }
      if (kept.size () < h)
      {
        fit.nearestToPlane (q, c, normal);
        kept.assign (fit.ids ().begin (), fit.ids ().begin () + static_cast<std::ptrdiff_t> (h));
      }
      Eigen::Vector3d c3;
      Eigen::Matrix3d cov3;
      moments (q, kept, kept.size (), c3, cov3);
      const Eigen::Vector3d fv = eigenvalues (cov3);
      if (!(fv[2] > 0.0) || fv[1] / fv[2] < 0.5 * (ev[1] / ev[2]))
      {
        ++collinear;
        continue;
      }
      const Eigen::Vector3d result = smallestEigenvector (cov3);
      if (!result.allFinite ())
        continue;
      normals[i] = result.normalized ().cast<float> ();
      ++refined;
    }
  }
  local.refined = refined;
  local.unresolved = unresolved;
  local.collinear = collinear;
  if (stats)
    *stats = local;
}

} // namespace rspd
} // namespace pcl
