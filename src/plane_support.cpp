/*
 * pcl_rspd: plane support (departure), see plane_support.h.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/normal_estimation.h> // resolveThreads
#include <pcl_rspd/patch_growth.h>      // kNoPatch, labelSamples
#include <pcl_rspd/plane_support.h>
#include <pcl_rspd/robust_statistics.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl
{
namespace rspd
{
namespace
{
/** Per plane, how much wider its members' gaps spread than uniform samples' would: the ratio of
  * their kGapSpreadQuantile quantile to their median, over that ratio for samples spread uniformly
  * (P(gap > x) = 2^(-(x / median)²)), at least 1. Samples in rows or stripes (a scan's lines, an
  * RGB-D camera's depth steps on a slanted plane) have a small median gap along the row and a
  * quantile across the rows: office1's planes spread 1 to 6.7 times. */
std::vector<double>
gapSpreads (const std::vector<std::uint32_t>& labels, const std::vector<float>& gap, std::size_t num_planes)
{
  std::vector<std::vector<float>> gaps (num_planes);
  for (std::size_t i = 0; i < labels.size (); ++i)
    if (labels[i] != kNoPatch && std::isfinite (gap[i]))
      gaps[labels[i]].push_back (gap[i]);
  const double uniform = std::sqrt (std::log (1.0 - kGapSpreadQuantile) / std::log (0.5));
  std::vector<double> spread (num_planes, 1.0);
  for (std::size_t l = 0; l < num_planes; ++l)
  {
    std::vector<float>& g = gaps[l];
    if (g.empty ())
      continue;
    const double median = medianInPlace (g);
    const auto at = static_cast<std::ptrdiff_t> (kGapSpreadQuantile * static_cast<double> (g.size () - 1));
    std::nth_element (g.begin (), g.begin () + at, g.end ());
    if (median > 0.0)
      spread[l] = std::max (1.0, static_cast<double> (g[at]) / median / uniform);
  }
  return spread;
}

/** Whether member \a i of its plane (\a normal) is in a detached group: the members reached from
  * it, hop by hop, each within kSupportGapRatio · \a spread times the median gap of its own plane
  * neighbours, number fewer than kDetachedGroupSize and are all candidates. \a fresh members (this
  * round's releases) are left out. */
bool
inDetachedGroup (const PointSet& points, const NeighborGraph& graph, const Eigen::Vector3d& normal, double spread,
                 const std::vector<std::uint32_t>& labels, const std::vector<float>& gap,
                 const std::vector<std::uint8_t>& candidate, const std::vector<std::uint8_t>& fresh, std::uint32_t i)
{
  const std::uint32_t l = labels[i];
  const auto inPlane = [&] (std::uint32_t m) { return labels[m] == l && !fresh[m]; };
  std::vector<std::uint32_t> group {i};
  std::vector<float> gaps;
  for (std::size_t at = 0; at < group.size (); ++at)
  {
    const std::uint32_t u = group[at];
    if (!candidate[u])
      return false; // reaches the plane's body
    gaps.clear ();
    graph.forEachNeighbor (u, [&] (std::uint32_t m) {
      if (inPlane (m) && std::isfinite (gap[m]))
        gaps.push_back (gap[m]);
    });
    if (gaps.empty ())
      continue;
    const double reach = kSupportGapRatio * spread * medianInPlace (gaps);
    if (!(reach > 0.0))
      return false; // coincident samples: no scale to judge by (as in pass 2)
    const Eigen::Vector3d p = points.points[u].cast<double> ();
    bool large = false;
    graph.forEachNeighbor (u, [&] (std::uint32_t m) {
      if (large || !inPlane (m) || std::find (group.begin (), group.end (), m) != group.end ())
        return;
      const Eigen::Vector3d q = points.points[m].cast<double> () - p;
      if ((q - q.dot (normal) * normal).norm () <= reach)
      {
        group.push_back (m);
        large = group.size () >= kDetachedGroupSize;
      }
    });
    if (large)
      return false;
  }
  return true;
}

/** The in-plane distance between samples \a i and \a m, in the plane of normal \a normal. */
double
inPlaneDistance (const PointSet& points, const Eigen::Vector3d& normal, std::uint32_t i, std::uint32_t m)
{
  const Eigen::Vector3d v = points.points[m].cast<double> () - points.points[i].cast<double> ();
  return (v - v.dot (normal) * normal).norm ();
}

} // namespace

std::vector<float>
vouchingGaps (const PointSet& points, const NeighborGraph& graph, const std::vector<PlanarPatch>& patches,
              const std::vector<std::uint32_t>& labels, const std::vector<std::uint32_t>& open,
              const std::vector<char>& judged, int num_threads)
{
  const int threads = resolveThreads (num_threads);
  std::vector<float> gap (labels.size (), -1.0f);
  // The members next to an open sample (they vouch), then their neighbours in their own plane
  // (they tell whether those are supported).
  std::vector<std::uint32_t> members;
  const auto collect = [&] (std::uint32_t m, std::uint32_t l) {
    if (labels[m] != kNoPatch && labels[m] == l && judged[l] && gap[m] < 0.0f)
    {
      gap[m] = 0.0f;
      members.push_back (m);
    }
  };
  for (const std::uint32_t i : open)
    graph.forEachNeighbor (i, [&] (std::uint32_t m) { collect (m, labels[m]); });
  const std::size_t vouching = members.size ();
  for (std::size_t j = 0; j < vouching; ++j)
    graph.forEachNeighbor (members[j], [&] (std::uint32_t m) { collect (m, labels[members[j]]); });
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (members.size ());
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (std::ptrdiff_t j = 0; j < count; ++j)
  {
    const std::uint32_t m = members[j];
    // The spacing of the plane's samples, not of duplicates (a scan's repeated points): the
    // nearest member apart from it in the plane.
    double nearest = HUGE_VAL;
    graph.forEachNeighbor (m, [&] (std::uint32_t o) {
      if (labels[o] != labels[m])
        return;
      const double d = inPlaneDistance (points, patches[labels[m]].normal, m, o);
      if (d > 0.0)
        nearest = std::min (nearest, d);
    });
    gap[m] = static_cast<float> (nearest);
  }
  std::vector<float> vouch (vouching);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (std::ptrdiff_t j = 0; j < static_cast<std::ptrdiff_t> (vouching); ++j)
  {
    const std::uint32_t m = members[j];
    std::vector<float> around;
    graph.forEachNeighbor (m, [&] (std::uint32_t o) {
      if (labels[o] == labels[m] && std::isfinite (gap[o]))
        around.push_back (gap[o]);
    });
    const bool supported = !around.empty () && gap[m] <= kSupportGapRatio * medianInPlace (around);
    vouch[j] = supported ? gap[m] : std::numeric_limits<float>::infinity ();
  }
  for (std::size_t j = 0; j < vouching; ++j)
    gap[members[j]] = vouch[j];
  for (std::size_t j = vouching; j < members.size (); ++j)
    gap[members[j]] = -1.0f; // measured only to judge the members next to open samples
  return gap;
}

float
admittingGap (const PointSet& points, const NeighborGraph& graph, const PlanarPatch& plane, std::uint32_t l,
              const std::vector<std::uint32_t>& labels, const std::vector<float>& gaps, std::uint32_t i)
{
  std::vector<float> around;
  double gap = HUGE_VAL; // to the nearest neighbour in l, vouching or not
  graph.forEachNeighbor (i, [&] (std::uint32_t m) {
    if (labels[m] != l)
      return;
    gap = std::min (gap, inPlaneDistance (points, plane.normal, i, m));
    if (gaps[m] >= 0.0f && std::isfinite (gaps[m]))
      around.push_back (gaps[m]);
  });
  if (around.empty ())
    return std::numeric_limits<float>::quiet_NaN ();
  const float typical = medianInPlace (around);
  return gap <= kSupportGapRatio * static_cast<double> (typical) ? typical : std::numeric_limits<float>::quiet_NaN ();
}

namespace
{
/** Volume of the ball of radius \a r about the origin between the planes z = \a a and z = \a b. */
double
ballSlice (double r, double a, double b)
{
  a = std::max (a, -r);
  b = std::min (b, r);
  if (!(b > a))
    return 0.0;
  const double r2 = r * r;
  return M_PI * ((r2 * b - b * b * b / 3.0) - (r2 * a - a * a * a / 3.0));
}

/** The clutter share (see releaseUnsupportedMembers): whether a member whose graph neighbours hold
  * \a own samples of its plane and \a off unlabelled samples outside its \a band, the farthest at
  * \a reach, has, in the ball of that radius, its plane's samples within the band no denser than
  * those unlabelled samples outside it; \a d is its signed distance to its plane. */
bool
amidAsDenseClutter (std::size_t own, std::size_t off, double reach, double d, double band)
{
  if (off == 0)
    return false;
  const double in_band = ballSlice (reach, -band - d, band - d); // the band spans [-band - d, band - d] about it
  const double outside = 4.0 / 3.0 * M_PI * reach * reach * reach - in_band;
  // own / in_band <= off / outside, without dividing (a ball wholly inside the band: outside 0).
  return static_cast<double> (own) * outside <= static_cast<double> (off) * in_band;
}
} // namespace

std::size_t
releaseUnsupportedMembers (const PointSet& points, const NeighborGraph& graph, const std::vector<double>& band,
                           int num_threads, std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels,
                           bool clutter_share, std::size_t* clutter_released)
{
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (labels.size ());
  const int threads = resolveThreads (num_threads);
  constexpr float kNone = std::numeric_limits<float>::infinity ();

  // Per member, from its neighbours in its plane: the in-plane gap to the nearest (infinite when it
  // has none; 0 when one coincides with it or lies on its normal line), the depth (how far it lies
  // beyond all of them along their mean direction) and whether it is a candidate (one-sided, in no
  // other plane's band). Kept across rounds: a round recomputes only what a release changed.
  std::vector<float> gap (labels.size (), kNone);
  std::vector<float> depth (labels.size (), 0.0f);
  std::vector<std::uint8_t> candidate (labels.size (), 0);
  std::vector<std::uint8_t> stale (labels.size (), 1);    // its own figures must be recomputed
  std::vector<std::uint8_t> affected (labels.size (), 1); // its verdict may have changed
  std::vector<std::uint8_t> release (labels.size (), 0);  // released in an earlier round
  std::vector<std::uint8_t> fresh (labels.size (), 0);    // released in this round
  std::vector<std::uint8_t> grouped (labels.size (), 0);  // in a small detached group
  // Per member, the clutter share's verdict (clutter_share), measured with its other figures; a
  // member it holds for is released in the same round, so at the end it marks those releases.
  std::vector<std::uint8_t> amid_clutter (clutter_share ? labels.size () : 0, 0);
  std::vector<double> spread; // per plane, gapSpreads of the first round
  // Per member, the lowest and highest index in its graph row (rows are sorted), read in the first
  // round: a later round decodes only the rows whose range holds one of its releases, not all.
  std::vector<std::uint32_t> row_lo (labels.size (), 0), row_hi (labels.size (), 0);
  std::vector<std::uint32_t> released_now; // this round's releases, in increasing order

  for (int round = 0; round < kSupportRounds; ++round)
  {
    // Pass 1: the figures of the stale members. A row's in-plane offsets are gathered into a fixed
    // buffer first and their lengths taken in a loop of their own, then summed in the row's order,
    // as the one loop did (same figures; the 1M cube's whole support pass 0.33 -> 0.25 s).
#pragma omp parallel num_threads(threads)
    {
      // Offsets to the neighbours in the plane, within it (the first `count`), and their lengths.
      std::vector<Eigen::Vector3d> along (static_cast<std::size_t> (graph.k ()));
      std::vector<double> lengths (along.size ());
#pragma omp for schedule(dynamic, 1024)
      for (std::ptrdiff_t ii = 0; ii < n; ++ii)
      {
        const std::uint32_t i = static_cast<std::uint32_t> (ii);
        const std::uint32_t l = labels[i];
        if (l == kNoPatch || !stale[i])
          continue;
        const Eigen::Vector3d& normal = patches[l].normal;
        const Eigen::Vector3d p = points.points[i].cast<double> ();
        const double d = (p - patches[l].center).dot (normal);
        bool near_other = false;
        std::uint32_t lo = std::numeric_limits<std::uint32_t>::max (), hi = 0;
        std::size_t count = 0, off = 0; // neighbours in the plane; unlabelled ones outside its band
        double reach2 = 0.0;
        graph.forEachNeighbor (i, [&] (std::uint32_t m) {
          lo = std::min (lo, m);
          hi = std::max (hi, m);
          const std::uint32_t o = labels[m];
          if (clutter_share)
          {
            const Eigen::Vector3d q = points.points[m].cast<double> () - p;
            reach2 = std::max (reach2, q.squaredNorm ());
            off += o == kNoPatch && std::abs (q.dot (normal) + d) > band[l];
          }
          if (o == kNoPatch)
            return;
          if (o != l)
          {
            near_other = near_other || std::abs ((p - patches[o].center).dot (patches[o].normal)) <= band[o];
            return;
          }
          const Eigen::Vector3d q = points.points[m].cast<double> () - p;
          along[count++] = q - q.dot (normal) * normal;
        });
        if (clutter_share)
          amid_clutter[i] = amidAsDenseClutter (count, off, std::sqrt (reach2), d, band[l]);
        for (std::size_t t = 0; t < count; ++t)
          lengths[t] = along[t].norm ();
        double nearest = HUGE_VAL;
        Eigen::Vector3d directions = Eigen::Vector3d::Zero ();
        int directed = 0;
        for (std::size_t t = 0; t < count; ++t)
        {
          nearest = std::min (nearest, lengths[t]);
          if (lengths[t] > 0.0)
          {
            directions += along[t] * (1.0 / lengths[t]); // one division, not three
            ++directed;
          }
        }
        if (round == 0)
        {
          row_lo[i] = lo;
          row_hi[i] = hi;
        }
        gap[i] = static_cast<float> (nearest);
        const double resultant = directed > 0 ? directions.norm () / directed : 1.0;
        candidate[i] = !near_other && resultant > kOneSidedResultant;
        depth[i] = 0.0f;
        if (candidate[i] && directed > 0 && directions.norm () > 0.0)
        {
          // Depth: the least offset, along the mean direction into the plane, of its plane's
          // neighbours; a sample ahead of them all is beyond the plane's rim by that much.
          const Eigen::Vector3d inward = directions.normalized ();
          double least = HUGE_VAL;
          for (std::size_t t = 0; t < count; ++t)
            least = std::min (least, along[t].dot (inward));
          depth[i] = static_cast<float> (least);
        }
      }
    }

    // Pass 2: a candidate whose gap or depth is far beyond its neighbours' gaps, or with too few
    // neighbours in its plane to tell, is released.
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
    for (std::ptrdiff_t ii = 0; ii < n; ++ii)
    {
      const std::uint32_t i = static_cast<std::uint32_t> (ii);
      fresh[i] = 0;
      if (labels[i] == kNoPatch || !affected[i])
        continue;
      if (clutter_share && amid_clutter[i])
      {
        fresh[i] = 1; // the clutter share (DetectorParameters::support_clutter), for every member
        continue;
      }
      if (!candidate[i])
        continue;
      if (std::isinf (gap[i]))
      {
        fresh[i] = 1; // no neighbour in its own plane
        continue;
      }
      std::vector<float> gaps;
      std::size_t neighbours = 0;
      graph.forEachNeighbor (i, [&] (std::uint32_t m) {
        ++neighbours;
        if (labels[m] == labels[i] && std::isfinite (gap[m]))
          gaps.push_back (gap[m]);
      });
      if (static_cast<double> (gaps.size ()) < kMinSupportShare * static_cast<double> (neighbours))
      {
        fresh[i] = 1;
        continue;
      }
      const double typical = medianInPlace (gaps);
      fresh[i] = typical > 0.0 && (static_cast<double> (gap[i]) > kSupportGapRatio * typical ||
                                   static_cast<double> (depth[i]) > kSupportDepthRatio * typical);
    }

    if (round == 0)
      spread = gapSpreads (labels, gap, patches.size ());

    // Pass 3: a candidate in a detached group (kDetachedGroupSize) is released. The walk reads the
    // labels and figures before this round's releases and writes only its own sample's verdict.
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
    for (std::ptrdiff_t ii = 0; ii < n; ++ii)
    {
      const std::uint32_t i = static_cast<std::uint32_t> (ii);
      if (labels[i] != kNoPatch && !fresh[i] && candidate[i] && affected[i])
        grouped[i] = inDetachedGroup (points, graph, patches[labels[i]].normal, spread[labels[i]], labels, gap, candidate, fresh, i);
    }
    for (std::ptrdiff_t i = 0; i < n; ++i)
      if (grouped[i])
      {
        fresh[i] = 1;
        grouped[i] = 0;
      }

    released_now.clear ();
    for (std::ptrdiff_t i = 0; i < n; ++i)
      if (fresh[i])
      {
        release[i] = 1;
        labels[i] = kNoPatch;
        released_now.push_back (static_cast<std::uint32_t> (i));
      }
    if (released_now.empty ())
      break;

    // Peeling: a release exposes the members behind it. Stale: a neighbour was released (its
    // figures change); affected: it or a neighbour is stale (its verdict reads their gaps). Only a
    // candidate's verdict is read, and a member that is not stale keeps its candidacy, so affected
    // is worked out for stale members and candidates alone.
#pragma omp parallel for schedule(dynamic, 4096) num_threads(threads)
    for (std::ptrdiff_t ii = 0; ii < n; ++ii)
    {
      const std::uint32_t i = static_cast<std::uint32_t> (ii);
      bool s = false;
      const auto first = std::lower_bound (released_now.begin (), released_now.end (), row_lo[i]);
      if (labels[i] != kNoPatch && first != released_now.end () && *first <= row_hi[i])
        graph.forEachNeighbor (i, [&] (std::uint32_t m) { s = s || fresh[m] != 0; });
      stale[i] = s;
    }
#pragma omp parallel for schedule(dynamic, 4096) num_threads(threads)
    for (std::ptrdiff_t ii = 0; ii < n; ++ii)
    {
      const std::uint32_t i = static_cast<std::uint32_t> (ii);
      bool a = stale[i] != 0;
      if (labels[i] != kNoPatch && !a && candidate[i])
        graph.forEachNeighbor (i, [&] (std::uint32_t m) { a = a || stale[m] != 0; });
      affected[i] = a;
    }
  }

  if (clutter_released)
    *clutter_released = static_cast<std::size_t> (std::count (amid_clutter.begin (), amid_clutter.end (), 1));
  std::size_t released = 0;
  for (auto& patch : patches)
  {
    const auto end = std::remove_if (patch.members.begin (), patch.members.end (),
                                     [&] (std::uint32_t i) { return release[i] != 0; });
    released += static_cast<std::size_t> (patch.members.end () - end);
    patch.members.erase (end, patch.members.end ());
  }
  if (released > 0)
  {
    patches.erase (std::remove_if (patches.begin (), patches.end (),
                                   [] (const PlanarPatch& p) { return p.members.empty (); }),
                   patches.end ());
    labels = labelSamples (labels.size (), patches);
  }
  return released;
}

} // namespace rspd
} // namespace pcl
