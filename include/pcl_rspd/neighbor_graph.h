/*
 * pcl_rspd: the k-nearest-neighbour graph G of Sec. 3.3, stored as one flat array.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Directed k-NN graph: row i holds the k nearest samples of sample i, the sample itself
  * excluded, ordered by increasing distance (ties by increasing index).
  *
  * One flat array of n*k indices rather than a vector per sample: a vector per point costs a heap
  * block each and was most of the neighbour-graph time in the peers.
  */
class NeighborGraph
{
public:
  NeighborGraph () = default;

  /** \brief Allocate a graph of \a n rows of \a k neighbours each (contents undefined). */
  NeighborGraph (std::size_t n, int k) : k_ (k), n_ (n), data_ (n * static_cast<std::size_t> (k)) {}

  /** \brief Neighbours per sample. */
  int
  k () const { return k_; }

  /** \brief Number of samples (rows). */
  std::size_t
  size () const { return n_; }

  /** \brief The k neighbours of sample \a i. */
  const std::uint32_t*
  neighbors (std::size_t i) const { return data_.data () + i * static_cast<std::size_t> (k_); }

  /** \brief Writable row of sample \a i (for builders). */
  std::uint32_t*
  row (std::size_t i) { return data_.data () + i * static_cast<std::size_t> (k_); }

  /** \brief Whether the graph holds no rows. */
  bool
  empty () const { return n_ == 0; }

private:
  int k_ = 0;
  std::size_t n_ = 0;
  std::vector<std::uint32_t> data_;
};

/** \brief Exact k-NN graph of \a points by the library's own method (a uniform grid with ring
  * search; see neighbor_graph.cpp for why not a k-d tree).
  *
  * Row i gets the k samples nearest to sample i other than i itself (duplicates of i count as
  * neighbours at distance 0), ordered by increasing squared distance, ties by increasing index; the
  * same sets KdTreeFLANN returns, ties aside.
  * \param[in] points finite positions
  * \param[in] k neighbours per sample; must be < points.size()
  * \param[in] num_threads OpenMP threads (0: OpenMP's default); the result does not depend on it
  * \param[out] graph the graph
  * \return false (graph left empty) if k < 1 or there are not more than k points
  */
bool
buildKnnGraph (const std::vector<Eigen::Vector3f>& points, int k, int num_threads, NeighborGraph& graph);

} // namespace rspd
} // namespace pcl
