/*
 * Tests of the edge-side rule (departure, settleEdgeSides).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/edge_sides.h>
#include <pcl_rspd/patch_growth.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace pcl::rspd;

namespace
{
/** Label every sample with the plane it is nearer to, as a distance-only pass would. */
std::vector<std::uint32_t>
nearestLabels (const PointSet& s, const std::vector<PlanarPatch>& patches)
{
  std::vector<std::uint32_t> labels (s.size ());
  for (std::size_t i = 0; i < s.size (); ++i)
  {
    double best = HUGE_VAL;
    for (std::uint32_t l = 0; l < patches.size (); ++l)
    {
      const double d = std::abs ((s.points[i].cast<double> () - patches[l].center).dot (patches[l].normal));
      if (d < best)
      {
        best = d;
        labels[i] = l;
      }
    }
  }
  return labels;
}

std::vector<PlanarPatch>
patchesOf (const std::vector<std::uint32_t>& labels, std::vector<PlanarPatch> planes)
{
  for (auto& p : planes)
    p.members.clear ();
  for (std::uint32_t i = 0; i < labels.size (); ++i)
    planes[labels[i]].members.push_back (i);
  return planes;
}

/** A step's nose: tread z = 0 over x in [0, 0.5], riser x = 0 over z in [-0.5, 0], 1 cm apart, noise
  * 4 mm along each normal; the tread is plane 0, the riser plane 1. */
struct Nose
{
  PointSet set;
  std::vector<PlanarPatch> planes;
};

Nose
makeNose (std::uint32_t seed)
{
  Nose n;
  const auto tread = rspd_test::addRectangle (n.set, {0, 0, 0}, {0.5f, 0, 0}, {0, 0.2f, 0}, 50, 20, 0.004f, seed);
  const auto riser = rspd_test::addRectangle (n.set, {0, 0, -0.5f}, {0, 0, 0.5f}, {0, 0.2f, 0}, 50, 20, 0.004f, seed + 1);
  n.planes = {rspd_test::makePatch ({tread[0]}, {0, 0, 0}, {0, 0, 1}, 0.01, 0.1),
              rspd_test::makePatch ({riser[0]}, {0, 0, 0}, {1, 0, 0}, 0.01, 0.1)};
  return n;
}
} // namespace

TEST (EdgeSides, SamplesBeyondTheLineGoToThePlaneWhoseSideTheyAreOn)
{
  // A riser sample pushed outwards (x < 0) within noise of the tread is nearer the tread, yet no
  // tread sample has x < 0: it is the riser's; likewise z > 0 is the tread's. Inside the step
  // (x > 0, z < 0) both planes may own a sample; it is left alone.
  const Nose nose = makeNose (1);
  const PointSet& s = nose.set;
  const std::vector<PlanarPatch>& planes = nose.planes;
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 12);
  std::vector<std::uint32_t> labels = nearestLabels (s, planes);
  std::vector<PlanarPatch> patches = patchesOf (labels, planes);
  const std::vector<std::uint32_t> before = labels;
  std::size_t wrong_before = 0;
  for (std::size_t i = 0; i < s.size (); ++i)
    wrong_before += (s.points[i].x () < 0 && labels[i] != 1) || (s.points[i].z () > 0 && labels[i] != 0);
  ASSERT_GT (wrong_before, 3u); // the test needs some

  const EdgeSideCounts c = settleEdgeSides (s, g, {0.012, 0.012}, 1, patches, labels);
  EXPECT_EQ (c.moved, wrong_before);
  EXPECT_EQ (c.released, 0u);
  for (std::size_t i = 0; i < s.size (); ++i)
  {
    const Eigen::Vector3f& p = s.points[i];
    if (p.x () < 0)
      EXPECT_EQ (labels[i], 1u) << i;
    else if (p.z () > 0)
      EXPECT_EQ (labels[i], 0u) << i;
    else
      EXPECT_EQ (labels[i], before[i]) << i;
  }
  // Members follow the labels.
  for (std::uint32_t l = 0; l < 2; ++l)
    for (const auto m : patches[l].members)
      EXPECT_EQ (labels[m], l);
  EXPECT_EQ (patches[0].members.size () + patches[1].members.size (), s.size ());
}

TEST (EdgeSides, PlaneThatStraddlesTheOtherKeepsItsSamples)
{
  // A wall x = 0 over z in [-0.25, 0.25] and a shelf z = 0 out of it over x in [0, 0.5]. The wall
  // holds both sides of the shelf's plane, so no wall sample is judged against the shelf; a wall
  // sample behind the wall (x < 0) that the shelf took goes back to the wall (the wall has no side
  // of the shelf to keep to).
  PointSet s;
  const auto shelf = rspd_test::addRectangle (s, {0, 0, 0}, {0.5f, 0, 0}, {0, 0.2f, 0}, 50, 20, 0.004f, 3);
  const auto wall = rspd_test::addRectangle (s, {0, 0, -0.25f}, {0, 0, 0.5f}, {0, 0.2f, 0}, 50, 20, 0.004f, 4);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 12);
  const std::vector<PlanarPatch> planes{rspd_test::makePatch ({shelf[0]}, {0, 0, 0}, {0, 0, 1}, 0.01, 0.1),
                                        rspd_test::makePatch ({wall[0]}, {0, 0, 0}, {1, 0, 0}, 0.01, 0.1)};
  std::vector<std::uint32_t> labels = nearestLabels (s, planes);
  std::vector<PlanarPatch> patches = patchesOf (labels, planes);
  const std::vector<std::uint32_t> before = labels;
  std::size_t behind = 0;
  for (std::size_t i = 0; i < s.size (); ++i)
    behind += s.points[i].x () < 0 && labels[i] == 0;
  ASSERT_GT (behind, 0u);

  const EdgeSideCounts c = settleEdgeSides (s, g, {0.012, 0.012}, 1, patches, labels);
  EXPECT_EQ (c.moved, behind);
  EXPECT_EQ (c.released, 0u);
  for (std::size_t i = 0; i < s.size (); ++i)
    if (s.points[i].x () < 0)
      EXPECT_EQ (labels[i], 1u) << i;
    else
      EXPECT_EQ (labels[i], before[i]) << i; // no wall sample leaves for the shelf's sake
}

TEST (EdgeSides, PlanesWithinTheirNormalDeviationAreLeftAlone)
{
  // Two planes 3° apart with MND 5°: not an edge the rule judges.
  PointSet s;
  const float t = std::tan (3.0f * static_cast<float> (M_PI) / 180.0f);
  rspd_test::addRectangle (s, {-0.5f, 0, 0}, {0.5f, 0, 0}, {0, 0.2f, 0}, 50, 20, 0.004f, 5);
  rspd_test::addRectangle (s, {0, 0, 0}, {0.5f, 0, 0.5f * t}, {0, 0.2f, 0}, 50, 20, 0.004f, 6);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 12);
  const double mnd = 5.0 * M_PI / 180.0;
  const std::vector<PlanarPatch> planes{
    rspd_test::makePatch ({0}, {0, 0, 0}, {0, 0, 1}, 0.01, mnd),
    rspd_test::makePatch ({1000}, {0, 0, 0}, Eigen::Vector3d (-t, 0, 1).normalized (), 0.01, mnd)};
  std::vector<std::uint32_t> labels = nearestLabels (s, planes);
  std::vector<PlanarPatch> patches = patchesOf (labels, planes);
  const std::vector<std::uint32_t> before = labels;
  const EdgeSideCounts c = settleEdgeSides (s, g, {0.012, 0.012}, 1, patches, labels);
  EXPECT_EQ (c.moved + c.released, 0u);
  EXPECT_EQ (labels, before);
}

TEST (EdgeSides, ResultDoesNotDependOnTheThreadCount)
{
  const Nose nose = makeNose (7);
  const PointSet& s = nose.set;
  const std::vector<PlanarPatch>& planes = nose.planes;
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 12);
  std::vector<std::uint32_t> one = nearestLabels (s, planes), two = one;
  std::vector<PlanarPatch> p1 = patchesOf (one, planes), p2 = p1;
  settleEdgeSides (s, g, {0.012, 0.012}, 1, p1, one);
  settleEdgeSides (s, g, {0.012, 0.012}, 2, p2, two);
  EXPECT_EQ (one, two);
  for (std::size_t l = 0; l < 2; ++l)
    EXPECT_EQ (p1[l].members, p2[l].members);
}
