/*
 * pcl_rspd: the split phase (Sec. 3.1, Algorithm 1) over an index-range octree.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/plane_detector.h>
#include <pcl_rspd/point_set.h>

#include <cmath>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Split phase: detect planar patches bottom-up in an octree (Algorithm 1).
  *
  * The octree is built over one array of sample indices that is partitioned in place, so each node
  * is a contiguous slice of it (pcl::octree only keeps indices in leaves and snaps its box to a
  * power-of-two resolution, which suits neither a count-driven split nor the bottom-up test).
  * The root cell is the bounding cube of the samples. A cell with fewer than ε samples returns;
  * otherwise it is split into eight children and recursed into; only if none of its children
  * produced a patch is the cell itself tested; an accepted cell drops its outliers and becomes a
  * patch unless fewer than ε samples remain. Subdivision stops where all samples of a cell coincide
  * or at params.max_octree_depth: such a cell is tested as a leaf.
  *
  * \param[in] points valid samples with normals
  * \param[in] params constants (ε = params.min_patch_size)
  * \param[out] stats cells tested and patches found are added (may be null)
  * \param[in] subset if given, the octree is built over these samples only (the root cell is their
  *            bounding cube); otherwise over all samples
  * \param[in] retest_rim_cells a cell that passes T1 and T2 but fails T3 is tested again on its own
  *            inliers, which seed a patch if they pass (DetectorParameters::rim_cell_retest; the
  *            small-cell pass only, false = the paper), and their own inliers while T3 still fails
  *            (DetectorParameters::rim_retest_until_stable)
  * \param[out] rim_seeds patches found that way are counted here (may be null)
  * \param[out] joined_out with params.join_thick_cells: the groups
  *            of thick cells that pass T1-T3 and are not bentAtAnEdge (bent_planes.h) go here (null: they are appended to the
  *            patches, after the cells' own, and counted in stats->joined_seeds; on a subset, thick
  *            cells are joined only if this is given). Thick cells are
  *            the largest cells that fail T1 alone (T2 and T3 pass, ε inliers; on a subset, not a
  *            cell bentAtAnEdge over thick cells of its own); touching ones join
  *            when their planes agree (normals within either's MND, at least 1 - T3's share of
  *            each one's samples within the other's MDP).
  * \param[in] thick_max_mnd a cell whose MND is above this is not kept as thick (the small-plane
  *            pass: the noisiest plane found; blobs of outliers, whose cells are as thick as wide,
  *            have MNDs up to T2's 60°)
  * \param[in] shifted_grid the octree's cells are those of the shifted grid (kShiftedGridOffset)
  *            instead of the bounding cube's (DetectorParameters::shifted_small_grid)
  * \return the patches, in depth-first octree order (deterministic)
  */
std::vector<PlanarPatch>
splitPhase (const PointSet& points, const DetectorParameters& params, DetectorStatistics* stats = nullptr,
            const std::vector<std::uint32_t>* subset = nullptr, bool retest_rim_cells = false,
            std::size_t* rim_seeds = nullptr, std::vector<PlanarPatch>* joined_out = nullptr,
            double thick_max_mnd = HUGE_VAL, bool shifted_grid = false);

/** \brief The shifted grid (splitPhase's shifted_grid): its root is the bounding cube doubled, with
  * its lower corner moved back by this share of the cube's edge. Its level l + 1 then has the cells
  * of the bounding cube's level l, each moved by a third or two thirds of a cell along every axis
  * (2^l / 3 is never a whole number), so no boundary of any level is the first grid's; the octree is
  * one level deeper (max_octree_depth + 1) to reach the same smallest cells. A face that every cell
  * of the first grid cuts into pieces too small to test (0.8 m across, cells of 0.38 m) lies whole
  * in some cell of the shifted grid's level below whenever the face is wider than two thirds of a
  * cell of it. A share of the cube, not a length. */
constexpr double kShiftedGridOffset = 1.0 / 3.0;

} // namespace rspd
} // namespace pcl
