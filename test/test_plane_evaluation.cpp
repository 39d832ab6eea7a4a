/*
 * Tests of the Sec. 4.2 evaluation protocol on tiny clouds whose voxel counts are known by hand.
 * SPDX-License-Identifier: BSD-3-Clause
 */

#include <pcl_rspd/plane_evaluation.h>

#include "label_io.h"

#include <pcl/io/pcd_io.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

using pcl::rspd::EvaluationResult;
using pcl::rspd::evaluatePlaneDetection;
using pcl::rspd::evaluateOverGridPhases;
using pcl::rspd::gridPhase;

namespace
{
/** Anchors at (0,0,0) and (8,8,8) make the extent 8, so this ratio gives unit voxels on the
  * integer grid. Every coordinate below is exact in float, so no point sits on a rounding edge. */
constexpr double kUnitVoxels = 0.125;

/** \brief A cloud with truth and detection labels, built voxel by voxel. */
struct Scene
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::uint32_t> truth, det;

  Scene ()
  {
    add (0.f, 0.f, 0.f, 0, 0);
    add (8.f, 8.f, 8.f, 0, 0);
  }

  void
  add (float x, float y, float z, std::uint32_t t, std::uint32_t d)
  {
    cloud.push_back (pcl::PointXYZ (x, y, z));
    truth.push_back (t);
    det.push_back (d);
  }

  /** One point at the centre of each voxel of the inclusive box [x0,x1] x [y0,y1] x [z0,z1]. */
  void
  box (int x0, int x1, int y0, int y1, int z0, int z1, std::uint32_t t, std::uint32_t d)
  {
    for (int x = x0; x <= x1; ++x)
      for (int y = y0; y <= y1; ++y)
        for (int z = z0; z <= z1; ++z)
          add (x + 0.5f, y + 0.5f, z + 0.5f, t, d);
  }

  EvaluationResult
  eval (double ratio = kUnitVoxels) const
  {
    return evaluatePlaneDetection (cloud, truth, det, ratio);
  }
};

void
expectCounts (const EvaluationResult& r, std::size_t tp, std::size_t fp, std::size_t fn)
{
  EXPECT_EQ (r.tp, tp);
  EXPECT_EQ (r.fp, fp);
  EXPECT_EQ (r.fn, fn);
  const double p = tp + fp ? double (tp) / double (tp + fp) : 0.0;
  const double rc = tp + fn ? double (tp) / double (tp + fn) : 0.0;
  EXPECT_DOUBLE_EQ (r.precision, p);
  EXPECT_DOUBLE_EQ (r.recall, rc);
  EXPECT_DOUBLE_EQ (r.f1, p + rc > 0 ? 2 * p * rc / (p + rc) : 0.0);
}

/** Floor: 4 x 4 voxels at z = 0 (16). Wall: 4 x 3 voxels at y = 4, z = 1..3 (12), normal y. */
void
addRoom (Scene& s, std::uint32_t floor_det, std::uint32_t wall_det)
{
  s.box (0, 3, 0, 3, 0, 0, 1, floor_det);
  s.box (0, 3, 4, 4, 1, 3, 2, wall_det);
}
} // namespace

TEST (PlaneEvaluation, PerfectDetectionScoresOne)
{
  Scene s;
  // Detection ids need not match truth ids, and any uint32 but 0 is a plane.
  addRoom (s, 7, std::numeric_limits<std::uint32_t>::max ());
  const auto r = s.eval ();
  expectCounts (r, 28, 0, 0);
  EXPECT_DOUBLE_EQ (r.f1, 1.0);
  EXPECT_EQ (r.found, 2);
  EXPECT_EQ (r.planes, 2);
  EXPECT_EQ (r.detected, 2);
  EXPECT_EQ (r.fragments, 0);
  EXPECT_EQ (r.false_planes, 0);
}

TEST (PlaneEvaluation, SplitPlaneCountsOneFragmentAndFullRecall)
{
  Scene s;
  s.box (0, 1, 0, 3, 0, 0, 1, 10); // floor, left half: IoU 8/16
  s.box (2, 3, 0, 3, 0, 0, 1, 11); // floor, right half: IoU 8/16
  s.box (0, 3, 4, 4, 1, 3, 2, 12); // wall
  const auto r = s.eval ();
  expectCounts (r, 28, 0, 0);
  EXPECT_EQ (r.found, 2);
  EXPECT_EQ (r.detected, 3);
  EXPECT_EQ (r.fragments, 1);
  EXPECT_EQ (r.false_planes, 0);
}

TEST (PlaneEvaluation, MergedPerpendicularPlanesFailTheNormalTest)
{
  Scene s;
  addRoom (s, 5, 5);
  // Best IoU is the floor (16 of 28 voxels, 57 % >= 50 %), but the L-shaped union spreads less
  // along x than across the L, so its least-squares normal is x, 90 degrees from both: no match.
  const auto r = s.eval ();
  expectCounts (r, 0, 28, 28);
  EXPECT_EQ (r.found, 0);
  EXPECT_EQ (r.detected, 1);
  EXPECT_EQ (r.false_planes, 1);
  EXPECT_EQ (r.f1, 0.0);
}

TEST (PlaneEvaluation, MergedCoplanarPlanesFailTheFiftyPercentRule)
{
  Scene s;
  s.box (0, 3, 0, 3, 0, 0, 1, 9); // truth plane 1, 16 voxels
  s.box (4, 7, 0, 3, 0, 0, 2, 9); // truth plane 2, 16 voxels, same plane
  s.box (0, 1, 4, 4, 0, 0, 0, 9); // 2 voxels on no truth plane
  // 34 voxels, of which at most 16 (47 %) in one truth plane.
  const auto r = s.eval ();
  expectCounts (r, 0, 34, 32);
  EXPECT_EQ (r.found, 0);
  EXPECT_EQ (r.false_planes, 1);
}

TEST (PlaneEvaluation, ExactlyHalfInsideMatches)
{
  Scene s;
  s.box (0, 1, 0, 3, 0, 0, 1, 4); // 8 voxels of the truth plane detected
  s.box (2, 3, 0, 3, 0, 0, 1, 0); // 8 voxels of the truth plane missed
  s.box (0, 3, 4, 5, 0, 0, 0, 4); // 8 coplanar clutter voxels detected
  const auto r = s.eval ();
  expectCounts (r, 8, 8, 8);
  EXPECT_EQ (r.found, 1);
  EXPECT_EQ (r.false_planes, 0);
}

TEST (PlaneEvaluation, DetectionShiftedAlongThePlane)
{
  Scene s;
  s.box (0, 0, 0, 3, 0, 0, 1, 0); // truth column the detection misses
  s.box (1, 3, 0, 3, 0, 0, 1, 3); // 12 shared voxels
  s.box (4, 4, 0, 3, 0, 0, 0, 3); // 4 detected clutter voxels beyond the edge
  const auto r = s.eval ();
  expectCounts (r, 12, 4, 4);
  EXPECT_DOUBLE_EQ (r.f1, 0.75);
  EXPECT_EQ (r.found, 1);
}

TEST (PlaneEvaluation, ParallelDetectionInTheNextVoxelLayerIsFalse)
{
  Scene s;
  s.box (0, 3, 0, 3, 0, 0, 1, 0);
  s.box (0, 3, 0, 3, 1, 1, 0, 6); // parallel, one voxel up: no shared voxel
  const auto r = s.eval ();
  expectCounts (r, 0, 16, 16);
  EXPECT_EQ (r.found, 0);
  EXPECT_EQ (r.false_planes, 1);
}

TEST (PlaneEvaluation, ParallelOffsetWithinTheSameVoxelsMatches)
{
  Scene s;
  // Regularization absorbs offsets below the voxel size: truth at z = 0.125, detection at 0.875.
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y)
    {
      s.add (x + 0.5f, y + 0.5f, 0.125f, 1, 0);
      s.add (x + 0.5f, y + 0.5f, 0.875f, 0, 2);
    }
  const auto r = s.eval ();
  expectCounts (r, 16, 0, 0);
  EXPECT_EQ (r.found, 1);
}

TEST (PlaneEvaluation, EmptyDetectionScoresZero)
{
  Scene s;
  addRoom (s, 0, 0);
  const auto r = s.eval ();
  expectCounts (r, 0, 0, 28);
  EXPECT_EQ (r.precision, 0.0);
  EXPECT_EQ (r.recall, 0.0);
  EXPECT_EQ (r.f1, 0.0);
  EXPECT_EQ (r.found, 0);
  EXPECT_EQ (r.planes, 2);
  EXPECT_EQ (r.detected, 0);
  EXPECT_EQ (r.false_planes, 0);
}

/** Truth: a strip 8 x 1 voxels at z = 0.5. Detection: other points in the same 8 voxels, on a
  * plane through the strip's axis tilted by the test's angle; only the normal test can tell. */
class TiltedStrip : public ::testing::TestWithParam<double>
{};

TEST_P (TiltedStrip, MatchesOnlyWithinThirtyDegrees)
{
  const double degrees = GetParam ();
  const double slope = std::tan (degrees * std::acos (-1.0) / 180.0);
  Scene s;
  for (int i = 0; i < 80; ++i)
    for (int j = 0; j < 10; ++j)
    {
      const float x = 0.05f + 0.1f * i, y = 0.05f + 0.1f * j;
      s.add (x, y, 0.5f, 1, 0);
      s.add (x, y, static_cast<float> (0.5 + slope * (y - 0.5)), 0, 1);
    }
  const auto r = s.eval ();
  if (degrees <= 30.0)
  {
    expectCounts (r, 8, 0, 0);
    EXPECT_EQ (r.found, 1);
  }
  else
  {
    expectCounts (r, 0, 8, 8);
    EXPECT_EQ (r.false_planes, 1);
  }
}

INSTANTIATE_TEST_SUITE_P (PlaneEvaluation, TiltedStrip, ::testing::Values (0.0, 20.0, 29.0, 31.0, 40.0));

TEST (PlaneEvaluation, DegenerateDetections)
{
  // A single point fixes no orientation: only the voxel rules apply.
  {
    Scene s;
    s.box (0, 3, 0, 3, 0, 0, 1, 0);
    s.add (0.25f, 0.25f, 0.25f, 0, 2);
    const auto r = s.eval ();
    expectCounts (r, 1, 0, 15);
    EXPECT_EQ (r.found, 1);
  }
  // A line lying in the truth plane is compatible with it...
  {
    Scene s;
    s.box (0, 3, 0, 3, 0, 0, 1, 0);
    for (int k = 0; k < 8; ++k)
      s.add (0.25f + 0.5f * k, 0.25f, 0.25f, 0, 2);
    const auto r = s.eval ();
    expectCounts (r, 4, 0, 12);
    EXPECT_EQ (r.found, 1);
  }
  // ...a line along the truth plane's normal is not, even inside one of its voxels.
  {
    Scene s;
    s.box (0, 3, 0, 3, 0, 0, 1, 0);
    for (int k = 0; k < 8; ++k)
      s.add (0.25f, 0.25f, 0.0625f + 0.125f * k, 0, 2);
    const auto r = s.eval ();
    expectCounts (r, 0, 1, 16);
    EXPECT_EQ (r.false_planes, 1);
  }
}

TEST (PlaneEvaluation, GridPhaseShiftsTheVoxelBoundaries)
{
  // Truth at z = 0.25, detection at z = 0.75: one voxel layer on the paper's grid. A phase of 0.5
  // along z puts the boundary between them (0.25 + 0.5 < 1 <= 0.75 + 0.5); along x it changes nothing.
  Scene s;
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y)
    {
      s.add (x + 0.5f, y + 0.5f, 0.25f, 1, 0);
      s.add (x + 0.5f, y + 0.5f, 0.75f, 0, 2);
    }
  expectCounts (s.eval (), 16, 0, 0);
  const auto z = evaluatePlaneDetection (s.cloud, s.truth, s.det, kUnitVoxels, {0.0, 0.0, 0.5});
  expectCounts (z, 0, 16, 16);
  EXPECT_EQ (z.false_planes, 1);
  expectCounts (evaluatePlaneDetection (s.cloud, s.truth, s.det, kUnitVoxels, {0.5, 0.0, 0.0}), 16, 0, 0);
  // A point at the maximum corner stays on the grid whatever the phase.
  const auto top = evaluatePlaneDetection (s.cloud, s.truth, s.det, kUnitVoxels, {0.999, 0.999, 0.999});
  EXPECT_EQ (top.planes, 1);
}

TEST (PlaneEvaluation, GridPhasesAreFixedAndSpread)
{
  const auto zero = gridPhase (0);
  EXPECT_EQ (zero, (std::array<double, 3>{0.0, 0.0, 0.0}));
  // The R3 sequence: multiples of 1/g, 1/g^2, 1/g^3 modulo 1, g^3 = g + 1.
  const double g = 1.32471795724474602596;
  const auto one = gridPhase (1);
  EXPECT_NEAR (one[0], 1.0 / g, 1e-12);
  EXPECT_NEAR (one[1], 1.0 / (g * g), 1e-12);
  EXPECT_NEAR (one[2], 1.0 / (g * g * g), 1e-12);
  // 64 phases: all in [0, 1), and every half of every axis gets between a third and two thirds.
  std::array<int, 3> low{0, 0, 0};
  for (std::size_t i = 0; i < 64; ++i)
  {
    const auto f = gridPhase (i);
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_GE (f[a], 0.0);
      EXPECT_LT (f[a], 1.0);
      low[a] += f[a] < 0.5;
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_GT (low[a], 64 / 3) << a;
    EXPECT_LT (low[a], 2 * 64 / 3) << a;
  }
}

TEST (PlaneEvaluation, PhaseScoresSummariseEveryGrid)
{
  // Truth at z = 0.25, detection at z = 0.6: one layer unless the phase along z is in (0.4, 0.75].
  Scene s;
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y)
    {
      s.add (x + 0.5f, y + 0.5f, 0.25f, 1, 0);
      s.add (x + 0.5f, y + 0.5f, 0.6f, 0, 2);
    }
  const auto one = evaluateOverGridPhases (s.cloud, s.truth, s.det, kUnitVoxels, 1);
  EXPECT_EQ (one.phases, 1u);
  EXPECT_DOUBLE_EQ (one.f1_median, s.eval ().f1);
  EXPECT_DOUBLE_EQ (one.f1_min, one.f1_max);

  const std::size_t n = 20;
  std::vector<double> f1;
  int found_min = 1;
  for (std::size_t i = 0; i < n; ++i)
  {
    const auto r = evaluatePlaneDetection (s.cloud, s.truth, s.det, kUnitVoxels, gridPhase (i));
    f1.push_back (r.f1);
    found_min = std::min (found_min, r.found);
  }
  std::sort (f1.begin (), f1.end ());
  ASSERT_EQ (f1.front (), 0.0); // some phase separates the layers
  ASSERT_EQ (f1.back (), 1.0);
  const auto all = evaluateOverGridPhases (s.cloud, s.truth, s.det, kUnitVoxels, n);
  EXPECT_EQ (all.phases, n);
  EXPECT_DOUBLE_EQ (all.f1_min, 0.0);
  EXPECT_DOUBLE_EQ (all.f1_max, 1.0);
  EXPECT_DOUBLE_EQ (all.f1_median, 0.5 * (f1[n / 2 - 1] + f1[n / 2]));
  EXPECT_EQ (all.found_min, found_min);
}

TEST (PlaneEvaluation, CountsVoxelsNotPoints)
{
  Scene s;
  // Left half sampled 100 times denser than the right; only the sparse right half is detected.
  for (int x = 0; x < 2; ++x)
    for (int y = 0; y < 4; ++y)
      for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j)
          s.add (x + 0.05f + 0.1f * i, y + 0.05f + 0.1f * j, 0.5f, 1, 0);
  s.box (2, 3, 0, 3, 0, 0, 1, 8);
  const auto r = s.eval ();
  expectCounts (r, 8, 0, 8);
  EXPECT_DOUBLE_EQ (r.recall, 0.5);
}

TEST (PlaneEvaluation, SharedVoxelCountsOncePerPlane)
{
  Scene s;
  // Floor (8 voxels at z = 0) and wall (8 voxels at x = 0) both reach voxels (0, 0..1, 0).
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 2; ++y)
      s.add (x + 0.5f, y + 0.5f, 0.25f, 1, 1);
  for (int y = 0; y < 2; ++y)
    for (int z = 0; z < 4; ++z)
      s.add (0.25f, y + 0.5f, z + 0.5f, 2, 2);
  const auto r = s.eval ();
  expectCounts (r, 16, 0, 0); // 14 distinct voxels, 16 (plane, voxel) pairs
  EXPECT_EQ (r.found, 2);
}

TEST (PlaneEvaluation, NonFinitePointsAreIgnored)
{
  Scene clean;
  addRoom (clean, 3, 3); // merged: a non-trivial result worth reproducing
  Scene noisy = clean;
  const float nan = std::numeric_limits<float>::quiet_NaN ();
  const float inf = std::numeric_limits<float>::infinity ();
  noisy.add (nan, nan, nan, 5, 6);   // labels seen only on non-finite points do not count
  noisy.add (1e6f, 1e6f, inf, 1, 3); // would blow up the extent if used
  noisy.add (-inf, 0.5f, 0.5f, 2, 9);
  noisy.add (0.5f, nan, 0.5f, 1, 3);
  const auto a = clean.eval ();
  const auto b = noisy.eval ();
  EXPECT_EQ (b.planes, 2);
  EXPECT_EQ (b.detected, 1);
  EXPECT_EQ (a.tp, b.tp);
  EXPECT_EQ (a.fp, b.fp);
  EXPECT_EQ (a.fn, b.fn);
  EXPECT_EQ (a.found, b.found);
  EXPECT_EQ (a.false_planes, b.false_planes);
}

TEST (PlaneEvaluation, EmptyOrAllNonFiniteCloud)
{
  const pcl::PointCloud<pcl::PointXYZ> empty;
  const auto r = evaluatePlaneDetection (empty, {}, {});
  EXPECT_EQ (r.planes, 0);
  EXPECT_EQ (r.f1, 0.0);

  pcl::PointCloud<pcl::PointXYZ> nans;
  nans.push_back (pcl::PointXYZ (std::numeric_limits<float>::quiet_NaN (), 0.f, 0.f));
  const auto q = evaluatePlaneDetection (nans, {1}, {1});
  EXPECT_EQ (q.planes, 0);
  EXPECT_EQ (q.detected, 0);
  EXPECT_EQ (q.tp + q.fp + q.fn, 0u);
}

TEST (PlaneEvaluation, InvalidArgumentsThrow)
{
  Scene s;
  addRoom (s, 1, 2);
  auto short_truth = s.truth;
  short_truth.pop_back ();
  EXPECT_THROW (evaluatePlaneDetection (s.cloud, short_truth, s.det), std::invalid_argument);
  auto long_det = s.det;
  long_det.push_back (1);
  EXPECT_THROW (evaluatePlaneDetection (s.cloud, s.truth, long_det), std::invalid_argument);
  EXPECT_THROW (s.eval (0.0), std::invalid_argument);
  EXPECT_THROW (s.eval (-0.01), std::invalid_argument);
  EXPECT_THROW (s.eval (std::numeric_limits<double>::quiet_NaN ()), std::invalid_argument);
  for (const double f : {-0.1, 1.0, std::numeric_limits<double>::quiet_NaN ()})
    EXPECT_THROW (evaluatePlaneDetection (s.cloud, s.truth, s.det, kUnitVoxels, {0.0, f, 0.0}),
                  std::invalid_argument) << f;
  EXPECT_THROW (evaluateOverGridPhases (s.cloud, s.truth, s.det, kUnitVoxels, 0), std::invalid_argument);
}

TEST (PlaneEvaluation, RotatedSceneWithDefaultVoxels)
{
  // Two perpendicular 1 m planes, densely sampled, rotated off the axes: the default 1 % voxels
  // do not line up with anything, and a perfect detection must still score 1.
  const Eigen::Matrix3f rot =
      (Eigen::AngleAxisf (0.3f, Eigen::Vector3f::UnitZ ()) *
       Eigen::AngleAxisf (0.7f, Eigen::Vector3f::UnitX ())).toRotationMatrix ();
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::uint32_t> truth, split;
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j)
    {
      const float u = i * 0.005f, v = j * 0.005f;
      cloud.push_back (pcl::PointXYZ (0, 0, 0));
      cloud.back ().getVector3fMap () = rot * Eigen::Vector3f (u, v, 0.f);
      truth.push_back (1);
      split.push_back (u < 0.5f ? 1 : 2);
      cloud.push_back (pcl::PointXYZ (0, 0, 0));
      cloud.back ().getVector3fMap () = rot * Eigen::Vector3f (u, 1.2f, 0.1f + v);
      truth.push_back (2);
      split.push_back (3);
    }
  const auto r = evaluatePlaneDetection (cloud, truth, truth);
  EXPECT_DOUBLE_EQ (r.f1, 1.0);
  EXPECT_EQ (r.found, 2);
  const auto f = evaluatePlaneDetection (cloud, truth, split);
  EXPECT_DOUBLE_EQ (f.recall, 1.0);
  EXPECT_EQ (f.fragments, 1);
  EXPECT_EQ (f.found, 2);
  EXPECT_EQ (f.false_planes, 0);
}

// --- label files ---------------------------------------------------------------------------------

namespace
{
std::string
tempPath (const std::string& name)
{
  return (std::filesystem::temp_directory_path () /
          ("pcl_rspd_eval_" + std::to_string (::getpid ()) + "_" + name))
      .string ();
}
} // namespace

TEST (LabelIO, RawRoundTripAndSizeCheck)
{
  const std::string path = tempPath ("labels.gt");
  const std::vector<std::uint32_t> labels = {0, 1, 2, 0xDEADBEEFu, 7};
  std::string error;
  ASSERT_TRUE (rspd_tools::writeRawLabels (path, labels, error)) << error;
  EXPECT_FALSE (std::filesystem::exists (path + ".tmp"));
  EXPECT_EQ (std::filesystem::file_size (path), 20u);
  {
    // Little-endian on disk whatever the host.
    std::ifstream in (path, std::ios::binary);
    unsigned char b[16];
    in.read (reinterpret_cast<char*> (b), 16);
    EXPECT_EQ (b[12], 0xEF);
    EXPECT_EQ (b[15], 0xDE);
  }
  std::vector<std::uint32_t> back;
  ASSERT_TRUE (rspd_tools::readLabels (path, labels.size (), back, error)) << error;
  EXPECT_EQ (back, labels);
  EXPECT_FALSE (rspd_tools::readLabels (path, 4, back, error));
  EXPECT_FALSE (error.empty ());
  std::filesystem::remove (path);
  EXPECT_FALSE (rspd_tools::readLabels (path, 5, back, error));
}

TEST (LabelIO, PcdLabelField)
{
  const std::string path = tempPath ("labels.pcd");
  pcl::PointCloud<pcl::PointXYZRGBL> cloud;
  for (std::uint32_t i = 0; i < 6; ++i)
  {
    pcl::PointXYZRGBL p;
    p.x = p.y = p.z = static_cast<float> (i);
    p.label = i % 3 == 0 ? 0 : 100 + i;
    cloud.push_back (p);
  }
  ASSERT_EQ (pcl::io::savePCDFileBinary (path, cloud), 0);
  std::vector<std::uint32_t> labels;
  std::string error;
  ASSERT_TRUE (rspd_tools::readLabels (path, 6, labels, error)) << error;
  EXPECT_EQ (labels, (std::vector<std::uint32_t>{0, 101, 102, 0, 104, 105}));
  EXPECT_FALSE (rspd_tools::readLabels (path, 7, labels, error));

  // A PCD without a label field, and a file that is not a PCD at all, are errors, not crashes.
  pcl::PointCloud<pcl::PointXYZ> xyz;
  xyz.push_back (pcl::PointXYZ (1, 2, 3));
  ASSERT_EQ (pcl::io::savePCDFileBinary (path, xyz), 0);
  EXPECT_FALSE (rspd_tools::readLabels (path, 1, labels, error));
  EXPECT_NE (error.find ("label"), std::string::npos);
  {
    std::ofstream out (path, std::ios::trunc);
    out << "not a point cloud\n";
  }
  EXPECT_FALSE (rspd_tools::readLabels (path, 1, labels, error));
  std::filesystem::remove (path);
}

// --- real data, when ../shared/data is present ---------------------------------------------------

namespace
{
bool
loadSharedScene (const std::string& name, pcl::PointCloud<pcl::PointXYZ>& cloud,
                 std::vector<std::uint32_t>& truth)
{
#ifdef PCL_RSPD_SHARED_DATA_DIR
  const std::string base = std::string (PCL_RSPD_SHARED_DATA_DIR) + "/" + name;
  if (!std::filesystem::exists (base + ".pcd") || !std::filesystem::exists (base + ".gt"))
    return false;
  if (pcl::io::loadPCDFile (base + ".pcd", cloud) < 0)
    return false;
  std::string error;
  return rspd_tools::readLabels (base + ".gt", cloud.size (), truth, error);
#else
  (void) name;
  (void) cloud;
  (void) truth;
  return false;
#endif
}
} // namespace

TEST (PlaneEvaluationData, SynPebTruthAgainstItself)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::uint32_t> truth;
  if (!loadSharedScene ("synpeb_test100", cloud, truth))
    GTEST_SKIP () << "shared data not available";
  ASSERT_EQ (cloud.size (), 10000u);
  const auto r = evaluatePlaneDetection (cloud, truth, truth);
  EXPECT_DOUBLE_EQ (r.precision, 1.0);
  EXPECT_DOUBLE_EQ (r.recall, 1.0);
  EXPECT_DOUBLE_EQ (r.f1, 1.0);
  EXPECT_EQ (r.found, 12);
  EXPECT_EQ (r.planes, 12);
  EXPECT_EQ (r.detected, 12);
  EXPECT_EQ (r.fragments, 0);
  EXPECT_EQ (r.false_planes, 0);

  // Renaming the planes changes nothing; dropping one costs exactly its voxels in recall.
  std::vector<std::uint32_t> renamed (truth), dropped (truth);
  for (auto& l : renamed)
    l = l ? 1000 - l : 0;
  const std::uint32_t victim = truth[std::distance (
      truth.begin (), std::find_if (truth.begin (), truth.end (), [] (auto l) { return l != 0; }))];
  for (auto& l : dropped)
    if (l == victim)
      l = 0;
  EXPECT_DOUBLE_EQ (evaluatePlaneDetection (cloud, truth, renamed).f1, 1.0);
  const auto d = evaluatePlaneDetection (cloud, truth, dropped);
  EXPECT_DOUBLE_EQ (d.precision, 1.0);
  EXPECT_LT (d.recall, 1.0);
  EXPECT_EQ (d.found, 11);
  EXPECT_EQ (d.tp + d.fn, r.tp);
}
