/*
 * pcl_rspd: outlier-resistant normals on the same k-neighbourhoods (least trimmed squares planes).
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
/** \brief How an estimated normal is fitted to its neighbourhood. */
enum class NormalFit
{
  Pca,         ///< least squares over the whole k-neighbourhood (the paper's PCA normals)
  TrimmedPlane ///< least trimmed squares, then reweighted (refineNormalsTrimmed)
};

/** \brief What refineNormalsTrimmed did, for logs and tests. */
struct TrimmedNormalStatistics
{
  std::size_t refined = 0;     ///< samples given the reweighted trimmed plane's normal
  std::size_t unresolved = 0;  ///< samples whose k-neighbourhood resolves no surface (left as given)
  std::size_t collinear = 0;   ///< samples whose trimmed plane rests on a line (left as given)
};

/** \brief Replace each sample's normal by that of the least-trimmed-squares plane of its
  * k-neighbourhood, reweighted.
  *
  * Why: a PCA normal within a neighbourhood radius of an edge averages the two faces (it bends),
  * and one stray sample tilts it; the bent normals widen every patch's MND there and stop growth
  * short of the edge. The paper's evaluation used FAST-MCD normals for this reason. Here, per
  * sample, over the sample and its k graph neighbours (m = k + 1):
  *  - the plane minimising the sum of the h = ⌊(m + 4) / 2⌋ smallest squared residuals (LTS's
  *    coverage (m + p + 1) / 2 with p = 3), found by concentration steps (refit on the h samples
  *    nearest the current plane until the sum stops falling) from two starts: the PCA plane of all m,
  *    and that of the h samples nearest the sample itself (its own face near an edge); the lower sum
  *    wins;
  *  - reweighting: every sample within 2.24 σ of that plane (χ²₁ at 97.5 %), σ from the h smallest
  *    squared residuals made consistent for a Gaussian; the normal is the PCA normal of those. This
  *    gives back the efficiency trimming costs on a flat, noisy surface.
  * Left as given: samples whose k-neighbourhood resolves no surface (λ0/λ1 at or above
  * isotropicEigenRatioQuantile (k, 0.05); their normal may come from a wider scale), and samples
  * whose reweighted set is elongated more than twice the whole neighbourhood (λ1/λ2 below half of
  * the neighbourhood's): on a scan whose lines are farther apart than the points along them, the
  * trimmed set can be one or two scan lines, whose plane is undetermined about them.
  * No length is involved (residuals are compared to their own scale); the result does not depend on
  * the thread count or on the orientation of the cloud.
  * \param[in] points centred positions
  * \param[in] graph their k-NN graph
  * \param[in] num_threads OpenMP threads (0: default)
  * \param[in,out] normals one unit vector per sample, replaced where refined
  * \param[out] stats what happened (may be null)
  * \param[in] subset only these samples are refined (all when null)
  */
void
refineNormalsTrimmed (const std::vector<Eigen::Vector3f>& points, const NeighborGraph& graph, int num_threads,
                      std::vector<Eigen::Vector3f>& normals, TrimmedNormalStatistics* stats = nullptr,
                      const std::vector<std::uint32_t>* subset = nullptr);

} // namespace rspd
} // namespace pcl
