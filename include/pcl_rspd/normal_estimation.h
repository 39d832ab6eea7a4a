/*
 * pcl_rspd: PCA normals over the growth graph's k-neighbourhoods.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/neighbor_graph.h>

#include <Eigen/Core>

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

/** \brief OpenMP thread count for a request (0: OpenMP's default, i.e. OMP_NUM_THREADS). */
int
resolveThreads (int requested);

} // namespace rspd
} // namespace pcl
