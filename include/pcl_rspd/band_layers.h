/*
 * pcl_rspd: band layers — the tests that a seed (of the small-plane pass, or of released samples) is
 * part of a plane already found, and the merge of grown planes that are layers of one plane's band.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/neighbor_graph.h>
#include <pcl_rspd/plane_detector.h>
#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/point_set.h>

#include <cstdint>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Whether a seed of the small-plane pass (or a plane seeded on what growth left) is a layer
  * of a plane already found rather than a new plane: more than half of its members lie within the
  * noise band of a plane that one of their graph neighbours holds.
  *
  * Such a seed is the samples between a door 2 cm proud of its wall and the wall, or a second copy
  * of a small plane's own noise rim.
  *
  * A plane that is itself bent at an edge, and that the seed bends away from, does not count: the
  * seed is the rest of the face that plane grew onto, not a layer of its noise. Where normals are
  * noisy, growth crosses a shallow edge (MND reaches 30-70° on synpeb_pc01), the plane holds part of
  * the face beyond, its spread and band widen, and the band covers the rest of that face
  * (synpeb_pc01: a band of 17 cm over a box face 28° away, whose seed of 753 samples was turned
  * down; the bent-plane split, later, cuts the part the plane holds off again). Bent: two planes
  * meeting at an edge explain its members (bentAtAnEdge). Bends away: the seed's own plane lowers
  * the robust σ of its samples' distances to at most DetectorParameters::bent_sigma_ratio of that
  * plane's, and the two meet at more than 90° minus T1's angle (the bent-plane split's measure,
  * isBend). A flat plane keeps its band: the next facet of a pipe or tank, a face 20-30° from the
  * facet beside it, or a strip along a real room's edge is still a layer (measured: with no
  * condition on the plane, room_scan1 got three more planes, strips along its edges; with "noisier
  * than the seed" as the condition, the industrial scene at σ = 3 cm let 46 pipe and tank facets in
  * and got one more false plane, a strip of a tank).
  * \param[in] points samples (positions and normals)
  * \param[in] graph their k-NN graph
  * \param[in] params T1's angle and bent_sigma_ratio
  * \param[in] patches the planes found
  * \param[in] band per plane, the distance within which its noise lies
  * \param[in] labels per sample, the plane holding it (kNoPatch: none)
  * \param[in] seed the candidate (members, center, normal)
  * \param[out] beside if not null: whether the seed is no layer only because it is a face beside a
  * plane (without that rule, it would be one)
  */
bool
isBandLayer (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
             const std::vector<PlanarPatch>& patches, const std::vector<double>& band,
             const std::vector<std::uint32_t>& labels, const PlanarPatch& seed, bool* beside = nullptr);

/** \brief Whether a candidate plane's members lie on a plane already found at least as closely as on
  * their own: for some plane that a graph neighbour of a member holds (where no member has one: that
  * a sample holds which counts a member among its neighbours), the robust σ of the members'
  * distances to it is no larger than to the candidate's own plane (center, normal), within twice
  * that σ's standard error (robustSigmaBound).
  *
  * The candidate's plane rests on its members' normals (the median of Eq. 4), its neighbour's on
  * thousands of samples. Samples along an edge, released by the plane across it, have normals bent
  * towards it: the plane beside them, which they lie on, turns them down by its normal test, and
  * together they pass T1-T3 as a narrow strip whose median normal is bent too (the staircase's top
  * tread on PCL's k = 50 normals: 162 samples in a strip 4 cm wide, tilted 22°, σ 2.6 mm about its
  * own plane against 1.2 mm about the tread's). A real plane beside another lies off it: a recessed
  * window's samples are 5-10 times farther from the wall than from their own plane (the facade at
  * 10,000 points). Within the error: the candidate's own plane was fitted to its members, so a piece
  * of the plane beside it measures a little closer to its own as often as not (a room scanned on a
  * grid: the ceiling's samples around the zenith, on rings whose neighbourhoods give normals in the
  * ceiling, 1,197 of them at σ 4.79 mm about their own plane against 4.86 about the ceiling's, were
  * kept as a plane of their own). The rings of such a scan below and above its head are dense
  * enough that a disc of them is each other's nearest: no edge leads out of it, but the floor's
  * samples around it have members among their nearest (the grid room in layout 315 at 212,000
  * points: 1,195 ring samples kept as a fragment of the floor without the edges into them).
  * \param[in] points samples
  * \param[in] graph their k-NN graph
  * \param[in] patches the planes found
  * \param[in] labels per sample, the plane holding it (kNoPatch: none)
  * \param[in] candidate its members (none held by a plane), center and normal
  * \param[out] on if given and the candidate lies on a plane: that plane (the first of those beside it
  *   in index order that it lies on); otherwise untouched */
bool
liesOnNeighbourPlane (const PointSet& points, const NeighborGraph& graph, const std::vector<PlanarPatch>& patches,
                      const std::vector<std::uint32_t>& labels, const PlanarPatch& candidate,
                      std::uint32_t* on = nullptr);

/** \brief One pass of the layer merge (DetectorParameters::layer_merge): each plane A that is a layer
  * of a larger plane B's noise band joins B, and B is estimated again on both (estimatePlane).
  *
  * A layer of B: at least half of A's members have a graph neighbour held by B (A lies among B's
  * samples, not beside them), M2 holds (normalsCompatible), the median distance of A's members to
  * B's plane is within B's band, and A's tilt against B across its extent (sine of the angle times
  * the farthest member's distance from A's centre in B's plane) is within B's band too; and, with
  * DetectorParameters::layer_steps, A is no step beside B: its members' neighbourhoods (their
  * samples held by A or B) average, at the median member, within half a robust σ of A's and B's
  * joint least-squares plane (a window recessed within its wall's band, whose near samples the wall
  * holds, has a wall neighbour at every member but stands 2 σ off that plane).
  *
  * Why: two seeds of one noisy face grow at once, each takes the samples on its side of the face's
  * noise band, and re-estimation (Sec. 3.5) centres each on its own side: two interleaved planes a
  * noise σ or so apart, each with an MDP too narrow for M3 and M4 to join them (the room's cabinet
  * front, σ 5 mm along the ray: 1,208 and 621 samples 4.6 mm apart, MDPs 5.3 and 3.8 mm; a σ = 6 mm
  * box side at 300,000 points: 738 and 535 samples 8.1 mm apart). A plane beside B is not among its
  * samples (a door 2 cm proud of its wall: more than half of its 739 samples border the wall, but
  * they lie 2.0 cm off it, beyond its 1.4 cm band); a plane across a shallow edge tilts out of B's
  * band (synpeb_pc01: a plane of two faces 22° from a plane whose band is 12 cm wide, tilted 14 cm
  * across its 0.32 m). A plane that is a layer itself takes no layer in the same pass.
  * \param[in] points samples (positions and normals)
  * \param[in] graph their k-NN graph
  * \param[in] params Eqs. 3-9's parameters for the estimate again; num_threads
  * \param[in] band per plane, the distance within which its noise lies
  * \param[in,out] patches the planes; layers merged are removed, order otherwise kept
  * \param[in] labels per sample, the plane holding it (kNoPatch: none), as before the call
  * \return planes merged into another
  */
std::size_t
mergeBandLayers (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                 const std::vector<double>& band, std::vector<PlanarPatch>& patches,
                 const std::vector<std::uint32_t>& labels);

} // namespace rspd
} // namespace pcl
