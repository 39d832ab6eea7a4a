/*
 * pcl_rspd: position planes — planes found by their samples' positions alone among what every pass
 * left, where the normals bend too much for any cell to pass T2 and T3 (a departure from the paper).
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
/** \brief Seed planes by position among the samples no plane holds (departure, see
  * DetectorParameters::position_planes).
  *
  * The samples no plane holds, but for those inside the noise band of a plane a neighbour holds (its
  * tail: on one side of a face's plane at its rim, it would curl the face's quadric), are cut into
  * the parts the k-NN graph connects. In each part of ε or more, a plane is fitted from 32 starts,
  * or 4 per ε samples of the part if that is more (a sample and its neighbours in the part, spread
  * over it in index order; a start inside the members an earlier start settled on is skipped): the
  * samples connected to the start within 3 \a noise of the plane are its members, the plane is their
  * least-squares plane again, until they no longer change. The plane with the most members, trimmed
  * to kRefitTrimSigmas of their own robust σ, is kept if ε members lie within 3 σ of the trimmed
  * ones' plane (its support: the trim takes 1.2 % of a Gaussian plane's samples, and the last
  * assignment gives them back), the trimmed ones are no noisier than
  * \a noise (robust σ of their distances) by more than twice the standard error of that σ (a
  * face as noisy as the noisiest plane measures a little above it as often as below), their
  * quadric bends no more than noise would
  * (chanceBendShare at DetectorParameters::curved_turn_confidence, the curved check's; with
  * DetectorParameters::position_bend_band, judged again where it does with the samples beside them
  * in its band that the pass left out as lying in a neighbouring plane's band; with
  * DetectorParameters::position_bend_slabs, where it still does, without the members in the bands
  * of the planes found beside them that cross it), they are no
  * tube, no layer of a plane found (isBandLayer) and lie no closer to a neighbouring plane than to
  * their own (liesOnNeighbourPlane; with DetectorParameters::position_join_beside, one that lies on
  * a plane beside it gives that plane its members within the plane's band); then the part is
  * searched again without them. Where the best
  * plane is turned down the part is left. Then (DetectorParameters::position_surface_parts) what
  * the parts left so still hold on a surface (a sample with half of its neighbourhood, it and its k
  * neighbours, within 3 \a noise and within a quarter of the neighbourhood's radius of the
  * neighbourhood's plane: least squares, then again on the half of it nearest to that fit) is cut
  * into parts again and searched once more, as above but for three rules: a plane turned down
  * leaves the part and the search goes on among the rest, unless it bends (the strips of a curved
  * surface that would follow measure flat); a plane must lie inside a surface, its median member
  * having half of its k neighbours among the members (or of the members but itself, where they are
  * fewer); and (DetectorParameters::position_surface_normals) a member's neighbourhood plane must be
  * nearer parallel to the plane than perpendicular (the strips of the faces beside a noisy face
  * would bend it). Then (DetectorParameters::position_surface_ladder) what is still left is
  * searched so again for planes up to noisy_group_ratio times as noisy as the noisiest plane kept,
  * with a reach as much wider, step by step while a step keeps a plane noisier than the last, or
  * (DetectorParameters::position_ladder_rungs) keeps none but turned one down for its noise alone
  * within the next step; there a plane holds more than k samples.
  * Why: outliers join a scene's free samples into one part, whose best plane is a slab of them, and
  * the faces beside it were never tried; and rough faces among outliers are seeded by no earlier
  * pass, each bounded by the planes found. The pass runs on one thread, in index order: the result
  * does not depend on the thread count.
  *
  * Why by position: a small face bordered by others on most sides, sampled sparsely, has PCA normals
  * bent over most of it (the cabinet's top in the room at 30,000 points: 95 samples, k = 15, every
  * cell of it fails T3 or has an MND of 23-27°), while its positions lie within the noise of a plane.
  * \param[in] points samples (positions and normals)
  * \param[in] graph their k-NN graph
  * \param[in] params ε (min_patch_size), α, curved_turn_confidence, T1's angle (isBandLayer)
  * \param[in] noise the robust σ of the noisiest plane found (its members' distances to it)
  * \param[in] band per plane, the distance within which its noise lies (isBandLayer)
  * \param[in,out] patches the planes found; new planes are appended
  * \param[in,out] labels per sample, the plane holding it (kNoPatch: none)
  * \return planes added */
std::size_t
seedPositionPlanes (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params, double noise,
                    std::vector<double> band, std::vector<PlanarPatch>& patches,
                    std::vector<std::uint32_t>& labels);

} // namespace rspd
} // namespace pcl
