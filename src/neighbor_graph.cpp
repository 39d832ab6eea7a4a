/*
 * pcl_rspd: exact k-nearest-neighbour graph on a linear octree (Morton-sorted points).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/neighbor_graph.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <utility>

/*
 * Why not a k-d tree: pcl::KdTreeFLANN takes 7 s for a million points with k = 50 on one thread of
 * the target machines (3.4 s on two), mostly pointer chasing and per-query allocations; this
 * builder takes about 1 s (0.6 s).
 *
 * Why not a plain uniform grid: one cell size cannot fit scans whose density varies by orders of
 * magnitude (near and far from the sensor, tight clusters); the dense cells then hold thousands of
 * points and every query there scans 9-27 of them.
 *
 * What is done instead: the points are sorted along a Morton (Z-order) curve of 21 bits per axis.
 * Every cell of every level of the implied octree is then one contiguous range of that order, so
 * all grid resolutions are available at once without storing any tree. The points are partitioned
 * into leaves: the largest cells holding at most leaf_size points. The queries of one leaf are
 * answered on the uniform grid of the leaf's own level: the 3x3x3 block of cells around the leaf
 * (looked up once per leaf by binary search in the sorted codes) is searched, nearest cells first,
 * skipping cells whose lower distance bound exceeds the current k-th distance. A neighbouring cell
 * much denser than the leaf is descended into rather than scanned. The leaf's parent holds more
 * than leaf_size > k points and lies inside the block, so the block always yields enough
 * candidates; the answer is final as soon as the k-th distance is below the distance from the
 * query to the outside of the block (the exactness condition). The few queries for which it is not
 * continue with the next shell of cells, then with a pruned descent from the root that skips the
 * cells already searched.
 *
 * Per query, candidates are 64-bit keys (distance bits, index) appended without branches to a
 * buffer, filtered by a threshold seeded from the previous query's result; the buffer is sorted
 * once, by a counting sort on the distance. Queries are processed in Morton order and each writes
 * only its own row, so the work splits over threads with no effect on the result.
 *
 * Exactness with floats: distances are always computed by the same kernel (in float, bit for bit
 * the value Eigen's (a - b).squaredNorm () gives), so the order (distance, index) is a fixed total
 * order and the result is unique, hence independent of the thread count. Cell boundaries are exact
 * in double: the finest cell size is a power of two, so the cell of a point is an exact floor.
 * Pruning bounds are computed in double and shrunk by more than the float kernel's rounding error
 * before they are compared, so a cell is skipped only if none of its points can compare below or
 * equal to the k-th candidate.
 *
 * The finest cell is 2^-21 of the bounding box. A cloud spanning more than that many sample
 * spacings (a wild outlier, a microscopic cluster) would put many distinct samples in one finest
 * cell, whose queries would each scan all of them; such cells are solved as a separate, smaller
 * problem with its own, finer grid (see solveLevel). Exact duplicates need no such care: queries
 * at one position share one search.
 */

namespace pcl
{
namespace rspd
{
namespace
{
/** \brief Bits per axis of the Morton codes; 3 * 21 = 63 bits fit an uint64. */
constexpr int kMaxDepth = 21;

/** \brief Spread the low 21 bits of \a v so that bit b lands on bit 3b. */
inline std::uint64_t
spreadBits (std::uint32_t v)
{
  std::uint64_t x = v & 0x1fffffu;
  x = (x | (x << 32)) & 0x001f00000000ffffULL;
  x = (x | (x << 16)) & 0x001f0000ff0000ffULL;
  x = (x | (x << 8)) & 0x100f00f00f00f00fULL;
  x = (x | (x << 4)) & 0x10c30c30c30c30c3ULL;
  x = (x | (x << 2)) & 0x1249249249249249ULL;
  return x;
}

/** \brief Morton code of integer cell coordinates (each below 2^21). */
inline std::uint64_t
mortonKey (const std::int64_t c[3])
{
  return spreadBits (static_cast<std::uint32_t> (c[0])) |
         (spreadBits (static_cast<std::uint32_t> (c[1])) << 1) |
         (spreadBits (static_cast<std::uint32_t> (c[2])) << 2);
}

/** \brief The one distance kernel of the builder, from query q to sample p. Its evaluation order,
  * x^2 + (y^2 + z^2), is the one Eigen's unrolled (p - q).squaredNorm () uses for a Vector3f, so
  * callers can recompute the very same floats (and ties) with Eigen. */
inline float
squaredDistance (float px, float py, float pz, float qx, float qy, float qz)
{
  const float dx = px - qx;
  const float dy = py - qy;
  const float dz = pz - qz;
  return dx * dx + (dy * dy + dz * dz);
}

/** \brief A cell of the implied octree: its level, integer coordinates at that level, and the
  * range of sorted points it holds. */
struct Cell
{
  int depth;
  std::int64_t c[3];
  std::uint32_t begin;
  std::uint32_t end;
};

/** \brief The points in Morton order, structure-of-arrays so the distance kernel vectorizes. */
class LinearOctree
{
public:
  /** \brief Quantize, sort, and copy in Morton order the points listed in \a subset (all points
    * if it is null). ids_ holds their indices in \a points. */
  void
  build (const std::vector<Eigen::Vector3f>& points, const std::vector<std::uint32_t>* subset,
         int num_threads)
  {
    const std::size_t n = subset ? subset->size () : points.size ();
    const auto id_of = [subset] (std::size_t i) {
      return subset ? (*subset)[i] : static_cast<std::uint32_t> (i);
    };
    Eigen::Vector3f lo = points[id_of (0)], hi = lo;
    for (std::size_t i = 0; i < n; ++i)
    {
      lo = lo.cwiseMin (points[id_of (i)]);
      hi = hi.cwiseMax (points[id_of (i)]);
    }
    double extent = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      origin_[a] = static_cast<double> (lo[a]);
      extent = std::max (extent, static_cast<double> (hi[a]) - origin_[a]);
    }
    // A power-of-two cell size makes the cell of a point an exact floor in double, so the cell
    // boundaries the pruning bounds use are the ones the points were sorted by. Identical points
    // (extent 0) get an arbitrary positive size: everything lands in cell 0.
    if (!(extent > 0.0))
      extent = 1.0;
    int e2 = 0;
    std::frexp (extent, &e2); // extent < 2^e2
    h0_ = std::ldexp (1.0, e2 - kMaxDepth);
    for (int depth = 0; depth <= kMaxDepth; ++depth)
      cell_size_[depth] = std::ldexp (h0_, kMaxDepth - depth);
    // Cell boundaries and distance bounds in double are off by a few double ulps of the
    // coordinates, far less than this; used to shrink distance bounds. (The float kernel's error
    // is relative to the distance, see shrink ().)
    double coord_max = 0.0;
    for (int a = 0; a < 3; ++a)
      coord_max = std::max ({coord_max, std::abs (static_cast<double> (lo[a])),
                             std::abs (static_cast<double> (hi[a]))});
    slack_ = 1e-12 * (extent + coord_max);

    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed (n);
    const double inv_h0 = 1.0 / h0_; // exact: h0_ is a power of two
    const std::int64_t cmax = (std::int64_t (1) << kMaxDepth) - 1;
#pragma omp parallel for num_threads(num_threads) schedule(static)
    for (std::int64_t i = 0; i < static_cast<std::int64_t> (n); ++i)
    {
      const std::uint32_t id = id_of (static_cast<std::size_t> (i));
      std::int64_t c[3];
      for (int a = 0; a < 3; ++a)
      {
        const double t = std::floor ((static_cast<double> (points[id][a]) - origin_[a]) * inv_h0);
        c[a] = std::min (std::max (static_cast<std::int64_t> (t), std::int64_t (0)), cmax);
      }
      keyed[i] = {mortonKey (c), id};
    }
    sortKeyed (keyed);

    codes_.resize (n);
    ids_.resize (n);
    xs_.resize (n);
    ys_.resize (n);
    zs_.resize (n);
#pragma omp parallel for num_threads(num_threads) schedule(static)
    for (std::int64_t i = 0; i < static_cast<std::int64_t> (n); ++i)
    {
      codes_[i] = keyed[i].first;
      const std::uint32_t id = keyed[i].second;
      ids_[i] = id;
      xs_[i] = points[id][0];
      ys_[i] = points[id][1];
      zs_[i] = points[id][2];
    }
  }

  /** \brief Whether all points of \a cell are at the same position. */
  bool
  samePosition (const Cell& cell) const
  {
    for (std::uint32_t i = cell.begin + 1; i < cell.end; ++i)
      if (xs_[i] != xs_[cell.begin] || ys_[i] != ys_[cell.begin] || zs_[i] != zs_[cell.begin])
        return false;
    return true;
  }

  /** \brief Call \a visit on the non-empty cells within \a radius cells of \a cell (same level). */
  template <typename Visit> void
  forEachNear (const Cell& cell, int radius, Visit visit) const
  {
    const std::int64_t side = std::int64_t (1) << cell.depth;
    for (std::int64_t dz = -radius; dz <= radius; ++dz)
      for (std::int64_t dy = -radius; dy <= radius; ++dy)
        for (std::int64_t dx = -radius; dx <= radius; ++dx)
        {
          Cell near;
          near.depth = cell.depth;
          near.c[0] = cell.c[0] + dx;
          near.c[1] = cell.c[1] + dy;
          near.c[2] = cell.c[2] + dz;
          if (near.c[0] < 0 || near.c[1] < 0 || near.c[2] < 0 || near.c[0] >= side ||
              near.c[1] >= side || near.c[2] >= side)
            continue;
          if (dx == 0 && dy == 0 && dz == 0)
          {
            near.begin = cell.begin;
            near.end = cell.end;
          }
          else
            cellRange (near.depth, near.c, near.begin, near.end);
          if (near.begin < near.end)
            visit (near);
        }
  }

  /** \brief Sorted range of the cell at \a depth with coordinates \a c (which must be in range). */
  void
  cellRange (int depth, const std::int64_t c[3], std::uint32_t& begin, std::uint32_t& end) const
  {
    const int shift = 3 * (kMaxDepth - depth);
    const std::uint64_t key = mortonKey (c);
    const std::uint64_t first = key << shift;
    const auto it = std::lower_bound (codes_.begin (), codes_.end (), first);
    begin = static_cast<std::uint32_t> (it - codes_.begin ());
    // Cells are small compared to the whole array: gallop from the start instead of a second full
    // binary search.
    const std::uint64_t key_end = key + 1;
    std::size_t lo = begin, step = 1, hi = begin;
    while (hi < codes_.size () && (codes_[hi] >> shift) < key_end)
    {
      lo = hi + 1;
      hi = begin + step;
      step *= 2;
    }
    hi = std::min (hi, codes_.size ());
    const auto it_end =
      std::partition_point (codes_.begin () + lo, codes_.begin () + hi,
                            [&] (std::uint64_t v) { return (v >> shift) < key_end; });
    end = static_cast<std::uint32_t> (it_end - codes_.begin ());
  }

  /** \brief Split a cell's range into its non-empty children (at most 8), in Morton order. */
  int
  children (const Cell& parent, Cell* out) const
  {
    const int depth = parent.depth + 1;
    const int shift = 3 * (kMaxDepth - depth);
    int count = 0;
    std::uint32_t b = parent.begin;
    while (b < parent.end)
    {
      const std::uint64_t digit = (codes_[b] >> shift) & 7u;
      const std::uint64_t key = codes_[b] >> shift;
      const auto it = std::partition_point (codes_.begin () + b, codes_.begin () + parent.end,
                                            [&] (std::uint64_t v) { return (v >> shift) == key; });
      Cell& ch = out[count++];
      ch.depth = depth;
      for (int a = 0; a < 3; ++a)
        ch.c[a] = 2 * parent.c[a] + static_cast<std::int64_t> ((digit >> a) & 1u);
      ch.begin = b;
      ch.end = static_cast<std::uint32_t> (it - codes_.begin ());
      b = ch.end;
    }
    return count;
  }

  /** \brief The cell holding all points. */
  Cell
  root () const
  {
    Cell cell;
    cell.depth = 0;
    cell.c[0] = cell.c[1] = cell.c[2] = 0;
    cell.begin = 0;
    cell.end = static_cast<std::uint32_t> (codes_.size ());
    return cell;
  }

  /** \brief Cell size at \a depth. */
  double
  cellSize (int depth) const { return cell_size_[depth]; }

  /** \brief Squared distance from \a q to the box of \a cell, shrunk so that it is a lower bound of
    * what the float kernel computes for any point of the cell. */
  double
  lowerBound2 (const double q[3], const Cell& cell) const
  {
    const double h = cellSize (cell.depth);
    double s = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const double lo = origin_[a] + static_cast<double> (cell.c[a]) * h;
      const double hi = lo + h;
      double t = 0.0;
      if (q[a] < lo)
        t = lo - q[a];
      else if (q[a] > hi)
        t = q[a] - hi;
      t = std::max (0.0, t - slack_);
      s += t * t;
    }
    return shrink (s);
  }

  /** \brief Shrink an exact squared distance below the float kernel's worst rounding (relative
    * ~6 ulp, plus underflow of tiny squares). */
  static double
  shrink (double d2) { return d2 * (1.0 - 1e-6) - 1e-37; }

  double origin_[3] = {0.0, 0.0, 0.0};
  double h0_ = 1.0;
  double cell_size_[kMaxDepth + 1] = {};
  double slack_ = 0.0;
  std::vector<std::uint64_t> codes_;
  std::vector<std::uint32_t> ids_;
  std::vector<float> xs_, ys_, zs_;

private:
  /** \brief Sort by code: an LSD radix sort (11-bit digits), stable, hence deterministic. */
  static void
  sortKeyed (std::vector<std::pair<std::uint64_t, std::uint32_t>>& v)
  {
    if (v.size () < 4096)
    {
      std::sort (v.begin (), v.end ());
      return;
    }
    std::vector<std::pair<std::uint64_t, std::uint32_t>> tmp (v.size ());
    constexpr int kBits = 11;
    constexpr std::size_t kRadix = std::size_t (1) << kBits;
    std::vector<std::size_t> count (kRadix);
    std::uint64_t all_or = 0, all_and = ~std::uint64_t (0);
    for (const auto& e : v)
    {
      all_or |= e.first;
      all_and &= e.first;
    }
    const std::uint64_t varying = all_or ^ all_and;
    for (int shift = 0; shift < 64; shift += kBits)
    {
      // Digits on which all keys agree do not reorder anything.
      if (((varying >> shift) & (kRadix - 1)) == 0)
        continue;
      std::fill (count.begin (), count.end (), 0);
      for (const auto& e : v)
        ++count[(e.first >> shift) & (kRadix - 1)];
      std::size_t sum = 0;
      for (auto& c : count)
      {
        const std::size_t t = c;
        c = sum;
        sum += t;
      }
      for (const auto& e : v)
        tmp[count[(e.first >> shift) & (kRadix - 1)]++] = e;
      v.swap (tmp);
    }
  }
};

/** \brief Points scanned per batch by the distance kernel. */
constexpr int kChunk = 64;

/** \brief The candidates of one query that may still be among its \a count nearest samples.
  *
  * A candidate is one 64-bit key: the bits of its (non-negative) float distance above its index.
  * Non-negative floats order like their bit patterns, so comparing keys compares (distance, index)
  * with the tie rule built in, in a single integer comparison.
  *
  * Candidates below the threshold are appended unsorted, without a branch; when the buffer fills
  * up, and when the search needs the exact count-th distance, it is sorted and cut back to the
  * count best, which also tightens the threshold. A sorted list or a heap instead spent most of the
  * search time in unpredictable branches and element moves.
  */
class CandidateSet
{
public:
  explicit CandidateSet (int count)
    : count_ (count)
    , capacity_ (4 * count + kChunk)
    , keys_ (static_cast<std::size_t> (capacity_))
    , scratch_ (static_cast<std::size_t> (capacity_))
    , bucket_ (static_cast<std::size_t> (capacity_))
    , bucket_start_ (2 * static_cast<std::size_t> (capacity_))
  {}

  static std::uint64_t
  makeKey (float d2, std::uint32_t id)
  {
    std::uint32_t bits;
    std::memcpy (&bits, &d2, sizeof (bits));
    return (static_cast<std::uint64_t> (bits) << 32) | id;
  }

  static float
  keyDistance (std::uint64_t key)
  {
    const std::uint32_t bits = static_cast<std::uint32_t> (key >> 32);
    float d2;
    std::memcpy (&d2, &bits, sizeof (d2));
    return d2;
  }

  /** \brief Start a query. Distances above \a max_d2 (if finite) will be rejected: the caller
    * guarantees that \a count samples lie within it. */
  void
  clear (float max_d2 = kInfinity)
  {
    size_ = 0;
    sorted_ = true;
    bounded_ = max_d2 < kInfinity;
    setThreshold (bounded_ ? makeKey (std::nextafter (max_d2, kInfinity), 0) : kNoKey);
  }

  /** \brief Keys below this one may be among the best. */
  std::uint64_t
  threshold () const { return threshold_; }

  /** \brief Distances above this one cannot enter. */
  float
  worst () const { return worst_; }

  /** \brief Room for kChunk more keys: write them there, then call grow () with the number of
    * them to keep (those first). */
  std::uint64_t*
  tail () { return keys_.data () + size_; }

  void
  grow (int added)
  {
    size_ += added;
    sorted_ = sorted_ && added == 0;
    // The first count candidates give the first finite threshold; a full buffer is cut back.
    if ((!bounded_ && size_ >= count_) || size_ + kChunk > capacity_)
      settle ();
  }

  /** \brief Whether count candidates are known; after settle (), worst () is then the exact
    * count-th distance among them. */
  bool
  full () const { return size_ >= count_; }

  /** \brief Sort the candidates and keep the count best. */
  void
  settle ()
  {
    if (sorted_)
      return;
    sortKeys ();
    sorted_ = true;
    if (size_ >= count_)
    {
      size_ = count_;
      bounded_ = true;
      setThreshold (keys_[count_ - 1]);
    }
  }

  /** \brief Write the indices of the best candidates other than \a self_key, nearest first:
    * count - 1 of them, as the query itself is one of its own candidates. */
  void
  write (std::uint64_t self_key, std::uint32_t* row)
  {
    settle ();
    int t = 0;
    for (int j = 0; j < size_ && t < count_ - 1; ++j)
      if (keys_[j] != self_key)
        row[t++] = static_cast<std::uint32_t> (keys_[j]);
  }

private:
  static constexpr float kInfinity = std::numeric_limits<float>::infinity ();
  static constexpr std::uint64_t kNoKey = ~std::uint64_t (0);

  void
  setThreshold (std::uint64_t key)
  {
    threshold_ = key;
    worst_ = key == kNoKey ? kInfinity : keyDistance (key);
  }

  /** \brief Sort keys_[0, size_), dropping keys that cannot be among the count first: a counting
    * sort on the distance scaled to 2 size_ buckets, then an insertion sort that only has to order
    * keys within a bucket, and only up to the bucket holding the count-th key. The bucket of a key
    * is monotonic in its distance, so the result is exactly ordered; one query's candidate
    * distances are spread fairly evenly, so buckets rarely hold more than one or two keys. */
  void
  sortKeys ()
  {
    int n = size_;
    std::uint64_t* a = keys_.data ();
    // All keys lie below the threshold, so worst_ bounds their distances once it is finite.
    float range = worst_;
    if (!(range < kInfinity))
    {
      std::uint64_t max_key = 0;
      for (int i = 0; i < n; ++i)
        max_key = std::max (max_key, a[i]);
      range = keyDistance (max_key);
    }
    const int buckets = 2 * n;
    const float scale = range > 0.f ? static_cast<float> (buckets) / range : 0.f;
    if (n > 24 && scale > 0.f && scale < kInfinity)
    {
      std::uint32_t* bucket = bucket_.data ();
      std::uint32_t* start = bucket_start_.data ();
      std::fill (start, start + buckets, 0u);
      for (int i = 0; i < n; ++i)
      {
        const int b = static_cast<int> (keyDistance (a[i]) * scale);
        bucket[i] = static_cast<std::uint32_t> (std::min (b, buckets - 1));
        ++start[bucket[i]];
      }
      // The running sum stays in a register: summing in place waits on a store per bucket.
      std::uint32_t sum = 0;
      for (int b = 0; b < buckets; ++b)
      {
        const std::uint32_t c = start[b];
        start[b] = sum;
        sum += c;
      }
      std::uint64_t* out = scratch_.data ();
      for (int i = 0; i < n; ++i)
        out[start[bucket[i]]++] = a[i];
      // start[b] is now the end of bucket b. Buckets after the one holding the count-th key hold
      // nothing of the count best.
      if (n > count_)
      {
        int b = 0;
        while (start[b] < static_cast<std::uint32_t> (count_))
          ++b;
        n = static_cast<int> (start[b]);
      }
      std::copy (out, out + n, a);
    }
    for (int i = 1; i < n; ++i)
    {
      const std::uint64_t x = a[i];
      int j = i;
      for (; j > 0 && a[j - 1] > x; --j)
        a[j] = a[j - 1];
      a[j] = x;
    }
    size_ = n;
  }

  int count_;
  int capacity_;
  int size_ = 0;
  bool sorted_ = true;
  bool bounded_ = false;
  std::uint64_t threshold_ = kNoKey;
  float worst_ = kInfinity;
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint64_t> scratch_;
  std::vector<std::uint32_t> bucket_;
  std::vector<std::uint32_t> bucket_start_;
};

/** \brief The cube of (2 radius + 1)^3 cells around a leaf already searched for a query, to be
  * skipped by the fallback. */
struct Block
{
  int depth;
  int radius;
  std::int64_t c[3];
};

/** \brief Rows of a dense table, either every sample's (slot = index) or only those of a few
  * queries (slot_of maps a sample to its row). */
struct DenseRows
{
  int k = 0;
  const std::vector<std::uint32_t>* slot_of = nullptr;
  std::uint32_t* data = nullptr;

  std::uint32_t*
  row (std::uint32_t id) const
  {
    const std::size_t slot = slot_of ? (*slot_of)[id] : id;
    return data + slot * static_cast<std::size_t> (k);
  }
};

/** \brief Where a searcher puts the row of a query: storage to write it to, then done (). */
class RowSink
{
public:
  virtual ~RowSink () = default;
  /** \brief Storage for the row of \a id (for a dense table, it holds the row found so far). */
  virtual std::uint32_t*
  row (std::uint32_t id) = 0;
  /** \brief The row of \a id is final. */
  virtual void
  done (std::uint32_t, const std::uint32_t*) {}
};

/** \brief Rows written in place into a dense table. */
class DenseSink : public RowSink
{
public:
  explicit DenseSink (const DenseRows& rows) : rows_ (rows) {}
  std::uint32_t*
  row (std::uint32_t id) override { return rows_.row (id); }

private:
  const DenseRows& rows_;
};

/** \brief Rows compressed into a NeighborGraph as soon as they are found (one per thread). */
class AppendSink : public RowSink
{
public:
  AppendSink (NeighborGraph& graph, int k) : appender_ (graph), scratch_ (static_cast<std::size_t> (k)) {}
  std::uint32_t*
  row (std::uint32_t) override { return scratch_.data (); }
  void
  done (std::uint32_t id, const std::uint32_t* row) override { appender_.setRow (id, row); }

private:
  NeighborGraph::Appender appender_;
  std::vector<std::uint32_t> scratch_;
};

/** \brief Rows handed to the caller's visitor as soon as they are final (one per thread). */
class VisitSink : public RowSink
{
public:
  VisitSink (const KnnRowVisitor& visit, int k) : visit_ (visit), scratch_ (static_cast<std::size_t> (k)) {}
  std::uint32_t*
  row (std::uint32_t) override { return scratch_.data (); }
  void
  done (std::uint32_t id, const std::uint32_t* row) override { visit_ (id, row); }

private:
  const KnnRowVisitor& visit_;
  std::vector<std::uint32_t> scratch_;
};

/** \brief Per-thread search state. */
class Searcher
{
public:
  Searcher (const LinearOctree& tree, const std::vector<Eigen::Vector3f>& points, int k,
            std::uint32_t leaf_size)
    : tree_ (tree), points_ (points), k_ (k), cands_ (k + 1), leaf_size_ (leaf_size)
  {}

  /** \brief Answer the queries of \a leaf, writing their rows to \a rows.
    * \param[in] leaf the leaf
    * \param[in] is_query flags by sample index, or null: all samples are queries
    * \param[in] rows_hold_block_result each query's row already holds its k nearest among samples
    * that include the leaf's 3x3x3 block (see solveLevel); it is kept if that proves it final, and
    * the query is searched otherwise (only with a dense sink)
    * \param[in,out] rows where the rows go */
  void
  processLeaf (const Cell& leaf, const std::vector<char>* is_query, bool rows_hold_block_result,
               RowSink& rows)
  {
    const int d = leaf.depth;
    const std::int64_t side = std::int64_t (1) << d;
    int num_cells = -1; // the block's cells, looked up once per leaf when first needed

    // The query itself is one of its own candidates (at distance 0): the set keeps the k + 1 best
    // and the row drops the query. That takes the self test out of the distance loop, and makes a
    // run of queries at one position (duplicated samples) cost one search: their distances to
    // every sample are the same floats, so they share the k + 1 best.
    //
    // The previous query's k-th neighbour distance r bounds this one's: its k neighbours and
    // itself are all within r + |q - q_prev| of q. Seeding the candidate set with that radius
    // prunes far cells before they are scanned and keeps most far candidates out of the set.
    bool have_prev = false;
    double prev_r = 0.0;
    for (std::uint32_t i = leaf.begin; i < leaf.end; ++i)
    {
      const std::uint32_t id = tree_.ids_[i];
      if (is_query && !(*is_query)[id])
        continue;
      const float q[3] = {tree_.xs_[i], tree_.ys_[i], tree_.zs_[i]};
      std::uint32_t* row = rows.row (id);
      const std::uint64_t self_key = CandidateSet::makeKey (0.f, id);
      if (have_prev && q[0] == qf_[0] && q[1] == qf_[1] && q[2] == qf_[2])
      {
        cands_.write (self_key, row);
        rows.done (id, row);
        continue;
      }
      float seed = std::numeric_limits<float>::infinity ();
      if (rows_hold_block_result)
      {
        const Eigen::Vector3f& p = points_[row[k_ - 1]];
        seed = squaredDistance (p[0], p[1], p[2], q[0], q[1], q[2]);
        for (int a = 0; a < 3; ++a)
          qd_[a] = static_cast<double> (q[a]);
        if (finalWithin (leaf, 1, seed))
          continue;
      }
      else if (have_prev)
      {
        double step2 = 0.0;
        for (int a = 0; a < 3; ++a)
          step2 += (static_cast<double> (q[a]) - qd_[a]) * (static_cast<double> (q[a]) - qd_[a]);
        // Grown by more than the float kernel's rounding, both in the previous k-th distance and in
        // the distances to come.
        const double r = prev_r * (1.0 + 1e-6) + std::sqrt (step2);
        seed = std::nextafter (static_cast<float> (r * r * (1.0 + 1e-6) + 1e-37),
                               std::numeric_limits<float>::infinity ());
      }
      for (int a = 0; a < 3; ++a)
      {
        qf_[a] = q[a];
        qd_[a] = static_cast<double> (q[a]);
      }
      if (num_cells < 0)
      {
        num_cells = 0;
        tree_.forEachNear (leaf, 1, [this, &num_cells] (const Cell& cell) {
          block_cells_[num_cells++] = cell;
        });
      }
      cands_.clear (seed);
      searchBlock (num_cells);
      cands_.settle ();

      // Rarely (a query near the block's side, a sparse leaf, or k + 1 samples within the seed
      // radius that are not all in the block) the search must go on beyond the block: first the
      // next shell of cells, each looked up only if it is near enough, then a descent from the
      // root.
      if (!exactWithin (leaf, 1))
      {
        for (int dz = -2; dz <= 2; ++dz)
          for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx)
            {
              if (std::max ({std::abs (dx), std::abs (dy), std::abs (dz)}) != 2)
                continue;
              Cell cell;
              cell.depth = d;
              cell.c[0] = leaf.c[0] + dx;
              cell.c[1] = leaf.c[1] + dy;
              cell.c[2] = leaf.c[2] + dz;
              if (!inGrid (cell.c, side) || tree_.lowerBound2 (qd_, cell) > cands_.worst ())
                continue;
              tree_.cellRange (d, cell.c, cell.begin, cell.end);
              if (cell.begin < cell.end)
                visit (cell);
            }
        cands_.settle ();
        if (!exactWithin (leaf, 2))
        {
          const Block block{d, 2, {leaf.c[0], leaf.c[1], leaf.c[2]}};
          descend (tree_.root (), &block);
        }
      }
      cands_.write (self_key, row);
      rows.done (id, row);
      have_prev = true;
      prev_r = std::sqrt (static_cast<double> (cands_.worst ()));
    }
  }

private:
  /** \brief Search the 3x3x3 block of the current leaf for the current query, nearest cells first
    * so that the k-th distance drops fast and the far cells get pruned. */
  void
  searchBlock (int num_cells)
  {
    int order[27];
    double bound[27];
    for (int c = 0; c < num_cells; ++c)
    {
      const double b = tree_.lowerBound2 (qd_, block_cells_[c]);
      int j = c;
      while (j > 0 && bound[j - 1] > b)
      {
        bound[j] = bound[j - 1];
        order[j] = order[j - 1];
        --j;
      }
      bound[j] = b;
      order[j] = c;
    }
    for (int j = 0; j < num_cells; ++j)
    {
      if (bound[j] > cands_.worst ())
        break;
      visit (block_cells_[order[j]]);
    }
  }

  static bool
  inGrid (const std::int64_t c[3], std::int64_t side)
  {
    return c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[0] < side && c[1] < side && c[2] < side;
  }

  /** \brief Whether the k + 1 candidates found are final once the cube of cells within \a radius
    * of \a leaf has been searched. */
  bool
  exactWithin (const Cell& leaf, int radius) const
  {
    return cands_.full () && finalWithin (leaf, radius, cands_.worst ());
  }

  /** \brief Whether every sample outside the cube of cells within \a radius of \a leaf is farther
    * from the current query than \a worst (hence compares above any candidate within it). */
  bool
  finalWithin (const Cell& leaf, int radius, float worst) const
  {
    const double h = tree_.cellSize (leaf.depth);
    const std::int64_t side = std::int64_t (1) << leaf.depth;
    double out = std::numeric_limits<double>::infinity ();
    for (int a = 0; a < 3; ++a)
    {
      // No point lies beyond the border of the grid.
      const double lo = tree_.origin_[a] + static_cast<double> (leaf.c[a] - radius) * h;
      const double hi = tree_.origin_[a] + static_cast<double> (leaf.c[a] + radius + 1) * h;
      if (leaf.c[a] - radius > 0)
        out = std::min (out, qd_[a] - lo);
      if (leaf.c[a] + radius < side - 1)
        out = std::min (out, hi - qd_[a]);
    }
    if (out == std::numeric_limits<double>::infinity ())
      return true;
    out = std::max (0.0, out - tree_.slack_);
    return static_cast<double> (worst) < LinearOctree::shrink (out * out);
  }

  /** \brief Search a cell of the block: scan it, or descend if it is much denser than a leaf. */
  void
  visit (const Cell& cell)
  {
    if (cell.end - cell.begin > leaf_size_ && cell.depth < kMaxDepth)
      descend (cell, nullptr);
    else
      scan (cell.begin, cell.end);
  }

  /** \brief Offer all points of a sorted range to the candidate set. */
  void
  scan (std::uint32_t begin, std::uint32_t end)
  {
    alignas (16) float buf[kChunk];
    const float qx = qf_[0], qy = qf_[1], qz = qf_[2];
    for (std::uint32_t s = begin; s < end; s += kChunk)
    {
      const int m = static_cast<int> (std::min<std::uint32_t> (kChunk, end - s));
      const float* __restrict xs = tree_.xs_.data () + s;
      const float* __restrict ys = tree_.ys_.data () + s;
      const float* __restrict zs = tree_.zs_.data () + s;
      const std::uint32_t* __restrict ids = tree_.ids_.data () + s;
      for (int j = 0; j < m; ++j)
        buf[j] = squaredDistance (xs[j], ys[j], zs[j], qx, qy, qz);
      // Branch-free filter: a third to a half of the candidates pass, unpredictably.
      const std::uint64_t threshold = cands_.threshold ();
      std::uint64_t* __restrict out = cands_.tail ();
      int kept = 0;
      for (int j = 0; j < m; ++j)
      {
        const std::uint64_t key = CandidateSet::makeKey (buf[j], ids[j]);
        out[kept] = key;
        kept += static_cast<int> (key < threshold);
      }
      cands_.grow (kept);
    }
  }

  /** \brief Pruned depth-first search of \a cell, nearest children first. With \a block, the
    * points inside it (already searched) are skipped. */
  void
  descend (const Cell& cell, const Block* block)
  {
    bool partial = false;
    if (block)
    {
      const std::int64_t r = block->radius;
      bool inside = true, disjoint = false;
      if (cell.depth >= block->depth)
      {
        const int up = cell.depth - block->depth;
        for (int a = 0; a < 3; ++a)
        {
          const std::int64_t c = cell.c[a] >> up;
          if (c < block->c[a] - r || c > block->c[a] + r)
            inside = false;
        }
        disjoint = !inside;
      }
      else
      {
        const int down = block->depth - cell.depth;
        for (int a = 0; a < 3; ++a)
        {
          const std::int64_t lo = cell.c[a] << down;
          const std::int64_t hi = ((cell.c[a] + 1) << down) - 1;
          if (lo < block->c[a] - r || hi > block->c[a] + r)
            inside = false;
          if (hi < block->c[a] - r || lo > block->c[a] + r)
            disjoint = true;
        }
      }
      if (inside)
        return;
      if (disjoint)
        block = nullptr;
      else
        partial = true;
    }
    if (!partial && (cell.end - cell.begin <= leaf_size_ || cell.depth == kMaxDepth))
    {
      scan (cell.begin, cell.end);
      return;
    }
    Cell ch[8];
    double bound[8];
    int order[8];
    const int m = tree_.children (cell, ch);
    for (int c = 0; c < m; ++c)
    {
      const double b = tree_.lowerBound2 (qd_, ch[c]);
      int j = c;
      while (j > 0 && bound[j - 1] > b)
      {
        bound[j] = bound[j - 1];
        order[j] = order[j - 1];
        --j;
      }
      bound[j] = b;
      order[j] = c;
    }
    for (int j = 0; j < m; ++j)
    {
      if (bound[j] > cands_.worst ())
        break;
      descend (ch[order[j]], block);
    }
  }

  const LinearOctree& tree_;
  const std::vector<Eigen::Vector3f>& points_;
  int k_;
  CandidateSet cands_;
  std::uint32_t leaf_size_;
  Cell block_cells_[27];
  float qf_[3] = {0.f, 0.f, 0.f};
  double qd_[3] = {0.0, 0.0, 0.0};
};

/** \brief Partition the sorted points into leaves: the largest cells with at most \a leaf_size
  * points (or of the finest level). */
void
collectLeaves (const LinearOctree& tree, const Cell& cell, std::uint32_t leaf_size,
               std::vector<Cell>& leaves)
{
  if (cell.end - cell.begin <= leaf_size || cell.depth == kMaxDepth)
  {
    leaves.push_back (cell);
    return;
  }
  Cell ch[8];
  const int m = tree.children (cell, ch);
  for (int c = 0; c < m; ++c)
    collectLeaves (tree, ch[c], leaf_size, leaves);
}

/** \brief Nesting limit of solveLevel: each level refines the finest cell by 2^19 or more, so
  * float positions are separated long before. */
constexpr int kMaxLevels = 4;

/** \brief Rows for the queries among the samples \a subset (all if null): their k nearest within
  * \a subset, written to \a dense (in place) or, when it is null, compressed into \a graph or,
  * when that is null too, handed to \a visit.
  *
  * A finest-level leaf holding more than leaf_size distinct positions (a cloud whose extent is
  * over 10^6 times its sample spacing, such as one with a wild outlier) would cost its queries a
  * scan of the whole leaf each. Such leaves are solved as a separate problem instead, on the
  * samples of their 3x3x3 blocks, whose much smaller extent gives a much finer grid; a query keeps
  * that result if nothing outside its block can be nearer, and is searched again otherwise. That
  * check reads the row back, so those (few) queries go through a small dense table. */
void
solveLevel (const std::vector<Eigen::Vector3f>& points, const std::vector<std::uint32_t>* subset,
            const std::vector<char>* is_query, int k, int threads, int level, const DenseRows* dense,
            NeighborGraph* graph, const KnnRowVisitor* visit = nullptr)
{
  LinearOctree tree;
  tree.build (points, subset, threads);

  // Leaves of up to 2k points (but not tiny ones, whose 26 neighbour look-ups would cost more than
  // their queries): the block around a leaf then holds a few k candidates, and queries rarely need
  // more than the block. The parent of a leaf holds more than leaf_size > k points and lies in the
  // block, which guarantees k + 1 candidates. Measured on 1M points, leaves of 1k-3k points were
  // within 10 % of each other for k = 50; 2k was best for k = 10, 24 for k = 1.
  const std::uint32_t leaf_size = static_cast<std::uint32_t> (
    std::max<std::size_t> (2 * static_cast<std::size_t> (k), 24));
  std::vector<Cell> leaves;
  collectLeaves (tree, tree.root (), leaf_size, leaves);

  std::vector<char> overfull (leaves.size (), 0);
  bool any_overfull = false;
  if (level + 1 < kMaxLevels)
    for (std::size_t l = 0; l < leaves.size (); ++l)
      if (leaves[l].depth == kMaxDepth && leaves[l].end - leaves[l].begin > leaf_size &&
          !tree.samePosition (leaves[l]))
      {
        overfull[l] = 1;
        any_overfull = true;
      }

#pragma omp parallel num_threads(threads)
  {
    Searcher searcher (tree, points, k, leaf_size);
    std::unique_ptr<RowSink> sink;
    if (dense)
      sink.reset (new DenseSink (*dense));
    else if (graph)
      sink.reset (new AppendSink (*graph, k));
    else
      sink.reset (new VisitSink (*visit, k));
#pragma omp for schedule(dynamic, 16)
    for (std::int64_t l = 0; l < static_cast<std::int64_t> (leaves.size ()); ++l)
      if (!overfull[l])
        searcher.processLeaf (leaves[l], is_query, false, *sink);
  }
  if (!any_overfull)
    return;

  std::vector<std::uint32_t> sub;
  std::vector<char> sub_query (points.size (), 0);
  std::vector<std::uint32_t> queries; // the overfull leaves' queries, ascending
  {
    std::vector<char> in_sub (tree.ids_.size (), 0);
    for (std::size_t l = 0; l < leaves.size (); ++l)
    {
      if (!overfull[l])
        continue;
      tree.forEachNear (leaves[l], 1, [&in_sub] (const Cell& cell) {
        std::fill (in_sub.begin () + cell.begin, in_sub.begin () + cell.end, 1);
      });
      for (std::uint32_t i = leaves[l].begin; i < leaves[l].end; ++i)
        if (!is_query || (*is_query)[tree.ids_[i]])
          sub_query[tree.ids_[i]] = 1;
    }
    for (std::size_t i = 0; i < in_sub.size (); ++i)
      if (in_sub[i])
        sub.push_back (tree.ids_[i]);
  }

  // Into a graph or a visitor: the overfull leaves' queries get a dense table of their own for
  // this step.
  std::vector<std::uint32_t> slot_of, local_data;
  DenseRows local;
  if (!dense)
  {
    slot_of.assign (points.size (), std::numeric_limits<std::uint32_t>::max ());
    for (std::uint32_t id = 0; id < points.size (); ++id)
      if (sub_query[id])
      {
        slot_of[id] = static_cast<std::uint32_t> (queries.size ());
        queries.push_back (id);
      }
    local_data.resize (queries.size () * static_cast<std::size_t> (k));
    local.k = k;
    local.slot_of = &slot_of;
    local.data = local_data.data ();
  }
  const DenseRows& rows = dense ? *dense : local;
  solveLevel (points, &sub, &sub_query, k, threads, level + 1, &rows, nullptr);

#pragma omp parallel num_threads(threads)
  {
    Searcher searcher (tree, points, k, leaf_size);
    DenseSink sink (rows);
#pragma omp for schedule(dynamic, 1)
    for (std::int64_t l = 0; l < static_cast<std::int64_t> (leaves.size ()); ++l)
      if (overfull[l])
        searcher.processLeaf (leaves[l], is_query, true, sink);
  }
  if (!dense && graph)
  {
#pragma omp parallel num_threads(threads)
    {
      NeighborGraph::Appender appender (*graph);
#pragma omp for schedule(static)
      for (std::int64_t q = 0; q < static_cast<std::int64_t> (queries.size ()); ++q)
        appender.setRow (queries[q], rows.row (queries[q]));
    }
  }
  else if (!dense)
  {
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::int64_t q = 0; q < static_cast<std::int64_t> (queries.size ()); ++q)
      (*visit) (queries[q], rows.row (queries[q]));
  }
}

bool
validShape (std::size_t n, int k)
{
  // Row entries are 32-bit indices.
  return k >= 1 && n > static_cast<std::size_t> (k) && n <= std::numeric_limits<std::uint32_t>::max ();
}

} // namespace

// --- NeighborGraph ------------------------------------------------------------------------------

NeighborGraph::NeighborGraph (std::size_t n, int k)
  : k_ (k), n_ (n), offsets_ (n, 0)
{
  // A row is one zigzag varint (up to 10 bytes) and k - 1 deltas of up to 5 bytes; a page holds
  // many rows, and a row never straddles two pages.
  max_row_bytes_ = 10 + 5 * static_cast<std::size_t> (k > 1 ? k - 1 : 0);
  page_shift_ = 18;
  while ((std::size_t (1) << page_shift_) < 4 * max_row_bytes_)
    ++page_shift_;
  page_mask_ = (std::uint64_t (1) << page_shift_) - 1;
}

std::size_t
NeighborGraph::memoryBytes () const
{
  return offsets_.capacity () * sizeof (std::uint64_t) + pages_.size () * (std::size_t (1) << page_shift_);
}

std::uint64_t
NeighborGraph::newPage (std::uint8_t*& data)
{
  std::unique_ptr<std::uint8_t[]> page (new std::uint8_t[std::size_t (1) << page_shift_]);
  data = page.get ();
  std::uint64_t index;
#pragma omp critical(pcl_rspd_neighbor_graph_pages)
  {
    index = pages_.size ();
    pages_.push_back (std::move (page));
  }
  return index;
}

NeighborGraph::Appender::Appender (NeighborGraph& graph)
  : graph_ (graph), sorted_ (static_cast<std::size_t> (graph.k ()))
{}

void
NeighborGraph::Appender::setRow (std::size_t i, const std::uint32_t* row)
{
  const int k = graph_.k_;
  // Sort by rank: each entry goes to the count of entries below it. k^2 comparisons, but without
  // a branch, and the compiler vectorizes them: for k = 50 about twice as fast as an insertion sort
  // and four times std::sort (this sort was a third of the graph's build time). Entries must be
  // distinct for ranks to be; a repeated entry leaves a slot unset, and that row is sorted plainly.
  constexpr std::uint32_t kUnset = std::numeric_limits<std::uint32_t>::max (); // never an index
  std::uint32_t* v = sorted_.data ();
  std::fill (v, v + k, kUnset);
  for (int t = 0; t < k; ++t)
  {
    const std::uint32_t x = row[t];
    int rank = 0;
    for (int j = 0; j < k; ++j)
      rank += static_cast<int> (row[j] < x);
    v[rank] = x;
  }
  if (std::find (v, v + k, kUnset) != v + k)
  {
    std::copy (row, row + k, v);
    std::sort (v, v + k);
  }
  if (page_ == nullptr || used_ + graph_.max_row_bytes_ > (std::size_t (1) << graph_.page_shift_))
  {
    page_index_ = graph_.newPage (page_);
    used_ = 0;
  }
  graph_.offsets_[i] = (page_index_ << graph_.page_shift_) | used_;
  std::uint8_t* out = page_ + used_;
  const auto put = [&out] (std::uint64_t x) {
    while (x >= 0x80)
    {
      *out++ = static_cast<std::uint8_t> (x | 0x80);
      x >>= 7;
    }
    *out++ = static_cast<std::uint8_t> (x);
  };
  const std::int64_t first = static_cast<std::int64_t> (v[0]) - static_cast<std::int64_t> (i);
  put ((static_cast<std::uint64_t> (first) << 1) ^ static_cast<std::uint64_t> (first >> 63));
  for (int t = 1; t < k; ++t)
  {
    const std::uint32_t d = v[t] - v[t - 1];
    if (d < 0x80)
      *out++ = static_cast<std::uint8_t> (d); // most deltas: neighbours a few samples apart
    else
      put (d);
  }
  used_ = static_cast<std::size_t> (out - page_);
}

NeighborGraph
NeighborGraph::fromTable (const NeighborTable& table)
{
  NeighborGraph graph (table.size (), table.k ());
  Appender appender (graph);
  for (std::size_t i = 0; i < table.size (); ++i)
    appender.setRow (i, table.neighbors (i));
  return graph;
}

// --- builders -----------------------------------------------------------------------------------

bool
buildKnnGraph (const std::vector<Eigen::Vector3f>& points, int k, int num_threads,
               NeighborGraph& graph)
{
  const std::size_t n = points.size ();
  graph = NeighborGraph ();
  if (!validShape (n, k))
    return false;
  const int threads = num_threads > 0 ? num_threads : omp_get_max_threads ();
  graph = NeighborGraph (n, k);
  solveLevel (points, nullptr, nullptr, k, threads, 0, nullptr, &graph);
  return true;
}

bool
buildKnnTable (const std::vector<Eigen::Vector3f>& points, int k, int num_threads, NeighborTable& table)
{
  const std::size_t n = points.size ();
  if (!validShape (n, k))
  {
    table = NeighborTable ();
    return false;
  }
  const int threads = num_threads > 0 ? num_threads : omp_get_max_threads ();
  // Every row is overwritten: a table of the right shape is reused as it is.
  if (table.size () != n || table.k () != k)
    table = NeighborTable (n, k);
  DenseRows rows;
  rows.k = k;
  rows.data = table.row (0);
  solveLevel (points, nullptr, nullptr, k, threads, 0, &rows, nullptr);
  return true;
}

bool
visitKnnRows (const std::vector<Eigen::Vector3f>& points, int k, int num_threads, const std::vector<char>& is_query,
              const KnnRowVisitor& visit)
{
  if (!validShape (points.size (), k) || is_query.size () != points.size ())
    return false;
  const int threads = num_threads > 0 ? num_threads : omp_get_max_threads ();
  solveLevel (points, nullptr, &is_query, k, threads, 0, nullptr, nullptr, &visit);
  return true;
}

std::vector<std::uint32_t>
spatialOrder (const std::vector<Eigen::Vector3f>& points, int num_threads)
{
  if (points.empty ())
    return {};
  LinearOctree tree;
  tree.build (points, nullptr, num_threads > 0 ? num_threads : omp_get_max_threads ());
  return std::move (tree.ids_);
}

} // namespace rspd
} // namespace pcl
