/*
 * pcl_rspd: final refit — a departure that gives every grown plane the least-squares plane of its
 * members before the last passes judge samples by their distance to it.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/point_set.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief A member counts in the refit when its distance to the plane is at most this many robust
  * sigmas (1.4826 times the median distance): 2.5 keeps 98.8 % of a Gaussian plane's samples and
  * leaves out the far members of its noise band (outliers in the band, a neighbour's samples at an
  * edge), which would tilt a least-squares fit. */
constexpr double kRefitTrimSigmas = 2.5;

/** \brief Rounds of the refit: the least-squares plane of all members, then of those within
  * kRefitTrimSigmas of the last plane, this many times. Two settle: a third (measured with
  * `rspd_segment` on 17 clouds) left the generated scenes' labels identical or 2 samples apart, and
  * moved F1 by at most 0.0002 (synpeb_pc01 0.92855 → 0.92850, cgal_building 0.86756 → 0.86742). */
constexpr int kRefitRounds = 2;

/** \brief Least-squares plane of the \a members that \a use marks (all when \a use is empty), summed
  * about \a origin in double precision (a point near them keeps far-off clouds exact).
  * \param[out] center the members' mean
  * \param[out] normal unit normal of their plane (the scatter's least eigenvector)
  * \return false, outputs untouched, when fewer than three members count or they are collinear */
bool
leastSquaresPlane (const PointSet& points, const std::vector<std::uint32_t>& members, const std::vector<char>& use,
                   const Eigen::Vector3d& origin, Eigen::Vector3d& center, Eigen::Vector3d& normal);

/** \brief Final refit (departure, DetectorParameters::final_refit): set each plane's C and N to the
  * least-squares plane of its members, trimmed (kRefitTrimSigmas, kRefitRounds); MDP, MND and the
  * members are kept.
  *
  * Why: C and N are the paper's robust estimate (Eqs. 3-9): the median of the positions and the
  * median of the normals. The median normal of PCA normals is tilted by the normals that bend near
  * the plane's edges, and the median position is not on the plane's mid-surface, so over a plane of
  * a few noise widths the estimate is off by a large part of the noise at its rims (the staircase at
  * σ = 1 cm: samples of a riser and its tread within 1 cm of their edge lay beyond the edge line of
  * both estimated planes and were released, recall 0.952 against 0.972 for the true planes). A grown
  * plane has thousands of members: their least-squares plane is the better estimate, and the last
  * assignment, the edge and step sides and the plane support read distances to it. The trim keeps
  * the members that the robust estimate admitted but the least-squares plane should not follow.
  * Each plane is fitted alone, in double precision about its old centre: the result does not depend
  * on the thread count, and scaling, turning or moving the cloud moves the planes with it.
  * \param[in] points samples
  * \param[in] num_threads OpenMP threads (0: default)
  * \param[in,out] patches C and N updated (N keeps its side); planes with fewer than three members,
  *   or whose members are collinear, keep their estimate
  */
void
refitPlanes (const PointSet& points, int num_threads, std::vector<PlanarPatch>& patches);

} // namespace rspd
} // namespace pcl
