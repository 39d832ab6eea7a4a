/*
 * Tests of the detector's checks beyond the paper: the curvature measure behind the curved-surface
 * check, and the check and the last assignment pass inside detectPlanes.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/plane_detector.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace pcl::rspd;

namespace
{
/** Samples on a cylinder of radius r around the y axis, arc of +-half_arc radians about +z, length
  * 1, Gaussian noise along the radius; exact normals. */
std::vector<std::uint32_t>
addCylinderArc (PointSet& s, double r, double half_arc, int n, float noise, std::uint32_t seed = 1)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<double> u (0.0, 1.0);
  std::normal_distribution<float> g (0.0f, 1.0f);
  std::vector<std::uint32_t> added;
  for (int i = 0; i < n; ++i)
  {
    const double a = (2.0 * u (rng) - 1.0) * half_arc;
    const Eigen::Vector3f normal (static_cast<float> (std::sin (a)), 0.0f, static_cast<float> (std::cos (a)));
    const float radius = static_cast<float> (r) + noise * g (rng);
    added.push_back (static_cast<std::uint32_t> (s.points.size ()));
    s.points.push_back (radius * normal + Eigen::Vector3f (0, static_cast<float> (u (rng)), 0));
    s.normals.push_back (normal);
    s.input_indices.push_back (static_cast<pcl::index_t> (s.input_indices.size ()));
  }
  return added;
}
} // namespace

TEST (Curvature, FlatNoisyPatchHasNoBend)
{
  PointSet s;
  const auto m = rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 40, 40, 0.01f);
  const PlaneCurvature c = measureCurvature (s, m);
  EXPECT_LT (c.share, 0.02);
  EXPECT_LT (c.half_bend, 2.0 * M_PI / 180.0);
}

TEST (Curvature, CylinderFacetBendsByHalfItsArc)
{
  // A 40° arc of a cylinder: the normal turns by 20° from the middle to either rim.
  PointSet s;
  const auto m = addCylinderArc (s, 1.0, 20.0 * M_PI / 180.0, 2000, 0.002f);
  const PlaneCurvature c = measureCurvature (s, m);
  EXPECT_GT (c.share, 0.9);
  EXPECT_NEAR (c.half_bend * 180.0 / M_PI, 20.0, 3.0);
}

TEST (Curvature, ScaleAndNoiseLevelDoNotChangeTheMeasure)
{
  PointSet a, b;
  const auto ma = addCylinderArc (a, 1.0, 0.3, 1500, 0.01f, 3);
  const auto mb = addCylinderArc (b, 1.0, 0.3, 1500, 0.01f, 3);
  for (auto& p : b.points)
    p = 1000.0f * p + Eigen::Vector3f (5, -7, 2); // the same arc in millimetres, moved
  const PlaneCurvature ca = measureCurvature (a, ma), cb = measureCurvature (b, mb);
  EXPECT_NEAR (ca.share, cb.share, 1e-3);
  EXPECT_NEAR (ca.half_bend, cb.half_bend, 1e-3);
}

TEST (Curvature, TooFewSamplesMeasureNothing)
{
  PointSet s;
  const auto m = addCylinderArc (s, 1.0, 0.5, 11, 0.0f);
  const PlaneCurvature c = measureCurvature (s, m);
  EXPECT_EQ (c.share, 0.0);
  EXPECT_EQ (c.half_bend, 0.0);
}
