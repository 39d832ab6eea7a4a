/*
 * pcl_rspd: PCA normals over the growth graph's k-neighbourhoods, at the k-scale or at the finest
 * scale that resolves a surface.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/neighbor_graph.h>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Unit normals by PCA over each sample and its graph neighbours.
  *
  * The neighbourhoods of the growth graph are reused (one k-NN pass serves both), so this costs one
  * 3x3 eigenproblem per sample. Each normal is the eigenvector of the smallest eigenvalue of the
  * covariance of the sample and its k neighbours (double precision), unoriented. A degenerate
  * neighbourhood (all samples coincide) gets +Z; it fails T2 wherever it matters.
  * \param[in] points centred positions
  * \param[in] graph their k-NN graph
  * \param[in] num_threads OpenMP threads (0: default); the result does not depend on it
  * \param[out] normals one unit vector per sample
  */
void
estimateNormals (const std::vector<Eigen::Vector3f>& points, const NeighborGraph& graph, int num_threads,
                 std::vector<Eigen::Vector3f>& normals);

/** \brief Which neighbourhood a sample's normal comes from when the caller gives no normals. */
enum class NormalScale
{
  /** \brief The sample's k-neighbourhood in the growth graph (the paper; estimateNormals). */
  Fixed,
  /** \brief Per sample, the finest scale whose neighbourhood resolves a surface
    * (estimateAdaptiveScaleNormals): the k-neighbourhood wherever it resolves one. */
  Adaptive,
  /** \brief Adaptive when the k-scale fails for the scene as a whole, i.e. for most of its samples
    * (the median sample's k-neighbourhood resolves no surface); Fixed otherwise. */
  Automatic
};

/** \brief What the adaptive scale did, for logs and tests. */
struct NormalScaleStatistics
{
  double isotropic_ratio = 0.0;     ///< the resolution test's bound on λ0/λ1 (for this k)
  std::size_t unresolved_at_k = 0;  ///< samples whose k-neighbourhood resolves no surface
  /** \brief Of those, samples that passed the test while most of their neighbours did not (a chance
    * pass; counted only where most samples are unresolved at k). */
  std::size_t chance_resolved = 0;
  /** \brief [s]: samples whose normal comes from the k-neighbourhood among every 2^s-th sample; [0]:
    * the k-scale, including the samples no scale resolved and, when no wider scale was searched,
    * every sample. */
  std::vector<std::size_t> samples_per_scale;
  std::size_t unresolved = 0;       ///< samples left unresolved; they keep the k-scale normal
  bool widened_scales = false;      ///< whether wider scales were searched at all

  /** \brief Samples whose normal comes from a wider scale than the k-neighbourhood. */
  std::size_t
  widened () const
  {
    std::size_t w = 0;
    for (std::size_t s = 1; s < samples_per_scale.size (); ++s)
      w += samples_per_scale[s];
    return w;
  }
};

/** \brief Unit normals by PCA at the finest scale whose neighbourhood resolves a surface.
  *
  * Why: when the noise along the normal is about as large as the radius of a k-neighbourhood (a
  * million samples on a unit cube with 1 % noise, k = 50), the k samples fill a ball rather than a
  * slab, the smallest-variance direction is noise (it may lie in the plane), and T2, T3 and the growth,
  * which all test per-sample normals, find nothing. A wider neighbourhood would resolve the plane, but a
  * wider one everywhere blurs every edge, so each sample gets the finest scale that works for it.
  *
  * Scales: scale s is the k-neighbourhood among every 2^s-th sample of \a points, which must be in
  * spatial (Morton) order, as RobustPlaneSegmentation stores them: that subsample is spread evenly, so
  * its k neighbours span about 2^s times the area of the k-neighbourhood, while k stays k. Scale 0 is
  * the graph's own neighbourhood (the normal estimateNormals gives, bit for bit).
  *
  * Resolution test: a neighbourhood resolves a surface when the ratio λ0/λ1 of its two smallest
  * covariance eigenvalues is below isotropicEigenRatioQuantile (k, 0.05), the value that k + 1 samples
  * filling a ball (no surface at that scale) stay under only 5 % of the time: the test rejects
  * "volume, not surface" at the 5 % level. Nothing else is a constant, and every quantity is a ratio or
  * a count, so the scale picked does not depend on units, position or orientation.
  *
  * Chance passes: where most samples are unresolved at the k-scale, a sample that passes the test
  * while fewer than half of its graph neighbours do is counted unresolved too (the 5 % level passes
  * one noise-dominated neighbourhood in twenty by chance).
  *
  * Each sample starts at scale 0. While unresolved it moves to the next scale, where it reads the
  * neighbourhood of its representative: of the two samples of every 2^(s+1)-th that bracket it in
  * the spatial order, the nearer (every other sample of the scale: a normal over k of them changes
  * over the neighbourhood's radius, not from one sample to the next, and this halves the searches).
  * Only the representatives of still unresolved samples are searched (visitKnnRows), so a scene
  * resolved at the k-scale pays one eigenvalue ratio per sample, and a scale is searched only for the
  * samples that need it. A sample that no scale resolves (a stray outlier, a thin wire, a corner)
  * keeps its scale-0 normal. The result does not depend on the thread count.
  *
  * Known cost of widening every unresolved sample (measured, README): a cloud's outliers or clutter
  * can look like a surface at a wide scale (uniform outliers filling a thin box), so some of them get
  * a surface normal and join a plane. NormalScale::Automatic (\a only_when_most_unresolved) widens only
  * when the k-scale fails for most samples, which leaves every scene it resolves untouched.
  * \param[in] points centred positions, in spatial order
  * \param[in] graph their k-NN graph
  * \param[in] num_threads OpenMP threads (0: default)
  * \param[out] normals one unit vector per sample
  * \param[out] stats what happened (may be null)
  * \param[in] only_when_most_unresolved search wider scales only if more than half of the samples are
  * unresolved at the k-scale (NormalScale::Automatic); otherwise the result is estimateNormals'
  */
void
estimateAdaptiveScaleNormals (const std::vector<Eigen::Vector3f>& points, const NeighborGraph& graph,
                              int num_threads, std::vector<Eigen::Vector3f>& normals,
                              NormalScaleStatistics* stats = nullptr, bool only_when_most_unresolved = false);

/** \brief The \a quantile of λ0/λ1 (smallest over middle covariance eigenvalue) for a sample at the
  * centre of a ball and \a k others drawn uniformly in it: the k-neighbourhood of a volume that holds
  * no surface. A deterministic Monte Carlo estimate (4000 draws, fixed seed; standard error about
  * 0.003), computed once per (k, quantile) and cached. For k = 50: 0.58 at the 5 % quantile.
  * \param[in] k neighbours (>= 2)
  * \param[in] quantile in (0, 1)
  */
double
isotropicEigenRatioQuantile (int k, double quantile);

/** \brief What givenNormalsAreNoise measured, for logs and tests. */
struct GivenNormalCheck
{
  std::size_t probes = 0;          ///< samples tested (every n/4096-th, at least every sample up to 4096)
  std::size_t unresolved = 0;      ///< of those, samples whose k-neighbourhood resolves no surface
  double given_spread = 0.0;       ///< median over probes of the median angle (radians) to the neighbours' given normals
  double neighbourhood_spread = 0.0; ///< the same for the k-neighbourhoods' PCA normals (0 when not measured)
  int fine_k = 0;                  ///< givenNormalsBlurFaces: the finer neighbourhood's size (0: not measured)
  std::size_t fine_resolved = 0;   ///< of the probes, those whose fine_k nearest resolve a surface
  std::size_t fine_tilted = 0;     ///< of those, the ones the given normal fits worse than kBlurResidualRatio allows
  std::size_t graph_tilted = 0;    ///< of the resolved probes, those the graph's k-neighbourhood PCA normal fits worse so
  std::size_t graph_and_given_tilted = 0; ///< of those, the ones the given normal fits worse too
};

/** \brief givenNormalsBlurFaces: a given normal is tilted off its sample's surface when its plane
  * through the fine neighbourhood's mean leaves more than this many times the residual variance of
  * that neighbourhood's own plane: the tilt adds more than the noise does. */
constexpr double kBlurResidualRatio = 2.0;

/** \brief Whether normals given with a cloud blur the faces the samples resolve at a finer scale:
  * of the probed samples (every n/4096-th) most have their \a fine_k nearest neighbours resolving a
  * surface (the resolution test of estimateAdaptiveScaleNormals at that size), and either at most of
  * those the given normal fits that neighbourhood worse than kBlurResidualRatio times its own PCA
  * plane (variance along the given normal about the neighbourhood's mean, against its least
  * eigenvalue), or it does so at most of those where the PCA normal of the graph's whole
  * k-neighbourhood does: the given normals blur the faces as normals of the graph's scale do.
  *
  * The second test asks about the scale of the normals, not about how much of the scene lies near
  * an edge: PCL's k = 50 normals of a 8,000-sample facade are tilted at 12 % of the resolved probes
  * only (its faces are large), but at 95 % of those where the 50-neighbourhood is, and on them one
  * plane held two windows' panes (15 of 16 planes found; 16 at the automatic k). Normals of the finer
  * scale are tilted at none of them, the true planes' normals at 0-19 % (measured on generated
  * scenes at 8,000-50,000 samples); a noisy cube's true normals, tilted at 65 % of the few such
  * probes (5 % of the resolved, made by its noise of 1 % of its edge), are the exception measured:
  * at 20,000 samples they were estimated again, F1 0.9856 -> 0.9847.
  *
  * PCL's k = 50 normals on a sparse staircase (5,000-8,000 samples on 30-38 faces, each a few
  * hundred) come from balls that span two or three steps: they turn towards the stair's slope,
  * smoothly, so they agree with their neighbours and givenNormalsAreNoise keeps them; every cell then
  * seeds the slope, and one plane held the stair (F1 0.02 and 0.01; 0.98 on normals estimated here
  * at the automatic k = 15). Where the given normals do describe the faces the finer neighbourhoods
  * resolve, only those near edges fit worse (3.5-23 % of the resolved probes, measured on generated
  * scenes and synpeb_test100). Ratios only: free of any length. Deterministic.
  * \param[in] points samples
  * \param[in] graph their k-NN graph (k > fine_k)
  * \param[in] fine_k the finer neighbourhood: the fine_k nearest of each probe's graph neighbours
  * \param[in] num_threads OpenMP threads (0: OpenMP's default)
  * \param[in] given the caller's normals, one per sample (unit length)
  * \param[out] check if not null: probes, fine_k, fine_resolved and fine_tilted are set (the rest kept) */
bool
givenNormalsBlurFaces (const std::vector<Eigen::Vector3f>& points, const NeighborGraph& graph, int fine_k,
                       int num_threads, const std::vector<Eigen::Vector3f>& given, GivenNormalCheck* check = nullptr);

/** \brief Whether normals given with a cloud are noise at the graph's scale: most probed samples'
  * k-neighbourhoods resolve no surface (the resolution test of estimateAdaptiveScaleNormals), and
  * the given normals agree with their neighbours' no better than those k-neighbourhoods' PCA
  * normals do (median over the probes of the median angle to the graph neighbours' normals).
  *
  * PCA normals over k = 50 neighbours of a 1M-point cube with noise 1 % of its edge come from a
  * ball about as wide as the noise: every face's normals spread past T2, and no cell seeds a plane.
  * Normals the caller estimated at a wider scale agree with each other better than the
  * k-neighbourhoods' and are kept. Relative, so free of any length. Deterministic.
  * \param[in] points samples
  * \param[in] graph their k-NN graph
  * \param[in] num_threads OpenMP threads (0: OpenMP's default)
  * \param[in] given the caller's normals, one per sample (unit length)
  * \param[out] check if not null: what was measured */
bool
givenNormalsAreNoise (const std::vector<Eigen::Vector3f>& points, const NeighborGraph& graph, int num_threads,
                      const std::vector<Eigen::Vector3f>& given, GivenNormalCheck* check = nullptr);

/** \brief OpenMP thread count for a request (0: OpenMP's default, i.e. OMP_NUM_THREADS). */
int
resolveThreads (int requested);

/** \brief Prefix sizes narrowNormalsAtEdges steps through: k_min, k_min + 5, ..., k. */
constexpr int kEdgeNormalStep = 5;
/** \brief narrowNormalsAtEdges: a prefix whose variance along its normal exceeds this many times the
  * k_min nearest's reaches across an edge. The smallest eigenvalue of a flat face's neighbourhood is
  * its noise variance whatever the radius; one across an edge grows with the radius squared. */
constexpr double kEdgeSpreadRatio = 3.0;
/** \brief narrowNormalsAtEdges: the face's normal replaces the k-normal only if they differ by more
  * than this many standard errors of the face's normal (noise alone rarely does). */
constexpr double kEdgeTurnErrors = 4.0;

/** \brief Edge-aware normals (departure; RobustPlaneSegmentation::setEdgeAwareNormals for every
  * sample, off by default, and setLeftNormalNarrowing for the samples the small-plane pass left, on):
  * each sample's PCA normal over the widest prefix of its neighbours, nearest first, that stays on one
  * face, where that differs from its k-neighbourhood's normal by more than noise.
  *
  * Why: a PCA normal over k neighbours bends within a neighbourhood's radius of an edge, and on a
  * small face (a cabinet's top of 250-300 samples in a 100,000-point room, k = 50) that band is most
  * of the face; every cell of it then fails T1 or T3, and the face is never seeded. The smallest
  * covariance eigenvalue λ0 of a neighbourhood on one flat face is its noise variance, whatever its
  * radius; once the neighbourhood reaches across an edge it grows with the radius squared. So the
  * prefixes k_min, k_min + kEdgeNormalStep, ..., k are fitted in turn, λ0 of the k_min nearest is the
  * reference, and the first prefix whose λ0 exceeds kEdgeSpreadRatio times it ends the sample's face
  * (the prefix before it). Its normal replaces the k-normal only if the two differ by more than
  * kEdgeTurnErrors standard errors of the face's normal, sqrt(λ0 / ((m + 1) λ1)): in noise, where a
  * narrower normal is only a noisier one, the k-normal stands. Ratios and angles only: no length
  * enters. Per sample, so the result does not depend on the thread count.
  * \param[in] points centred positions
  * \param[in] graph their k-NN graph
  * \param[in] num_threads OpenMP threads (0: default)
  * \param[in] k_min the narrowest prefix (>= 2; nothing happens unless k > k_min)
  * \param[in,out] normals the k-neighbourhoods' PCA normals (estimateNormals), narrowed in place
  * \param[out] narrowed_flags if given, per sample whether its normal was narrowed
  * \param[in] subset if given, only these samples' normals are narrowed (the others are kept, and
  *            flagged 0)
  * \return samples whose normal was narrowed */
std::size_t
narrowNormalsAtEdges (const std::vector<Eigen::Vector3f>& points, const NeighborGraph& graph, int num_threads,
                      int k_min, std::vector<Eigen::Vector3f>& normals, std::vector<char>* narrowed_flags = nullptr,
                      const std::vector<std::uint32_t>* subset = nullptr);

} // namespace rspd
} // namespace pcl
