/*
 * pcl_rspd: the k-nearest-neighbour graph G of Sec. 3.3, delta-compressed, and the exact k-NN
 * search that builds it.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Dense k-NN table: row i holds the k nearest samples of sample i, the sample itself
  * excluded, ordered by increasing distance (ties by increasing index). 4·k bytes per sample;
  * the pipeline keeps the compressed NeighborGraph instead. */
class NeighborTable
{
public:
  NeighborTable () = default;

  /** \brief Allocate a table of \a n rows of \a k neighbours each (contents undefined). */
  NeighborTable (std::size_t n, int k) : k_ (k), n_ (n), data_ (n * static_cast<std::size_t> (k)) {}

  /** \brief Neighbours per sample. */
  int
  k () const { return k_; }

  /** \brief Number of samples (rows). */
  std::size_t
  size () const { return n_; }

  /** \brief Whether the table holds no rows. */
  bool
  empty () const { return n_ == 0; }

  /** \brief The k neighbours of sample \a i, nearest first. */
  const std::uint32_t*
  neighbors (std::size_t i) const { return data_.data () + i * static_cast<std::size_t> (k_); }

  /** \brief Writable row of sample \a i (for builders). */
  std::uint32_t*
  row (std::size_t i) { return data_.data () + i * static_cast<std::size_t> (k_); }

private:
  int k_ = 0;
  std::size_t n_ = 0;
  std::vector<std::uint32_t> data_;
};

/** \brief Directed k-NN graph: row i is the set of the k nearest samples of sample i (the sample
  * itself excluded), read back in increasing index order.
  *
  * Why compressed: k = 50 plain 32-bit indices are 200 bytes per sample, 200 MB per million points,
  * more than everything else the method keeps. With the samples in spatial (Morton) order, as
  * RobustPlaneSegmentation stores them, a row sorted by index is a few runs of nearby indices, so
  * each index is stored as a LEB128 varint of its difference to the previous one (the first one
  * relative to i): about 1.2-1.5 bytes per neighbour instead of 4. No phase needs the neighbours in
  * distance order (PCA normals, growth and merge treat a row as a set), so the order is not kept.
  * Rows live in fixed-size pages filled by per-thread Appenders, so building never holds a dense
  * table and threads never wait on each other except to take a new page.
  */
class NeighborGraph
{
public:
  NeighborGraph () = default;

  /** \brief A graph of \a n rows of \a k neighbours; every row must then be set once through an
    * Appender before it is read. */
  NeighborGraph (std::size_t n, int k);

  NeighborGraph (NeighborGraph&&) noexcept = default;
  NeighborGraph&
  operator= (NeighborGraph&&) noexcept = default;

  /** \brief Neighbours per sample. */
  int
  k () const { return k_; }

  /** \brief Number of samples (rows). */
  std::size_t
  size () const { return n_; }

  /** \brief Whether the graph holds no rows. */
  bool
  empty () const { return n_ == 0; }

  /** \brief Bytes held by the graph (pages and row offsets). */
  std::size_t
  memoryBytes () const;

  /** \brief Call \a visit (std::uint32_t j) for each of the k neighbours j of sample \a i, in
    * increasing order of j. */
  template <typename Visit> void
  forEachNeighbor (std::size_t i, Visit&& visit) const
  {
    const std::uint64_t at = offsets_[i];
    const std::uint8_t* p = pages_[at >> page_shift_].get () + (at & page_mask_);
    const std::uint64_t z = readVarint (p);
    // Zigzag: the first neighbour may lie before or after i.
    const std::int64_t delta = static_cast<std::int64_t> (z >> 1) ^ -static_cast<std::int64_t> (z & 1);
    std::uint32_t j = static_cast<std::uint32_t> (static_cast<std::int64_t> (i) + delta);
    visit (j);
    for (int t = 1; t < k_; ++t)
    {
      j += static_cast<std::uint32_t> (readVarint (p));
      visit (j);
    }
  }

  /** \brief Copy the k neighbours of sample \a i into \a out, in increasing order. */
  void
  neighbors (std::size_t i, std::uint32_t* out) const
  {
    forEachNeighbor (i, [&out] (std::uint32_t j) { *out++ = j; });
  }

  /** \brief Fills rows of a graph; one per thread (each takes its own pages). */
  class Appender
  {
  public:
    explicit Appender (NeighborGraph& graph);

    /** \brief Set row \a i to the k indices at \a row (any order; the array is not modified). */
    void
    setRow (std::size_t i, const std::uint32_t* row);

  private:
    NeighborGraph& graph_;
    std::vector<std::uint32_t> sorted_;
    std::uint8_t* page_ = nullptr;
    std::uint64_t page_index_ = 0;
    std::size_t used_ = 0;
  };

  /** \brief The graph of a dense table (rows as sets). */
  static NeighborGraph
  fromTable (const NeighborTable& table);

private:
  static std::uint64_t
  readVarint (const std::uint8_t*& p)
  {
    std::uint64_t b = *p++;
    if (b < 0x80)
      return b;
    std::uint64_t v = b & 0x7f;
    int shift = 7;
    do
    {
      b = *p++;
      v |= (b & 0x7f) << shift;
      shift += 7;
    } while (b >= 0x80);
    return v;
  }

  /** \brief Take a fresh page (thread-safe); returns its index. */
  std::uint64_t
  newPage (std::uint8_t*& data);

  int k_ = 0;
  std::size_t n_ = 0;
  int page_shift_ = 0;
  std::uint64_t page_mask_ = 0;
  std::size_t max_row_bytes_ = 0;
  std::vector<std::uint64_t> offsets_;                 ///< row i: page << page_shift_ | offset
  std::vector<std::unique_ptr<std::uint8_t[]>> pages_;
};

/** \brief Exact k-NN graph of \a points by the library's own method (a linear octree with ring
  * search; see neighbor_graph.cpp for why not a k-d tree).
  *
  * Row i gets the k samples nearest to sample i other than i itself (duplicates of i count as
  * neighbours at distance 0; ties at the k-th distance go to the lower index): the same sets
  * KdTreeFLANN returns, ties aside. Never holds a dense table: rows are compressed as they are found.
  * \param[in] points finite positions (spatially ordered positions compress best)
  * \param[in] k neighbours per sample; must be < points.size()
  * \param[in] num_threads OpenMP threads (0: OpenMP's default); the result does not depend on it
  * \param[out] graph the graph
  * \return false (graph left empty) if k < 1 or there are not more than k points
  */
bool
buildKnnGraph (const std::vector<Eigen::Vector3f>& points, int k, int num_threads, NeighborGraph& graph);

/** \brief The same search as buildKnnGraph, into a dense table in (distance, index) order. */
bool
buildKnnTable (const std::vector<Eigen::Vector3f>& points, int k, int num_threads, NeighborTable& table);

/** \brief Receives one row of a k-NN search: the \a query's k nearest samples (itself excluded), nearest
  * first, in a buffer valid for the call only. Called from several threads at once, once per query. */
using KnnRowVisitor = std::function<void (std::uint32_t query, const std::uint32_t* row)>;

/** \brief The search of buildKnnGraph for the samples flagged in \a is_query only (the neighbours are
  * searched among all samples), each row handed to \a visit as soon as it is final instead of being
  * stored. For a few queries it costs those queries plus sorting the points, and holds no table.
  * \param[in] points finite positions
  * \param[in] k neighbours per query; must be < points.size()
  * \param[in] num_threads OpenMP threads (0: OpenMP's default); the rows do not depend on it
  * \param[in] is_query one flag per point (non-zero: find its row)
  * \param[in] visit called once per flagged point, concurrently; must be thread-safe
  * \return false (nothing visited) if k < 1, there are not more than k points, or the flags do not
  * match the points */
bool
visitKnnRows (const std::vector<Eigen::Vector3f>& points, int k, int num_threads, const std::vector<char>& is_query,
              const KnnRowVisitor& visit);

/** \brief A spatial order of \a points: the permutation that sorts them along the Morton curve of
  * their bounding box (ties by index). Storing samples in this order makes NeighborGraph compact
  * and every phase cache-friendly. */
std::vector<std::uint32_t>
spatialOrder (const std::vector<Eigen::Vector3f>& points, int num_threads);

} // namespace rspd
} // namespace pcl
