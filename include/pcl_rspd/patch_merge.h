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

/** \brief Which merge conditions apply beyond the paper's M1-M3 (defaults: the library's). */
struct MergeRules
{
  /** \brief M4, coplanar groups (DetectorParameters::coplanar_merge). */
  bool coplanar = true;
  /** \brief T3's outlier ratio: M4 needs at least (1 - this) of the smaller group within the band. */
  double max_outlier_ratio = 0.25;
  /** \brief OpenMP threads for the boundary scan (0: default); the result does not depend on it. */
  int num_threads = 0;

  /** \brief The paper's M1-M3 and nothing else. */
  static MergeRules
  paper () { return {false, 0.25, 0}; }
};

/** \brief Whether patches \a a and \a b may merge by M2: the angle between their normals is below
  * max(MND_A, MND_B). */
bool
normalsCompatible (const PlanarPatch& a, const PlanarPatch& b);

/** \brief Merge patches (Sec. 3.4).
  *
  * A pair (A, B) may merge when M1: a graph edge, in either direction, joins a sample of A and a
  * sample of B; M2: normalsCompatible(A, B); M3: on such an edge, the sample of A is an inlier of B
  * or the sample of B is an inlier of A (the boundary samples carry the test). Groups are closed
  * transitively by union-find; the largest patch (ties: lowest member index) represents its group
  * and keeps its plane, its estimate size and its place; the others' members join it. Whether the
  * merged patch needs re-estimating is left to the caller (Sec. 3.5). It stays PlanarPatch::retested
  * only if every patch of the group was.
  *
  * With rules.coplanar (M4), the pairs are joined one at a time, the pair whose larger representative
  * is largest first, and only if the group with the smaller representative lies in the larger
  * representative's distance band: at least (1 - T3 ratio) of its samples within that plane's MDP,
  * or the smaller representative's own MDP when that is wider.
  * M1-M3 look at one boundary; M4 looks at the whole group, so a chain of small steps (facets of a
  * curved or faceted object, a patch straddling a step) cannot carry a plane around a bend.
  * \param[in] points samples
  * \param[in] graph k-NN graph
  * \param[in,out] patches merged in place (absorbed patches are removed, order otherwise kept)
  * \param[in,out] labels per-sample labels, rewritten to the new positions
  * \param[in,out] flags SampleFlag bits per sample (see growPatches), kept across calls (null: none)
  * \param[in] rules conditions beyond M1-M3 (MergeRules::paper() for none)
  * \return number of patches absorbed
  */
std::size_t
mergePatches (const PointSet& points, const NeighborGraph& graph, std::vector<PlanarPatch>& patches,
              std::vector<std::uint32_t>& labels, std::vector<std::uint8_t>* flags = nullptr,
              const MergeRules& rules = MergeRules ());

} // namespace rspd
} // namespace pcl
