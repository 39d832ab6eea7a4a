/*
 * Tests of the detection frame (orientation independence): pcl::rspd::dominantFrame.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/dominant_frame.h>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

using namespace pcl::rspd;

namespace
{
/** A box corner: floor (most samples), a wall along x, a smaller wall along y, σ = 2 mm. */
PointSet
corner ()
{
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {2, 0, 0}, {0, 2, 0}, 80, 80, 0.002f, 1);
  rspd_test::addRectangle (s, {0, 0, 0}, {2, 0, 0}, {0, 0, 1}, 80, 40, 0.002f, 2);
  rspd_test::addRectangle (s, {0, 0, 0}, {0, 2, 0}, {0, 0, 0.5f}, 60, 20, 0.002f, 3);
  return s;
}

/** Largest |cosine| between \a axis and a row of \a frame. */
double
bestAlignment (const Eigen::Matrix3d& frame, const Eigen::Vector3d& axis)
{
  return (frame * axis).cwiseAbs ().maxCoeff ();
}
} // namespace

TEST (DominantFrame, RowsFollowThePlaneFamiliesMostCommonFirst)
{
  const PointSet s = corner ();
  const Eigen::Matrix3d f = dominantFrame (s);
  EXPECT_TRUE ((f * f.transpose ()).isIdentity (1e-9));
  EXPECT_NEAR (f.determinant (), 1.0, 1e-9);
  EXPECT_GT (std::abs (f.row (0).z ()), 0.9999) << "the floor's normal is the most common";
  EXPECT_GT (std::abs (f.row (1).y ()), 0.9999) << "then the larger wall's";
  EXPECT_GT (std::abs (f.row (2).x ()), 0.9999);
}

TEST (DominantFrame, TurnsWithTheCloud)
{
  PointSet s = corner ();
  const Eigen::Matrix3d before = dominantFrame (s);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd (0.7, Eigen::Vector3d (1, 2, 3).normalized ()).toRotationMatrix ();
  rotateSamples (s, turn);
  const Eigen::Matrix3d after = dominantFrame (s);
  // The turned cloud's axes are the turned axes (as lines: signs do not matter).
  for (int r = 0; r < 3; ++r)
    EXPECT_GT (bestAlignment (after, turn * before.row (r).transpose ()), 0.99999) << "axis " << r;
}

TEST (DominantFrame, OnePlaneFamilyTakesThePointsMainDirection)
{
  // Only floor normals: the second axis is the long side of the samples.
  PointSet s;
  const Eigen::Vector3f u = Eigen::Vector3f (1, 1, 0).normalized (), v = Eigen::Vector3f (-1, 1, 0).normalized ();
  rspd_test::addRectangle (s, {0, 0, 0}, 4.0f * u, 1.0f * v, 120, 30, 0.0f, 1);
  const Eigen::Matrix3d f = dominantFrame (s);
  EXPECT_GT (std::abs (f.row (0).z ()), 0.9999);
  EXPECT_GT (std::abs (f.row (1).dot (u.cast<double> ())), 0.9999);
  EXPECT_TRUE ((f * f.transpose ()).isIdentity (1e-9));
}

TEST (DominantFrame, NoSamplesGiveTheIdentity)
{
  EXPECT_TRUE (dominantFrame (PointSet ()).isIdentity ());
}

TEST (DominantFrame, RotateSamplesThereAndBack)
{
  PointSet s = corner ();
  const PointSet original = s;
  const Eigen::Matrix3d f = dominantFrame (s);
  rotateSamples (s, Eigen::AngleAxisd (1.1, Eigen::Vector3d::UnitX ()).toRotationMatrix () * f);
  rotateSamples (s, (Eigen::AngleAxisd (1.1, Eigen::Vector3d::UnitX ()).toRotationMatrix () * f).transpose ());
  for (std::size_t i = 0; i < s.size (); ++i)
  {
    EXPECT_LT ((s.points[i] - original.points[i]).norm (), 1e-5f);
    EXPECT_LT ((s.normals[i] - original.normals[i]).norm (), 1e-5f);
  }
}
