/*
 * pcl_rspd: plane curvature — how far a set of samples bends away from its plane, and whether that
 * bend is real: the flat test of noisy seeds and the curved-surface check (departures from the paper).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/plane_detector.h>
#include <pcl_rspd/point_set.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief How much a set of samples bends away from its least-squares plane (the curved-surface
  * check, DetectorParameters::min_curvature_share, and the flat test, isFlatPatch). */
struct PlaneCurvature
{
  double share = 0.0;        ///< 1 - RSS(quadric) / RSS(plane): share of the residual a quadric explains
  double half_bend = 0.0;    ///< radians the quadric's normal turns from the middle of the samples to their rim
  double minor_extent = 0.0; ///< width of the samples along their plane's second principal axis (its narrow side): their range, or their inner 95 % / 0.95 where less
  std::size_t samples = 0;   ///< samples measured; 0 when too few (fewer than 12) or no residual
  Eigen::Vector3d normal = Eigen::Vector3d::Zero (); ///< the samples' least-squares plane normal
  Eigen::Vector3d along = Eigen::Vector3d::Zero ();  ///< in that plane, the quadric's most curved direction
};

/** \brief Fit w = a u² + b uv + c v² + d u + e v + f over the samples' least-squares plane (u, v in
  * the plane, w along its normal) and report how much of the residual the bend explains and how far
  * it turns the normal. Fewer than 12 samples or no residual: zeros. */
PlaneCurvature
measureCurvature (const PointSet& points, const std::vector<std::uint32_t>& members);

/** \brief The share of a flat plane's residual that the quadric of measureCurvature, fitted to
  * \a samples of it with Gaussian noise, stays below with probability \a confidence.
  *
  * Over the least-squares plane the linear and constant terms explain nothing, and the three
  * quadratic terms explain χ²₃ of the noise against χ²ₙ₋₆ left: the share is Beta(3/2, (n-6)/2),
  * whose mean 3/(n-3) is 0.23 at 16 samples, 0.06 at 50 and 0.015 at 200. A fixed share cannot tell
  * a bend from noise at every size: 0.25 calls a flat 16-sample seed bent two times in five.
  * \return the quantile (1 for 6 samples or fewer: nothing can be told), 0 for \a confidence <= 0 */
double
chanceBendShare (std::size_t samples, double confidence);

/** \brief Whether a patch noisier than the planes grown is flat: noise, not a bend, spreads its
  * normals (the outlier-seed retest, the thick-cell groups and the small-plane pass).
  *
  * Its quadric's share (measureCurvature) is one noise explains (chanceBendShare at
  * DetectorParameters::bend_confidence), or it is below min_curvature_share and, once \a grown, the
  * bend turns the normal from the middle to the rim by less than half the patch's MND (a bend too
  * small to spread its normals). A seed is not judged by its bend: fitted to 50 samples of noise,
  * six coefficients bend it by about its MND (a box face at σ 6 mm: 0.05-0.16 rad against MND
  * 0.04-0.08). Grown, a patch must also be thinner than it is wide: a noise band (MDP) as wide as
  * half its narrow side is a tube sampled all round (a pipe 0.3 m across at 30,000 points: 30° where
  * the paper's T1 asks 75° of the long side), whose quadric explains nothing. */
bool
isFlatPatch (const PointSet& points, const DetectorParameters& params, const PlanarPatch& patch, bool grown);

/** \brief isFlatPatch on the patch's curvature \a c measured already (measureCurvature of its members). */
bool
isFlatPatch (const PlaneCurvature& c, const DetectorParameters& params, const PlanarPatch& patch, bool grown);

/** \brief Whether a measured patch is a tube: its noise band \a mdp as wide as half its narrow side
  * (see isFlatPatch). */
bool
isTube (const PlaneCurvature& c, double mdp);

/** \brief Whether a plane is a facet of a curved surface (DetectorParameters::min_curvature_share):
  * the bend explains at least min_curvature_share of the residual and more than noise would
  * (chanceBendShare), and turns the normal by at least half the plane's MND (a facet of a curved
  * surface grows until its rim normals reach MND; a scanned wall bends by a small part of it). A
  * quadric that leaves no residual at all was not determined by the samples (a few scan lines, which
  * six coefficients interpolate): not judged. */
bool
isCurvedPatch (const PlaneCurvature& c, double mnd, const DetectorParameters& params);

/** \brief Whether the normals show a plane to be a facet of a curved surface where noise hides the
  * bend from isCurvedPatch's fixed bounds (DetectorParameters::curved_normal_turn): the quadric
  * bends beyond chance and the normals turn across the plane (\a turn_across, normalTurnAcross) by
  * at least half its MND. The caller still asks that they turn smoothly (normalTurnRatio). */
bool
isCurvedByNormals (const PlaneCurvature& c, double turn_across, double mnd, const DetectorParameters& params);

/** \brief How smoothly the sample normals turn across a plane: the residual of their angle, measured
  * along the quadric's most curved direction (PlaneCurvature::along), about a straight line in the
  * position along it, over its residual about the best single step (two levels, each side at least a
  * twentieth of the samples).
  *
  * On a curved surface the normal turns in proportion to the position: the line fits and the ratio
  * is σ² / (σ² + T²/48) for normal noise σ and a turn T across the samples, below 1/2 once T exceeds
  * √48 ≈ 7 σ. Two faces meeting at an edge turn in one step: the ratio is at least 1. Three equal
  * faces over two edges give (σ² + Δ²/12) / (σ² + Δ²/6) for a turn Δ per edge: from about 1/2
  * (no noise) to 1. Used by the curved-surface check (DetectorParameters::curved_fold_ratio).
  * \return the ratio; +inf when it cannot be measured (fewer than 12 samples, no curved direction) */
double
normalTurnRatio (const PointSet& points, const std::vector<std::uint32_t>& members, const PlaneCurvature& c);

/** \brief How far the sample normals turn across a plane along the quadric's most curved direction
  * (PlaneCurvature::along): the slope of their angle as a straight line in the position, times the
  * extent a uniform spread with the positions' variance would have (√12 standard deviations). On an
  * arc sampled evenly it is the arc's turn; on a flat plane, noise about 0. Compared with the
  * quadric's own turn (twice PlaneCurvature::half_bend) it tells whether the normals confirm a bend
  * the positions show (DetectorParameters::judge_normal_turn).
  * \return the turn in radians; +inf when it cannot be measured (fewer than 12 samples, no curved
  * direction) */
double
normalTurnAcross (const PointSet& points, const std::vector<std::uint32_t>& members, const PlaneCurvature& c);
} // namespace rspd
} // namespace pcl
