/*
 * pcl_rspd: plane support — a departure that takes off a plane the samples that lie beyond its
 * other samples, where only outliers can be.
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
/** \brief A member is unsupported when its gap to the nearest other member of its plane, measured
  * in the plane, is more than this many times the median gap of its neighbours in the plane. For
  * samples spread uniformly over a plane, the nearest-neighbour distance r has P(r > c · median) =
  * 2^(-c²), or 2^(-c²/2) on the rim, where half the disc is empty: 6 makes that 4·10⁻⁶ for a rim
  * sample. */
constexpr double kSupportGapRatio = 6.0;

/** \brief A one-sided member is unsupported when it lies ahead of all its neighbours in its plane,
  * along their mean direction from it, by more than this many times the median gap of those
  * neighbours. On a straight rim of a uniform plane the nearest of the ~k samples in the strip
  * behind a rim sample lies ahead of it by an exponential distance of mean ~s²/(2R) (s the sample
  * spacing, R the neighbourhood's radius), far below the gap (~0.47 s): for k = 50, P(depth > c ·
  * median gap) ≈ e^(-5.3 c), 2.5·10⁻⁵ for 2. An outlier a few spacings beyond the rim, whose gap is
  * still ordinary, is ahead by about its distance. */
constexpr double kSupportDepthRatio = 2.0;

/** \brief Rounds of release at most: each round's releases expose the members behind them (a
  * small cluster of outliers beyond a rim, each the other's support), and only their neighbourhoods
  * are judged again. The bound keeps the cost linear whatever the cloud. */
constexpr int kSupportRounds = 8;

/** \brief A one-sided member whose plane neighbours within reach (kSupportGapRatio times their
  * median gap, times the plane's gap spread), and theirs, hop by hop, number fewer than this, all
  * one-sided, is in a detached group: outliers beyond the rim that support one another's gaps and
  * depths (the facade: pairs 7 to 20 spacings beyond its wall and its windows). The detector's
  * smallest seed cell holds 10 samples, so no plane is this small; a sliver of a plane cut off by
  * an occluder loses at most this many samples. */
constexpr std::size_t kDetachedGroupSize = 5;

/** \brief Quantile of a plane's member gaps that measures their spread against the median: 0.9,
  * where uniform samples' gaps are 1.82 times the median and rows of samples' gaps are the row
  * spacing, so that the reach of a detached group spans the rows of a scan (see
  * kDetachedGroupSize). */
constexpr double kGapSpreadQuantile = 0.9;

/** \brief A member with fewer than this share of its graph neighbours in its own plane cannot be
  * vouched for by their gaps: a few outliers near one another support one another's gaps. A plane's
  * own sample has half its neighbourhood in the plane on a straight rim and a quarter in a corner. */
constexpr double kMinSupportShare = 0.1;

/** \brief A member is one-sided, i.e. on or beyond its plane's rim, when the mean of the unit
  * in-plane directions to its neighbours in the plane is longer than this: 0 for a sample amid its
  * plane, 2/π ≈ 0.64 on a straight rim, towards 1 beyond it. */
constexpr double kOneSidedResultant = 0.5;

/** \brief Plane support (departure, DetectorParameters::support_check): release every member that
  * lies beyond the rest of its plane, where the plane's own samples would be rare.
  *
  * Growth and the last assignment admit a sample by its distance to the plane (and growth by its
  * normal). An outlier within the plane's noise band just beyond its rim passes both: its
  * k-neighbourhood is the rim, so its PCA normal is the plane's; a voxel metric counts each such
  * sample as a voxel of false plane (the facade's 15 % outliers in its wall's band beyond the wall
  * and inside the window openings). A member i of plane l is released when (1) its in-plane gap to
  * the nearest graph neighbour in l (0 for one that coincides with it) exceeds kSupportGapRatio
  * times the median of those neighbours' own gaps, or it lies ahead of all of them by more than
  * kSupportDepthRatio times that median (an outlier a few spacings beyond a straight rim), or fewer
  * than kMinSupportShare of its neighbours are in l (a pair of outliers is each other's support),
  * or it belongs to a detached group of fewer than kDetachedGroupSize one-sided members;
  * (2) it is one-sided (kOneSidedResultant), so a hole amid a plane keeps its samples; and (3) it
  * lies within the noise band of no other plane that a graph neighbour holds: where two planes
  * meet, the edge-side rule has settled the owner, and a sample of a sparse plane beside a dense one
  * has few neighbours in its own. The gaps are ratios of lengths in the sample's neighbourhood, so
  * the rule does not depend on scale or density. The rule peels: up to kSupportRounds rounds, each judging again the members next to the last round's
  * releases. Each round's passes read the labels before it: the result does not depend on the
  * thread count.
  *
  * With \a clutter_share (DetectorParameters::support_clutter), a member anywhere in its plane,
  * rim or not, is also released when its plane is no denser in its noise band than the clutter
  * outside the band: within the ball its k-neighbourhood spans (radius R, to its farthest
  * neighbour), the plane's samples per volume of the band's slice of the ball are at most the
  * unlabelled samples per volume of the rest of the ball. A sheet of clutter that a noisy plane's
  * band took is that clutter's density by construction, while a plane's own samples, even a sparse
  * wall's among 20 % outliers, are many times denser within a band a few σ wide. Counts over
  * volumes of one ball are ratios: no scale enters.
  * \param[in] points samples
  * \param[in] graph k-NN graph
  * \param[in] band per patch, the distance within which its own samples lie (the noise band)
  * \param[in] num_threads OpenMP threads (0: default)
  * \param[in,out] patches members updated; planes left without members are removed
  * \param[in,out] labels per-sample patch label, updated (kNoPatch for the released samples)
  * \param[in] clutter_share also release members whose plane is no denser than the clutter there
  * \param[out] clutter_released if given, the samples released for that alone
  * \return samples released
  */
std::size_t
releaseUnsupportedMembers (const PointSet& points, const NeighborGraph& graph, const std::vector<double>& band,
                           int num_threads, std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels,
                           bool clutter_share = false, std::size_t* clutter_released = nullptr);

/** \brief Member gaps (departure, DetectorParameters::member_gaps): the in-plane gaps by which the
  * members next to the \a open samples vouch for them in the last assignment.
  *
  * The last assignment offers a sample growth left to the planes its graph neighbours hold, round by
  * round, each joiner offering the plane on to the samples beside it. In clutter beside a plane's
  * rim (the facade's outliers in its wall's band) that chain crossed the clutter: an outlier whose
  * k-neighbourhood reaches the dense rim has its neighbours in the plane, the next one has the first
  * one, and so on (a facade at σ 4.3 cm, 15 % outliers: 1,027 outliers more than 20 cm beyond their
  * planes' rims, F1 0.928). A sample joins a plane only where it lies among its members: its
  * in-plane gap to the nearest of them within kSupportGapRatio times their own gaps
  * (admittingGap); a joiner vouches for the next with the spacing that admitted it, so the chain
  * follows the plane's own samples along an edge band but not across clutter many spacings apart.
  *
  * Per member next to an open sample: its in-plane gap to the nearest graph neighbour in its own
  * plane that does not coincide with it (duplicates, as a scan repeats points, are no spacing),
  * if that is within kSupportGapRatio times the median of those neighbours' own gaps (as the plane
  * support asks); infinity for an unsupported member (an outlier growth took beside the rim,
  * which would vouch for the clutter around it); -1 for every other sample. Gaps are lengths in
  * the samples' own neighbourhoods, compared as ratios: no scale enters.
  * \param[in] points samples
  * \param[in] graph k-NN graph
  * \param[in] patches planes, indexed by label
  * \param[in] labels per-sample plane label (kNoPatch: none)
  * \param[in] open the samples the last assignment offers to the planes
  * \param[in] judged per plane, whether its members are measured (the planes in clutter)
  * \param[in] num_threads OpenMP threads (0: default)
  */
std::vector<float>
vouchingGaps (const PointSet& points, const NeighborGraph& graph, const std::vector<PlanarPatch>& patches,
              const std::vector<std::uint32_t>& labels, const std::vector<std::uint32_t>& open,
              const std::vector<char>& judged, int num_threads);

/** \brief Whether sample \a i lies among the members of plane \a l beside it (member gaps, see
  * vouchingGaps): the median of the vouching \a gaps of its graph neighbours in \a l, if its in-plane
  * gap to the nearest of those neighbours is within kSupportGapRatio times it; NaN otherwise (none
  * vouches, or it lies beyond their spacing).
  * \param[in] gaps as vouchingGaps returns, with the last assignment's joiners given the gap that
  *            admitted them
  */
float
admittingGap (const PointSet& points, const NeighborGraph& graph, const PlanarPatch& plane, std::uint32_t l,
              const std::vector<std::uint32_t>& labels, const std::vector<float>& gaps, std::uint32_t i);

} // namespace rspd
} // namespace pcl
