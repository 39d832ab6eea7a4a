/*
 * pcl_rspd: step split (departure) — a region of a plane that lies parallel to the rest, offset by a
 * step within the noise band (a door 2 cm proud of its wall), is split off as a plane of its own;
 * step regions (departure) — a region of a plane that lies off it toward a parallel plane beside it
 * goes to that plane; and planes across a step (departure) — a plane that only bridges such a step is
 * dropped.
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
/** \brief Step split (departure, DetectorParameters::step_split): a plane that holds a region offset
  * parallel to the rest of it, by less than its noise band, is split in two.
  *
  * A door 2 cm proud of a wall scanned at σ = 1.5 cm lies within the wall's band; growth takes it
  * with the wall and no test that reads one sample (distance, normal) can tell it apart. Its samples
  * can: averaged over a neighbourhood, their distances to the plane sit 2 cm off, where single
  * distances scatter over 1.5. Per plane, each member's distance to the plane is averaged over its
  * graph neighbours in that plane; members whose mean departs from the median distance by more than
  * kStepSmoothSigmas robust σ, on one side, join in graph-connected regions. The largest region that
  * is a step becomes a plane of its own (one split per plane and call; the detector calls it again
  * until none splits, as a wall whose band took several recessed windows holds a step at each),
  * provided:
  *  - it and the rest hold ε samples each;
  *  - it has an inside: at most kStepBorderShare of its members border the rest (a strip along an
  *    edge, where the next face's samples bend the mean, is all border);
  *  - its plane and the rest's are parallel across it: they meet no nearer to its centre than
  *    kStepCrossReach times its half extent, and the angle between them is within both MNDs;
  *  - the offset happens at once: the median distance (to the rest's plane) of the region's border
  *    members and that of the rest's members beside them differ, on the offset's side, by at least
  *    kStepJumpShare of the offset between the two planes (a bowed or warped surface changes its
  *    distance gradually, a step at once); or, failing that, the same across the border of the
  *    region's part where the step is half made (its members whose neighbourhood's mean distance to
  *    the rest's plane is past half the offset): the region ends where the means first depart by
  *    kStepSmoothSigmas σ, and a step of several σ can put mostly the rest's samples on that border;
  *  - the offset is at least the robust σ of each part about its own plane.
  * Planes are judged independently on the labels at the call, so the result does not depend on the
  * thread count; the new planes are appended in the order of the planes they were split from.
  * \param[in] points samples (positions and normals)
  * \param[in] graph k-NN graph
  * \param[in] params ε (min_patch_size), the estimate's parameters and num_threads
  * \param[in,out] patches planes; a split plane keeps the rest, the region is appended
  * \return planes split
  */
std::size_t
splitSteps (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
            std::vector<PlanarPatch>& patches);

/** \brief Step regions (departure, DetectorParameters::step_regions): a plane's region that lies off
  * it toward a parallel plane beside it goes to that plane when its members lie nearer to it.
  *
  * Where a step is shallower than the planes' noise bands (a window 10 cm deep in a facade at
  * σ = 4 cm, 3σ bands of 12 cm), growth gives the overlap to the plane that reached it first: the
  * wall keeps blocks of a window's samples, and neither distance (settleStepSides moves no sample
  * between planes closer than their bands) nor a majority of neighbours (a block's samples are each
  * other's neighbours) gives them back. As a group they can be told apart: per plane, its regions
  * off it on one side, as splitSteps finds them (graph-connected members whose neighbourhood's mean
  * distance departs from the median by kStepSmoothSigmas robust σ); a region goes to the parallel
  * plane (normalsCompatible) on its side that holds most of its members' graph neighbours, offset
  * from it by no more than the wider of their \a band (deeper steps are settleStepSides' to judge,
  * sample by sample), when the median of its members' distances to that plane is below the median
  * of their distances to their own by kRegionMedianErrors standard errors of a median of as many
  * samples at the plane's robust σ (a few samples along a rim, which nearness cannot tell, stay). A
  * layer of a plane's own noise beside the other plane lies nearer its own: its mean is a fraction
  * of σ off, the other plane an offset away.
  * Every plane is judged on the labels at the call, independently, so the result does not depend on
  * the thread count; planes are kept as they are (a plane may be left empty).
  * \param[in] points samples
  * \param[in] graph k-NN graph
  * \param[in] band per plane, the distance within which its own samples lie (the noise band)
  * \param[in] num_threads OpenMP threads (0: default)
  * \param[in,out] patches members updated
  * \param[in,out] labels per-sample plane, updated
  * \return samples moved
  */
std::size_t
settleStepRegions (const PointSet& points, const NeighborGraph& graph, const std::vector<double>& band, int num_threads,
                   std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels);

/** \brief Planes across a step (departure, DetectorParameters::across_step_check): a plane whose
  * members lie on two planes beside it at least as closely as on its own plane is dropped.
  *
  * Until the far-member release parts them, a door 2 cm proud of its wall lies within the wall's
  * band; the small-plane pass, which runs before that, may seed a strip of leftover samples across
  * the door's edge, half wall and half door, that passes T1-T3 as one plane tilted by the step (the
  * room at seed 7: 299 samples tilted 8.6°, robust σ 9.6 mm about its own plane against 4.0 mm
  * about the nearer of the wall and the door). Such a plane holds no surface of its own.
  *
  * Per plane P: the planes that hold a graph neighbour of a member; for each pair (A, B) of them
  * parallel to each other by M2 (normalsCompatible) and neither parallel to P, the robust σ
  * (kMadScale × median) of each member's distance to the nearer of A and B. P is dropped when that
  * is no larger than the robust σ about P's own plane. The pair must be parallel so that two planes
  * meeting at an edge, whose distances both vanish along it, never explain a plane away, and neither
  * may be parallel to P so that a coplanar plane elsewhere (another window of a facade) does not
  * either. A face joining two parallel planes across its width w (a window's reveal) has distances
  * spread evenly up to w / 2 from the nearer, a robust σ of about 0.37 w: it is dropped only when
  * narrower than 2.7 times its own noise σ.
  * Every plane is judged on the labels at the call, independently, so the result does not depend on
  * the thread count; the planes kept keep their order. Dropped planes' samples are held by none.
  * \param[in] points samples
  * \param[in] graph k-NN graph
  * \param[in] params num_threads
  * \param[in,out] patches planes
  * \return planes dropped
  */
std::size_t
dropPlanesAcrossSteps (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                       std::vector<PlanarPatch>& patches);

} // namespace rspd
} // namespace pcl
