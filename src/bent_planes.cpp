/*
 * pcl_rspd: bent planes (departure), see bent_planes.h.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/bent_planes.h>
#include <pcl_rspd/normal_estimation.h>  // resolveThreads
#include <pcl_rspd/patch_growth.h>       // labelSamples, kNoPatch
#include <pcl_rspd/plane_curvature.h>    // isFlatPatch
#include <pcl_rspd/robust_statistics.h> // medianInPlace, kMadScale

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace pcl
{
namespace rspd
{
namespace
{
/** Sums for the least-squares plane of a set of samples, offsets taken from a fixed origin (one of
  * them) so that precision does not depend on where the cloud lies. */
struct PlaneSums
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero ();
  double n = 0.0;

  void
  add (const Eigen::Vector3d& d)
  {
    sum += d;
    outer += d * d.transpose ();
    n += 1.0;
  }

  void
  add (const PlaneSums& o)
  {
    sum += o.sum;
    outer += o.outer;
    n += o.n;
  }

  void
  remove (const PlaneSums& o)
  {
    sum -= o.sum;
    outer -= o.outer;
    n -= o.n;
  }

  Eigen::Matrix3d
  covariance () const
  {
    const Eigen::Vector3d mean = sum / n;
    return outer / n - mean * mean.transpose ();
  }

  /** Sum of squared distances to the least-squares plane (n λ0); +inf below three samples. */
  double
  residual () const
  {
    if (n < 3.0)
      return std::numeric_limits<double>::infinity ();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig (covariance (), Eigen::EigenvaluesOnly);
    return n * std::max (0.0, eig.eigenvalues () (0));
  }

  /** Centroid (as an offset) and normal; false if the samples are collinear or coincide. */
  bool
  plane (Eigen::Vector3d& center, Eigen::Vector3d& normal, Eigen::Matrix3d* axes = nullptr) const
  {
    if (n < 3.0)
      return false;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig (covariance ());
    if (eig.info () != Eigen::Success || !(eig.eigenvalues () (1) > 0.0))
      return false;
    center = sum / n;
    normal = eig.eigenvectors ().col (0);
    if (axes)
      *axes = eig.eigenvectors ();
    return normal.allFinite ();
  }
};

/** Appends to \a d the distances of \a samples to their own least-squares plane, whose normal goes to
  * \a normal. False (nothing appended) if they determine no plane. */
bool
appendDistances (const PointSet& points, const std::vector<std::uint32_t>& samples, const Eigen::Vector3d& origin,
                 std::vector<float>& d, Eigen::Vector3d& normal)
{
  PlaneSums s;
  for (const auto i : samples)
    s.add (points.points[i].cast<double> () - origin);
  Eigen::Vector3d center;
  if (!s.plane (center, normal))
    return false;
  for (const auto i : samples)
    d.push_back (static_cast<float> (std::abs ((points.points[i].cast<double> () - origin - center).dot (normal))));
  return true;
}

constexpr int kDirections = 16;
constexpr int kBins = 128;
constexpr std::size_t kSearchSamples = 16384;
constexpr int kMaxLevels = 3;
} // namespace

bool
fitHinge (const PointSet& points, const std::vector<std::uint32_t>& samples, HingeFit& fit)
{
  const std::size_t n = samples.size ();
  fit = HingeFit ();
  if (n < 6)
    return false;
  const Eigen::Vector3d origin = points.points[samples.front ()].cast<double> ();
  // A large set is searched on every m-th member: a uniform subset, and the cut is a coarse feature.
  const std::size_t stride = (n + kSearchSamples - 1) / kSearchSamples;
  std::vector<Eigen::Vector3d> q;
  q.reserve (n / stride + 1);
  PlaneSums all;
  for (std::size_t t = 0; t < n; t += stride)
  {
    q.push_back (points.points[samples[t]].cast<double> () - origin);
    all.add (q.back ());
  }
  Eigen::Vector3d center, normal;
  Eigen::Matrix3d axes;
  if (!all.plane (center, normal, &axes))
    return false;

  std::vector<PlaneSums> bins (kBins);
  std::vector<double> along (q.size ());
  double best = std::numeric_limits<double>::infinity ();
  Eigen::Vector3d best_dir = Eigen::Vector3d::Zero ();
  double best_cut = 0.0;
  for (int k = 0; k < kDirections; ++k)
  {
    const double a = k * (M_PI / kDirections);
    const Eigen::Vector3d dir = std::cos (a) * axes.col (2) + std::sin (a) * axes.col (1);
    double lo = std::numeric_limits<double>::infinity (), hi = -lo;
    for (std::size_t t = 0; t < q.size (); ++t)
    {
      along[t] = q[t].dot (dir);
      lo = std::min (lo, along[t]);
      hi = std::max (hi, along[t]);
    }
    if (!(hi > lo))
      continue;
    std::fill (bins.begin (), bins.end (), PlaneSums ());
    const double scale = kBins / (hi - lo);
    for (std::size_t t = 0; t < q.size (); ++t)
      bins[std::min (kBins - 1, static_cast<int> ((along[t] - lo) * scale))].add (q[t]);
    PlaneSums below, above = all;
    for (int b = 0; b + 1 < kBins; ++b)
    {
      if (bins[b].n == 0.0)
        continue; // the same cut as the previous bin's
      below.add (bins[b]);
      above.remove (bins[b]);
      const double r = below.residual () + above.residual ();
      if (r < best)
      {
        best = r;
        best_dir = dir;
        best_cut = lo + (b + 1) / scale;
      }
    }
  }
  if (!std::isfinite (best))
    return false;

  // Sides and spreads on every sample.
  for (const auto i : samples)
    fit.parts[(points.points[i].cast<double> () - origin).dot (best_dir) >= best_cut ? 1 : 0].push_back (i);
  std::vector<float> d;
  d.reserve (n);
  for (int s = 0; s < 2; ++s)
    if (!appendDistances (points, fit.parts[s], origin, d, fit.side_normal[s]))
      return false;
  fit.split_sigma = kMadScale * medianInPlace (d);
  d.clear ();
  Eigen::Vector3d whole_normal;
  appendDistances (points, samples, origin, d, whole_normal);
  fit.single_sigma = kMadScale * medianInPlace (d);
  fit.angle = std::acos (std::min (1.0, std::abs (fit.side_normal[0].dot (fit.side_normal[1]))));
  return true;
}

bool
isBend (const HingeFit& fit, const DetectorParameters& params)
{
  return fit.split_sigma <= params.bent_sigma_ratio * fit.single_sigma && fit.angle > 0.5 * M_PI - params.min_distance_angle;
}

namespace
{
/** The angle between the mean normals of \a fit's two sides (each sample's turned towards its
  * side's plane normal: unoriented), or NaN when a side's normals have no mean direction. */
double
sideNormalTurn (const PointSet& points, const HingeFit& fit)
{
  Eigen::Vector3d mean[2];
  for (int s = 0; s < 2; ++s)
  {
    mean[s].setZero ();
    for (const auto i : fit.parts[s])
    {
      const Eigen::Vector3d n = points.normals[i].cast<double> ();
      mean[s] += n.dot (fit.side_normal[s]) < 0.0 ? -n : n;
    }
    if (!(mean[s].norm () > 0.0))
      return std::numeric_limits<double>::quiet_NaN ();
    mean[s].normalize ();
  }
  return std::acos (std::min (1.0, std::abs (mean[0].dot (mean[1]))));
}
} // namespace

bool
isEdgeTheNormalsConfirm (const PointSet& points, const HingeFit& fit, const DetectorParameters& params)
{
  const double slope = 0.5 * M_PI - params.min_distance_angle; // what T1 accepts within one plane
  const double ratio = params.bent_sigma_ratio;
  if (!params.bent_normal_edges || !(fit.angle > slope) ||
      !(fit.split_sigma <= std::sqrt (0.5 * (1.0 + ratio * ratio)) * fit.single_sigma))
    return false;
  if (!(sideNormalTurn (points, fit) > slope)) // NaN: no direction to confirm anything
    return false;
  // One step, not a steady turn: across a curved surface the normals turn with the position (the
  // room's pillar at σ = 3 cm, whose plane of 159 samples two chords explain as well: ratio 0.55).
  std::vector<std::uint32_t> both (fit.parts[0]);
  both.insert (both.end (), fit.parts[1].begin (), fit.parts[1].end ());
  return normalTurnRatio (points, both, measureCurvature (points, both)) >= 1.0;
}

bool
bentAtAnEdge (const PointSet& points, const std::vector<std::uint32_t>& samples, const DetectorParameters& params)
{
  HingeFit fit;
  if (!fitHinge (points, samples, fit) || !isBend (fit, params))
    return false;
  if (!params.hinge_normal_turn)
    return true;
  // The normals must turn at the edge as the positions do (DetectorParameters::hinge_normal_turn).
  const double turn = sideNormalTurn (points, fit);
  return std::isnan (turn) || turn > 0.5 * M_PI - params.min_distance_angle; // NaN: positions decide
}

namespace
{
/** Whether \a side, cut from \a whole, is a plane by T1-T3, T2 bounded by the whole's MND where
  * that is wider than T2's (DetectorParameters::bent_side_parent_mnd). */
bool
isPlaneSide (const PointSet& points, const DetectorParameters& params, const std::vector<std::uint32_t>& whole,
             const std::vector<std::uint32_t>& side)
{
  const PlanarityVerdict verdict = robustPlanarityTest (points, side, params).verdict;
  if (verdict != PlanarityVerdict::FailedNormal || !params.bent_side_parent_mnd)
    return verdict == PlanarityVerdict::Planar;
  PlaneEstimate parent;
  if (!estimatePlane (points, whole, params, parent) || !(parent.mnd () > params.max_normal_deviation))
    return false;
  DetectorParameters bounded = params;
  bounded.max_normal_deviation = parent.mnd ();
  return robustPlanarityTest (points, side, bounded).verdict == PlanarityVerdict::Planar;
}

/** The leaves of \a members split at edges (see splitBentPlanes), appended to \a leaves; false, and
  * nothing appended, where \a members is no bent plane or cannot be split into planes. */
bool
splitAtEdges (const PointSet& points, const DetectorParameters& params, const std::vector<std::uint32_t>& members,
              int level, std::vector<std::vector<std::uint32_t>>& leaves)
{
  HingeFit fit;
  if (level >= kMaxLevels || members.size () < 2 * params.min_patch_size || !fitHinge (points, members, fit) ||
      !(isBend (fit, params) || isEdgeTheNormalsConfirm (points, fit, params)) ||
      fit.parts[0].size () < params.min_patch_size || fit.parts[1].size () < params.min_patch_size)
    return false;
  std::vector<std::vector<std::uint32_t>> found;
  for (auto& side : fit.parts)
  {
    // A side that is a plane by T1-T3 is a leaf unless it is bent itself; one that is not must
    // split into planes (one cut through the middle face of three leaves 1.5 faces a side).
    if (splitAtEdges (points, params, side, level + 1, found))
      continue;
    if (!isPlaneSide (points, params, members, side))
      return false;
    found.push_back (std::move (side));
  }
  for (auto& f : found)
    leaves.push_back (std::move (f));
  return true;
}

/** Whether two planes explain \a samples far better than one (fitHinge lowers the robust σ to at
  * most bent_sigma_ratio, or the normals confirm the edge: isEdgeTheNormalsConfirm): an edge or a
  * step between two parts, whatever their angle. */
bool
twoPlanesExplain (const PointSet& points, const std::vector<std::uint32_t>& samples, const DetectorParameters& params)
{
  HingeFit fit;
  return fitHinge (points, samples, fit) && (fit.split_sigma <= params.bent_sigma_ratio * fit.single_sigma ||
                                             isEdgeTheNormalsConfirm (points, fit, params));
}

/** Joins leaves whose union is no bent plane (a face the cuts divided) until none is left. */
void
joinUnbentLeaves (const PointSet& points, const DetectorParameters& params, std::vector<std::vector<std::uint32_t>>& leaves)
{
  for (bool joined = true; joined && leaves.size () > 1;)
  {
    joined = false;
    for (std::size_t a = 0; a < leaves.size () && !joined; ++a)
      for (std::size_t b = a + 1; b < leaves.size () && !joined; ++b)
      {
        std::vector<std::uint32_t> both (leaves[a]);
        both.insert (both.end (), leaves[b].begin (), leaves[b].end ());
        if (twoPlanesExplain (points, both, params))
          continue; // an edge or a step between them
        leaves[a].swap (both);
        leaves.erase (leaves.begin () + static_cast<std::ptrdiff_t> (b));
        joined = true;
      }
  }
}
} // namespace

std::size_t
splitBentPlanes (const PointSet& points, const DetectorParameters& params, std::vector<PlanarPatch>& patches,
                 std::vector<char>* split)
{
  const std::size_t count = patches.size ();
  // Per plane, the member lists it ends as (none: unchanged).
  std::vector<std::vector<std::vector<std::uint32_t>>> pieces (count);
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolveThreads (params.num_threads))
  for (std::ptrdiff_t p = 0; p < static_cast<std::ptrdiff_t> (count); ++p)
    if (splitAtEdges (points, params, patches[p].members, 0, pieces[p]))
      joinUnbentLeaves (points, params, pieces[p]);

  std::size_t added = 0;
  if (split)
    split->assign (count, 0);
  for (std::size_t p = 0; p < count; ++p)
  {
    auto& parts = pieces[p];
    if (parts.size () < 2)
      continue;
    if (split)
    {
      (*split)[p] = 1;
      split->resize (split->size () + parts.size () - 1, 1);
    }
    for (auto& part : parts)
      std::sort (part.begin (), part.end ());
    // The largest part keeps the plane's place; ties to the lower first sample.
    std::sort (parts.begin (), parts.end (), [] (const auto& a, const auto& b) {
      return a.size () != b.size () ? a.size () > b.size () : a.front () < b.front ();
    });
    for (std::size_t s = 0; s < parts.size (); ++s)
    {
      PlanarPatch part;
      part.first_index = parts[s].front ();
      part.members = std::move (parts[s]);
      PlaneEstimate estimate;
      estimatePlane (points, part.members, params, estimate); // each part passed T1-T3: it succeeds
      part.setEstimate (estimate);
      if (s == 0)
        patches[p] = std::move (part);
      else
      {
        patches.push_back (std::move (part));
        ++added;
      }
    }
  }
  return added;
}

std::size_t
splitBentNoisyPlanes (const PointSet& points, const DetectorParameters& params, std::vector<PlanarPatch>& patches,
                      std::vector<char>* flat_out)
{
  std::size_t added = 0;
  const std::size_t count = patches.size ();
  std::vector<char> local;
  std::vector<char>& judged = flat_out ? *flat_out : local;
  judged.assign (count, 1);
  for (std::size_t p = 0; p < count; ++p)
  {
    if (!patches[p].retested || isFlatPatch (points, params, patches[p], true))
      continue;
    judged[p] = 0;
    HingeFit fit;
    if (!fitHinge (points, patches[p].members, fit) || !isBend (fit, params) ||
        fit.parts[0].size () < params.min_patch_size || fit.parts[1].size () < params.min_patch_size)
      continue;
    PlanarPatch sides[2];
    bool flat = true;
    for (int k = 0; k < 2 && flat; ++k)
    {
      std::sort (fit.parts[k].begin (), fit.parts[k].end ());
      sides[k].members = std::move (fit.parts[k]);
      sides[k].first_index = sides[k].members.front ();
      sides[k].retested = true; // judged as the plane it comes from
      PlaneEstimate estimate;
      flat = estimatePlane (points, sides[k].members, params, estimate);
      if (flat)
      {
        sides[k].setEstimate (estimate);
        flat = isFlatPatch (points, params, sides[k], true);
      }
    }
    if (!flat)
      continue; // a facet of a curved surface, or worse: the judgement drops it
    patches[p] = std::move (sides[0]);
    patches.push_back (std::move (sides[1]));
    judged[p] = 1;
    judged.push_back (1);
    ++added;
  }
  return added;
}

std::size_t
joinSplitFaces (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                std::vector<PlanarPatch>& patches, const std::vector<char>& split)
{
  // A plane past the end of split is no part (a caller's shorter list).
  const auto isPart = [&] (std::size_t p) { return p < split.size () && split[p]; };
  if (patches.size () < 2 || std::find (split.begin (), split.end (), 1) == split.end ())
    return 0;
  const std::vector<std::uint32_t> labels = labelSamples (points.size (), patches);
  // Touching pairs with a part of a split plane in them, each once (M1).
  std::vector<std::uint64_t> keys;
  for (std::uint32_t p = 0; p < patches.size (); ++p)
  {
    if (!isPart (p))
      continue;
    for (const auto i : patches[p].members)
      graph.forEachNeighbor (i, [&] (std::uint32_t m) {
        const std::uint32_t q = labels[m];
        if (q != kNoPatch && q != p)
          keys.push_back ((static_cast<std::uint64_t> (std::min (p, q)) << 32) | std::max (p, q));
      });
  }
  std::sort (keys.begin (), keys.end ());
  keys.erase (std::unique (keys.begin (), keys.end ()), keys.end ());
  // Largest pairs first (by the smaller plane, then the larger), so that a face's big parts meet
  // before a sliver decides; ties by position.
  const auto size = [&] (std::uint64_t k, bool first) {
    return patches[first ? k >> 32 : k & 0xffffffffu].members.size ();
  };
  std::stable_sort (keys.begin (), keys.end (), [&] (std::uint64_t x, std::uint64_t y) {
    const std::size_t xs = std::min (size (x, true), size (x, false)), ys = std::min (size (y, true), size (y, false));
    if (xs != ys)
      return xs > ys;
    return std::max (size (x, true), size (x, false)) > std::max (size (y, true), size (y, false));
  });
  // A joined plane's members gather in the larger one's place; owner leads an absorbed plane there.
  std::vector<std::uint32_t> owner (patches.size ());
  std::iota (owner.begin (), owner.end (), 0u);
  const auto root = [&] (std::uint32_t p) {
    while (owner[p] != p)
      p = owner[p];
    return p;
  };
  std::size_t absorbed = 0;
  for (const auto key : keys)
  {
    std::uint32_t a = root (static_cast<std::uint32_t> (key >> 32)), b = root (static_cast<std::uint32_t> (key & 0xffffffffu));
    if (a == b)
      continue;
    const double angle = std::acos (std::min (1.0, std::abs (patches[a].normal.dot (patches[b].normal))));
    if (angle > 0.5 * M_PI - params.min_distance_angle)
      continue;
    std::vector<std::uint32_t> both (patches[a].members);
    both.insert (both.end (), patches[b].members.begin (), patches[b].members.end ());
    if (twoPlanesExplain (points, both, params))
      continue; // an edge or a step between them
    const std::size_t na = patches[a].members.size (), nb = patches[b].members.size ();
    if (nb > na || (nb == na && b < a))
      std::swap (a, b);
    std::sort (both.begin (), both.end ());
    patches[a].members.swap (both);
    patches[a].first_index = patches[a].members.front ();
    patches[b].members.clear ();
    owner[b] = a;
    PlaneEstimate estimate;
    if (estimatePlane (points, patches[a].members, params, estimate))
      patches[a].setEstimate (estimate); // the next pair is judged against the joined plane
    ++absorbed;
  }
  if (absorbed > 0)
    patches.erase (std::remove_if (patches.begin (), patches.end (), [] (const PlanarPatch& p) { return p.members.empty (); }),
                   patches.end ());
  return absorbed;
}

} // namespace rspd
} // namespace pcl
