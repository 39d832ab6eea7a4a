/*
 * pcl_rspd: seed groups — a departure that joins small-plane seeds too noisy to seed alone.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/neighbor_graph.h>
#include <pcl_rspd/plane_detector.h>
#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/point_set.h>

#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Groups of the small-plane pass's seeds that the pass turned down as noisier than every plane
  * found (DetectorParameters::noisy_seed_groups): seeds that touch in the k-NN graph and whose planes
  * agree are joined, and a group seeds a plane when, as a whole, it
  * - holds at least ε samples and passes T1-T3 (what the first split asks of a cell),
  * - is not explained by two planes meeting at an edge (bentAtAnEdge) and is flat (isFlatPatch),
  * - is at most DetectorParameters::noisy_group_ratio times as noisy (MND) and as thick (MDP) as
  *   the noisiest and the thickest plane found.
  *
  * With DetectorParameters::noisy_lone_seeds, a seed that joins no other seeds alone on the last two
  * terms (it passed T1-T3 as a cell of the pass; ε is asked of its grown plane): a rough face whose
  * few seeds lie apart or disagree has no group (the boxes with 15 % outliers on PCL's k = 50
  * normals: the roughest box's two sides, one seed of 207 samples against ε = 300, three of 67-177
  * whose bands disagree). A group of fewer than ε samples is then judged as a lone seed is: T1-T3
  * at the pass's cell size (DetectorParameters::small_cell_size), ε asked of its grown plane (the
  * room with 10 % outliers: the cabinet top, 479 samples, had two seeds of 117 and 68 against
  * ε = 200, and was missed while the group was held to ε).
  *
  * Why: the first split seeds a plane only where one octree cell holds ε of its samples within T1's
  * angle. A rough face that two cells of the grid share, each cell also holding a piece of the next
  * face, gets no cell (the boxes with 15 % outliers: the outliers widen the root cell, the roughest
  * box's cells of 0.86 m straddle its edges and those of 0.43 m fail T1 at 74° against 75°, while
  * without the outliers one cell of 0.75 m fits a face). Its small seeds are as noisy as the face,
  * above every plane found, and one at a time they look like the band of bent normals along an edge,
  * which the pass's MND bound keeps out. A band seeds nothing here either: its group is bent at the
  * edge or is a layer of the plane whose band it is (isBandLayer, in the caller). The bound on the
  * ratio keeps out slabs of scattered outliers whose normals agree by chance (the facade: a group of
  * two seeds, MDP 5 times the thickest plane's) and facets of tanks, locally flat but whose normals
  * turn (the industrial scene with outliers: MND 5 to 15 times the noisiest plane's); the rough faces
  * let in were within 1.8 times (MND) and 1.4 times (MDP), and one more, 2.04 times as noisy (a box
  * face at σ = 5 cm), is kept out (debug prints; measured figures in the README).
  *
  * \param[in] points samples (positions and normals)
  * \param[in] graph their k-NN graph
  * \param[in] params ε, T1-T3, α, bend tests and noisy_group_ratio
  * \param[in] seeds the turned-down seeds (disjoint sets of samples no plane holds)
  * \param[in] max_mnd MND of the noisiest plane found (radians)
  * \param[in] max_mdp MDP of the thickest plane found
  * \return one seed per group that passes, in order of its first seed (deterministic)
  */
std::vector<PlanarPatch>
joinNoisySeeds (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                const std::vector<PlanarPatch>& seeds, double max_mnd, double max_mdp);

} // namespace rspd
} // namespace pcl
