/*
 * pcl_rspd: connected parts — a departure that splits a plane whose members form separate surfaces.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/neighbor_graph.h>
#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/plane_detector.h>
#include <pcl_rspd/point_set.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Connected parts (departure, DetectorParameters::connected_parts): split every plane whose
  * core members fall into two or more pieces of surface of at least \a min_part_size samples that no
  * graph edge joins.
  *
  * M1 joins patches only through a graph edge, so a plane of the paper is one connected piece of
  * surface. A plane can still hold two pieces of one geometric plane that do not touch: growth
  * tests a sample against the estimate of the moment, so samples of a surface that crosses the plane
  * in the gap between the pieces join both and carry M1 across (synpeb_pc01's two largest planes,
  * 13 cm apart). Those samples fail the plane's inlier test (Sec. 3.3: distance within MDP, normal
  * within MND) at its final estimate. A core member passes it and has at least a third of its k
  * neighbours in the plane: clutter inside the band passes the test too, but has its neighbours
  * mostly outside (outliers behind a facade, percolating between its coplanar windows). Core members
  * are joined by the graph's edges (either direction) into parts; a part is a piece of surface when
  * its median sample has at least three quarters of its neighbours in the plane (a plane of clutter
  * falls into parts too, whose samples have neighbours all around outside it). With two or more
  * such pieces, each becomes a plane (largest first keeps the plane's place; ties to the lower
  * sample index) and is estimated again; every other member joins the piece of a graph neighbour in
  * it (the lowest piece), or is released where it has none (one hop: a member chained farther is
  * clutter between the pieces). With \a release_strays (DetectorParameters::final_parts, on the final
  * members), a plane of one such piece keeps only the members that a chain of graph edges between
  * its members joins to the piece: the rest was claimed by distance alone, through clutter that has
  * since left the plane.
  * \param[in] points samples
  * \param[in] graph k-NN graph
  * \param[in] params constants (min_patch_size is the smallest part that becomes a plane)
  * \param[in,out] patches planes; new parts are appended
  * \param[in,out] labels per-sample patch label, rewritten when a plane is split or loses members
  * \param[in] release_strays also trim a plane of one piece to the members joined to it (see above)
  * \param[out] strays_released if given, the members so released
  * \return planes added
  */
std::size_t
splitDisconnectedPlanes (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                         std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels,
                         bool release_strays = false, std::size_t* strays_released = nullptr);

} // namespace rspd
} // namespace pcl
