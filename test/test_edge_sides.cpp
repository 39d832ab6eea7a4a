/*
 * Tests of the edge-side and step-side rules (departures, settleEdgeSides, settleStepSides).
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

/** Append one sample at \a p with normal \a n. */
void
addSample (PointSet& s, const Eigen::Vector3f& p, const Eigen::Vector3f& n)
{
  s.points.push_back (p);
  s.normals.push_back (n);
  s.input_indices.push_back (static_cast<pcl::index_t> (s.input_indices.size ()));
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

TEST (EdgeSides, SamplesInsideTheCornerGoToTheNearerPlane)
{
  // Inside the step (x > 0, z < 0) noise can put a sample of either plane; near the nose, give each
  // such sample to the plane it is farther from, as growth may have. With corners on, each goes to
  // the nearer plane (bands equal); with corners off, the beyond rule leaves them all as they were.
  const Nose nose = makeNose (11);
  const PointSet& s = nose.set;
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 12);
  std::vector<std::uint32_t> nearest = nearestLabels (s, nose.planes);
  std::vector<std::uint32_t> start = nearest;
  std::size_t swapped = 0;
  const auto inCorner = [&s] (std::size_t i) {
    const Eigen::Vector3f& p = s.points[i];
    return p.x () > 0 && p.z () < 0 && p.x () < 0.012f && p.z () > -0.012f;
  };
  for (std::size_t i = 0; i < s.size (); ++i)
    if (inCorner (i))
    {
      start[i] = 1 - nearest[i];
      ++swapped;
    }
  ASSERT_GT (swapped, 3u); // the test needs some

  std::vector<std::uint32_t> on = start, off = start;
  std::vector<PlanarPatch> p_on = patchesOf (on, nose.planes), p_off = patchesOf (off, nose.planes);
  const EdgeSideCounts c_on = settleEdgeSides (s, g, {0.012, 0.012}, 1, p_on, on, true);
  const EdgeSideCounts c_off = settleEdgeSides (s, g, {0.012, 0.012}, 1, p_off, off, false);
  EXPECT_EQ (c_on.cornered, swapped);
  EXPECT_EQ (c_on.released, 0u);
  EXPECT_EQ (c_off.cornered, 0u);
  for (std::size_t i = 0; i < s.size (); ++i)
    if (inCorner (i))
    {
      EXPECT_EQ (on[i], nearest[i]) << i;
      EXPECT_EQ (off[i], start[i]) << i;
    }
  for (std::uint32_t l = 0; l < 2; ++l)
    for (const auto m : p_on[l].members)
      EXPECT_EQ (on[m], l);
}

TEST (EdgeSides, SamplesOutsideTheEdgeGoToThePlaneTheyLieFartherFrom)
{
  // Outside the nose (x < 0, z > 0) noise along the normals puts no sample; noise across the edge
  // does. Samples there, labelled by the nearer plane as growth may have: with wedges on, each goes
  // to the plane it lies farther from (bands equal) if it is within both bands, else to none; with
  // wedges off, all go to none.
  Nose nose = makeNose (21);
  PointSet& s = nose.set;
  const std::size_t first = s.size ();
  // (x, z): depth beyond the riser's plane and above the tread's.
  const std::vector<std::pair<float, float>> outside{{-0.002f, 0.006f}, {-0.008f, 0.003f}, {-0.005f, 0.0045f},
                                                     {-0.001f, 0.011f}, {-0.003f, 0.02f},  {-0.015f, 0.002f}};
  for (std::size_t t = 0; t < outside.size (); ++t)
    addSample (s, {outside[t].first, 0.02f + 0.03f * static_cast<float> (t), outside[t].second}, {0.f, 0.f, 1.f});
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 12);
  const std::vector<std::uint32_t> start = nearestLabels (s, nose.planes);
  std::vector<std::uint32_t> on = start, off = start;
  std::vector<PlanarPatch> p_on = patchesOf (on, nose.planes), p_off = patchesOf (off, nose.planes);
  const EdgeSideCounts c_on = settleEdgeSides (s, g, {0.012, 0.012}, 1, p_on, on, true, true);
  const EdgeSideCounts c_off = settleEdgeSides (s, g, {0.012, 0.012}, 1, p_off, off, true, false);
  // Farther from the tread (z > -x): the tread; farther from the riser: the riser; beyond a band
  // (1.2 cm): none.
  const std::vector<std::uint32_t> expected{0, 1, 1, 0, kNoPatch, kNoPatch};
  for (std::size_t t = 0; t < outside.size (); ++t)
  {
    EXPECT_EQ (on[first + t], expected[t]) << t;
    EXPECT_EQ (off[first + t], kNoPatch) << t;
  }
  EXPECT_EQ (c_on.outside, 4u);
  EXPECT_EQ (c_off.outside, 0u);
  EXPECT_EQ (c_off.released, c_on.released + 4u);
  // Elsewhere the two agree.
  for (std::size_t i = 0; i < first; ++i)
    EXPECT_EQ (on[i], off[i]) << i;
  for (std::uint32_t l = 0; l < 2; ++l)
    for (const auto m : p_on[l].members)
      EXPECT_EQ (on[m], l);
}

TEST (EdgeSides, SamplesBeyondTheLineStayWithTheirPlaneWithinItsOwnBand)
{
  // The riser noisier than the tread (bands 3 cm and 1.2 cm): a riser sample above the nose (z > 0)
  // and beyond the tread's band lies where the tread's noise does not reach; the riser's noise
  // across its edge does, up to the riser's band. With wedges on it stays with the riser there and
  // goes to none beyond; with wedges off both go to none.
  Nose nose = makeNose (31);
  PointSet& s = nose.set;
  const std::size_t first = s.size ();
  for (const float z : {0.02f, 0.04f})
    addSample (s, {0.003f, 0.1f + 2.0f * z, z}, {1.f, 0.f, 0.f});
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 12);
  const std::vector<std::uint32_t> start = nearestLabels (s, nose.planes);
  ASSERT_EQ (start[first], 1u);
  ASSERT_EQ (start[first + 1], 1u);
  std::vector<std::uint32_t> on = start, off = start;
  std::vector<PlanarPatch> p_on = patchesOf (on, nose.planes), p_off = patchesOf (off, nose.planes);
  settleEdgeSides (s, g, {0.012, 0.03}, 1, p_on, on, true, true);
  settleEdgeSides (s, g, {0.012, 0.03}, 1, p_off, off, true, false);
  EXPECT_EQ (on[first], 1u);
  EXPECT_EQ (on[first + 1], kNoPatch);
  EXPECT_EQ (off[first], kNoPatch);
  EXPECT_EQ (off[first + 1], kNoPatch);
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

namespace
{
/** A wall z = 0 over [0, 1] x [0, 0.4] around a panel over x in [0.4, 0.6] at z = depth, 1 cm grid,
  * noise 5 mm along z (band 1.5 cm); labelled as if the wall had grown first: the wall (plane 0) holds
  * its own samples and the panel's within its band, the panel (plane 1) the rest of its own. */
struct Recess
{
  PointSet set;
  std::vector<bool> in_panel;
  std::vector<PlanarPatch> planes;
  std::vector<std::uint32_t> labels;
};

Recess
makeRecess (float depth, std::uint32_t seed)
{
  Recess r;
  rspd_test::addRectangle (r.set, {0, 0, 0}, {0.4f, 0, 0}, {0, 0.4f, 0}, 40, 40, 0.005f, seed);
  r.in_panel.assign (r.set.size (), false);
  rspd_test::addRectangle (r.set, {0.4f, 0, depth}, {0.2f, 0, 0}, {0, 0.4f, 0}, 20, 40, 0.005f, seed + 1);
  r.in_panel.resize (r.set.size (), true);
  rspd_test::addRectangle (r.set, {0.6f, 0, 0}, {0.4f, 0, 0}, {0, 0.4f, 0}, 40, 40, 0.005f, seed + 2);
  r.in_panel.resize (r.set.size (), false);
  r.labels.resize (r.set.size ());
  for (std::size_t i = 0; i < r.set.size (); ++i)
    r.labels[i] = r.in_panel[i] && std::abs (r.set.points[i].z ()) > 0.015f ? 1 : 0;
  r.planes = patchesOf (r.labels, {rspd_test::makePatch ({0}, {0, 0, 0}, {0, 0, 1}, 0.015, 0.1),
                                   rspd_test::makePatch ({1600}, {0, 0, depth}, {0, 0, 1}, 0.015, 0.1)});
  return r;
}
} // namespace

TEST (StepSides, RecessedPanelTakesItsSamplesBackFromTheWall)
{
  // 2 cm deep, 1.5 cm bands: the wall holds the panel's samples within 1.5 cm of it (a sixth).
  Recess r = makeRecess (0.02f, 11);
  const NeighborGraph g = rspd_test::bruteForceGraph (r.set.points, 12);
  std::size_t wrong_before = 0, panel_in_both_bands = 0;
  for (std::size_t i = 0; i < r.set.size (); ++i)
  {
    wrong_before += r.labels[i] != (r.in_panel[i] ? 1u : 0u);
    panel_in_both_bands += r.in_panel[i] && r.labels[i] == 0 && r.set.points[i].z () >= 0.005f;
  }
  ASSERT_GT (panel_in_both_bands, 50u);
  const std::vector<std::uint32_t> before = r.labels;

  // As the detector runs it: passes until none moves a sample (the first leaves clusters of the
  // wall's samples that hold each other).
  std::size_t moved = 0, passes = 0;
  for (std::size_t m = 1; m > 0 && passes < 8; ++passes)
    moved += m = settleStepSides (r.set, g, {0.015, 0.015}, 1, r.planes, r.labels);
  EXPECT_LT (passes, 8u);
  std::size_t wrong_after = 0;
  for (std::size_t i = 0; i < r.set.size (); ++i)
  {
    wrong_after += r.labels[i] != (r.in_panel[i] ? 1u : 0u);
    if (!r.in_panel[i] && before[i] == 0)
      EXPECT_EQ (r.labels[i], 0u) << i; // the wall's own samples beside the panel stay
  }
  EXPECT_GE (moved, panel_in_both_bands * 9 / 10);
  EXPECT_LT (wrong_after * 10, wrong_before);
  for (std::uint32_t l = 0; l < 2; ++l)
    for (const auto m : r.planes[l].members)
      EXPECT_EQ (r.labels[m], l);
}

TEST (StepSides, StepWithinTheBandsIsLeftAlone)
{
  // 1 cm deep against 1.5 cm bands: one surface as far as nearness can tell.
  Recess r = makeRecess (0.01f, 21);
  const NeighborGraph g = rspd_test::bruteForceGraph (r.set.points, 12);
  const std::vector<std::uint32_t> before = r.labels;
  EXPECT_EQ (settleStepSides (r.set, g, {0.015, 0.015}, 1, r.planes, r.labels), 0u);
  EXPECT_EQ (r.labels, before);
}

TEST (StepSides, EdgesAreLeftToTheEdgeSideRule)
{
  // Planes that meet along a line are not a step.
  Nose nose = makeNose (9);
  const NeighborGraph g = rspd_test::bruteForceGraph (nose.set.points, 12);
  std::vector<std::uint32_t> labels = nearestLabels (nose.set, nose.planes);
  std::vector<PlanarPatch> patches = patchesOf (labels, nose.planes);
  const std::vector<std::uint32_t> before = labels;
  EXPECT_EQ (settleStepSides (nose.set, g, {0.012, 0.012}, 1, patches, labels), 0u);
  EXPECT_EQ (labels, before);
}

TEST (StepSides, ResultDoesNotDependOnTheThreadCount)
{
  Recess one = makeRecess (0.02f, 31), two = one;
  const NeighborGraph g = rspd_test::bruteForceGraph (one.set.points, 12);
  settleStepSides (one.set, g, {0.015, 0.015}, 1, one.planes, one.labels);
  settleStepSides (two.set, g, {0.015, 0.015}, 2, two.planes, two.labels);
  EXPECT_EQ (one.labels, two.labels);
  for (std::size_t l = 0; l < 2; ++l)
    EXPECT_EQ (one.planes[l].members, two.planes[l].members);
}
