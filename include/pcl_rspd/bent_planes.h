/*
 * pcl_rspd: bent planes — a departure that splits a plane whose members lie on two planes meeting at an edge.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/neighbor_graph.h>
#include <pcl_rspd/plane_detector.h>
#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/point_set.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Two planes fitted to one set of samples, one on each side of a straight cut (fitHinge). */
struct HingeFit
{
  std::vector<std::uint32_t> parts[2]; ///< the samples on each side of the cut
  double single_sigma = 0.0;           ///< robust σ (1.4826 median |d|) about the set's least-squares plane
  double split_sigma = 0.0;            ///< robust σ about each side's own least-squares plane
  double angle = 0.0;                  ///< angle between the two sides' planes (radians, in [0, π/2])
  Eigen::Vector3d side_normal[2];      ///< each side's least-squares plane normal
};

/** \brief The straight cut across a set of samples whose two sides are best explained by two planes.
  *
  * Cuts run perpendicular to 16 in-plane directions of the set's least-squares plane (every 11.25
  * degrees), at each of 127 evenly spaced positions along the direction; the cut whose two sides'
  * least-squares planes leave the smallest sum of squared distances wins. Per-bin sums make a cut
  * O(1), so the search is O(16 n); sets of more than 16,384 samples are searched on an evenly spaced
  * subset of that size (the cut is a coarse feature), and the result is measured on all of them.
  * \param[in] points samples
  * \param[in] samples the set (internal indices)
  * \param[out] fit both sides, their robust spreads and angle
  * \return false if no cut leaves two sides that each determine a plane
  */
bool
fitHinge (const PointSet& points, const std::vector<std::uint32_t>& samples, HingeFit& fit);

/** \brief Whether \a fit is a bend, as splitBentPlanes judges one: the two sides' planes lower the
  * robust σ to at most DetectorParameters::bent_sigma_ratio of the one plane's, and they meet at more
  * than 90° minus T1's angle. */
bool
isBend (const HingeFit& fit, const DetectorParameters& params);

/** \brief Whether the normals confirm \a fit as an edge where the positions alone do not (see
  * DetectorParameters::bent_normal_edges): its sides' planes meet at more than 90° minus T1's angle,
  * the σ ratio is at most √((1 + r²) / 2) for r = bent_sigma_ratio, the sides' mean normals turn by
  * more than 90° minus T1's angle, and across the two sides they turn in one step at least as
  * clearly as steadily (normalTurnRatio >= 1: an edge, not a curved surface). Always false when the
  * option is off. */
bool
isEdgeTheNormalsConfirm (const PointSet& points, const HingeFit& fit, const DetectorParameters& params);

/** \brief Whether two planes meeting at an edge explain \a samples (fitHinge, then isBend), and, with
  * DetectorParameters::hinge_normal_turn, whether the two sides' mean normals turn by more than 90°
  * minus T1's angle too. A group of thick cells along a noisy cube's edge (half on either face, each
  * half's normals bent towards the other) passes T1-T3 as a long strip; a riser as narrow is flat. */
bool
bentAtAnEdge (const PointSet& points, const std::vector<std::uint32_t>& samples, const DetectorParameters& params);

/** \brief Bent planes (departure, DetectorParameters::bent_plane_split): split every plane whose
  * members lie on two planes meeting at an edge, and each part again (at most three levels).
  *
  * Where PCA normals are noisy (a k-neighbourhood barely wider than the noise), MND is wide: growth
  * crosses an edge to a face bent by less than MND, each re-estimate (Sec. 3.5) tilts the plane
  * towards that face and widens MDP, and the plane ends up holding both faces (synpeb_pc01's boxes:
  * faces 19-42 degrees apart, MND 30-70 degrees). Positions still tell the faces apart. A plane is
  * split at fitHinge's cut when
  *  - the two sides' planes lower the robust σ of the distances to at most
  *    DetectorParameters::bent_sigma_ratio (0.8) of the one plane's: a bend, not noise (on flat
  *    noisy planes of 100 to 30,000 samples the search never got below 0.85), or the normals
  *    confirm an edge the positions show less clearly (isEdgeTheNormalsConfirm);
  *  - they meet at more than 90° minus T1's angle (15° by default): T1 accepts a cell whose samples
  *    spread over that slope as one plane, so a gentler bend is what the paper calls a plane (a
  *    scanned wall that bows, or steps by its noise);
  *  - each side has at least ε samples and passes the robust planarity test (Sec. 3.2, T1-T3), its
  *    T2 bounded by the MND of the plane it was cut from where that is wider than T2's 60°
  *    (DetectorParameters::bent_side_parent_mnd).
  * The result does not depend on the thread count (planes are independent).
  * \param[in] points samples
  * \param[in] params constants (ε, T1-T3, bent_sigma_ratio, threads)
  * \param[in,out] patches planes; a split plane keeps its place for its largest part, the others are
  * appended, and every part is estimated again (Eqs. 3-9)
  * \param[out] split if not null: per plane (after the split), whether it is a part of a split plane
  * \return planes added
  */
std::size_t
splitBentPlanes (const PointSet& points, const DetectorParameters& params, std::vector<PlanarPatch>& patches,
                 std::vector<char>* split = nullptr);

/** \brief Bent planes among noisy seeds' planes (departure, DetectorParameters::noisy_bent_split):
  * before a plane a noisy seed seeded (PlanarPatch::retested) is judged flat once grown, one that is
  * not flat (isFlatPatch) is split at fitHinge's cut when the cut is a bend (isBend), each side has
  * at least ε samples and each side is flat once grown (a retested plane each); what is still not flat
  * is then dropped by that judgement. Such a plane's MND is wide and growth carries it over an edge
  * onto the next face, whose samples bend it: it was dropped whole, and the bent-plane split, which
  * runs later, never saw it (the boxes at 10,000 points on PCL's k = 50 normals, faces of 40-120
  * samples). A facet of a pipe cut in two leaves halves that still bend, and is dropped as before.
  * Planes are taken in order; the result does not depend on the thread count.
  * \param[in] points samples
  * \param[in] params constants (ε, T1's angle, bent_sigma_ratio, bend_confidence, min_curvature_share)
  * \param[in,out] patches planes; a split plane keeps its place for the side below the cut and the
  * other side is appended, each estimated again (Eqs. 3-9)
  * \param[out] flat if not null: per plane (after the split), whether it is flat once grown (true
  * for a plane no noisy seed seeded, and for both sides of a split), so that the judgement need
  * not measure it again
  * \return planes added */
std::size_t
splitBentNoisyPlanes (const PointSet& points, const DetectorParameters& params, std::vector<PlanarPatch>& patches,
                      std::vector<char>* flat = nullptr);

/** \brief Bent planes, second step: join again a face that two bent planes shared.
  *
  * Where growth carried two planes across their edges onto the same face (synpeb_pc01: a box face
  * of 4,102 samples, 1,518 held by one plane and 2,318 by another, each also holding a face of its
  * own), splitBentPlanes cuts each at its edge and leaves the face in two parts, coplanar and
  * touching, which no merge joins any more. Two planes are joined when at least one of them is a
  * part the split produced, a graph edge joins their members (M1), their normals meet at no more
  * than 90° minus T1's angle (15°: what T1 accepts as one plane), and their union is neither bent
  * nor stepped (fitHinge lowers its robust σ by less than bent_sigma_ratio and the normals confirm
  * no edge, isEdgeTheNormalsConfirm: the test by which the split joins its own leaves). Pairs are
  * taken largest first; a joined plane is estimated again. The result does not depend on the thread
  * count.
  * \param[in] points samples
  * \param[in] graph their k-NN graph
  * \param[in] params constants (T1's angle, bent_sigma_ratio, ε)
  * \param[in,out] patches planes; a joined pair keeps the larger's place
  * \param[in] split per plane, whether splitBentPlanes produced it (as it reports)
  * \return planes absorbed
  */
std::size_t
joinSplitFaces (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                std::vector<PlanarPatch>& patches, const std::vector<char>& split);

} // namespace rspd
} // namespace pcl
