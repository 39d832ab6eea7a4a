/*
 * pcl_rspd: the growth phase (Sec. 3.3, Algorithm 2) and re-estimation after growth (Sec. 3.5).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/neighbor_graph.h>
#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/point_set.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Label of a sample that belongs to no patch. */
constexpr std::uint32_t kNoPatch = std::numeric_limits<std::uint32_t>::max ();

/** \brief Per-sample patch labels (position in \a patches, or kNoPatch) for the current members. */
std::vector<std::uint32_t>
labelSamples (std::size_t num_samples, const std::vector<PlanarPatch>& patches);

/** \brief The inverse of labelSamples, for passes that move samples by their labels: each patch's
  * members from \a labels, ascending, and its first_index the lowest of them (patches whose label
  * no sample carries are left without members). */
void
membersFromLabels (const std::vector<std::uint32_t>& labels, std::vector<PlanarPatch>& patches);

/** \brief The labels a pass decided (\a next, one per sample) replace \a labels, and the patches'
  * members follow (membersFromLabels), when any differs; for the passes that judge every sample on
  * the labels before them and move some at once.
  * \return samples whose label changed */
std::size_t
adoptLabels (std::vector<std::uint32_t>& next, std::vector<std::uint32_t>& labels, std::vector<PlanarPatch>& patches);

/** \brief Per-sample flags that let later grow-merge iterations skip a sample's graph row.
  *
  * During grow-merge a labelled sample never loses its label and merging relabels whole patches,
  * so both flags, once true, stay true: a saturated sample (every neighbour is in some patch) can
  * add nothing to its patch by growth, and an interior sample (every neighbour is in its own patch)
  * carries no merge edge. Skipping their rows changes no result; it takes most of the k-NN graph out
  * of every iteration after the first. */
enum SampleFlag : std::uint8_t
{
  kSaturated = 1,
  kInterior = 2
};

/** \brief Grow every patch breadth-first over the k-NN graph (Algorithm 2).
  *
  * Patches grow one after the other by increasing MND (ties: lowest member index), so the least
  * noisy ones get first pick. From every member, a graph neighbour that belongs to no patch joins
  * when it meets the patch's inlier condition (d <= MDP, φ <= MND) and is then grown from; one that
  * fails is marked as an outlier of that patch and not visited again by it.
  * \param[in] points samples
  * \param[in] graph directed k-NN graph (out-neighbours are visited)
  * \param[in,out] patches members are appended (first_index kept up to date)
  * \param[in,out] labels per-sample patch label, updated
  * \param[in,out] flags SampleFlag bits per sample, kept across calls (null: none kept). With
  *   flags, the caller keeps every labelled sample labelled between calls (as grow-merge does), and
  *   a patch already grown with its current plane and members (PlanarPatch::grown) is skipped: each
  *   neighbour still free was refused by that same plane, so growing it again would add nothing.
  * \param[in] trimmed if not null: the same samples with other normals (the trimmed ones of what
  *   growth left), read instead of \a points' normals by the patches marked PlanarPatch::trimmed
  * \return samples added
  */
std::size_t
growPatches (const PointSet& points, const NeighborGraph& graph, std::vector<PlanarPatch>& patches,
             std::vector<std::uint32_t>& labels, std::vector<std::uint8_t>* flags = nullptr,
             const PointSet* trimmed = nullptr);

/** \brief Sec. 3.5: re-estimate C, N, MDP and MND of every patch that grew by more than
  * DetectorParameters::update_growth_ratio since its last estimate. Members are kept; T1-T3 are not
  * re-run, but with DetectorParameters::bounded_reestimation a plane keeps its last estimate when
  * the new one fails T2. Thread-count independent (patches are independent).
  * \param[in] points samples
  * \param[in] params constants
  * \param[in,out] patches patches; each one measured is marked as estimated at its current size
  * \param[out] kept if not null: re-estimates refused as failing T2
  * \param[in] trimmed if not null: normals read by the patches marked PlanarPatch::trimmed (see growPatches)
  * \return patches measured (updated or kept) */
std::size_t
reestimateGrownPatches (const PointSet& points, const DetectorParameters& params, std::vector<PlanarPatch>& patches,
                        std::size_t* kept = nullptr, const PointSet* trimmed = nullptr);

} // namespace rspd
} // namespace pcl
