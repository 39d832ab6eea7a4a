/*
 * pcl_rspd: edge and step sides — departures that settle which plane owns the samples where two planes meet.
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
/** \brief What settleEdgeSides did. */
struct EdgeSideCounts
{
  std::size_t moved = 0;    ///< samples given to the other plane
  std::size_t released = 0; ///< samples that left their plane for none
  std::size_t cornered = 0; ///< samples inside the corner of two planes given to the nearer one
  std::size_t outside = 0;  ///< samples outside the edge of two planes kept by the farther one
};

/** \brief Edge sides (departure, DetectorParameters::edge_sides): a sample next to another plane
  * leaves its plane when its projection onto that plane lies beyond the line where the two meet.
  *
  * Where planes a and b meet along a line, a's samples lie on one side of it, and noise along a's
  * normal does not move their projection onto a across it; growth and the distance-only passes,
  * which compare a sample with each plane's band, cannot tell a's samples from b's within a noise
  * band of the line. The side of b that a's members hold is voted by a's members that border b and
  * lie beyond b's band (the others are within noise of b): one side needs at least three votes in
  * four, else a straddles b (a wall through a shelf) and the pair is left alone; so are pairs whose
  * normals are within either plane's MND. A sample of a that borders b and whose projection onto a
  * lies on b's other side goes to the bordering plane that would own it by the same rule (within its
  * band, projection on its own side of a unless it straddles a, and some of its members voted;
  * nearest relative to the band, ties to the lower label), or to none. One pass over the samples that border another plane at its start: it reads the labels
  * before it, so the result does not depend on the thread count, and repeating it would walk a strip
  * along the line where b's plane cuts through a beyond b's extent.
  *
  * With \a corners, a sample of a that borders b, whose projection onto a lies on a's side of b and
  * whose projection onto b lies on b's side of a (inside the corner the two planes make, where noise
  * along either normal can put a sample of either plane), goes to the nearer plane relative to its
  * band, when that is b's and b holds it within its band: noise of σ along a's normal moves a's
  * sample as far off a as it moves b's sample off b, so the nearer plane is the likelier one (the
  * beyond rule settles only the half of such samples that the noise pushed out of the corner).
  * Pairs where either plane straddles the other, or has no vote, are left alone here too.
  *
  * With \a wedges, a sample of a whose projection onto a lies beyond b and whose projection onto b
  * lies beyond a (outside the edge, where noise across the line, not along a normal, put it: a
  * range sensor's noise along its rays, seen obliquely) goes to the plane it lies farther from,
  * relative to that plane's band, if it is within both bands, instead of to none. For noise of one σ
  * in every direction, a's sample at depth u off a and v beyond b's plane is likelier than b's
  * exactly when u > v, since φ(u) Q(v) > φ(v) Q(u) there (φ / Q, the normal's hazard, grows). Where
  * noise is along the normals only, no plane's sample lies there and clutter is what the rule takes.
  * Likewise a sample of a beyond b's line and b's band, on b's side of a (b cannot own it), stays with
  * a if it lies within a's band and its projection onto a lies within a's band of the line: a's own
  * noise across its edge, where a is the noisier plane.
  * \param[in] points samples
  * \param[in] graph k-NN graph
  * \param[in] band per patch, the distance within which its own samples lie (the noise band)
  * \param[in] num_threads OpenMP threads (0: default)
  * \param[in,out] patches members updated (planes kept as they are)
  * \param[in,out] labels per-sample patch label, updated
  * \param[in] corners whether samples inside a corner go to the nearer plane
  *            (DetectorParameters::edge_corners)
  * \param[in] wedges whether samples outside an edge go to the farther plane rather than to none
  *            (DetectorParameters::edge_wedges)
  */
EdgeSideCounts
settleEdgeSides (const PointSet& points, const NeighborGraph& graph, const std::vector<double>& band, int num_threads,
                 std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels, bool corners = true,
                 bool wedges = true);

/** \brief Step sides (departure, DetectorParameters::step_sides): a sample next to a parallel plane
  * (normals within either plane's MND) offset from its own by more than the wider noise band goes to
  * it when it lies within that plane's band and that plane holds more of its neighbours than its own.
  *
  * Two parallel planes do not meet along a line; they make a step, and where it is shallow against
  * the noise (a window recessed 20 cm behind a facade scanned at σ = 5 cm) their noise bands overlap.
  * Growth gives a sample in the overlap to whichever plane reached it first: the wall, grown first,
  * keeps up to 30 % of a window's samples, scattered over it, and hands the window the wall's noise
  * along its rim. Within the overlap, distance cannot tell; where the sample lies on the surface can,
  * and its neighbours' planes say that. Planes offset by less than the wider band are left alone
  * unless \a within_bands: one surface in two parts, or a step within noise, where the plane that
  * holds most of a region holds most of each sample's neighbours in it too. One pass, reading the
  * labels before it (the result does not depend on the thread count); a sample in a cluster of its
  * plane's samples within the other plane moves on a later pass, once the cluster's rim has.
  * \param[in] points samples
  * \param[in] graph k-NN graph
  * \param[in] band per patch, the distance within which its own samples lie (the noise band)
  * \param[in] num_threads OpenMP threads (0: default)
  * \param[in,out] patches members updated (planes kept as they are)
  * \param[in,out] labels per-sample patch label, updated
  * \param[in] within_bands also between parallel planes offset by no more than the wider band, once
  *            settleStepRegions has given each its regions (DetectorParameters::step_regions): along
  *            the rim of a window inside a wall's band, the wall's samples in its noise tail lie
  *            nearer the window, and their neighbours, not their distance, say where they lie
  * \return samples moved
  */
std::size_t
settleStepSides (const PointSet& points, const NeighborGraph& graph, const std::vector<double>& band, int num_threads,
                 std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels, bool within_bands = false);

} // namespace rspd
} // namespace pcl
