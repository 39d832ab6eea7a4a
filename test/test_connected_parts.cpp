/*
 * Tests of the connected-parts split (departure, splitDisconnectedPlanes).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/connected_parts.h>
#include <pcl_rspd/patch_growth.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace pcl::rspd;

namespace
{
/** Two 0.5 m squares of one plane z = 0, 0.2 m apart along x, and a strip of samples of a surface
  * crossing the gap (normals 45° off the plane), all held by one plane. */
struct Bridged
{
  PointSet set;
  std::vector<std::uint32_t> left, right, bridge;
};

Bridged
makeBridged (int bridge_samples)
{
  Bridged b;
  b.left = rspd_test::addRectangle (b.set, {0, 0, 0}, {0.5f, 0, 0}, {0, 0.5f, 0}, 25, 25);
  b.right = rspd_test::addRectangle (b.set, {0.7f, 0, 0}, {0.5f, 0, 0}, {0, 0.5f, 0}, 25, 25);
  for (int t = 0; t < bridge_samples; ++t)
  {
    b.bridge.push_back (static_cast<std::uint32_t> (b.set.size ()));
    b.set.points.emplace_back (0.5f + 0.2f * (t + 0.5f) / bridge_samples, 0.25f, 0.0f);
    b.set.normals.push_back (Eigen::Vector3f (1, 0, 1).normalized ());
    b.set.input_indices.push_back (static_cast<pcl::index_t> (b.set.input_indices.size ()));
  }
  return b;
}

/** The bridge's samples given the plane's own normal: they pass its inlier test. */
void
bridgeOfInliers (Bridged& b)
{
  for (const auto i : b.bridge)
    b.set.normals[i] = Eigen::Vector3f::UnitZ ();
}

/** The left square in plane 0, the right one in plane 1. */
void
expectSquaresApart (const Bridged& b, const std::vector<std::uint32_t>& labels)
{
  for (const auto i : b.left)
    EXPECT_EQ (labels[i], 0u) << i;
  for (const auto i : b.right)
    EXPECT_EQ (labels[i], 1u) << i;
}

std::vector<PlanarPatch>
onePlane (std::size_t n)
{
  return rspd_test::onePatchOfAll (n, 0.01, 0.1);
}

} // namespace

TEST (ConnectedParts, PlaneBridgedByAnotherSurfaceIsSplitIntoItsParts)
{
  const Bridged b = makeBridged (20);
  const NeighborGraph g = rspd_test::bruteForceGraph (b.set.points, 8);
  std::vector<PlanarPatch> patches = onePlane (b.set.size ());
  std::vector<std::uint32_t> labels = labelSamples (b.set.size (), patches);
  EXPECT_EQ (splitDisconnectedPlanes (b.set, g, rspd_test::unitParameters (1), patches, labels), 1u);
  ASSERT_EQ (patches.size (), 2u);
  // Equal parts: the one holding the lower sample keeps the plane's place.
  expectSquaresApart (b, labels);
  // The bridge's ends follow the part they neighbour, its left end the left square, its right end
  // the right; its middle, more than one hop from either, is released.
  EXPECT_EQ (labels[b.bridge.front ()], 0u);
  EXPECT_EQ (labels[b.bridge.back ()], 1u);
  EXPECT_EQ (labels[b.bridge[b.bridge.size () / 2]], kNoPatch);
  EXPECT_LT (patches[0].members.size () + patches[1].members.size (), b.set.size ());
  EXPECT_GE (patches[0].members.size () + patches[1].members.size (), b.left.size () + b.right.size ());
  for (std::uint32_t l = 0; l < 2; ++l)
  {
    EXPECT_TRUE (std::is_sorted (patches[l].members.begin (), patches[l].members.end ()));
    EXPECT_EQ (patches[l].first_index, patches[l].members.front ());
    EXPECT_NEAR (std::abs (patches[l].normal.z ()), 1.0, 1e-6); // each part estimated again
  }
}

TEST (ConnectedParts, BridgeOfInliersKeepsThePlaneWhole)
{
  // The same strip with the plane's own normal: inliers join the squares into one part.
  Bridged b = makeBridged (20);
  bridgeOfInliers (b);
  const NeighborGraph g = rspd_test::bruteForceGraph (b.set.points, 8);
  std::vector<PlanarPatch> patches = onePlane (b.set.size ());
  std::vector<std::uint32_t> labels = labelSamples (b.set.size (), patches);
  const std::vector<std::uint32_t> before = labels;
  EXPECT_EQ (splitDisconnectedPlanes (b.set, g, rspd_test::unitParameters (1), patches, labels), 0u);
  EXPECT_EQ (patches.size (), 1u);
  EXPECT_EQ (labels, before);
}

TEST (ConnectedParts, CluttersWebOfInliersIsNoPart)
{
  // The gap between the squares crossed by samples that pass the plane's inlier test (its normal, on
  // its plane), the middle ones in clutter: six samples no plane holds within 5 mm of each, so most
  // of their neighbours are outside the plane (outliers behind a facade, in its windows' band). They
  // are no core of a part, so the squares are two parts, and the web's middle is released.
  Bridged b = makeBridged (20);
  bridgeOfInliers (b);
  const std::size_t members = b.set.size ();
  for (std::size_t t = 3; t + 3 < b.bridge.size (); ++t) // the web's middle, clear of the squares
    for (int c = 0; c < 6; ++c)
    {
      const float a = static_cast<float> (c) * 1.0472f; // 60 degrees apart, across the gap
      const Eigen::Vector3f at = b.set.points[b.bridge[t]];
      b.set.points.push_back (at + Eigen::Vector3f (0, 0.004f * std::cos (a), 0.004f * std::sin (a)));
      b.set.normals.push_back (Eigen::Vector3f::UnitY ());
      b.set.input_indices.push_back (static_cast<pcl::index_t> (b.set.input_indices.size ()));
    }
  const NeighborGraph g = rspd_test::bruteForceGraph (b.set.points, 8);
  std::vector<PlanarPatch> patches = onePlane (members); // the added samples in no plane
  std::vector<std::uint32_t> labels = labelSamples (b.set.size (), patches);
  EXPECT_EQ (splitDisconnectedPlanes (b.set, g, rspd_test::unitParameters (1), patches, labels), 1u);
  ASSERT_EQ (patches.size (), 2u);
  expectSquaresApart (b, labels);
  EXPECT_EQ (labels[b.bridge[b.bridge.size () / 2]], kNoPatch);
  for (std::size_t i = members; i < b.set.size (); ++i)
    EXPECT_EQ (labels[i], kNoPatch) << i; // the clutter stays in no plane
}

TEST (ConnectedParts, PartsOfClutterAreNoPiecesOfSurface)
{
  // The bridged squares again, but every sample of theirs has a twin 1 mm above it that no plane
  // holds, as samples of a plane of clutter have neighbours outside it: each part passes the core
  // test (about half of each sample's neighbours in the plane) but its median sample has less than
  // three quarters, so the parts are no pieces of surface and the plane is left whole.
  Bridged b = makeBridged (20);
  const std::size_t members = b.set.size ();
  std::vector<std::uint32_t> squares = b.left;
  squares.insert (squares.end (), b.right.begin (), b.right.end ());
  for (const auto i : squares)
  {
    const Eigen::Vector3f at = b.set.points[i];
    b.set.points.push_back (at + Eigen::Vector3f (0, 0, 0.001f));
    b.set.normals.push_back (Eigen::Vector3f::UnitZ ());
    b.set.input_indices.push_back (static_cast<pcl::index_t> (b.set.input_indices.size ()));
  }
  const NeighborGraph g = rspd_test::bruteForceGraph (b.set.points, 8);
  std::vector<PlanarPatch> patches = onePlane (members); // the added samples in no plane
  std::vector<std::uint32_t> labels = labelSamples (b.set.size (), patches);
  const std::vector<std::uint32_t> before = labels;
  EXPECT_EQ (splitDisconnectedPlanes (b.set, g, rspd_test::unitParameters (1), patches, labels), 0u);
  EXPECT_EQ (patches.size (), 1u);
  EXPECT_EQ (labels, before);
}

TEST (ConnectedParts, PartsSmallerThanEpsilonStayWithThePlane)
{
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {0.5f, 0, 0}, {0, 0.5f, 0}, 25, 25);
  rspd_test::addRectangle (s, {0.7f, 0, 0}, {0.1f, 0, 0}, {0, 0.1f, 0}, 5, 5); // 25 < ε = 50
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 8);
  std::vector<PlanarPatch> patches = onePlane (s.size ());
  std::vector<std::uint32_t> labels = labelSamples (s.size (), patches);
  EXPECT_EQ (splitDisconnectedPlanes (s, g, rspd_test::unitParameters (1), patches, labels), 0u);
  EXPECT_EQ (patches[0].members.size (), s.size ());
}

TEST (ConnectedParts, NoSamplesOrNoPlaneChangesNothing)
{
  // Bad input: an empty set, and samples no plane holds (a scene where nothing was found).
  PointSet empty;
  std::vector<PlanarPatch> none;
  std::vector<std::uint32_t> no_labels;
  EXPECT_EQ (splitDisconnectedPlanes (empty, NeighborGraph (), rspd_test::unitParameters (1), none, no_labels), 0u);
  EXPECT_TRUE (none.empty ());
  const Bridged b = makeBridged (20);
  const NeighborGraph g = rspd_test::bruteForceGraph (b.set.points, 8);
  std::vector<std::uint32_t> labels (b.set.size (), kNoPatch);
  EXPECT_EQ (splitDisconnectedPlanes (b.set, g, rspd_test::unitParameters (1), none, labels), 0u);
  EXPECT_TRUE (none.empty ());
  EXPECT_EQ (std::count (labels.begin (), labels.end (), kNoPatch), static_cast<std::ptrdiff_t> (b.set.size ()));
  // The same with the final parts' release of strays: nothing to release, and the count says so.
  std::size_t strays = 99;
  EXPECT_EQ (splitDisconnectedPlanes (empty, NeighborGraph (), rspd_test::unitParameters (1), none, no_labels, true, &strays), 0u);
  EXPECT_EQ (strays, 0u);
  strays = 99;
  EXPECT_EQ (splitDisconnectedPlanes (b.set, g, rspd_test::unitParameters (1), none, labels, true, &strays), 0u);
  EXPECT_EQ (strays, 0u);
  EXPECT_TRUE (none.empty ());
  EXPECT_EQ (std::count (labels.begin (), labels.end (), kNoPatch), static_cast<std::ptrdiff_t> (b.set.size ()));
}

TEST (ConnectedParts, ResultDoesNotDependOnTheThreadCount)
{
  const Bridged b = makeBridged (20);
  const NeighborGraph g = rspd_test::bruteForceGraph (b.set.points, 8);
  std::vector<PlanarPatch> p1 = onePlane (b.set.size ()), p2 = p1;
  std::vector<std::uint32_t> l1 = labelSamples (b.set.size (), p1), l2 = l1;
  splitDisconnectedPlanes (b.set, g, rspd_test::unitParameters (1), p1, l1);
  splitDisconnectedPlanes (b.set, g, rspd_test::unitParameters (2), p2, l2);
  EXPECT_EQ (l1, l2);
  ASSERT_EQ (p1.size (), p2.size ());
  for (std::size_t l = 0; l < p1.size (); ++l)
    EXPECT_EQ (p1[l].members, p2[l].members);
}

namespace
{
/** A 0.5 m square of 625 samples and, 0.2 m beside it on its plane, a 0.1 m square of 25 (fewer than
  * ε = 50), joined by \a bridge samples along the line between them (none: apart), all in one plane. */
PointSet
squareAndStray (int bridge)
{
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {0.5f, 0, 0}, {0, 0.5f, 0}, 25, 25);
  rspd_test::addRectangle (s, {0.7f, 0.2f, 0}, {0.1f, 0, 0}, {0, 0.1f, 0}, 5, 5);
  for (int t = 0; t < bridge; ++t)
  {
    s.points.emplace_back (0.5f + 0.2f * (t + 0.5f) / bridge, 0.25f, 0.0f);
    s.normals.push_back (Eigen::Vector3f (1, 0, 1).normalized ()); // no inliers: not even core
    s.input_indices.push_back (static_cast<pcl::index_t> (s.input_indices.size ()));
  }
  return s;
}
} // namespace

TEST (ConnectedParts, FinalPartsReleaseWhatNoChainOfMembersJoinsToTheOnlyPiece)
{
  // One piece of surface and a small square apart from it: the connected parts leave the plane as
  // it is (PartsSmallerThanEpsilonStayWithThePlane); the final parts (release_strays) release the
  // square, which no chain of the plane's members joins to the piece.
  const PointSet s = squareAndStray (0);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 8);
  std::vector<PlanarPatch> patches = onePlane (s.size ());
  std::vector<std::uint32_t> labels = labelSamples (s.size (), patches);
  std::size_t strays = 99;
  EXPECT_EQ (splitDisconnectedPlanes (s, g, rspd_test::unitParameters (1), patches, labels, true, &strays), 0u);
  EXPECT_EQ (strays, 25u);
  ASSERT_EQ (patches.size (), 1u);
  EXPECT_EQ (patches[0].members.size (), 625u);
  EXPECT_TRUE (std::is_sorted (patches[0].members.begin (), patches[0].members.end ()));
  EXPECT_EQ (patches[0].first_index, 0u);
  for (std::size_t i = 0; i < s.size (); ++i)
    EXPECT_EQ (labels[i], i < 625 ? 0u : kNoPatch) << i;
}

TEST (ConnectedParts, FinalPartsKeepWhatAChainOfAnyMembersJoins)
{
  // The same square joined to the piece by a line of members that fail the inlier test (no core
  // samples, no part of their own): the chain is the plane's, so nothing is released. And a plane
  // of two pieces is split as the connected parts split it.
  const PointSet s = squareAndStray (20);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 8);
  std::vector<PlanarPatch> patches = onePlane (s.size ());
  std::vector<std::uint32_t> labels = labelSamples (s.size (), patches);
  const std::vector<std::uint32_t> before = labels;
  std::size_t strays = 99;
  EXPECT_EQ (splitDisconnectedPlanes (s, g, rspd_test::unitParameters (1), patches, labels, true, &strays), 0u);
  EXPECT_EQ (strays, 0u);
  EXPECT_EQ (labels, before);

  const Bridged b = makeBridged (20);
  const NeighborGraph gb = rspd_test::bruteForceGraph (b.set.points, 8);
  std::vector<PlanarPatch> split = onePlane (b.set.size ()), last = split;
  std::vector<std::uint32_t> split_labels = labelSamples (b.set.size (), split), last_labels = split_labels;
  EXPECT_EQ (splitDisconnectedPlanes (b.set, gb, rspd_test::unitParameters (1), split, split_labels), 1u);
  EXPECT_EQ (splitDisconnectedPlanes (b.set, gb, rspd_test::unitParameters (1), last, last_labels, true, &strays), 1u);
  EXPECT_EQ (strays, 0u);
  EXPECT_EQ (split_labels, last_labels);
}

TEST (ConnectedParts, FinalPartsDoNotDependOnScaleOrThreadCount)
{
  PointSet s = squareAndStray (0);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 8);
  std::vector<PlanarPatch> p1 = onePlane (s.size ()), p2 = p1;
  std::vector<std::uint32_t> l1 = labelSamples (s.size (), p1), l2 = l1;
  splitDisconnectedPlanes (s, g, rspd_test::unitParameters (1), p1, l1, true);
  splitDisconnectedPlanes (s, g, rspd_test::unitParameters (2), p2, l2, true);
  EXPECT_EQ (l1, l2);
  // ×1000 and 1 km away: the same graph, the plane's band and centre with it.
  for (auto& p : s.points)
    p = 1000.0f * p + Eigen::Vector3f (1000.0f, 0, 0);
  std::vector<std::uint32_t> all (s.size ());
  for (std::uint32_t i = 0; i < s.size (); ++i)
    all[i] = i;
  std::vector<PlanarPatch> p3 {rspd_test::makePatch (all, {1000.0, 0, 0}, {0, 0, 1}, 10.0, 0.1)};
  std::vector<std::uint32_t> l3 = labelSamples (s.size (), p3);
  splitDisconnectedPlanes (s, rspd_test::bruteForceGraph (s.points, 8), rspd_test::unitParameters (1), p3, l3, true);
  EXPECT_EQ (l1, l3);
}
