/*
 * Tests of the step split (departure, splitSteps): a region offset parallel to the rest of its plane,
 * by less than the plane's noise band, is split off; bowls, strips and flat planes are not. And of
 * planes across a step (dropPlanesAcrossSteps): a strip bridging a step is dropped, a ramp is not. And
 * of step regions (settleStepRegions): a block of a door that its wall holds goes to the door.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/edge_sides.h>
#include <pcl_rspd/patch_growth.h>
#include <pcl_rspd/step_split.h>

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <functional>
#include <random>

using namespace pcl::rspd;

namespace
{
/** A 60 x 60 grid, 3 cm apart, in the plane z = 0 (1.8 m square), its height given by \a height
  * plus Gaussian noise \a sigma along z; exact normals (0, 0, 1). One patch holds every sample. */
struct Wall
{
  PointSet set;
  std::vector<PlanarPatch> patches;
  std::vector<char> raised; ///< per sample: whether \a height put it off z = 0
};

Wall
makeWall (const std::function<double (double, double)>& height, float sigma, std::uint32_t seed, float scale = 1.0f)
{
  Wall w;
  std::mt19937 rng (seed);
  std::normal_distribution<float> g (0.0f, 1.0f);
  std::vector<std::uint32_t> all;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j)
    {
      const double x = 0.03 * i, y = 0.03 * j, h = height (x, y);
      all.push_back (static_cast<std::uint32_t> (w.set.points.size ()));
      w.set.points.push_back (scale * Eigen::Vector3f (static_cast<float> (x), static_cast<float> (y), static_cast<float> (h) + sigma * g (rng)));
      w.set.normals.emplace_back (0.0f, 0.0f, 1.0f);
      w.set.input_indices.push_back (static_cast<pcl::index_t> (w.set.input_indices.size ()));
      w.raised.push_back (h != 0.0);
    }
  w.patches = {rspd_test::makePatch (all, {0, 0, 0}, {0, 0, 1}, 3.0 * sigma * scale, 0.1)};
  return w;
}

/** A 0.9 m square "door" (900 samples) 2 cm proud of the wall, away from its rim. A third of its
  * samples border the wall over k = 30 neighbours (a 0.6 m one, 400 samples, has half). */
double
door (double x, double y)
{
  return (x > 0.44 && x < 1.34 && y > 0.44 && y < 1.34) ? 0.02 : 0.0;
}

} // namespace

TEST (StepSplit, DoorProudOfItsWallWithinTheNoiseIsSplitOff)
{
  // 2 cm proud at σ = 1.5 cm: within the wall's band (4.5 cm); one sample's distance cannot tell,
  // its neighbourhood's mean can.
  Wall w = makeWall (door, 0.015f, 1);
  const NeighborGraph g = rspd_test::bruteForceGraph (w.set.points, 30);
  ASSERT_EQ (splitSteps (w.set, g, rspd_test::unitParameters (), w.patches), 1u);
  ASSERT_EQ (w.patches.size (), 2u);
  const PlanarPatch& rest = w.patches[0];
  const PlanarPatch& region = w.patches[1];
  EXPECT_EQ (rest.members.size () + region.members.size (), w.set.size ());
  std::size_t door_samples = 0, door_in_region = 0;
  for (std::size_t i = 0; i < w.set.size (); ++i)
    door_samples += w.raised[i];
  for (const auto i : region.members)
    door_in_region += w.raised[i];
  EXPECT_GE (door_in_region, 0.85 * door_samples) << door_in_region << " of " << door_samples;
  EXPECT_GE (door_in_region, 0.9 * region.members.size ()) << region.members.size ();
  // Both planes are parallel to the wall, 2 cm apart.
  EXPECT_GT (std::abs (region.normal.z ()), 0.999);
  EXPECT_GT (std::abs (rest.normal.z ()), 0.999);
  EXPECT_NEAR (region.center.z () - rest.center.z (), 0.02, 0.005);
  EXPECT_EQ (region.first_index, *std::min_element (region.members.begin (), region.members.end ()));
}

TEST (StepSplit, FlatPlaneIsNotSplit)
{
  Wall w = makeWall ([] (double, double) { return 0.0; }, 0.015f, 2);
  const NeighborGraph g = rspd_test::bruteForceGraph (w.set.points, 30);
  const std::vector<std::uint32_t> before = w.patches[0].members;
  EXPECT_EQ (splitSteps (w.set, g, rspd_test::unitParameters (), w.patches), 0u);
  ASSERT_EQ (w.patches.size (), 1u);
  EXPECT_EQ (w.patches[0].members, before);
}

TEST (StepSplit, BowedSurfaceIsNotSplit)
{
  // A bowl 4 cm deep over the wall's half-diagonal: its middle lies off the plane as a door would,
  // but its distance changes gradually across the region's border, where a step's changes at once.
  Wall w = makeWall ([] (double x, double y) { return 0.04 * ((x - 0.9) * (x - 0.9) + (y - 0.9) * (y - 0.9)) / 1.62 + 1e-9; },
                     0.01f, 3);
  const NeighborGraph g = rspd_test::bruteForceGraph (w.set.points, 30);
  EXPECT_EQ (splitSteps (w.set, g, rspd_test::unitParameters (), w.patches), 0u);
  EXPECT_EQ (w.patches.size (), 1u);
}

TEST (StepSplit, StripAlongTheRimIsNotSplit)
{
  // A strip two samples wide along one rim, 2 cm off: a step, but no region with an inside (every
  // sample borders the rest), as the strips that a next face's samples push off a wall's edge.
  Wall w = makeWall ([] (double x, double) { return x < 0.05 ? 0.02 : 0.0; }, 0.015f, 4);
  const NeighborGraph g = rspd_test::bruteForceGraph (w.set.points, 30);
  EXPECT_EQ (splitSteps (w.set, g, rspd_test::unitParameters (), w.patches), 0u);
}

TEST (StepSplit, RegionSmallerThanEpsilonIsNotSplit)
{
  Wall w = makeWall (door, 0.015f, 1);
  const NeighborGraph g = rspd_test::bruteForceGraph (w.set.points, 30);
  DetectorParameters p = rspd_test::unitParameters ();
  p.min_patch_size = 1000; // the door holds 900 samples
  EXPECT_EQ (splitSteps (w.set, g, p, w.patches), 0u);
}

TEST (StepSplit, SplitDoesNotDependOnScaleOrThreadCount)
{
  Wall a = makeWall (door, 0.015f, 5);
  Wall b = makeWall (door, 0.015f, 5, 1000.0f);
  Wall c = makeWall (door, 0.015f, 5);
  const NeighborGraph ga = rspd_test::bruteForceGraph (a.set.points, 30);
  const NeighborGraph gb = rspd_test::bruteForceGraph (b.set.points, 30);
  ASSERT_EQ (splitSteps (a.set, ga, rspd_test::unitParameters (1), a.patches), 1u);
  ASSERT_EQ (splitSteps (b.set, gb, rspd_test::unitParameters (1), b.patches), 1u);
  ASSERT_EQ (splitSteps (c.set, ga, rspd_test::unitParameters (2), c.patches), 1u);
  EXPECT_EQ (a.patches[1].members, b.patches[1].members);
  EXPECT_EQ (a.patches[1].members, c.patches[1].members);
  EXPECT_EQ (a.patches[0].members, c.patches[0].members);
}

TEST (StepSplit, NoPlanesAndNoiseFreePlanesAreLeftAlone)
{
  // No planes: nothing to judge. A noise-free wall has no robust σ to measure a region against (its
  // distances are all zero but the door's); such a door lies far outside the wall's band and is
  // seeded by the split, not by this pass.
  Wall w = makeWall (door, 0.0f, 1);
  const NeighborGraph g = rspd_test::bruteForceGraph (w.set.points, 30);
  std::vector<PlanarPatch> none;
  EXPECT_EQ (splitSteps (w.set, g, rspd_test::unitParameters (), none), 0u);
  EXPECT_TRUE (none.empty ());
  const std::vector<std::uint32_t> before = w.patches[0].members;
  EXPECT_EQ (splitSteps (w.set, g, rspd_test::unitParameters (), w.patches), 0u);
  ASSERT_EQ (w.patches.size (), 1u);
  EXPECT_EQ (w.patches[0].members, before);
}

// --- Planes across a step (dropPlanesAcrossSteps) ---------------------------------------------

namespace
{
/** The wall of makeWall with a step along x = 0.9 (z = 0 before it, \a rise after), cut into three
  * planes: A (x < 0.75, at z = 0), B (x > 1.05, at z = rise) and P between them. P's plane is its
  * least-squares plane unless \a p_normal is given; MND 0.03 rad for all three. */
struct Step
{
  Wall wall;
  std::vector<PlanarPatch> patches; ///< A, B, P
};

Step
makeStep (const std::function<double (double, double)>& height, double rise, float sigma, std::uint32_t seed,
          float scale = 1.0f, const Eigen::Vector3d* p_normal = nullptr)
{
  Step s{makeWall (height, sigma, seed, scale), {}};
  std::vector<std::uint32_t> a, b, p;
  for (std::uint32_t i = 0; i < s.wall.set.points.size (); ++i)
  {
    const float x = s.wall.set.points[i].x () / scale;
    (x < 0.75f ? a : x > 1.05f ? b : p).push_back (i);
  }
  // P's least-squares plane (centroid, smallest eigenvector), as a detector would fit the strip.
  Eigen::Vector3d c = Eigen::Vector3d::Zero ();
  for (const auto i : p)
    c += s.wall.set.points[i].cast<double> ();
  c /= static_cast<double> (p.size ());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero ();
  for (const auto i : p)
  {
    const Eigen::Vector3d d = s.wall.set.points[i].cast<double> () - c;
    cov += d * d.transpose ();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig (cov);
  const Eigen::Vector3d n = p_normal ? *p_normal : eig.eigenvectors ().col (0);
  const double band = 3.0 * sigma * scale;
  s.patches = {rspd_test::makePatch (a, {0, 0, 0}, {0, 0, 1}, band, 0.03),
               rspd_test::makePatch (b, {0, 0, rise * scale}, {0, 0, 1}, band, 0.03),
               rspd_test::makePatch (p, c, n, band, 0.03)};
  return s;
}

double
stepAt09 (double x, double)
{
  return x > 0.9 ? 0.02 : 0.0;
}

double
rampBetween (double x, double)
{
  // 3 cm over 0.75 < x < 1.05: a real sloped face between two parallel ones.
  return x <= 0.75 ? 0.0 : x >= 1.05 ? 0.03 : 0.1 * (x - 0.75);
}
} // namespace

namespace
{
/** The door wall at σ = 1.5 cm with the door \a height proud, shared as growth leaves a door within
  * the wall's band: the wall (plane 0) holds its own samples and those of the door's left half
  * (\a shared) or its own alone; the door (plane 1) the rest. Bands 3σ (4.5 cm). */
struct SharedDoor
{
  Wall w;
  std::vector<std::uint32_t> labels;
  std::vector<double> band;
};

SharedDoor
makeSharedDoor (double height, bool shared, std::uint32_t seed, float scale = 1.0f)
{
  SharedDoor d{makeWall ([height] (double x, double y) { return door (x, y) > 0.0 ? height : 0.0; }, 0.015f, seed, scale),
               {},
               {0.045 * scale, 0.045 * scale}};
  std::vector<std::uint32_t> wall, panel;
  for (std::uint32_t i = 0; i < d.w.set.size (); ++i)
    (d.w.raised[i] && (!shared || d.w.set.points[i].x () > 0.89f * scale) ? panel : wall).push_back (i);
  d.w.patches = {rspd_test::makePatch (wall, {0, 0, 0}, {0, 0, 1}, d.band[0], 0.1),
                 rspd_test::makePatch (panel, {0, 0, height * scale}, {0, 0, 1}, d.band[1], 0.1)};
  d.labels = labelSamples (d.w.set.size (), d.w.patches);
  return d;
}

/** Passes of settleStepRegions until none moves (at most 8), as the detector runs them. */
std::size_t
settleRegions (SharedDoor& d, const NeighborGraph& g, int threads = 1)
{
  std::size_t moved = 0;
  for (int pass = 0; pass < 8; ++pass)
  {
    const std::size_t m = settleStepRegions (d.w.set, g, d.band, threads, d.w.patches, d.labels);
    moved += m;
    if (m == 0)
      break;
  }
  return moved;
}

/** Door samples the wall holds, and wall samples the door holds. */
std::pair<std::size_t, std::size_t>
misplaced (const SharedDoor& d)
{
  std::size_t door_in_wall = 0, wall_in_door = 0;
  for (std::size_t i = 0; i < d.labels.size (); ++i)
  {
    door_in_wall += d.w.raised[i] && d.labels[i] == 0;
    wall_in_door += !d.w.raised[i] && d.labels[i] == 1;
  }
  return {door_in_wall, wall_in_door};
}
} // namespace

TEST (StepRegions, ABlockOfTheDoorThatTheWallHoldsGoesToTheDoor)
{
  // 3 cm proud, 2σ: within both bands, where the step sides move no sample, and the block's samples
  // are each other's neighbours.
  SharedDoor d = makeSharedDoor (0.03, true, 61);
  const NeighborGraph g = rspd_test::bruteForceGraph (d.w.set.points, 30);
  const auto before = misplaced (d);
  ASSERT_GT (before.first, 400u); // the door's left half
  EXPECT_GT (settleRegions (d, g), 0u);
  const auto after = misplaced (d);
  EXPECT_LT (after.first, before.first / 10) << after.first;
  EXPECT_LT (after.second, 60u) << after.second; // the wall's samples along the door's rim
  for (std::uint32_t l = 0; l < 2; ++l)
    for (const auto m : d.w.patches[l].members)
      EXPECT_EQ (d.labels[m], l);
}

TEST (StepRegions, WallBesideTheDoorKeepsItsSamples)
{
  // Each plane holds its own: the wall's noise beside the door lies off it toward the door, but a
  // fraction of σ off, nearer the wall than the door.
  SharedDoor d = makeSharedDoor (0.03, false, 62);
  const NeighborGraph g = rspd_test::bruteForceGraph (d.w.set.points, 30);
  const std::vector<std::uint32_t> before = d.labels;
  settleRegions (d, g);
  const auto after = misplaced (d);
  EXPECT_LT (after.first + after.second, 10u) << after.first << " " << after.second;
}

TEST (StepRegions, StepBeyondTheBandsIsLeftToTheStepSides)
{
  // 6 cm proud, beyond the 4.5 cm bands: distance tells each sample's plane (settleStepSides).
  SharedDoor d = makeSharedDoor (0.06, true, 63);
  const NeighborGraph g = rspd_test::bruteForceGraph (d.w.set.points, 30);
  const std::vector<std::uint32_t> before = d.labels;
  EXPECT_EQ (settleStepRegions (d.w.set, g, d.band, 1, d.w.patches, d.labels), 0u);
  EXPECT_EQ (d.labels, before);
}

TEST (StepRegions, WithinTheBandsSamplesFollowTheirNeighbours)
{
  // Each sample labelled by the nearer plane, as distance alone would: the wall's samples in its
  // upper tail (more than 1.5 cm up, a sixth of them, all over the wall) sit in the door, and the
  // door's lower tail in the wall. The step sides' majority of neighbours, asked within the bands
  // too (as the detector does once the step regions have run; there, twice as many neighbours in
  // the other plane as in the sample's own), puts them back; by default it leaves planes offset
  // within the bands alone.
  SharedDoor d = makeSharedDoor (0.03, false, 65);
  const NeighborGraph g = rspd_test::bruteForceGraph (d.w.set.points, 30);
  for (std::size_t i = 0; i < d.labels.size (); ++i)
    d.labels[i] = d.w.set.points[i].z () > 0.015f ? 1 : 0;
  membersFromLabels (d.labels, d.w.patches);
  const auto before = misplaced (d);
  ASSERT_GT (before.first + before.second, 400u);
  SharedDoor untouched = d;
  EXPECT_EQ (settleStepSides (untouched.w.set, g, untouched.band, 1, untouched.w.patches, untouched.labels), 0u);
  // Passes until none moves, at most 8, as the detector runs them.
  std::size_t last = 1;
  for (int pass = 0; last > 0 && pass < 8; ++pass)
    last = settleStepSides (d.w.set, g, d.band, 1, d.w.patches, d.labels, true);
  EXPECT_EQ (last, 0u);
  const auto after = misplaced (d);
  EXPECT_LT (after.first + after.second, (before.first + before.second) / 10) << after.first << " " << after.second;
}

TEST (StepRegions, ResultDoesNotDependOnScaleOrThreadCount)
{
  SharedDoor a = makeSharedDoor (0.03, true, 64);
  SharedDoor b = makeSharedDoor (0.03, true, 64, 1000.0f);
  SharedDoor c = makeSharedDoor (0.03, true, 64);
  const NeighborGraph ga = rspd_test::bruteForceGraph (a.w.set.points, 30);
  const NeighborGraph gb = rspd_test::bruteForceGraph (b.w.set.points, 30);
  const std::size_t moved = settleRegions (a, ga, 1);
  EXPECT_GT (moved, 0u);
  EXPECT_EQ (settleRegions (b, gb, 1), moved);
  EXPECT_EQ (settleRegions (c, ga, 2), moved);
  EXPECT_EQ (a.labels, b.labels);
  EXPECT_EQ (a.labels, c.labels);
}

TEST (AcrossSteps, StripAcrossADoorsEdgeIsDropped)
{
  // The strip holds the wall's and the door's samples either side of a 2 cm step at σ = 3 mm: its
  // least-squares plane is tilted about 5.7°, past the MNDs, and the nearer of the wall and the door
  // explains each sample better than the strip's own plane does.
  Step s = makeStep (stepAt09, 0.02, 0.003f, 3);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.wall.set.points, 30);
  const std::vector<std::uint32_t> a = s.patches[0].members, b = s.patches[1].members;
  EXPECT_EQ (dropPlanesAcrossSteps (s.wall.set, g, rspd_test::unitParameters (), s.patches), 1u);
  ASSERT_EQ (s.patches.size (), 2u);
  EXPECT_EQ (s.patches[0].members, a); // the planes kept keep their order and members
  EXPECT_EQ (s.patches[1].members, b);
}

TEST (AcrossSteps, SlopedFaceBetweenParallelPlanesStays)
{
  // A ramp rising 3 cm between the two parallel planes lies on its own plane (σ 3 mm) and up to
  // 1.5 cm from the nearer of the others (robust σ about 11 mm).
  Step s = makeStep (rampBetween, 0.03, 0.003f, 4);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.wall.set.points, 30);
  EXPECT_EQ (dropPlanesAcrossSteps (s.wall.set, g, rspd_test::unitParameters (), s.patches), 0u);
  EXPECT_EQ (s.patches.size (), 3u);
}

TEST (AcrossSteps, OnlyAParallelPairNotParallelToThePlaneExplainsIt)
{
  // The same strip given the wall's normal: parallel to both (M2), so no pair may explain it away
  // (it may be another window of a facade, coplanar with one beside it).
  const Eigen::Vector3d up (0, 0, 1);
  Step flat = makeStep (stepAt09, 0.02, 0.003f, 3, 1.0f, &up);
  const NeighborGraph g = rspd_test::bruteForceGraph (flat.wall.set.points, 30);
  EXPECT_EQ (dropPlanesAcrossSteps (flat.wall.set, g, rspd_test::unitParameters (), flat.patches), 0u);
  // The strip beside two planes that meet at an edge (B turned upright): the distances to both
  // vanish along their edge, so such a pair explains nothing either.
  Step edge = makeStep (stepAt09, 0.02, 0.003f, 3);
  edge.patches[1] = rspd_test::makePatch (edge.patches[1].members, {1.05, 0, 0}, {1, 0, 0}, 0.009, 0.03);
  EXPECT_EQ (dropPlanesAcrossSteps (edge.wall.set, g, rspd_test::unitParameters (), edge.patches), 0u);
  EXPECT_EQ (edge.patches.size (), 3u);
  // Fewer than three planes: nothing to judge.
  edge.patches.pop_back ();
  EXPECT_EQ (dropPlanesAcrossSteps (edge.wall.set, g, rspd_test::unitParameters (), edge.patches), 0u);
}

TEST (AcrossSteps, VerdictDoesNotDependOnScaleOrThreadCount)
{
  for (const float scale : {1.0f, 1000.0f})
    for (const int threads : {1, 2})
    {
      Step s = makeStep (stepAt09, 0.02, 0.003f, 3, scale);
      const NeighborGraph g = rspd_test::bruteForceGraph (s.wall.set.points, 30);
      EXPECT_EQ (dropPlanesAcrossSteps (s.wall.set, g, rspd_test::unitParameters (threads), s.patches), 1u)
          << scale << " " << threads;
      Step r = makeStep (rampBetween, 0.03, 0.003f, 4, scale);
      const NeighborGraph rg = rspd_test::bruteForceGraph (r.wall.set.points, 30);
      EXPECT_EQ (dropPlanesAcrossSteps (r.wall.set, rg, rspd_test::unitParameters (threads), r.patches), 0u)
          << scale << " " << threads;
    }
}
