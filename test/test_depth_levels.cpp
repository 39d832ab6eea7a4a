/*
 * Tests of depth levels: when a cloud's depths are a camera's quantization (findDepthLevels), the
 * dither within their bins (ditherDepthLevels), and the class's setDepthLevelDither on a camera view
 * of the generated room with structured-light depth levels.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/depth_levels.h>
#include <pcl_rspd/plane_evaluation.h>
#include <pcl_rspd/robust_plane_segmentation.h>
#include <pcl_rspd/synthetic_scenes.h>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace pcl::rspd;

namespace
{
/** A camera's depth level for depth z: K/m for the whole m nearest K/z (disparity steps). */
double
levelOf (double z, double k)
{
  return k / std::round (k / z);
}

/** n samples on a plane seen by a camera at the origin looking along +z, tilted by \a tilt radians
  * about the y axis, 4 m away, 3 x 3 m, each moved along its ray to its depth level (K = 357 m: about
  * 4.5 cm apart at 4 m), as a structured-light camera stores them: z a float level, x and y from it. */
std::vector<Eigen::Vector3d>
quantizedPlane (int n, double tilt, double k, std::uint32_t seed = 1)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<double> u (-1.5, 1.5);
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < n; ++i)
  {
    const double a = u (rng), b = u (rng);
    const Eigen::Vector3d p (a * std::cos (tilt), b, 4.0 + a * std::sin (tilt));
    const float z = static_cast<float> (levelOf (p.z (), k));
    const float x = static_cast<float> (p.x () * z / p.z ()), y = static_cast<float> (p.y () * z / p.z ());
    out.emplace_back (x, y, z);
  }
  return out;
}

const Eigen::Vector3d kOrigin = Eigen::Vector3d::Zero ();
const Eigen::Vector3d kAxis = Eigen::Vector3d::UnitZ ();
} // namespace

TEST (DepthLevels, ACameraPlanesDepthsAreLevelsMeasuredOnesAreNot)
{
  const std::vector<Eigen::Vector3d> quantized = quantizedPlane (20000, 0.6, 357.0);
  const DepthLevels q = findDepthLevels (quantized, kOrigin, kAxis);
  EXPECT_TRUE (q.quantized);
  EXPECT_EQ (q.samples, 20000u);
  EXPECT_EQ (q.on_levels, 20000u);
  EXPECT_GE (q.distinct, 16u);
  EXPECT_EQ (q.levels.size (), q.distinct);
  EXPECT_TRUE (std::is_sorted (q.levels.begin (), q.levels.end ()));
  // The same plane with continuous depths (noise of a millimetre): no level.
  std::mt19937 rng (2);
  std::normal_distribution<double> g (0.0, 0.001);
  std::vector<Eigen::Vector3d> measured;
  for (const auto& p : quantizedPlane (20000, 0.6, 1e12))
    measured.emplace_back (p.x (), p.y (), static_cast<float> (p.z () + g (rng)));
  const DepthLevels m = findDepthLevels (measured, kOrigin, kAxis);
  EXPECT_FALSE (m.quantized);
  EXPECT_LT (m.on_levels, 2000u);
  EXPECT_TRUE (m.levels.empty ());
}

TEST (DepthLevels, FlatFloorsWallsFewLevelsOrSamplesBehindTheCameraAreNoQuantization)
{
  // Noise-free treads (horizontal, each one depth along z) and risers (depth varies): the treads'
  // samples share their depth, the risers' do not: 62 % on levels, below 95 %.
  std::vector<Eigen::Vector3d> stairs;
  std::mt19937 rng (3);
  std::uniform_real_distribution<double> u (0.0, 1.0);
  for (int s = 0; s < 20; ++s)
    for (int i = 0; i < 1000; ++i)
    {
      const double x = u (rng);
      if (u (rng) < 0.3 / 0.48)
        stairs.emplace_back (x, 0.3 * s + 0.3 * u (rng), static_cast<float> (2.0 + 0.18 * s)); // tread
      else
        stairs.emplace_back (x, 0.3 * s, static_cast<float> (2.0 + 0.18 * s + 0.18 * u (rng))); // riser
    }
  const DepthLevels st = findDepthLevels (stairs, kOrigin, kAxis);
  EXPECT_FALSE (st.quantized);
  EXPECT_GT (st.on_levels, stairs.size () / 2);
  // Fewer than 16 levels: a noise-free box or a few floors.
  const std::vector<Eigen::Vector3d> few = quantizedPlane (5000, 0.05, 357.0);
  EXPECT_LT (findDepthLevels (few, kOrigin, kAxis).distinct, 16u);
  EXPECT_FALSE (findDepthLevels (few, kOrigin, kAxis).quantized);
  // Samples on or behind the camera: not a camera's frame.
  std::vector<Eigen::Vector3d> behind = quantizedPlane (20000, 0.6, 357.0);
  behind[7].z () = -behind[7].z ();
  EXPECT_FALSE (findDepthLevels (behind, kOrigin, kAxis).quantized);
  EXPECT_FALSE (findDepthLevels ({}, kOrigin, kAxis).quantized);
}

TEST (DepthLevels, LevelsAreFoundAlongATurnedCameraAxisGivenAsAFloatQuaternion)
{
  // The camera's frame turned and moved: depths recomputed from float coordinates along an axis from
  // a float quaternion differ by a float step or two within a level; they still form one level each.
  const std::vector<Eigen::Vector3d> local = quantizedPlane (20000, 0.6, 357.0);
  const Eigen::Quaternionf turn (Eigen::AngleAxisf (0.7f, Eigen::Vector3f (0.3f, -0.5f, 0.8f).normalized ()));
  const Eigen::Vector3d origin (12.5, -3.0, 1.25);
  std::vector<Eigen::Vector3d> world;
  for (const auto& p : local)
    world.push_back ((origin + turn.cast<double> () * p).cast<float> ().cast<double> ());
  const Eigen::Vector3d axis = (turn.cast<double> () * Eigen::Vector3d::UnitZ ()).normalized ();
  const DepthLevels in_camera = findDepthLevels (local, kOrigin, kAxis);
  const DepthLevels in_world = findDepthLevels (world, origin, axis);
  EXPECT_TRUE (in_world.quantized);
  EXPECT_EQ (in_world.distinct, in_camera.distinct);
  EXPECT_EQ (in_world.on_levels, in_world.samples);
}

TEST (DepthLevels, DitherKeepsEachSampleOnItsRayWithinItsBinWhateverTheOrder)
{
  const double k = 357.0;
  const std::vector<Eigen::Vector3d> quantized = quantizedPlane (20000, 0.6, k);
  const DepthLevels levels = findDepthLevels (quantized, kOrigin, kAxis);
  ASSERT_TRUE (levels.quantized);
  std::vector<Eigen::Vector3d> dithered = quantized;
  ditherDepthLevels (dithered, kOrigin, kAxis, levels);
  double sum = 0.0, sum2 = 0.0;
  std::size_t moved = 0;
  for (std::size_t i = 0; i < quantized.size (); ++i)
  {
    const Eigen::Vector3d& p = quantized[i];
    const Eigen::Vector3d& q = dithered[i];
    EXPECT_LT (p.normalized ().cross (q.normalized ()).norm (), 1e-9) << i; // same ray
    const auto it = std::lower_bound (levels.levels.begin (), levels.levels.end (), p.z () - 1e-6);
    ASSERT_NE (it, levels.levels.end ());
    const std::size_t m = static_cast<std::size_t> (it - levels.levels.begin ());
    const double lo = m > 0 ? 0.5 * (levels.levels[m] + levels.levels[m - 1]) : p.z () - 0.5 * (levels.levels[1] - levels.levels[0]);
    const double hi = m + 1 < levels.levels.size () ? 0.5 * (levels.levels[m] + levels.levels[m + 1])
                                                    : p.z () + 0.5 * (levels.levels[m] - levels.levels[m - 1]);
    EXPECT_GE (q.z (), lo - 1e-9) << i;
    EXPECT_LE (q.z (), hi + 1e-9) << i;
    const double gap = hi - lo;
    sum += (q.z () - p.z ()) / gap;
    sum2 += (q.z () - p.z ()) * (q.z () - p.z ()) / (gap * gap);
    moved += q.z () != p.z ();
  }
  // Uniform within the bin: mean offset about 0, spread about 1/√12 of the bin.
  const double count = static_cast<double> (quantized.size ());
  EXPECT_NEAR (sum / count, 0.0, 0.02);
  EXPECT_NEAR (std::sqrt (sum2 / count), 1.0 / std::sqrt (12.0), 0.02);
  EXPECT_GT (moved, quantized.size () * 99 / 100);
  // The draw belongs to the sample, not to its place in the cloud.
  std::vector<std::size_t> order (quantized.size ());
  for (std::size_t i = 0; i < order.size (); ++i)
    order[i] = i;
  std::shuffle (order.begin (), order.end (), std::mt19937 (4));
  std::vector<Eigen::Vector3d> shuffled;
  for (const auto i : order)
    shuffled.push_back (quantized[i]);
  ditherDepthLevels (shuffled, kOrigin, kAxis, findDepthLevels (shuffled, kOrigin, kAxis));
  for (std::size_t j = 0; j < order.size (); ++j)
    EXPECT_EQ (shuffled[j], dithered[order[j]]) << j;
  // Not quantized: nothing moves.
  std::vector<Eigen::Vector3d> same = quantized;
  ditherDepthLevels (same, kOrigin, kAxis, DepthLevels ());
  EXPECT_EQ (same, quantized);
}

namespace
{
/** The generated room seen by a structured-light camera at its scanner looking along \a axis: the
  * samples within 45° of the axis, each moved along its ray to its depth level (K = 357 m; as
  * scripts/quantize_depth.py --fov 45), the sensor's orientation turning +z onto the axis. */
void
cameraView (const Eigen::Vector3d& axis_in, pcl::PointCloud<pcl::PointXYZ>& cloud, std::vector<std::uint32_t>& truth)
{
  const Scene room = makeScene ("room");
  const Eigen::Vector3d origin = room.cloud.sensor_origin_.head<3> ().cast<double> ();
  const Eigen::Vector3d axis = axis_in.normalized ();
  cloud.clear ();
  truth.clear ();
  for (std::size_t i = 0; i < room.cloud.size (); ++i)
  {
    const Eigen::Vector3d d = room.cloud[i].getVector3fMap ().cast<double> () - origin;
    const double z = d.dot (axis);
    if (!(z >= std::cos (M_PI / 4.0) * d.norm ()) || z < 0.3)
      continue;
    const Eigen::Vector3d p = origin + d * (levelOf (z, 357.0) / z);
    cloud.push_back (pcl::PointXYZ (static_cast<float> (p.x ()), static_cast<float> (p.y ()), static_cast<float> (p.z ())));
    truth.push_back (room.labels[i]);
  }
  cloud.sensor_origin_ = room.cloud.sensor_origin_;
  cloud.sensor_orientation_ = Eigen::Quaternionf (Eigen::Quaterniond::FromTwoVectors (Eigen::Vector3d::UnitZ (), axis).cast<float> ());
}

EvaluationResult
detectView (const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud, const std::vector<std::uint32_t>& truth, bool dither,
            std::size_t* levels = nullptr)
{
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  EXPECT_FALSE (seg.getDepthLevelDither ());
  seg.setDepthLevelDither (dither);
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> planes;
  seg.segment (coefficients, planes);
  pcl::PointCloud<pcl::Label> labels;
  seg.getLabels (labels);
  std::vector<std::uint32_t> detected (labels.size ());
  for (std::size_t i = 0; i < labels.size (); ++i)
    detected[i] = labels[i].label;
  if (levels)
    *levels = seg.getStatistics ().depth_levels;
  const EvaluationResult r = evaluatePlaneDetection (*cloud, truth, detected, 0.01);
  std::printf ("    %s: F1 %.3f  found %d/%d  detected %d  fragments %d  false %d  levels %zu\n", dither ? "dithered" : "as given", r.f1, r.found,
               r.planes, r.detected, r.fragments, r.false_planes, seg.getStatistics ().depth_levels);
  return r;
}
} // namespace

TEST (DepthLevels, DitheredLevelsOfACameraViewOfTheRoomMakeNoPlanesOfTheirOwn)
{
  // The room's far wall 5.7° off square to the camera: its terraces, and the pillar's, were planes
  // of their own (measured: 25 planes for 11, 11 fragments, 4 false planes, F1 0.970; dithered 11
  // planes, one fragment, no false plane, F1 0.991). Since the rim bands the planes' rims take most
  // of the terraces beside them before those are judged (measured: 19 planes, 8 fragments, one false
  // plane, F1 0.990 as given; dithered 11, one fragment, none, 0.992). The caller's cloud is not
  // changed.
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  std::vector<std::uint32_t> truth;
  cameraView (Eigen::Vector3d (0.995, 0.0998, 0.0), *cloud, truth);
  const pcl::PointCloud<pcl::PointXYZ> before = *cloud;
  std::size_t levels_kept = 1, levels_dithered = 0;
  const EvaluationResult kept = detectView (cloud, truth, false, &levels_kept);
  const EvaluationResult dithered = detectView (cloud, truth, true, &levels_dithered);
  EXPECT_EQ (levels_kept, 0u);
  EXPECT_GE (levels_dithered, 100u);
  EXPECT_GE (kept.fragments, 5);
  EXPECT_GE (kept.false_planes, 1);
  EXPECT_LE (dithered.fragments, 2);
  EXPECT_EQ (dithered.false_planes, 0);
  EXPECT_GE (dithered.found, kept.found);
  EXPECT_GT (dithered.f1, kept.f1 + 0.001);
  ASSERT_EQ (cloud->size (), before.size ());
  for (std::size_t i = 0; i < cloud->size (); ++i)
    ASSERT_EQ ((*cloud)[i].getVector3fMap (), before[i].getVector3fMap ()) << i;
}
