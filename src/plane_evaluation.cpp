/*
 * pcl_rspd: the paper's evaluation protocol (Araujo & Oliveira 2020, Sec. 4.2).
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Exact rules implemented here
 * ----------------------------
 *  1. Input. cloud, truth and detected must have the same size and voxel_ratio must be > 0 (and not
 *     NaN), else std::invalid_argument. Points with a non-finite coordinate are ignored together with
 *     both of their labels. Label 0 means "on no plane"; every other value names one plane.
 *  2. Regularization. The voxel edge is voxel_ratio times the largest extent (max over x, y, z of
 *     max - min) of the finite points; the grid starts at their minimum corner, so a point falls in
 *     voxel floor ((p - min) / edge) per axis (clamped to the grid, so a point at the maximum stays in
 *     the last cell). With a grid phase f (per axis, in [0, 1)) the grid starts f edges below the
 *     minimum corner instead: voxel floor ((p - min) / edge + f), the edge unchanged. If all finite points coincide, there is one voxel. Voxels are identified by a
 *     64-bit linear key (or, for absurdly fine grids whose cell count overflows 64 bits, by the
 *     integer triple), then renumbered densely.
 *  3. Membership. A voxel belongs to every plane (truth or detected) that has at least one of its
 *     samples in it; a voxel may belong to several planes.
 *  4. Normals. A plane's orientation is the least-squares fit to its points about their median point:
 *     the centre is the component-wise median (mean of the two middle values for even counts), the
 *     normal is the eigenvector of the smallest eigenvalue of the scatter matrix about that centre,
 *     all in double. Two normals agree when the angle between the lines is <= 30 degrees, i.e.
 *     |n1 . n2| >= cos 30. Degenerate fits, where the least-squares plane is not unique, are judged
 *     by the best plane that is still a least-squares fit: points that all coincide agree with any
 *     normal; collinear points (middle eigenvalue <= 1e-10 times the largest) agree with a plane of
 *     normal n when the line's direction d satisfies |n . d| <= sin 30 (some plane through the line
 *     is within 30 degrees of n), and with another line always.
 *  5. Matching. Each detected plane D is compared with the truth plane T of largest voxel IoU
 *     |D & T| / |D | T| (compared exactly in integers; ties go first to a candidate that passes both
 *     tests below, then to the smaller truth label). D matches T iff |D & T| > 0,
 *     2 |D & T| >= |D| (at least 50 % of D's voxels lie in T) and their normals agree (rule 4).
 *     Otherwise D is unmatched: the second-best truth plane is not tried.
 *  6. Counts, per (plane, voxel) pair, summed over planes (a voxel may count more than once):
 *     TP += |D & T| and FP += |D \ T| for each matched D; FP += |D| for each unmatched D;
 *     FN += |T \ (union of the detections matched to T)| for each truth plane T.
 *     precision = TP / (TP + FP), recall = TP / (TP + FN), F1 = 2 P R / (P + R); each is 0 when its
 *     denominator is 0.
 *  7. Plane counts. planes = distinct non-zero truth labels, detected = distinct non-zero detection
 *     labels (finite points only); found = truth planes with at least one matched detection;
 *     fragments = sum over truth planes of (matched detections - 1) where positive;
 *     false_planes = unmatched detections.
 */

#include <pcl_rspd/plane_evaluation.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

namespace pcl
{
namespace rspd
{
namespace
{
constexpr std::uint32_t kNoVoxel = std::numeric_limits<std::uint32_t>::max ();

/** \brief How well a point set determines a plane, and the axis that describes it. */
struct Orientation
{
  enum Kind { kPlane, kLine, kPoint };
  Kind kind = kPoint;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ (); ///< normal for kPlane, direction for kLine
};

/** \brief One plane of either labelling: its label, points, voxels and fitted orientation. */
struct Plane
{
  std::uint32_t label = 0;
  std::vector<std::uint32_t> points;  ///< indices into the cloud
  std::vector<std::uint32_t> voxels;  ///< dense voxel ids, sorted, unique
  Orientation orientation;
};

inline bool
isFinitePoint (const pcl::PointXYZ& p)
{
  return std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z);
}

/** \brief Renumber per-point keys densely: equal keys get equal ids, in key order.
  * Sorting a copy and binary searching keeps memory at two key arrays, which matters at 10M points.
  */
template <typename Key> std::uint32_t
assignDenseIds (const std::vector<Key>& keys, std::vector<std::uint32_t>& ids)
{
  std::vector<Key> sorted (keys);
  std::sort (sorted.begin (), sorted.end ());
  sorted.erase (std::unique (sorted.begin (), sorted.end ()), sorted.end ());
  ids.resize (keys.size ());
  for (std::size_t i = 0; i < keys.size (); ++i)
    ids[i] = static_cast<std::uint32_t> (
        std::lower_bound (sorted.begin (), sorted.end (), keys[i]) - sorted.begin ());
  return static_cast<std::uint32_t> (sorted.size ());
}

/** \brief Voxel id of every point (kNoVoxel for non-finite ones); returns the number of voxels. */
std::uint32_t
voxelize (const pcl::PointCloud<pcl::PointXYZ>& cloud, double voxel_ratio,
          const std::array<double, 3>& phase, std::vector<std::uint32_t>& voxel_of)
{
  voxel_of.assign (cloud.size (), kNoVoxel);
  Eigen::Array3d lo = Eigen::Array3d::Constant (std::numeric_limits<double>::infinity ());
  Eigen::Array3d hi = -lo;
  std::size_t finite_count = 0;
  for (const auto& p : cloud.points)
  {
    if (!isFinitePoint (p))
      continue;
    const Eigen::Array3d q (p.x, p.y, p.z);
    lo = lo.min (q);
    hi = hi.max (q);
    ++finite_count;
  }
  if (finite_count == 0)
    return 0;

  const Eigen::Array3d range = hi - lo;
  double edge = voxel_ratio * range.maxCoeff ();
  // All points coincide: any positive edge puts them in one voxel.
  if (!(edge > 0.0))
    edge = 1.0;

  // Cells per axis; a point exactly at the maximum would otherwise land one past the grid.
  std::array<double, 3> cells;
  for (int a = 0; a < 3; ++a)
    cells[a] = std::floor (range[a] / edge + phase[a]) + 1.0;
  auto cell = [&] (double v, int a) -> std::int64_t {
    const double c = std::floor ((v - lo[a]) / edge + phase[a]);
    return static_cast<std::int64_t> (std::min (std::max (c, 0.0), cells[a] - 1.0));
  };

  std::vector<std::uint32_t> ids;
  std::uint32_t count = 0;
  const double total_cells = cells[0] * cells[1] * cells[2];
  if (total_cells < 9.0e18)
  {
    // Linear index into the (bounded) grid: exact, collision-free 64-bit keys.
    const auto nx = static_cast<std::uint64_t> (cells[0]);
    const auto ny = static_cast<std::uint64_t> (cells[1]);
    std::vector<std::uint64_t> keys;
    keys.reserve (finite_count);
    for (const auto& p : cloud.points)
      if (isFinitePoint (p))
        keys.push_back (static_cast<std::uint64_t> (cell (p.x, 0)) +
                        nx * (static_cast<std::uint64_t> (cell (p.y, 1)) +
                              ny * static_cast<std::uint64_t> (cell (p.z, 2))));
    count = assignDenseIds (keys, ids);
  }
  else
  {
    // A grid too fine for one 64-bit key (voxel_ratio below ~1e-6): key by the integer triple.
    std::vector<std::array<std::int64_t, 3>> keys;
    keys.reserve (finite_count);
    for (const auto& p : cloud.points)
      if (isFinitePoint (p))
        keys.push_back ({cell (p.x, 0), cell (p.y, 1), cell (p.z, 2)});
    count = assignDenseIds (keys, ids);
  }

  std::size_t k = 0;
  for (std::size_t i = 0; i < cloud.size (); ++i)
    if (isFinitePoint (cloud[i]))
      voxel_of[i] = ids[k++];
  return count;
}

/** \brief Median of \a values (mean of the two middle ones for even counts); reorders them. */
double
median (std::vector<double>& values)
{
  const std::size_t n = values.size ();
  const auto mid = values.begin () + n / 2;
  std::nth_element (values.begin (), mid, values.end ());
  const double upper = *mid;
  if (n % 2 == 1)
    return upper;
  const double lower = *std::max_element (values.begin (), mid);
  return 0.5 * (lower + upper);
}

/** \brief Least-squares orientation of the points \a indices about their component-wise median. */
Orientation
fitOrientation (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                const std::vector<std::uint32_t>& indices)
{
  Orientation result;
  if (indices.empty ())
    return result;

  Eigen::Vector3d centre;
  std::vector<double> values (indices.size ());
  for (int a = 0; a < 3; ++a)
  {
    for (std::size_t i = 0; i < indices.size (); ++i)
      values[i] = static_cast<double> (cloud[indices[i]].data[a]);
    centre[a] = median (values);
  }

  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero ();
  bool all_at_centre = true;
  for (const auto i : indices)
  {
    const Eigen::Vector3d d = cloud[i].getVector3fMap ().cast<double> () - centre;
    all_at_centre = all_at_centre && d.isZero (0.0);
    scatter.noalias () += d * d.transpose ();
  }
  // Coincident points (including a single point) constrain no orientation at all.
  if (all_at_centre)
    return result;

  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (scatter);
  const Eigen::Vector3d lambda = solver.eigenvalues (); // ascending
  if (lambda[1] <= 1e-10 * lambda[2])
  {
    // Collinear: every plane through the line is a least-squares fit; keep the line's direction.
    result.kind = Orientation::kLine;
    result.axis = solver.eigenvectors ().col (2).normalized ();
  }
  else
  {
    result.kind = Orientation::kPlane;
    result.axis = solver.eigenvectors ().col (0).normalized ();
  }
  return result;
}

/** \brief True when the two orientations are within 30 degrees (as lines), see rule 4. */
bool
orientationsAgree (const Orientation& a, const Orientation& b)
{
  // A hair of slack so that constructions at exactly 30 degrees are not decided by rounding.
  const double cos_max = std::sqrt (3.0) / 2.0 - 1e-12; // cos 30
  const double sin_max = 0.5 + 1e-12;
  if (a.kind == Orientation::kPoint || b.kind == Orientation::kPoint)
    return true;
  if (a.kind == Orientation::kLine && b.kind == Orientation::kLine)
    return true;
  const double dot = std::abs (a.axis.dot (b.axis));
  if (a.kind == Orientation::kPlane && b.kind == Orientation::kPlane)
    return dot >= cos_max;
  return dot <= sin_max; // one plane normal against one line direction
}

/** \brief Group the finite, labelled points into planes (sorted by label), with voxels and fits. */
std::vector<Plane>
buildPlanes (const pcl::PointCloud<pcl::PointXYZ>& cloud, const std::vector<std::uint32_t>& labels,
             const std::vector<std::uint32_t>& voxel_of)
{
  std::unordered_map<std::uint32_t, std::uint32_t> index_of;
  std::vector<Plane> planes;
  for (std::size_t i = 0; i < labels.size (); ++i)
  {
    if (labels[i] == 0 || voxel_of[i] == kNoVoxel)
      continue;
    const auto inserted = index_of.emplace (labels[i], static_cast<std::uint32_t> (planes.size ()));
    if (inserted.second)
    {
      planes.emplace_back ();
      planes.back ().label = labels[i];
    }
    planes[inserted.first->second].points.push_back (static_cast<std::uint32_t> (i));
  }
  std::sort (planes.begin (), planes.end (),
             [] (const Plane& a, const Plane& b) { return a.label < b.label; });

  for (auto& plane : planes)
  {
    plane.voxels.reserve (plane.points.size ());
    for (const auto i : plane.points)
      plane.voxels.push_back (voxel_of[i]);
    std::sort (plane.voxels.begin (), plane.voxels.end ());
    plane.voxels.erase (std::unique (plane.voxels.begin (), plane.voxels.end ()),
                        plane.voxels.end ());
    plane.orientation = fitOrientation (cloud, plane.points);
    // The points are no longer needed; at 10M points they are most of the memory.
    std::vector<std::uint32_t> ().swap (plane.points);
  }
  return planes;
}

inline double
safeRatio (std::size_t num, std::size_t den)
{
  return den == 0 ? 0.0 : static_cast<double> (num) / static_cast<double> (den);
}
} // namespace

EvaluationResult
evaluatePlaneDetection (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                        const std::vector<std::uint32_t>& truth,
                        const std::vector<std::uint32_t>& detected,
                        double voxel_ratio, const std::array<double, 3>& grid_phase)
{
  if (truth.size () != cloud.size () || detected.size () != cloud.size ())
    throw std::invalid_argument ("evaluatePlaneDetection: label count differs from point count");
  if (!(voxel_ratio > 0.0))
    throw std::invalid_argument ("evaluatePlaneDetection: voxel_ratio must be positive");
  for (const double f : grid_phase)
    if (!(f >= 0.0 && f < 1.0))
      throw std::invalid_argument ("evaluatePlaneDetection: grid phase must lie in [0, 1)");
  // Voxel and point ids are 32-bit to halve the memory at 10M points.
  if (cloud.size () >= static_cast<std::size_t> (kNoVoxel))
    throw std::invalid_argument ("evaluatePlaneDetection: too many points");

  std::vector<std::uint32_t> voxel_of;
  const std::uint32_t voxel_count = voxelize (cloud, voxel_ratio, grid_phase, voxel_of);
  const std::vector<Plane> truth_planes = buildPlanes (cloud, truth, voxel_of);
  const std::vector<Plane> detected_planes = buildPlanes (cloud, detected, voxel_of);

  EvaluationResult result;
  result.planes = static_cast<int> (truth_planes.size ());
  result.detected = static_cast<int> (detected_planes.size ());

  // Voxel -> truth planes containing it (CSR), so each detection's overlaps cost O(|D| + hits).
  // (plane, voxel) pairs are at most one per labelled point, so 32-bit offsets suffice.
  std::vector<std::uint32_t> offset (static_cast<std::size_t> (voxel_count) + 1, 0);
  for (const auto& t : truth_planes)
    for (const auto v : t.voxels)
      ++offset[v + 1];
  for (std::size_t v = 0; v < voxel_count; ++v)
    offset[v + 1] += offset[v];
  std::vector<std::uint32_t> planes_of (offset.back ());
  {
    std::vector<std::uint32_t> fill (offset.begin (), offset.end () - 1);
    for (std::uint32_t t = 0; t < truth_planes.size (); ++t)
      for (const auto v : truth_planes[t].voxels)
        planes_of[fill[v]++] = t;
  }

  constexpr std::uint32_t kUnmatched = std::numeric_limits<std::uint32_t>::max ();
  std::vector<std::uint32_t> match (detected_planes.size (), kUnmatched);
  std::vector<std::size_t> overlap (truth_planes.size (), 0);
  std::vector<std::uint32_t> touched;
  for (std::size_t d = 0; d < detected_planes.size (); ++d)
  {
    const Plane& det = detected_planes[d];
    touched.clear ();
    for (const auto v : det.voxels)
      for (std::uint32_t k = offset[v]; k < offset[v + 1]; ++k)
      {
        if (overlap[planes_of[k]]++ == 0)
          touched.push_back (planes_of[k]);
      }
    // Truth planes are sorted by label, so visiting them in index order breaks IoU ties by label.
    std::sort (touched.begin (), touched.end ());

    std::uint32_t best = kUnmatched;
    std::size_t best_inter = 0, best_union = 1;
    bool best_passes = false;
    for (const auto t : touched)
    {
      const std::size_t inter = overlap[t];
      const std::size_t uni = det.voxels.size () + truth_planes[t].voxels.size () - inter;
      const bool passes = 2 * inter >= det.voxels.size () &&
                          orientationsAgree (det.orientation, truth_planes[t].orientation);
      // Exact IoU comparison: counts are below 2^32, so the products fit in 64 bits.
      const auto lhs = static_cast<std::uint64_t> (inter) * best_union;
      const auto rhs = static_cast<std::uint64_t> (best_inter) * uni;
      if (best == kUnmatched || lhs > rhs || (lhs == rhs && passes && !best_passes))
      {
        best = t;
        best_inter = inter;
        best_union = uni;
        best_passes = passes;
      }
    }
    for (const auto t : touched)
      overlap[t] = 0;

    if (best != kUnmatched && best_passes)
    {
      match[d] = best;
      result.tp += best_inter;
      result.fp += det.voxels.size () - best_inter;
    }
    else
    {
      result.fp += det.voxels.size ();
      ++result.false_planes;
    }
  }

  // Per truth plane: which detections matched it, and which of its voxels they cover.
  std::vector<std::vector<std::uint32_t>> matched_to (truth_planes.size ());
  for (std::uint32_t d = 0; d < match.size (); ++d)
    if (match[d] != kUnmatched)
      matched_to[match[d]].push_back (d);
  std::vector<std::uint32_t> stamp (voxel_count, kUnmatched);
  for (std::uint32_t t = 0; t < truth_planes.size (); ++t)
  {
    const auto& dets = matched_to[t];
    if (!dets.empty ())
    {
      ++result.found;
      result.fragments += static_cast<int> (dets.size ()) - 1;
    }
    for (const auto d : dets)
      for (const auto v : detected_planes[d].voxels)
        stamp[v] = t;
    for (const auto v : truth_planes[t].voxels)
      if (stamp[v] != t)
        ++result.fn;
  }

  result.precision = safeRatio (result.tp, result.tp + result.fp);
  result.recall = safeRatio (result.tp, result.tp + result.fn);
  const double sum = result.precision + result.recall;
  result.f1 = sum > 0.0 ? 2.0 * result.precision * result.recall / sum : 0.0;
  return result;
}

std::array<double, 3>
gridPhase (std::size_t index)
{
  // R3 sequence: g is the real root of g^3 = g + 1; the multiples of (1/g, 1/g^2, 1/g^3) modulo 1
  // fill the unit cube more evenly than random draws, for any number of phases.
  const double g = 1.32471795724474602596;
  std::array<double, 3> phase;
  double step = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    step /= g;
    const double v = static_cast<double> (index) * step;
    phase[a] = v - std::floor (v);
    if (!(phase[a] < 1.0)) // rounding at huge indices
      phase[a] = 0.0;
  }
  return phase;
}

PhaseScores
evaluateOverGridPhases (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                        const std::vector<std::uint32_t>& truth,
                        const std::vector<std::uint32_t>& detected,
                        double voxel_ratio, std::size_t phases)
{
  if (phases == 0)
    throw std::invalid_argument ("evaluateOverGridPhases: at least one phase is needed");
  PhaseScores scores;
  scores.phases = phases;
  std::vector<double> f1;
  f1.reserve (phases);
  for (std::size_t i = 0; i < phases; ++i)
  {
    const EvaluationResult r = evaluatePlaneDetection (cloud, truth, detected, voxel_ratio, gridPhase (i));
    f1.push_back (r.f1);
    scores.found_min = i == 0 ? r.found : std::min (scores.found_min, r.found);
  }
  scores.f1_min = *std::min_element (f1.begin (), f1.end ());
  scores.f1_max = *std::max_element (f1.begin (), f1.end ());
  scores.f1_median = median (f1);
  return scores;
}

} // namespace rspd
} // namespace pcl
