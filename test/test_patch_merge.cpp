/*
 * Tests of the merge phase (Sec. 3.4): M1, M2, M3 on a scene like the paper's Fig. 5.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/patch_growth.h>
#include <pcl_rspd/patch_merge.h>

#include <gtest/gtest.h>

using namespace pcl::rspd;

TEST (UnionFind, JoinsTransitivelyAndIndependentlyOfOrder)
{
  UnionFind a (5), b (5);
  a.unite (0, 1); a.unite (3, 4); a.unite (1, 4);
  b.unite (4, 1); b.unite (4, 3); b.unite (1, 0);
  for (std::uint32_t i = 0; i < 5; ++i)
    EXPECT_EQ (a.find (i), b.find (i));
  EXPECT_EQ (a.find (3), a.find (0));
  EXPECT_NE (a.find (2), a.find (0));
  EXPECT_FALSE (a.unite (0, 4));
}

TEST (PatchMerge, FigureFiveConditions)
{
  // A: vertical wall x = 0 (normal x). B: floor strip next to it (normal z), adjacent to A.
  // C: floor strip next to B, 5 cm higher (parallel to B, adjacent, but no sample within MDP).
  // D: floor strip continuing C at the same height (coplanar, adjacent): C and D merge.
  // E: a strip coplanar with D far away (not adjacent, no edge): D and E stay apart.
  PointSet s;
  const auto A = rspd_test::addRectangle (s, {0, 0, 0}, {0, 1, 0}, {0, 0, 0.5f}, 20, 10);
  const auto B = rspd_test::addRectangle (s, {0.025f, 0, 0}, {0.5f, 0, 0}, {0, 1, 0}, 10, 20);
  const auto C = rspd_test::addRectangle (s, {0.55f, 0, 0.05f}, {0.5f, 0, 0}, {0, 1, 0}, 10, 20);
  const auto D = rspd_test::addRectangle (s, {1.05f, 0, 0.05f}, {0.5f, 0, 0}, {0, 1, 0}, 10, 20);
  const auto E = rspd_test::addRectangle (s, {5.0f, 0, 0.05f}, {0.5f, 0, 0}, {0, 1, 0}, 10, 20);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 12);
  const double mdp = 0.01, mnd = 0.1;
  std::vector<PlanarPatch> patches{
      rspd_test::makePatch (A, {0, 0.5, 0.25}, {1, 0, 0}, mdp, mnd), rspd_test::makePatch (B, {0.25, 0.5, 0}, {0, 0, 1}, mdp, mnd),
      rspd_test::makePatch (C, {0.8, 0.5, 0.05}, {0, 0, 1}, mdp, mnd), rspd_test::makePatch (D, {1.3, 0.5, 0.05}, {0, 0, 1}, mdp, mnd),
      rspd_test::makePatch (E, {5.25, 0.5, 0.05}, {0, 0, 1}, mdp, mnd)};
  EXPECT_FALSE (normalsCompatible (patches[0], patches[1])); // A-B fail M2
  EXPECT_TRUE (normalsCompatible (patches[1], patches[2]));  // B-C pass M2, fail M3
  auto labels = labelSamples (s.size (), patches);
  const std::size_t absorbed = mergePatches (s, g, patches, labels);
  EXPECT_EQ (absorbed, 1u);
  ASSERT_EQ (patches.size (), 4u);
  // C and D had equal size: C (lower first index) represents the group and keeps its plane.
  EXPECT_EQ (patches[2].members.size (), C.size () + D.size ());
  EXPECT_DOUBLE_EQ (patches[2].center.x (), 0.8);
  EXPECT_EQ (patches[2].estimate_size, C.size ()) << "merged patch: caller decides on re-estimation";
  for (const auto i : D)
    EXPECT_EQ (labels[i], 2u);
  for (const auto i : E)
    EXPECT_EQ (labels[i], 3u);
  for (const auto i : A)
    EXPECT_EQ (labels[i], 0u);
}

TEST (PatchMerge, LargestPatchRepresentsTheGroup)
{
  PointSet s;
  const auto a = rspd_test::addRectangle (s, {0, 0, 0}, {0.3f, 0, 0}, {0, 1, 0}, 6, 20);
  const auto b = rspd_test::addRectangle (s, {0.3f, 0, 0}, {0.7f, 0, 0}, {0, 1, 0}, 14, 20);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 10);
  std::vector<PlanarPatch> patches{rspd_test::makePatch (a, {0.1, 0.5, 0}, {0, 0, 1}, 0.01, 0.1),
                                   rspd_test::makePatch (b, {0.6, 0.5, 0}, Eigen::Vector3d (0, 0.01, 1).normalized (), 0.01, 0.1)};
  auto labels = labelSamples (s.size (), patches);
  EXPECT_EQ (mergePatches (s, g, patches, labels), 1u);
  ASSERT_EQ (patches.size (), 1u);
  EXPECT_EQ (patches[0].members.size (), 400u);
  EXPECT_DOUBLE_EQ (patches[0].center.x (), 0.6); // b's plane
  EXPECT_EQ (patches[0].first_index, 0u);
}

TEST (PatchMerge, MergedPlaneIsRetestedOnlyIfEveryPartWas)
{
  // The two coplanar strips of LargestPatchRepresentsTheGroup, flagged in each combination: the
  // group is judged again once grown only if both parts were seeded as noisy.
  for (const bool small_retested : {false, true})
    for (const bool large_retested : {false, true})
    {
      PointSet s;
      const auto a = rspd_test::addRectangle (s, {0, 0, 0}, {0.3f, 0, 0}, {0, 1, 0}, 6, 20);
      const auto b = rspd_test::addRectangle (s, {0.3f, 0, 0}, {0.7f, 0, 0}, {0, 1, 0}, 14, 20);
      const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 10);
      std::vector<PlanarPatch> patches{rspd_test::makePatch (a, {0.1, 0.5, 0}, {0, 0, 1}, 0.01, 0.1),
                                       rspd_test::makePatch (b, {0.6, 0.5, 0}, {0, 0, 1}, 0.01, 0.1)};
      patches[0].retested = small_retested;
      patches[1].retested = large_retested;
      auto labels = labelSamples (s.size (), patches);
      ASSERT_EQ (mergePatches (s, g, patches, labels), 1u);
      ASSERT_EQ (patches.size (), 1u);
      EXPECT_EQ (patches[0].retested, small_retested && large_retested) << small_retested << large_retested;
    }
}

TEST (PatchMerge, OneBoundaryInlierIsEnoughForM3)
{
  // B is tilted so that only the samples of B right at A's edge are inliers of A (M3 holds there),
  // while A's samples are not inliers of B.
  PointSet s;
  const auto a = rspd_test::addRectangle (s, {0, 0, 0}, {0.5f, 0, 0}, {0, 1, 0}, 10, 20);
  const auto b = rspd_test::addRectangle (s, {0.5f, 0, 0}, {0.5f, 0, 0.02f}, {0, 1, 0}, 10, 20);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 6);
  const Eigen::Vector3d nb = Eigen::Vector3d (-0.04, 0, 1).normalized ();
  std::vector<PlanarPatch> patches{rspd_test::makePatch (a, {0.25, 0.5, 0}, {0, 0, 1}, 0.002, 0.1),
                                   rspd_test::makePatch (b, {0.75, 0.5, 0.01}, nb, 0.0001, 0.1)};
  auto labels = labelSamples (s.size (), patches);
  EXPECT_EQ (mergePatches (s, g, patches, labels, nullptr, MergeRules::paper ()), 1u);
}

namespace
{
/** A flat strip A, then B bent up by 20° from A's edge, then C bent by 20° more from B's edge:
  * every adjacent pair is within MND (0.6 rad) and meets M3 along the fold. */
struct BentStrips
{
  PointSet s;
  std::vector<PlanarPatch> patches;
  NeighborGraph g;

  BentStrips ()
  {
    const float deg = 3.14159265f / 180.0f;
    const Eigen::Vector3f ab (0.25f * std::cos (20 * deg), 0, 0.25f * std::sin (20 * deg));
    const Eigen::Vector3f bc (0.2f * std::cos (40 * deg), 0, 0.2f * std::sin (40 * deg));
    const auto a = rspd_test::addRectangle (s, {0, 0, 0}, {0.5f, 0, 0}, {0, 1, 0}, 20, 20);
    const auto b = rspd_test::addRectangle (s, {0.5f, 0, 0}, ab, {0, 1, 0}, 10, 20);
    const Eigen::Vector3f c0 = Eigen::Vector3f (0.5f, 0, 0) + ab;
    const auto c = rspd_test::addRectangle (s, c0, bc, {0, 1, 0}, 8, 20);
    g = rspd_test::bruteForceGraph (s.points, 8);
    const auto normal = [] (const Eigen::Vector3f& u) { return Eigen::Vector3d (-u.z (), 0, u.x ()).normalized (); };
    patches = {rspd_test::makePatch (a, {0.25, 0.5, 0}, {0, 0, 1}, 0.01, 0.6),
               rspd_test::makePatch (b, (Eigen::Vector3f (0.5f, 0.5f, 0) + 0.5f * ab).cast<double> (), normal (ab), 0.01, 0.6),
               rspd_test::makePatch (c, (c0 + Eigen::Vector3f (0, 0.5f, 0) + 0.5f * bc).cast<double> (), normal (bc), 0.01, 0.6)};
  }
};
} // namespace

TEST (PatchMerge, PaperRulesChainFacetsAroundABend)
{
  BentStrips f;
  auto labels = labelSamples (f.s.size (), f.patches);
  EXPECT_EQ (mergePatches (f.s, f.g, f.patches, labels, nullptr, MergeRules::paper ()), 2u);
  EXPECT_EQ (f.patches.size (), 1u); // A, B and C, 40° apart at the ends, became one "plane"
}

TEST (PatchMerge, CoplanarGroupsStopTheChain)
{
  BentStrips f;
  auto labels = labelSamples (f.s.size (), f.patches);
  EXPECT_EQ (mergePatches (f.s, f.g, f.patches, labels), 0u); // M4 is on by default
  EXPECT_EQ (f.patches.size (), 3u);
}

TEST (PatchMerge, CoplanarGroupsAskTheLeadingGroupsOwnPlaneToo)
{
  // A large plane's representative holds a small part of it, and its normal's small error grows
  // with the distance across the group (a 10M-sample floor split in two). Here A's estimate is
  // tilted by 2°: B, which continues A's plane exactly, is out of that plane's band, but within the
  // band of the least-squares plane of A's samples, so the two still merge.
  PointSet s;
  const auto a = rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 30, 30, 0.001f, 1);
  const auto b = rspd_test::addRectangle (s, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}, 20, 20, 0.001f, 2);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 8);
  const double tilt = 2.0 * M_PI / 180.0;
  const auto patchesOf = [&] {
    return std::vector<PlanarPatch>{
      rspd_test::makePatch (a, {0.5, 0.5, 0}, {std::sin (tilt), 0, std::cos (tilt)}, 0.005, 0.3),
      rspd_test::makePatch (b, {1.5, 0.5, 0}, {0, 0, 1}, 0.005, 0.3)};
  };
  std::vector<PlanarPatch> patches = patchesOf ();
  auto labels = labelSamples (s.size (), patches);
  EXPECT_EQ (mergePatches (s, g, patches, labels), 1u);
  ASSERT_EQ (patches.size (), 1u);
  EXPECT_EQ (patches[0].members.size (), 1300u);
  // Bent by 20° instead, B stays apart: the group's own plane does not hold it either.
  PointSet bent;
  const auto a2 = rspd_test::addRectangle (bent, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 30, 30, 0.001f, 1);
  const float c = std::cos (0.35f), sn = std::sin (0.35f);
  const auto b2 = rspd_test::addRectangle (bent, {1, 0, 0}, {c, 0, sn}, {0, 1, 0}, 20, 20, 0.001f, 2);
  const NeighborGraph g2 = rspd_test::bruteForceGraph (bent.points, 8);
  std::vector<PlanarPatch> apart{rspd_test::makePatch (a2, {0.5, 0.5, 0}, {0, 0, 1}, 0.005, 0.5),
                                 rspd_test::makePatch (b2, {1 + 0.5 * c, 0.5, 0.5 * sn}, {-sn, 0, c}, 0.005, 0.5)};
  auto labels2 = labelSamples (bent.size (), apart);
  EXPECT_EQ (mergePatches (bent, g2, apart, labels2), 0u);
  EXPECT_EQ (apart.size (), 2u);
}

TEST (PatchMerge, CoplanarGroupsStillJoinANoisierPartOfTheSamePlane)
{
  // B continues A's plane with 4x the noise (a farther, sparser part of a scanned wall). Most of B
  // lies outside A's band, but inside its own: the wider band decides, and they merge.
  PointSet s;
  const auto a = rspd_test::addRectangle (s, {0, 0, 0}, {0.5f, 0, 0}, {0, 1, 0}, 20, 20, 0.002f, 1);
  const auto b = rspd_test::addRectangle (s, {0.5f, 0, 0}, {0.5f, 0, 0}, {0, 1, 0}, 10, 10, 0.008f, 2);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 8);
  std::vector<PlanarPatch> patches{rspd_test::makePatch (a, {0.25, 0.5, 0}, {0, 0, 1}, 0.005, 0.3),
                                   rspd_test::makePatch (b, {0.75, 0.5, 0}, {0, 0, 1}, 0.02, 0.3)};
  auto labels = labelSamples (s.size (), patches);
  EXPECT_EQ (mergePatches (s, g, patches, labels), 1u);
  ASSERT_EQ (patches.size (), 1u);
  EXPECT_EQ (patches[0].members.size (), 500u);
  EXPECT_EQ (patches[0].mdp, 0.005); // the larger patch represents the group and keeps its plane
}

TEST (PatchMerge, ResultDoesNotDependOnTheThreadCount)
{
  // A floor and a wall, each seeded as a grid of tiles (many boundary edges, most pairs meeting
  // M1-M3 several times over), plus a strip raised above the floor (M2 passes, M3 fails): enough
  // samples that the parallel boundary scan gives both threads rows.
  PointSet s;
  std::vector<std::vector<std::uint32_t>> tiles;
  std::vector<Eigen::Vector3d> centers, normals;
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b)
    {
      tiles.push_back (rspd_test::addRectangle (s, {0.1f * a + 0.0125f, 0.1f * b, 0}, {0.1f, 0, 0}, {0, 0.1f, 0}, 10, 10));
      centers.emplace_back (0.1 * a + 0.06, 0.1 * b + 0.05, 0);
      normals.emplace_back (0, 0, 1);
    }
  for (int b = 0; b < 8; ++b)
    for (int c = 0; c < 4; ++c)
    {
      tiles.push_back (rspd_test::addRectangle (s, {0, 0.1f * b, 0.1f * c + 0.0125f}, {0, 0.1f, 0}, {0, 0, 0.1f}, 10, 10));
      centers.emplace_back (0, 0.1 * b + 0.05, 0.1 * c + 0.06);
      normals.emplace_back (1, 0, 0);
    }
  tiles.push_back (rspd_test::addRectangle (s, {0.8125f, 0, 0.05f}, {0.2f, 0, 0}, {0, 0.8f, 0}, 20, 80));
  centers.emplace_back (0.91, 0.4, 0.05);
  normals.emplace_back (0, 0, 1);
  ASSERT_GT (s.size (), 2u * 4096u);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 12);
  std::vector<PlanarPatch> base;
  for (std::size_t t = 0; t < tiles.size (); ++t)
    base.push_back (rspd_test::makePatch (tiles[t], centers[t], normals[t], 0.01, 0.1));
  for (const bool coplanar : {true, false})
  {
    std::vector<PlanarPatch> one = base, two = base;
    auto l1 = labelSamples (s.size (), one), l2 = labelSamples (s.size (), two);
    MergeRules r1, r2;
    r1.coplanar = r2.coplanar = coplanar;
    r1.num_threads = 1;
    r2.num_threads = 2;
    const std::size_t a1 = mergePatches (s, g, one, l1, nullptr, r1);
    const std::size_t a2 = mergePatches (s, g, two, l2, nullptr, r2);
    EXPECT_EQ (a1, a2);
    EXPECT_EQ (l1, l2);
    ASSERT_EQ (one.size (), two.size ());
    for (std::size_t p = 0; p < one.size (); ++p)
      EXPECT_EQ (one[p].members, two[p].members);
    // Floor tiles into one, wall tiles into one, the raised strip apart.
    EXPECT_EQ (one.size (), 3u) << (coplanar ? "M4" : "paper");
  }
}
