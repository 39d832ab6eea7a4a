/*
 * Tests of the final refit (refitPlanes): least squares on a plane's members, trimmed.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/plane_refit.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace pcl::rspd;

namespace
{
constexpr double kDegree = M_PI / 180.0;

/** A noisy 1 x 1 m plane in z = 0 (40 x 40 samples, σ = 1 cm) as one patch whose estimate is off:
  * tilted by \a tilt about the y axis and shifted by \a shift along z, as a robust estimate from
  * bent normals can be. */
struct Scene
{
  PointSet set;
  std::vector<PlanarPatch> patches;
};

Scene
makeScene (double tilt = 2.0 * kDegree, double shift = 0.004)
{
  Scene s;
  const std::vector<std::uint32_t> added = rspd_test::addRectangle (s.set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 40, 40, 0.01f, 7);
  PlanarPatch p;
  p.members = added;
  p.first_index = added.front ();
  p.center = Eigen::Vector3d (0.5, 0.5, shift);
  p.normal = Eigen::Vector3d (std::sin (tilt), 0.0, std::cos (tilt));
  p.mdp = 0.03;
  p.mnd = 0.2;
  p.cos_mnd = std::cos (p.mnd);
  s.patches.push_back (p);
  return s;
}

double
angleToZ (const Eigen::Vector3d& n)
{
  return std::acos (std::min (1.0, std::abs (n.z ())));
}
} // namespace

TEST (PlaneRefit, AnOffEstimateBecomesTheMembersPlane)
{
  Scene s = makeScene ();
  refitPlanes (s.set, 0, s.patches);
  const PlanarPatch& p = s.patches.front ();
  // 1,600 samples at σ = 1 cm over 1 m: the least-squares normal is within 0.1° of the truth, the
  // centre within 1 mm of the plane (a 2° tilt and a 4 mm shift before).
  EXPECT_LT (angleToZ (p.normal), 0.1 * kDegree);
  EXPECT_GT (p.normal.z (), 0.0); // keeps its side
  EXPECT_LT (std::abs (p.center.z ()), 0.001);
  EXPECT_NEAR (p.center.x (), 0.5, 0.01);
  EXPECT_NEAR (p.normal.norm (), 1.0, 1e-12);
  // Members, MDP and MND are the estimate's.
  EXPECT_EQ (p.members.size (), 1600u);
  EXPECT_EQ (p.mdp, 0.03);
  EXPECT_EQ (p.mnd, 0.2);
}

TEST (PlaneRefit, FarMembersOfTheBandDoNotTiltThePlane)
{
  // Forty members 6-8 cm above one end of the plane (a neighbour's samples at an edge, outliers in
  // a wide band) tilt a plain least-squares fit by about 0.5°; the trim leaves them out.
  Scene s = makeScene (0.0, 0.0);
  std::vector<std::uint32_t>& members = s.patches.front ().members;
  for (int i = 0; i < 40; ++i)
  {
    members.push_back (static_cast<std::uint32_t> (s.set.points.size ()));
    s.set.points.emplace_back (0.95f + 0.001f * static_cast<float> (i), 0.02f * static_cast<float> (i % 40), 0.06f + 0.0005f * static_cast<float> (i));
    s.set.normals.emplace_back (0.0f, 0.0f, 1.0f);
  }
  refitPlanes (s.set, 0, s.patches);
  EXPECT_LT (angleToZ (s.patches.front ().normal), 0.1 * kDegree);
  EXPECT_LT (std::abs (s.patches.front ().center.z ()), 0.001);
}

TEST (PlaneRefit, PlanesWithoutAPlaneToFitKeepTheirEstimate)
{
  Scene s;
  for (int i = 0; i < 5; ++i)
  {
    s.set.points.emplace_back (0.1f * static_cast<float> (i), 0.0f, 0.0f); // collinear
    s.set.normals.emplace_back (0.0f, 0.0f, 1.0f);
  }
  PlanarPatch line;
  line.members = {0, 1, 2, 3, 4};
  line.center = Eigen::Vector3d (0.2, 0.0, 0.0);
  line.normal = Eigen::Vector3d::UnitZ ();
  PlanarPatch two = line;
  two.members = {0, 1}; // fewer than three
  PlanarPatch empty = line;
  empty.members.clear ();
  s.patches = {line, two, empty};
  refitPlanes (s.set, 0, s.patches);
  for (const auto& p : s.patches)
  {
    EXPECT_EQ (p.center, line.center);
    EXPECT_EQ (p.normal, line.normal);
  }
}

TEST (PlaneRefit, SamePlanesAtAnyScaleOffsetRotationAndThreadCount)
{
  const Scene base = makeScene ();
  Scene ref = base;
  refitPlanes (ref.set, 1, ref.patches);
  // Two threads, and several planes at once: each plane is fitted alone.
  Scene many = base;
  many.patches = {base.patches.front (), base.patches.front (), base.patches.front ()};
  refitPlanes (many.set, 2, many.patches);
  for (const auto& p : many.patches)
  {
    EXPECT_EQ (p.center, ref.patches.front ().center);
    EXPECT_EQ (p.normal, ref.patches.front ().normal);
  }
  // Scaled by 1000, turned and moved 1 km: the plane moves with the cloud.
  const Eigen::Matrix3d r = Eigen::AngleAxisd (0.7, Eigen::Vector3d (1, 2, 3).normalized ()).toRotationMatrix ();
  const Eigen::Vector3d t (1000.0, -250.0, 40.0);
  Scene moved = base;
  for (auto& q : moved.set.points)
    q = (1000.0 * (r * q.cast<double> ()) + t).cast<float> ();
  PlanarPatch& m = moved.patches.front ();
  m.center = 1000.0 * (r * m.center) + t;
  m.normal = r * m.normal;
  refitPlanes (moved.set, 0, moved.patches);
  const Eigen::Vector3d expected_normal = r * ref.patches.front ().normal;
  const Eigen::Vector3d expected_center = 1000.0 * (r * ref.patches.front ().center) + t;
  EXPECT_GT (m.normal.dot (expected_normal), std::cos (0.01 * kDegree));
  EXPECT_LT (std::abs ((m.center - expected_center).dot (expected_normal)), 0.1); // 0.1 mm at 1,000x
}
