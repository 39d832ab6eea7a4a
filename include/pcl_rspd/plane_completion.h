/*
 * pcl_rspd: small-plane completion — a departure that gives a small plane, before the ε rule drops
 * it, the samples of its own surface that growth could not reach.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/neighbor_graph.h>
#include <pcl_rspd/plane_detector.h>
#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/point_set.h>

#include <cstddef>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Small-plane completion (departure, DetectorParameters::small_plane_completion): the
  * small-plane pass's planes still short of ε once grown are offered the samples of their surface
  * that growth did not reach, and reach ε with them or are dropped as before.
  *
  * A small face beside a noisier one loses twice. Its PCA normals bend over the neighbour's
  * k-neighbourhoods along their edge, so the paper's estimate (the median normal, Eq. 4) tilts and
  * growth, bounded by MDP and MND about that plane, stops short of the face's rim; and the noisier
  * plane's band, wider than the face's, holds the strip along their edge (synpeb_pc01: faces of 271
  * and 452 samples, σ 2-3 mm, beside faces of σ 8-10 mm at 24°, grown to 182 and 156 samples against
  * ε = 250; their median distance to the least-squares plane of those members is 1.3-2.0 mm, to the
  * plane estimated 8.7-34.7 mm). A plane is completed when it
  *  - was seeded by a clean seed (not PlanarPatch::retested: no noisy or shifted-grid seed, whose
  *    planes the pass judges once grown);
  *  - holds at least half of ε: completion finishes a plane mostly found. A seed of a few dozen
  *    samples on a large tank's facet reached ε by position alone (the industrial scene at 80,000
  *    points in layout 11: 21 samples took 400 and became a false plane; measured);
  *  - is not flat to the float rounding of its coordinates: its band is at least 1 % of its sample
  *    spacing (a depth camera's quantized level makes exactly flat terraces on slanted surfaces:
  *    office1's 31 candidates, all terraces, measured 2e-6 to 4e-5 of their spacing, real faces 0.2
  *    and more).
  * It takes, through the k-NN graph from its members, the samples within its noise band (3 robust σ
  * about the least-squares plane of its members) that no plane holds, or that a plane holds whose
  * band is wider than its own, whose normal is turned from its own by more than its MND (not a
  * layer of the same surface), and from whose plane the sample lies farther relative to that band.
  * It keeps them if that brings it to ε and the plane they make is no layer of a plane found
  * (isBandLayer, as the pass asks of its seeds: each of room_scan1's 12 completions without it, strips
  * along the room's edges, is one); otherwise nothing moves. The test reads the candidate's own
  * members as held by it, so wherever its estimate fits its members it is a layer of itself and is
  * not completed: completion finishes the planes whose estimate tilted off their members, the case
  * above. Measured with its members left out (issue #6's fifty-fifth session, `bash
  * scripts/sweep.sh` on 426 rows): a box side among 20 % outliers completed (boxes in layout 552,
  * 29 -> 30 of 32, 0.9707 -> 0.9741), no other plane gained, seven rooms up to 0.0015 lower
  * (a plane found later anyway, completed first with a strip of the floor); not changed. Planes are taken in order, each reading
  * the labels the ones before it left: the result does not depend on the thread count.
  * Estimates are kept (the final refit gives every plane its least-squares plane later). A completed
  * plane is marked PlanarPatch::retested, so that the pass judges it flat once grown as it judges
  * the noisy seeds' planes (a depth camera's dithered view of a room, DepthLevels' test: an 18-sample
  * seed completed with 112 samples was a false plane until judged; measured).
  * \param[in] points samples
  * \param[in] graph their k-NN graph
  * \param[in] params ε (min_patch_size), threads
  * \param[in,out] patches the planes; a completed plane's members grow (and it is marked retested),
  *   and the planes it took samples from lose them; none is removed here
  * \return planes brought to ε
  */
std::size_t
completeSmallPlanes (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                     std::vector<PlanarPatch>& patches);

} // namespace rspd
} // namespace pcl
