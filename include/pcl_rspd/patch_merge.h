/*
 * pcl_rspd: the merge phase (Sec. 3.4): union-find over patch pairs meeting M1-M3.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/neighbor_graph.h>
#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/point_set.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Disjoint sets over patch positions, with path halving. */
class UnionFind
{
public:
  explicit UnionFind (std::size_t n);
  /** \brief Representative of \a x's set. */
  std::uint32_t
  find (std::uint32_t x);
  /** \brief Join the sets of \a a and \a b. \return whether they were apart */
  bool
  unite (std::uint32_t a, std::uint32_t b);

private:
  std::vector<std::uint32_t> parent_;
};

/** \brief Whether patches \a a and \a b may merge by M2: the angle between their normals is below
  * max(MND_A, MND_B). */
bool
normalsCompatible (const PlanarPatch& a, const PlanarPatch& b);

/** \brief Merge patches (Sec. 3.4).
  *
  * A pair (A, B) merges when M1: a graph edge, in either direction, joins a sample of A and a
  * sample of B; M2: normalsCompatible(A, B); M3: on such an edge, the sample of A is an inlier of B
  * or the sample of B is an inlier of A (the boundary samples carry the test). Groups are closed
  * transitively by union-find; the largest patch (ties: lowest member index) represents its group
  * and keeps its plane, its estimate size and its place; the others' members join it. Whether the
  * merged patch needs re-estimating is left to the caller (Sec. 3.5).
  * \param[in] points samples
  * \param[in] graph k-NN graph
  * \param[in,out] patches merged in place (absorbed patches are removed, order otherwise kept)
  * \param[in,out] labels per-sample labels, rewritten to the new positions
  * \param[in,out] flags SampleFlag bits per sample (see growPatches), kept across calls (null: none)
  * \return number of patches absorbed
  */
std::size_t
mergePatches (const PointSet& points, const NeighborGraph& graph, std::vector<PlanarPatch>& patches,
              std::vector<std::uint32_t>& labels, std::vector<std::uint8_t>* flags = nullptr);

} // namespace rspd
} // namespace pcl
