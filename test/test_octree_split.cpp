/*
 * Tests of the split phase (Sec. 3.1, Algorithm 1), including the paper's Fig. 3.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/octree_split.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <set>

using namespace pcl::rspd;

namespace
{
DetectorParameters
params (std::size_t eps)
{
  DetectorParameters p;
  p.min_patch_size = eps;
  return p;
}
} // namespace

TEST (OctreeSplit, BottomUpFindsSmallParallelPlanesThatTopDownMisses)
{
  // Fig. 3: a 1 x 1 floor with a 0.25 x 0.25 platform 1 cm above it, σ = 1 mm. Tested as one
  // cell (what a top-down split does first), the platform is just 6 % outliers of one plane.
  PointSet s;
  const auto floor = rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 150, 150, 0.001f, 1);
  PointSet with_platform;
  std::vector<bool> on_platform;
  for (const auto i : floor)
  {
    const Eigen::Vector3f& p = s.points[i];
    const bool raised = p.x () > 0.5f && p.x () < 0.75f && p.y () > 0.5f && p.y () < 0.75f;
    with_platform.points.push_back (p + Eigen::Vector3f (0, 0, raised ? 0.01f : 0.0f));
    with_platform.normals.push_back (s.normals[i]);
    with_platform.input_indices.push_back (static_cast<pcl::index_t> (i));
    on_platform.push_back (raised);
  }
  std::vector<std::uint32_t> all (with_platform.size ());
  std::iota (all.begin (), all.end (), 0u);
  const DetectorParameters prm = params (23); // ε = max(10, ceil(0.001 n))

  const PlanarityResult top_down = robustPlanarityTest (with_platform, all, prm);
  ASSERT_EQ (top_down.verdict, PlanarityVerdict::Planar);
  std::size_t platform_kept = 0;
  for (const auto i : top_down.inliers)
    platform_kept += on_platform[i];
  EXPECT_EQ (platform_kept, 0u) << "top-down: the platform is absorbed as outliers of the floor";

  DetectorStatistics stats;
  const std::vector<PlanarPatch> patches = splitPhase (with_platform, prm, &stats);
  std::size_t platform_patches = 0, mixed = 0, platform_members = 0;
  for (const auto& patch : patches)
  {
    std::size_t up = 0;
    for (const auto i : patch.members)
      up += on_platform[i];
    if (up == patch.members.size ())
    {
      ++platform_patches;
      platform_members += up;
    }
    else if (up > 0)
      ++mixed;
  }
  EXPECT_GT (platform_patches, 0u) << "bottom-up: the platform gets patches of its own";
  EXPECT_EQ (mixed, 0u) << "no patch mixes platform and floor";
  EXPECT_GT (platform_members, 300u) << "of ~1,400 platform samples (growth takes the rest)";
}

TEST (OctreeSplit, EveryPatchHoldsAtLeastEpsilonSamplesAndNoSampleTwice)
{
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 100, 100, 0.002f, 2);
  rspd_test::addRectangle (s, {0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 100, 100, 0.002f, 3);
  const std::vector<PlanarPatch> patches = splitPhase (s, params (20));
  ASSERT_FALSE (patches.empty ());
  std::set<std::uint32_t> seen;
  for (const auto& p : patches)
  {
    EXPECT_GE (p.members.size (), 20u);
    EXPECT_TRUE (std::is_sorted (p.members.begin (), p.members.end ()));
    EXPECT_EQ (p.first_index, p.members.front ());
    EXPECT_EQ (p.estimate_size, p.members.size ());
    for (const auto i : p.members)
      EXPECT_TRUE (seen.insert (i).second);
  }
}

TEST (OctreeSplit, CellsBelowEpsilonAreNotTested)
{
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 5, 5);
  DetectorStatistics stats;
  EXPECT_TRUE (splitPhase (s, params (26), &stats).empty ());
  EXPECT_EQ (stats.cells_tested, 0u);
}

TEST (OctreeSplit, CellsBelowTheCoarseSizeAreTestedOnlyAtNarrowedNormals)
{
  // 30 samples, cells down to 16 but a coarse size of 51 (edge-aware normals in the small-plane
  // pass): the cell is tested only if it holds a sample whose normal was narrowed.
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 6, 5);
  DetectorParameters p = params (16);
  p.coarse_cell_size = 51;
  DetectorStatistics stats;
  EXPECT_FALSE (splitPhase (s, p, &stats).empty ()) << "no flags: every cell down to 16 is tested";
  s.narrowed.assign (s.size (), 0);
  stats = DetectorStatistics ();
  EXPECT_TRUE (splitPhase (s, p, &stats).empty ());
  EXPECT_EQ (stats.cells_tested, 0u);
  s.narrowed[7] = 1;
  stats = DetectorStatistics ();
  const auto patches = splitPhase (s, p, &stats);
  EXPECT_EQ (stats.cells_tested, 1u);
  ASSERT_EQ (patches.size (), 1u);
  EXPECT_EQ (patches[0].members.size (), 30u);
  // At or above the coarse size the flags do not matter.
  s.narrowed.assign (s.size (), 0);
  p.coarse_cell_size = 30;
  EXPECT_EQ (splitPhase (s, p, nullptr).size (), 1u);
}

TEST (OctreeSplit, ShiftedGridHoldsAFaceThatTheFirstGridCutsIntoUntestablePieces)
{
  // The bounding cube is [0, 1]^3 (two corner samples). A 10 x 10 face of 0.2 m centred at x = y = 0.5
  // is cut by the first grid's level 1 into quadrants of 25 samples, below ε = 60, whose cells are not
  // tested; the root, with a vertical face of 50 samples beside, fails. The shifted grid's cells of
  // level 2 (edge 0.5, boundaries at 1/6 and 2/3) hold the whole face alone, and their children of
  // level 3 (boundaries at 5/12) 81 of its samples: that cell is the seed (bottom-up).
  PointSet s;
  s.points = {{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}};
  s.normals = {{0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.0f}};
  s.input_indices = {0, 1};
  const auto face = rspd_test::addRectangle (s, {0.4f, 0.4f, 0.3f}, {0.2f, 0.0f, 0.0f}, {0.0f, 0.2f, 0.0f}, 10, 10);
  rspd_test::addRectangle (s, {0.9f, 0.8f, 0.7f}, {0.0f, 0.2f, 0.0f}, {0.0f, 0.0f, 0.2f}, 10, 5);
  const DetectorParameters p = params (60);
  DetectorStatistics first;
  EXPECT_TRUE (splitPhase (s, p, &first).empty ());
  EXPECT_EQ (first.cells_tested, 1u) << "the root alone holds ε samples";
  DetectorStatistics shifted;
  const auto patches = splitPhase (s, p, &shifted, nullptr, false, nullptr, nullptr, HUGE_VAL, true);
  const auto onFace = [&] (const std::vector<std::uint32_t>& members) {
    return members.size () == 81u && std::includes (face.begin (), face.end (), members.begin (), members.end ());
  };
  ASSERT_EQ (patches.size (), 1u);
  EXPECT_TRUE (onFace (patches[0].members));
  EXPECT_NEAR (std::abs (patches[0].normal.z ()), 1.0, 1e-6);
  EXPECT_EQ (shifted.seed_patches, 1u);
  // On a subset the shifted grid is that subset's bounding cube's: the face and its corners alone
  // give the same cube, and the same cell.
  std::vector<std::uint32_t> subset = {0, 1};
  subset.insert (subset.end (), face.begin (), face.end ());
  const auto on_subset = splitPhase (s, p, nullptr, &subset, false, nullptr, nullptr, HUGE_VAL, true);
  ASSERT_EQ (on_subset.size (), 1u);
  EXPECT_TRUE (onFace (on_subset[0].members));
}

TEST (OctreeSplit, RootIsTestedWhenNoChildCanBe)
{
  // 40 samples, ε = 40: every child has fewer than ε, so the root itself is tested and accepted.
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 8, 5);
  DetectorStatistics stats;
  const auto patches = splitPhase (s, params (40), &stats);
  EXPECT_EQ (stats.cells_tested, 1u);
  ASSERT_EQ (patches.size (), 1u);
  EXPECT_EQ (patches[0].members.size (), 40u);
}

TEST (OctreeSplit, IdenticalPointsStopSubdivision)
{
  // More than ε coincident samples sent a peer into unbounded recursion.
  PointSet s;
  for (int i = 0; i < 10000; ++i)
  {
    s.points.emplace_back (0.5f, 0.5f, 0.5f);
    s.normals.emplace_back (0.0f, 0.0f, 1.0f);
  }
  s.input_indices.resize (s.size ());
  DetectorStatistics stats;
  EXPECT_TRUE (splitPhase (s, params (10), &stats).empty ());
  EXPECT_EQ (stats.cells_tested, 1u);
}

TEST (OctreeSplit, DepthCapBoundsATightClusterInsideALargeScene)
{
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 20, 20);
  for (int i = 0; i < 100; ++i) // a cluster a few float ulps wide
  {
    s.points.emplace_back (0.3f + i * 1e-7f, 0.3f, 0.0f);
    s.normals.emplace_back (0.0f, 0.0f, 1.0f);
  }
  s.input_indices.resize (s.size ());
  DetectorParameters p = params (10);
  p.max_octree_depth = 24;
  const auto patches = splitPhase (s, p); // terminates
  SUCCEED () << patches.size () << " patches";
}

TEST (OctreeSplit, DeterministicOrder)
{
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 60, 60, 0.003f, 5);
  const auto a = splitPhase (s, params (10));
  const auto b = splitPhase (s, params (10));
  ASSERT_EQ (a.size (), b.size ());
  for (std::size_t i = 0; i < a.size (); ++i)
    EXPECT_EQ (a[i].members, b[i].members);
}

TEST (OctreeSplit, RimCellIsTestedAgainOnItsInliersOnlyWhenAsked)
{
  // A noisy square whose normals, along one side, bend by 40° over a band of a third of its
  // samples (a neighbourhood reaching over the rim): T1 and T2 pass, T3 fails (33 % > 25 %). Only
  // the root cell is tested, as a small-plane pass cell that cannot be split further.
  PointSet s;
  const auto square = rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 30, 30, 0.002f, 4);
  std::size_t bent = 0;
  for (const auto i : square)
    if (s.points[i].x () < 1.0f / 3.0f)
    {
      s.normals[i] = Eigen::Vector3f (std::sin (0.7f), 0.0f, std::cos (0.7f));
      ++bent;
    }
  DetectorParameters params;
  params.min_patch_size = square.size () / 2; // the inliers can reach it
  params.max_octree_depth = 0;                // the root cell alone is tested
  const PlanarityResult direct = robustPlanarityTest (s, square, params);
  EXPECT_EQ (direct.verdict, PlanarityVerdict::TooManyOutliers);

  std::size_t rim = 99;
  EXPECT_TRUE (splitPhase (s, params, nullptr, nullptr, false, &rim).empty ());
  EXPECT_EQ (rim, 0u);

  const auto seeds = splitPhase (s, params, nullptr, nullptr, true, &rim);
  ASSERT_EQ (seeds.size (), 1u);
  EXPECT_EQ (rim, 1u);
  EXPECT_GE (seeds[0].members.size (), (square.size () - bent) * 9 / 10);
  for (const auto i : seeds[0].members)
    EXPECT_GE (s.points[i].x (), 1.0f / 3.0f) << "a bent-normal sample seeded";
  EXPECT_LT (seeds[0].mnd, 0.2);
}

namespace
{
/** A unit cube's six faces, 50 x 50 samples each, noise σ = 3 % of the edge along each face's
  * normal; face f holds samples [2500 f, 2500 (f + 1)). */
PointSet
noisyCube ()
{
  PointSet s;
  const float h = 0.5f;
  std::uint32_t seed = 40;
  for (int axis = 0; axis < 3; ++axis)
    for (const float side : {-h, h})
    {
      Eigen::Vector3f o = Eigen::Vector3f::Constant (-h), a = Eigen::Vector3f::Zero (), b = Eigen::Vector3f::Zero ();
      o[axis] = side;
      a[(axis + 1) % 3] = 1.0f;
      b[(axis + 2) % 3] = 1.0f;
      rspd_test::addRectangle (s, o, a, b, 50, 50, 0.03f, ++seed);
    }
  return s;
}
} // namespace

TEST (OctreeSplit, ThickCellsOfOneFaceAreJoinedIntoItsSeed)
{
  // Every cell that holds one face alone is too thin for T1 against σ = 3 cm (the paper seeds
  // nothing); cells across an edge look planar to T2 and T3 too, but are not joined to a face
  // (half their samples lie off it), and a strip of them along an edge is bent at it.
  const PointSet s = noisyCube ();
  DetectorParameters p = params (100);
  p.join_thick_cells = false;
  EXPECT_TRUE (splitPhase (s, p).empty ());

  p.join_thick_cells = true;
  DetectorStatistics st;
  const auto seeds = splitPhase (s, p, &st);
  ASSERT_EQ (seeds.size (), 6u);
  EXPECT_EQ (st.joined_seeds, 6u);
  std::set<std::uint32_t> faces, seen;
  for (const auto& seed : seeds)
  {
    for (const auto i : seed.members)
      EXPECT_TRUE (seen.insert (i).second) << "sample " << i << " in two seeds";
    std::array<std::size_t, 6> on{};
    for (const auto i : seed.members)
      ++on[i / 2500];
    const auto face = std::max_element (on.begin (), on.end ()) - on.begin ();
    faces.insert (static_cast<std::uint32_t> (face));
    EXPECT_GE (on[face], seed.members.size () * 95 / 100);
    EXPECT_GE (on[face], 2500u / 4); // the cells away from its rim
  }
  EXPECT_EQ (faces.size (), 6u);
}

TEST (OctreeSplit, ThickCellsOfASubsetAreJoinedOnlyWhenAskedAndUnderTheMndBound)
{
  // A subset split (the small-cell pass) joins its thick cells only if the caller takes the groups
  // (small_cell_thick_join), and keeps no thick cell noisier (MND) than the bound it is given.
  const PointSet s = noisyCube ();
  std::vector<std::uint32_t> all (s.size ());
  std::iota (all.begin (), all.end (), 0u);
  EXPECT_TRUE (splitPhase (s, params (100), nullptr, &all).empty ());

  std::vector<PlanarPatch> groups;
  DetectorStatistics st;
  EXPECT_TRUE (splitPhase (s, params (100), &st, &all, false, nullptr, &groups).empty ());
  EXPECT_EQ (groups.size (), 6u);
  EXPECT_EQ (st.joined_seeds, 0u); // the caller counts what it seeds

  // The faces' normals are exact: every cell's MND is the floor (normal_deviation_floor). A bound
  // just below it keeps no thick cell, one at it keeps the six groups.
  const double floor = params (100).normal_deviation_floor;
  for (const auto& g : groups)
    EXPECT_NEAR (g.mnd, floor, 1e-9);
  groups.clear ();
  splitPhase (s, params (100), nullptr, &all, false, nullptr, &groups, 0.5 * floor);
  EXPECT_TRUE (groups.empty ());
  splitPhase (s, params (100), nullptr, &all, false, nullptr, &groups, floor);
  EXPECT_EQ (groups.size (), 6u);
}

TEST (OctreeSplit, CellThatPassesHoldsItsThickCells)
{
  // Floor and ceiling 1 x 1, 1 apart, σ = 2 cm: the ε-sample cells (a quarter of a quarter) are too
  // thin for T1, their parents (a quarter of a plane, 40 cm in-plane against ~5 cm MDP) are not. A
  // parent's patch holds its thick cells' samples, which must not seed again (a sample in two seeds).
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 40, 40, 0.02f, 60);
  rspd_test::addRectangle (s, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, 40, 40, 0.02f, 61);
  DetectorStatistics st;
  const auto seeds = splitPhase (s, params (100), &st);
  EXPECT_EQ (seeds.size (), 8u);
  EXPECT_EQ (st.joined_seeds, 0u);
  std::set<std::uint32_t> seen;
  for (const auto& seed : seeds)
    for (const auto i : seed.members)
      EXPECT_TRUE (seen.insert (i).second) << "sample " << i << " in two seeds";
  EXPECT_GE (seen.size (), s.size () * 9 / 10);
}
