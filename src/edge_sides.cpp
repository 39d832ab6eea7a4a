/*
 * pcl_rspd: edge sides (departure), see edge_sides.h.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/edge_sides.h>
#include <pcl_rspd/normal_estimation.h> // resolveThreads
#include <pcl_rspd/patch_growth.h>      // kNoPatch, membersFromLabels

#include <algorithm>
#include <cmath>
#include <utility>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace pcl
{
namespace rspd
{
namespace
{
/** Side values besides +1 and -1: a's members lie on both sides of b; no member of a voted. */
constexpr int kStraddles = 0;
constexpr int kUnjudged = 2;

std::uint64_t
pairKey (std::uint32_t a, std::uint32_t b)
{
  return (static_cast<std::uint64_t> (a) << 32) | b;
}

/** Signed distance to plane b of p's projection onto plane a: p's coordinate in a across the line
  * where a meets b (times the sine of their angle). Noise along a's normal leaves it unchanged. */
double
across (const Eigen::Vector3d& p, const PlanarPatch& a, const PlanarPatch& b)
{
  const Eigen::Vector3d q = p - (p - a.center).dot (a.normal) * a.normal;
  return (q - b.center).dot (b.normal);
}

/** p's distance to plane \a l in units of its noise band. */
double
relativeDistance (const Eigen::Vector3d& p, const std::vector<PlanarPatch>& patches, const std::vector<double>& band,
                  std::uint32_t l)
{
  return std::abs ((p - patches[l].center).dot (patches[l].normal)) / band[l];
}

/** Step sides within the bands (settleStepSides' within_bands): a sample moves to a plane offset
  * from its own by less than the wider band only when that plane holds this many times as many of
  * its neighbours as its own. A plain majority (room at σ 1.2 cm, 20,000 points, seed 43: 0.9956 ->
  * 0.9937, 26 samples along the door's rim moved the wrong way) against twice (0.9953) and three
  * times (0.9956); the facade of draw_rows.py 57's windows 10 cm deep at σ 4 cm, whose rims this is
  * for, over five copies (as given, ×1000, 1 km, two turns): 0.969-0.976 with a plain majority,
  * 0.970-0.978 with twice, 0.968-0.977 with three times. */
constexpr double kWithinBandMajority = 2.0;

/** Normals farther apart than either plane's MND: the pair meets along a line worth judging. */
bool
distinct (const PlanarPatch& a, const PlanarPatch& b)
{
  return std::abs (a.normal.dot (b.normal)) < std::min (a.cos_mnd, b.cos_mnd);
}
} // namespace

EdgeSideCounts
settleEdgeSides (const PointSet& points, const NeighborGraph& graph, const std::vector<double>& band, int num_threads,
                 std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels, bool corners, bool wedges)
{
  EdgeSideCounts counts;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (labels.size ());
  const int threads = resolveThreads (num_threads);

  // Samples that border a distinct plane, and the votes of those beyond its band. Per-thread lists,
  // sorted after: the order of the threads does not matter.
  std::vector<std::vector<std::uint32_t>> border_of (threads);
  std::vector<std::vector<std::pair<std::uint64_t, int>>> votes_of (threads);
#pragma omp parallel num_threads(threads)
  {
#ifdef _OPENMP
    const int t = omp_get_thread_num ();
#else
    const int t = 0;
#endif
#pragma omp for schedule(dynamic, 1024)
    for (std::ptrdiff_t ii = 0; ii < n; ++ii)
    {
      const std::uint32_t i = static_cast<std::uint32_t> (ii);
      const std::uint32_t a = labels[i];
      if (a == kNoPatch)
        continue;
      const Eigen::Vector3d p = points.points[i].cast<double> ();
      std::uint32_t last = kNoPatch;
      bool border = false;
      graph.forEachNeighbor (i, [&] (std::uint32_t j) {
        const std::uint32_t b = labels[j];
        if (b == kNoPatch || b == a || b == last || !distinct (patches[a], patches[b]))
          return;
        last = b; // consecutive repeats only; a repeated vote per (sample, plane) is harmless
        border = true;
        const double s = across (p, patches[a], patches[b]);
        if (std::abs (s) > band[b])
          votes_of[t].emplace_back (pairKey (a, b), s > 0.0 ? 1 : -1);
      });
      if (border)
        border_of[t].push_back (i);
    }
  }
  std::vector<std::uint32_t> border;
  std::vector<std::pair<std::uint64_t, int>> votes;
  for (int t = 0; t < threads; ++t)
  {
    border.insert (border.end (), border_of[t].begin (), border_of[t].end ());
    votes.insert (votes.end (), votes_of[t].begin (), votes_of[t].end ());
  }
  std::sort (border.begin (), border.end ());
  std::sort (votes.begin (), votes.end ());

  std::vector<std::pair<std::uint64_t, int>> side; // (pair, +1, -1 or kStraddles), sorted by pair
  for (std::size_t v = 0; v < votes.size ();)
  {
    std::size_t w = v, pos = 0, neg = 0;
    for (; w < votes.size () && votes[w].first == votes[v].first; ++w)
      (votes[w].second > 0 ? pos : neg) += 1;
    if (pos >= 3 * neg)
      side.emplace_back (votes[v].first, 1);
    else if (neg >= 3 * pos)
      side.emplace_back (votes[v].first, -1);
    else
      side.emplace_back (votes[v].first, kStraddles);
    v = w;
  }
  const auto sideOf = [&side] (std::uint32_t a, std::uint32_t b) {
    const auto it = std::lower_bound (side.begin (), side.end (), std::make_pair (pairKey (a, b), -2));
    return it != side.end () && it->first == pairKey (a, b) ? it->second : kUnjudged;
  };

  std::vector<std::uint32_t> next (border.size ());
  std::vector<char> in_corner (border.size (), 0), outside (border.size (), 0);
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads)
  for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t> (border.size ()); ++k)
  {
    const std::uint32_t i = border[k];
    const std::uint32_t a = labels[i];
    next[k] = a;
    const Eigen::Vector3d p = points.points[i].cast<double> ();
    bool beyond = false;
    std::uint32_t best = kNoPatch;
    double best_r = HUGE_VAL;
    graph.forEachNeighbor (i, [&] (std::uint32_t j) {
      const std::uint32_t b = labels[j];
      if (b == kNoPatch || b == a)
        return;
      const int sa = sideOf (a, b);
      if (sa == kStraddles || sa == kUnjudged || sa * across (p, patches[a], patches[b]) >= 0.0)
        return;
      beyond = true;
      const int sb = sideOf (b, a);
      const double r = relativeDistance (p, patches, band, b);
      // b straddling a has no side of a to keep to; b with no vote is not trusted with the sample.
      if (sb != kUnjudged && (sb == kStraddles || sb * across (p, patches[b], patches[a]) >= 0.0) && r <= 1.0 &&
          (r < best_r || (r == best_r && b < best)))
      {
        best_r = r;
        best = b;
      }
    });
    if (beyond && best == kNoPatch && wedges)
    {
      // Outside the edge (beyond the line on a and on b): only noise across the line puts samples
      // here, and with the same noise in every direction the plane the sample lies farther from is
      // the likelier one (see the header); beyond any of the bands, none takes it.
      double far_r = relativeDistance (p, patches, band, a);
      std::uint32_t far = a;
      bool outside_edge = false; // some b's projection lies beyond a too (not merely beyond b's band)
      double excursion = 0.0;    // how far p's projection onto a lies beyond a's edge lines, in a
      graph.forEachNeighbor (i, [&] (std::uint32_t j) {
        const std::uint32_t b = labels[j];
        if (b == kNoPatch || b == a)
          return;
        const int sa = sideOf (a, b), sb = sideOf (b, a);
        const double s = across (p, patches[a], patches[b]);
        if (sa == kStraddles || sa == kUnjudged || sa * s >= 0.0)
          return;
        // across () is the in-plane distance times the sine of the planes' angle.
        const double c = patches[a].normal.dot (patches[b].normal);
        excursion = std::max (excursion, std::abs (s) / std::sqrt (std::max (1e-12, 1.0 - c * c)));
        if (sb == kStraddles || sb == kUnjudged || sb * across (p, patches[b], patches[a]) >= 0.0)
          return;
        outside_edge = true;
        const double r = relativeDistance (p, patches, band, b);
        if (r > far_r || (r == far_r && b < far))
        {
          far_r = r;
          far = b;
        }
      });
      // Beyond b's line and b's band but on b's side of a (b cannot own it): a's own noise across its
      // edge can, as far as a's band reaches.
      if (outside_edge ? far_r <= 1.0 : far_r <= 1.0 && excursion <= band[a])
      {
        best = far;
        outside[k] = 1;
      }
    }
    if (beyond)
    {
      next[k] = best;
      continue;
    }
    if (!corners)
      continue;
    // Inside the corner: the sample's projection onto a lies on a's side of b and its projection
    // onto b on b's side of a, so either plane's noise may have put it there. The likelier plane is
    // the nearer one, relative to its band (its noise): noise along a's normal moves a's sample
    // that far off a, along b's normal b's sample that far off b.
    best_r = relativeDistance (p, patches, band, a);
    graph.forEachNeighbor (i, [&] (std::uint32_t j) {
      const std::uint32_t b = labels[j];
      if (b == kNoPatch || b == a)
        return;
      const int sa = sideOf (a, b), sb = sideOf (b, a);
      if (sa == kStraddles || sa == kUnjudged || sb == kStraddles || sb == kUnjudged ||
          sb * across (p, patches[b], patches[a]) < 0.0)
        return; // p's projection onto a is on a's side of every b here: none was beyond (above)
      const double r = relativeDistance (p, patches, band, b);
      if (r <= 1.0 && (r < best_r || (r == best_r && next[k] != a && b < next[k])))
      {
        best_r = r;
        next[k] = b;
        in_corner[k] = 1;
      }
    });
  }

  bool changed = false;
  for (std::size_t k = 0; k < border.size (); ++k)
  {
    const std::uint32_t i = border[k];
    counts.outside += outside[k];
    if (next[k] == labels[i])
      continue;
    changed = true;
    (next[k] == kNoPatch ? counts.released : in_corner[k] ? counts.cornered : counts.moved) += 1;
    labels[i] = next[k];
  }
  if (changed)
    membersFromLabels (labels, patches);
  return counts;
}

std::size_t
settleStepSides (const PointSet& points, const NeighborGraph& graph, const std::vector<double>& band, int num_threads,
                 std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels, bool within_bands)
{
  // Parallel planes offset by more than the wider band: a step deeper than the noise.
  const auto deeper = [&] (std::uint32_t a, std::uint32_t b) {
    return std::abs ((patches[b].center - patches[a].center).dot (patches[a].normal)) > std::max (band[a], band[b]);
  };
  const auto step = [&] (std::uint32_t a, std::uint32_t b) {
    return !distinct (patches[a], patches[b]) && (within_bands || deeper (a, b));
  };
  // Each plane's step partners: a sample moves only into the band of one of them, which a few
  // distances tell without reading its neighbours (most samples lie in no other band).
  constexpr std::size_t kMaxPartnersChecked = 16;
  std::vector<std::vector<std::uint32_t>> partners (patches.size ());
  for (std::uint32_t a = 0; a < patches.size (); ++a)
    for (std::uint32_t b = 0; b < patches.size (); ++b)
      if (b != a && !patches[a].members.empty () && !patches[b].members.empty () && step (a, b))
        partners[a].push_back (b);
  const auto partnerOf = [&partners] (std::uint32_t a, std::uint32_t b) {
    return std::binary_search (partners[a].begin (), partners[a].end (), b);
  };
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (labels.size ());
  std::vector<std::uint32_t> next (labels);
#pragma omp parallel num_threads(resolveThreads (num_threads))
  {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> count; // (plane, neighbours in it); k is small
#pragma omp for schedule(dynamic, 1024)
    for (std::ptrdiff_t ii = 0; ii < n; ++ii)
    {
      const std::uint32_t i = static_cast<std::uint32_t> (ii);
      const std::uint32_t a = labels[i];
      if (a == kNoPatch || partners[a].empty ())
        continue;
      const Eigen::Vector3d p = points.points[i].cast<double> ();
      const auto relative = [&] (std::uint32_t l) {
        return relativeDistance (p, patches, band, l);
      };
      if (partners[a].size () <= kMaxPartnersChecked &&
          std::none_of (partners[a].begin (), partners[a].end (), [&] (std::uint32_t b) { return relative (b) <= 1.0; }))
        continue;
      count.clear ();
      graph.forEachNeighbor (i, [&] (std::uint32_t j) {
        const std::uint32_t b = labels[j];
        if (b == kNoPatch)
          return;
        auto it = std::find_if (count.begin (), count.end (), [b] (const auto& c) { return c.first == b; });
        if (it == count.end ())
          count.emplace_back (b, 1);
        else
          ++it->second;
      });
      std::uint32_t best = a, best_count = 0;
      for (const auto& c : count)
        if (c.first == a)
          best_count = c.second;
      const std::uint32_t own_count = best_count;
      double best_r = relative (a);
      for (const auto& c : count)
      {
        const std::uint32_t b = c.first;
        if (b == a || !partnerOf (a, b))
          continue;
        const double r = relative (b);
        // Between planes offset within their bands, where every sample along the rim lies in both,
        // a plain majority moves the rim back and forth and wears a door's corners away: twice as
        // many neighbours in b as in a.
        if (c.second < kWithinBandMajority * own_count && !deeper (a, b))
          continue;
        // Within b's band, the plane that holds more of the neighbours; ties stay, or go nearer.
        if (r <= 1.0 && (c.second > best_count ||
                         (c.second == best_count && best != a && (r < best_r || (r == best_r && b < best)))))
        {
          best = b;
          best_count = c.second;
          best_r = r;
        }
      }
      next[i] = best;
    }
  }
  return adoptLabels (next, labels, patches);
}

} // namespace rspd
} // namespace pcl
