/*
 * pcl_rspd: a planar patch (C, N, MDP, MND, members) and the robust planarity test of Sec. 3.2.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/plane_detector.h>
#include <pcl_rspd/point_set.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Robust plane of a set of samples and the spread of its observations (Sec. 3.2). */
struct PlaneEstimate
{
  Eigen::Vector3d center = Eigen::Vector3d::Zero (); ///< C, component-wise median of positions (Eq. 3)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ (); ///< N, normalised component-wise median of normals (Eq. 4)
  double distance_median = 0.0;    ///< median(D), D of Eq. 5
  double distance_halfwidth = 0.0; ///< max(α·MAD(D), floor): half-width of I_D (Eq. 6)
  double angle_median = 0.0;       ///< median(Φ), Φ of Eq. 8 (radians)
  double angle_halfwidth = 0.0;    ///< max(α·MAD(Φ), floor): half-width of I_Φ (Eq. 9)
  double width = 0.0;              ///< w: extent along the first in-plane principal axis
  double length = 0.0;             ///< l: extent along the second in-plane principal axis

  /** \brief MDP: upper limit of I_D. */
  double
  mdp () const { return distance_median + distance_halfwidth; }
  /** \brief MND: upper limit of I_Φ (radians). */
  double
  mnd () const { return angle_median + angle_halfwidth; }
};

/** \brief A detected planar patch: its plane, inlier limits and members. */
struct PlanarPatch
{
  std::vector<std::uint32_t> members;                 ///< internal sample indices
  Eigen::Vector3d center = Eigen::Vector3d::Zero ();  ///< C
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ (); ///< N (unit)
  double mdp = 0.0;                                   ///< maximum distance to plane
  double mnd = 0.0;                                   ///< maximum normal deviation (radians)
  double cos_mnd = 1.0;                               ///< cos(MND), so the inlier test needs no acos
  std::size_t estimate_size = 0;                      ///< members.size() at the last estimate (Sec. 3.5)
  std::uint32_t first_index = std::numeric_limits<std::uint32_t>::max (); ///< lowest member (tie-break)
  /** Grown from every member with the current plane (growPatches with flags): until the plane or
    * the members change otherwise, growing it again would add nothing. */
  bool grown = false;
  /** Seeded by an outlier seed tested again (DetectorParameters::retest_outlier_seeds), or by a
    * small-plane seed as noisy, which only such a seed lets in; kept by a merge only where every
    * part has it (a part seeded within the planes' own noise bound vouches for the plane). Such a
    * plane is judged flat again once grown. */
  bool retested = false;
  /** Seeded by a group of thick cells (DetectorParameters::join_thick_cells): noisy by nature, its
    * MND lets only flat seeds of the small-plane pass in, as a retested plane's does. */
  bool joined = false;
  /** Seeded on the trimmed normals of what growth left (DetectorParameters::left_normal_refit, its
    * second split) with DetectorParameters::trimmed_seed_growth: grown and re-estimated on those
    * normals, where the PCA normals it was not found on bend. */
  bool trimmed = false;

  /** \brief Take C, N, MDP and MND from \a estimate, and remember the current size as estimated. */
  void
  setEstimate (const PlaneEstimate& estimate);

  /** \brief The inlier condition of Sec. 3.3: d = |(P - C)·N| <= MDP and acos|n·N| <= MND. */
  bool
  isInlier (const Eigen::Vector3f& point, const Eigen::Vector3f& normal) const
  {
    const double d = std::abs ((point.cast<double> () - center).dot (this->normal));
    const double c = std::abs (normal.cast<double> ().dot (this->normal));
    return d <= mdp && c >= cos_mnd;
  }
};

/** \brief Estimate the robust plane of \a samples and the spread of D and Φ (Eqs. 3-9).
  * \return false if the median normal vanishes (normals cancel out) or there are no samples
  */
bool
estimatePlane (const PointSet& points, const std::vector<std::uint32_t>& samples,
               const DetectorParameters& params, PlaneEstimate& estimate);

/** \brief How a planarity test ended. */
enum class PlanarityVerdict
{
  Planar,            ///< passed T1, T2 and T3
  Degenerate,        ///< no plane could be estimated
  FailedDistance,    ///< T1: angle(F, N) not above the threshold
  FailedNormal,      ///< T2: MND not below the threshold
  TooManyOutliers,   ///< T3: outlier share at or above the threshold
  TooSmall           ///< passed, but fewer than ε samples are left once outliers are dropped
};

/** \brief Outcome of the robust planarity test. */
struct PlanarityResult
{
  PlanarityVerdict verdict = PlanarityVerdict::Degenerate;
  PlaneEstimate estimate;                 ///< the plane and spreads, over all samples of the cell
  double distance_angle = 0.0;            ///< angle between F and N (radians), T1
  double outlier_ratio = 0.0;             ///< share of samples outside I_D or I_Φ, T3
  std::vector<std::uint32_t> inliers;     ///< the samples kept when Planar
};

/** \brief The samples of \a samples inside both of \a estimate's intervals I_D and I_Φ (Eqs. 6 and 9):
  * T3's inliers. */
std::vector<std::uint32_t>
intervalInliers (const PointSet& points, const std::vector<std::uint32_t>& samples, const PlaneEstimate& estimate);

/** \brief The robust planarity test of Sec. 3.2 on the samples of one cell. */
PlanarityResult
robustPlanarityTest (const PointSet& points, const std::vector<std::uint32_t>& samples,
                     const DetectorParameters& params);

/** \brief Whether two touching sets of samples lie on one plane, as the thick-cell join and the
  * groups of noisy seeds ask: their planes' normals within the larger of the two MNDs, and at least
  * 1 - T3's share of each set within the other's MDP (T3 across the pair: a cell across an edge has
  * planar-looking noisy normals, but half its samples lie off either face). */
bool
setsShareAPlane (const PointSet& points, const DetectorParameters& params, const std::vector<std::uint32_t>& a,
                 const Eigen::Vector3d& a_center, const Eigen::Vector3d& a_normal, double a_mdp, double a_mnd,
                 const std::vector<std::uint32_t>& b, const Eigen::Vector3d& b_center, const Eigen::Vector3d& b_normal,
                 double b_mdp, double b_mnd);

} // namespace rspd
} // namespace pcl
