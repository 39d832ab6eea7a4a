/*
 * Tests of the plane-support rule (departure, releaseUnsupportedMembers).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/patch_growth.h>
#include <pcl_rspd/plane_support.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace pcl::rspd;

namespace
{
constexpr int kK = 12;

/** A 20 x 20 grid on z = 0 over [0, 1]^2 (spacing 0.05), all of it plane 0, plus \a extra samples
  * that plane 0 also holds. */
struct Scene
{
  PointSet set;
  std::vector<PlanarPatch> patches;
  std::vector<std::uint32_t> labels;
};

Scene
gridWith (const std::vector<Eigen::Vector3f>& extra)
{
  Scene s;
  rspd_test::addRectangle (s.set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 20, 20);
  for (const auto& p : extra)
  {
    s.set.points.push_back (p);
    s.set.normals.push_back (Eigen::Vector3f::UnitZ ());
    s.set.input_indices.push_back (static_cast<pcl::index_t> (s.set.input_indices.size ()));
  }
  s.patches = rspd_test::onePatchOfAll (s.set.size (), 0.01, 0.1);
  s.labels = labelSamples (s.set.size (), s.patches);
  return s;
}

std::size_t
run (Scene& s, int threads = 0, bool clutter_share = false, std::size_t* clutter_released = nullptr,
     double band_width = 0.01)
{
  const NeighborGraph g = rspd_test::bruteForceGraph (s.set.points, kK);
  std::vector<double> band (s.patches.size (), band_width);
  return releaseUnsupportedMembers (s.set, g, band, threads, s.patches, s.labels, clutter_share, clutter_released);
}

/** The grid (plane 0) and, beyond its rim, a box of uniform clutter (x in [1.2, 2.4], y in [0, 1],
  * z in [-0.6, 0.6], about 0.2 apart) whose samples within kSheetBand of z = 0 plane 0 holds too:
  * the sheet a noisy plane's band takes from the clutter. \a sheet receives their indices. */
constexpr double kSheetBand = 0.05;

Scene
gridAndClutterSheet (std::vector<std::uint32_t>& sheet)
{
  Scene s = gridWith ({});
  std::mt19937 rng (11);
  std::uniform_real_distribution<float> x (1.2f, 2.4f), y (0.0f, 1.0f), z (-0.6f, 0.6f);
  for (int i = 0; i < 180; ++i)
  {
    s.set.points.emplace_back (x (rng), y (rng), z (rng));
    s.set.normals.push_back (Eigen::Vector3f::UnitZ ());
    s.set.input_indices.push_back (static_cast<pcl::index_t> (s.set.input_indices.size ()));
    if (std::abs (s.set.points.back ().z ()) < kSheetBand)
    {
      sheet.push_back (static_cast<std::uint32_t> (s.set.size () - 1));
      s.patches[0].members.push_back (sheet.back ());
    }
  }
  s.labels = labelSamples (s.set.size (), s.patches);
  return s;
}
} // namespace

TEST (PlaneSupport, AnInBandSampleFarBeyondTheRimIsReleased)
{
  // 0.425 from the rim's nearest sample (8.5 grid spacings), within the band: released.
  Scene s = gridWith ({{1.4f, 0.525f, 0.001f}});
  EXPECT_EQ (run (s), 1u);
  EXPECT_EQ (s.labels.back (), kNoPatch);
  ASSERT_EQ (s.patches.size (), 1u);
  EXPECT_EQ (s.patches[0].members.size (), 400u);
}

TEST (PlaneSupport, ASampleJustBeyondTheRimIsKept)
{
  // 0.075 from the rim (1.5 spacings, depth 1.5 median gaps): a rim sample could lie there.
  Scene s = gridWith ({{1.05f, 0.525f, 0.001f}});
  EXPECT_EQ (run (s), 0u);
  EXPECT_EQ (s.patches[0].members.size (), 401u);
}

TEST (PlaneSupport, ASampleAFewSpacingsBeyondAStraightRimIsReleasedByItsDepth)
{
  // 0.125 from the rim: its gap is 2.5 median gaps (kept by the gap rule alone), but it lies 2.5
  // median gaps ahead of every rim sample, where a straight rim leaves none.
  Scene s = gridWith ({{1.1f, 0.525f, 0.001f}});
  EXPECT_EQ (run (s), 1u);
  EXPECT_EQ (s.labels.back (), kNoPatch);
  EXPECT_EQ (s.patches[0].members.size (), 400u);
}

TEST (PlaneSupport, ReleasesPeelOutliersThatShieldEachOther)
{
  // The inner outlier (3 median gaps out) is not ahead of the outer one, which shields it; once the
  // outer one (3.5 gaps beyond the inner) is released, the inner one is ahead of the rim and goes too.
  Scene s = gridWith ({{1.125f, 0.525f, 0.0f}, {1.3f, 0.525f, 0.0f}});
  EXPECT_EQ (run (s), 2u);
  EXPECT_EQ (s.patches[0].members.size (), 400u);

  // The inner one alone goes in the first round, the outer one alone too: each is ahead of the rim.
  Scene inner = gridWith ({{1.125f, 0.525f, 0.0f}});
  EXPECT_EQ (run (inner), 1u);
}

TEST (PlaneSupport, ASmallDetachedGroupBeyondTheRimIsReleased)
{
  // A pair 8 spacings beyond the rim, side by side along it, one spacing apart: each is the other's
  // nearest (a typical gap) and neither is ahead of the other; 11 of 12 neighbours are in the plane.
  // Nothing within 6 median gaps joins them to the plane: a detached group of 2, released.
  Scene s = gridWith ({{1.4f, 0.5f, 0.0f}, {1.4f, 0.55f, 0.0f}});
  EXPECT_EQ (run (s), 2u);
  EXPECT_EQ (s.patches[0].members.size (), 400u);

  // Five in a row, within reach of one another: as large as a group may be and be kept.
  std::vector<Eigen::Vector3f> row;
  for (int i = 0; i < static_cast<int> (kDetachedGroupSize); ++i)
    row.emplace_back (1.4f, 0.4f + 0.05f * static_cast<float> (i), 0.0f);
  Scene five = gridWith (row);
  EXPECT_EQ (run (five), 0u);
}

TEST (PlaneSupport, AGroupAsFarAsThePlanesOwnStripesAreApartIsKept)
{
  // A plane sampled in dense rows 0.08 apart (spacing 0.01 along them) with single samples between
  // the rows, 15 % of the plane (an RGB-D camera's depth steps on a slanted plane): the median gap
  // is 0.01, the 90th percentile 0.04. A fragment of 3 samples 0.09 beyond the last row is as far
  // from it as the rows are from one another: the reach, widened by the plane's gap spread (2.2),
  // joins it to the plane; with the median gap alone (reach 0.06) it would be a detached group.
  Scene s;
  const auto add = [&] (float x, float y) {
    s.set.points.emplace_back (x, y, 0.0f);
    s.set.normals.push_back (Eigen::Vector3f::UnitZ ());
    s.set.input_indices.push_back (static_cast<pcl::index_t> (s.set.input_indices.size ()));
  };
  for (int j = 0; j <= 10; ++j)
    for (int i = 0; i <= 100; ++i)
      add (0.01f * static_cast<float> (i), 0.08f * static_cast<float> (j));
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 20; ++i)
      add (0.025f + 0.05f * static_cast<float> (i), 0.04f + 0.08f * static_cast<float> (j));
  for (int i = 0; i < 3; ++i)
    add (0.5f + 0.01f * static_cast<float> (i), 0.89f);
  s.patches = rspd_test::onePatchOfAll (s.set.size (), 0.01, 0.1);
  s.labels = labelSamples (s.set.size (), s.patches);
  EXPECT_EQ (run (s), 0u);
}

TEST (PlaneSupport, TheGridItselfLosesNothing)
{
  // Rim and corner samples of a regular grid are one spacing from the next: nothing to release.
  Scene s = gridWith ({});
  EXPECT_EQ (run (s), 0u);
}

TEST (PlaneSupport, ASampleAmidAHoleIsKept)
{
  // The same gap, but with the plane all around it: not one-sided, kept.
  Scene s;
  for (int i = 0; i < 41; ++i)
    for (int j = 0; j < 41; ++j)
    {
      const Eigen::Vector3f p (i * 0.025f, j * 0.025f, 0.0f);
      const float r = (p - Eigen::Vector3f (0.5f, 0.5f, 0.0f)).norm ();
      if (r > 0.2f || r == 0.0f)
      {
        s.set.points.push_back (p);
        s.set.normals.push_back (Eigen::Vector3f::UnitZ ());
        s.set.input_indices.push_back (static_cast<pcl::index_t> (s.set.input_indices.size ()));
      }
    }
  s.patches = rspd_test::onePatchOfAll (s.set.size (), 0.01, 0.1);
  s.labels = labelSamples (s.set.size (), s.patches);
  const std::size_t before = s.set.size ();
  EXPECT_EQ (run (s), 0u);
  EXPECT_EQ (s.patches[0].members.size (), before);
}

TEST (PlaneSupport, ASampleInAnotherPlanesBandIsKept)
{
  // The far sample of plane 0 lies on plane 1 (x = 1.4), whose samples are its neighbours: where
  // two planes meet, the edge-side rule has settled the owner.
  Scene s = gridWith ({{1.4f, 0.525f, 0.0f}});
  const std::uint32_t far = static_cast<std::uint32_t> (s.set.size () - 1);
  const auto wall = rspd_test::addRectangle (s.set, {1.4f, 0, 0.025f}, {0, 1, 0}, {0, 0, 1}, 20, 20);
  s.patches.push_back (rspd_test::makePatch (wall, {1.4, 0.5, 0.5}, {1, 0, 0}, 0.01, 0.1));
  s.labels = labelSamples (s.set.size (), s.patches);
  EXPECT_EQ (run (s), 0u);
  EXPECT_EQ (s.labels[far], 0u);

  // Without plane 1 holding its samples, the same sample is released.
  s.patches.pop_back ();
  s.labels = labelSamples (s.set.size (), s.patches);
  EXPECT_EQ (run (s), 1u);
  EXPECT_EQ (s.labels[far], kNoPatch);
}

TEST (PlaneSupport, APairOfOutliersBeyondTheRimUnderAnotherPlaneIsReleased)
{
  // Two samples of plane 0 (z = 0), 1.5 beyond its rim and 2 cm apart, under plane 1 (z = 0.2,
  // out of their band): each is the other's only neighbour in plane 0, so each gap looks typical;
  // with one neighbour in twelve in their plane, nothing vouches for them (the facade's outliers
  // behind its wall, in a window's band).
  Scene s = gridWith ({{2.5f, 0.5f, 0.0f}, {2.52f, 0.5f, 0.0f}});
  const std::uint32_t first = static_cast<std::uint32_t> (s.set.size () - 2);
  const auto roof = rspd_test::addRectangle (s.set, {2, 0, 0.2f}, {1, 0, 0}, {0, 1, 0}, 20, 20);
  s.patches.push_back (rspd_test::makePatch (roof, {2.5, 0.5, 0.2}, {0, 0, 1}, 0.01, 0.1));
  s.labels = labelSamples (s.set.size (), s.patches);
  EXPECT_EQ (run (s), 2u);
  EXPECT_EQ (s.labels[first], kNoPatch);
  EXPECT_EQ (s.labels[first + 1], kNoPatch);
  EXPECT_EQ (s.patches[1].members.size (), 400u);
}

TEST (PlaneSupport, AMemberWithNoNeighbourInItsPlaneIsReleasedAndEmptyPlanesRemoved)
{
  // Plane 1 holds one sample above plane 0's band: it has no neighbour in its plane.
  Scene s = gridWith ({});
  s.set.points[210].z () = 0.05f;
  s.patches[0].members.erase (s.patches[0].members.begin () + 210);
  s.patches.push_back (rspd_test::makePatch ({210}, {0, 0, 0.5}, {1, 0, 0}, 0.01, 0.1));
  s.labels = labelSamples (s.set.size (), s.patches);
  EXPECT_EQ (run (s), 1u);
  EXPECT_EQ (s.patches.size (), 1u);
  EXPECT_EQ (s.labels[210], kNoPatch);
}

TEST (PlaneSupport, CoincidentSamplesAreKept)
{
  // Every grid sample 13 times over: each sample's neighbours all coincide with it (gap 0).
  Scene s;
  for (int copy = 0; copy < kK + 1; ++copy)
    rspd_test::addRectangle (s.set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 5, 5);
  s.patches = rspd_test::onePatchOfAll (s.set.size (), 0.01, 0.1);
  s.labels = labelSamples (s.set.size (), s.patches);
  EXPECT_EQ (run (s), 0u);
}

TEST (PlaneSupport, SameReleaseAtAnyScaleOffsetAndThreadCount)
{
  // In-band outliers 0.4-0.8 beyond the rim, one per 45° (so that no two are each other's
  // support): the released set does not change when the scene is scaled x1000 and moved 1 km, nor
  // with the thread count.
  std::mt19937 rng (7);
  std::uniform_real_distribution<float> jitter (-0.3f, 0.3f), z (-0.004f, 0.004f);
  std::vector<Eigen::Vector3f> extra;
  for (int i = 0; i < 8; ++i)
  {
    const float angle = static_cast<float> (M_PI / 4.0 * i) + jitter (rng);
    extra.emplace_back (0.5f + 1.2f * std::cos (angle), 0.5f + 1.2f * std::sin (angle), z (rng));
  }
  Scene a = gridWith (extra);
  Scene b = a;
  for (auto& p : b.set.points)
    p = p * 1000.0f + Eigen::Vector3f (1e6f, 0, 0);
  b.patches[0].setEstimate ([&] {
    PlaneEstimate e;
    e.center = Eigen::Vector3d (1e6, 0, 0);
    e.normal = Eigen::Vector3d::UnitZ ();
    e.distance_halfwidth = 10.0;
    e.angle_halfwidth = 0.1;
    return e;
  } ());
  Scene c = a;
  const std::size_t released = run (a, 1);
  const NeighborGraph gb = rspd_test::bruteForceGraph (b.set.points, kK);
  const std::vector<double> band_b (1, 10.0);
  EXPECT_EQ (releaseUnsupportedMembers (b.set, gb, band_b, 0, b.patches, b.labels), released);
  EXPECT_EQ (run (c, 2), released);
  EXPECT_EQ (released, 8u);
  EXPECT_EQ (a.labels, b.labels);
  EXPECT_EQ (a.labels, c.labels);
}

namespace
{
/** The grid with its last \a open samples taken off the plane (no plane holds them): the member
  * gaps beside them, as the last assignment measures them. */
struct OpenScene
{
  Scene s;
  NeighborGraph graph;
  std::vector<std::uint32_t> open;
  std::vector<float> gaps;
};

OpenScene
openLast (Scene s, std::size_t open)
{
  OpenScene o;
  const std::size_t members = s.set.size () - open;
  for (std::size_t i = members; i < s.set.size (); ++i)
  {
    s.labels[i] = kNoPatch;
    o.open.push_back (static_cast<std::uint32_t> (i));
  }
  s.patches[0].members.resize (members);
  o.graph = rspd_test::bruteForceGraph (s.set.points, kK);
  o.gaps = vouchingGaps (s.set, o.graph, s.patches, s.labels, o.open, {1}, 0);
  o.s = std::move (s);
  return o;
}

float
admitted (const OpenScene& o, std::uint32_t i)
{
  return admittingGap (o.s.set, o.graph, o.s.patches[0], 0, o.s.labels, o.gaps, i);
}
} // namespace

TEST (MemberGaps, ASampleAmongTheMembersIsAdmittedWithTheirSpacingAndOneBeyondItIsNot)
{
  // Three samples no plane holds: amid the grid (0.035 from its nearest member), 0.2 beyond the rim
  // (4 spacings) and 0.4 beyond it (8 spacings, more than kSupportGapRatio). The first two are
  // admitted at the grid's spacing, the third is not; the same x1000 and 1 km away.
  const std::vector<Eigen::Vector3f> extra {{0.5f, 0.5f, 0.002f}, {1.175f, 0.525f, 0.0f}, {1.375f, 0.525f, 0.0f}};
  const OpenScene a = openLast (gridWith (extra), 3);
  EXPECT_NEAR (admitted (a, 400), 0.05, 1e-5);
  EXPECT_NEAR (admitted (a, 401), 0.05, 1e-5);
  EXPECT_TRUE (std::isnan (admitted (a, 402)));

  Scene moved = gridWith (extra);
  for (auto& p : moved.set.points)
    p = p * 1000.0f + Eigen::Vector3f (1e6f, 0, 0);
  moved.patches[0].center = Eigen::Vector3d (1e6, 0, 0);
  const OpenScene b = openLast (moved, 3);
  EXPECT_NEAR (admitted (b, 400), 50.0, 0.1);
  EXPECT_NEAR (admitted (b, 401), 50.0, 0.1);
  EXPECT_TRUE (std::isnan (admitted (b, 402)));
}

TEST (MemberGaps, OnlySupportedMembersNextToOpenSamplesVouch)
{
  // The plane holds an outlier 0.525 beyond its rim (10 spacings, its own neighbours' gaps 0.05):
  // it does not vouch (infinite gap), the rim member beside the open sample does (0.05), and a
  // member next to no open sample is not measured (-1).
  const OpenScene o = openLast (gridWith ({{1.5f, 0.525f, 0.0f}, {1.6f, 0.525f, 0.0f}}), 1);
  EXPECT_TRUE (std::isinf (o.gaps[400]));
  EXPECT_NEAR (o.gaps[19 * 20 + 10], 0.05, 1e-5); // (0.975, 0.525): the rim's nearest
  EXPECT_EQ (o.gaps[0], -1.0f);                     // (0.025, 0.025)
  // The open sample lies 0.1 from the outlier member and is judged by the rim's spacing.
  EXPECT_NEAR (admitted (o, 401), 0.05, 1e-5);
}

TEST (MemberGaps, DuplicatedSamplesAreNoSpacing)
{
  // Every grid sample repeated (a scan's repeated points): each member's nearest member is its
  // copy, 0 away; its gap is the grid's spacing to the next one, so a sample 0.2 beyond the rim is
  // admitted as on the plain grid (with gaps of 0 every sample not on a member would be refused:
  // room_scan1 lost 1,884 samples of its planes' tails that way before this rule).
  Scene s = gridWith ({});
  const std::size_t n = s.set.size ();
  for (std::size_t i = 0; i < n; ++i)
  {
    const Eigen::Vector3f p = s.set.points[i];
    s.set.points.push_back (p);
    s.set.normals.push_back (Eigen::Vector3f::UnitZ ());
    s.set.input_indices.push_back (static_cast<pcl::index_t> (s.set.input_indices.size ()));
  }
  s.set.points.push_back ({1.175f, 0.525f, 0.0f});
  s.set.normals.push_back (Eigen::Vector3f::UnitZ ());
  s.set.input_indices.push_back (static_cast<pcl::index_t> (s.set.input_indices.size ()));
  s.patches = rspd_test::onePatchOfAll (s.set.size (), 0.01, 0.1);
  s.labels = labelSamples (s.set.size (), s.patches);
  const OpenScene o = openLast (std::move (s), 1);
  EXPECT_NEAR (o.gaps[19 * 20 + 10], 0.05, 1e-5);
  EXPECT_NEAR (admitted (o, 800), 0.05, 1e-5);
}

TEST (ClutterShare, ASheetOfClutterInThePlanesBandIsReleased)
{
  // Each sheet sample's 12 neighbours reach about 0.28 into the clutter around it: the plane's
  // samples in the band's slice of that ball are no denser than the clutter in the rest of it, so
  // the sheet is released, as the rim rules alone do not release it (it is no rim, and its gaps are
  // its own neighbours' gaps). The grid is denser than the clutter by far.
  std::vector<std::uint32_t> sheet;
  Scene on = gridAndClutterSheet (sheet);
  ASSERT_GE (sheet.size (), 10u);
  Scene off = on;
  std::size_t by_share = 0;
  run (on, 0, true, &by_share, kSheetBand);
  for (const auto i : sheet)
    EXPECT_EQ (on.labels[i], kNoPatch) << i;
  EXPECT_GT (by_share, sheet.size () / 2);
  ASSERT_EQ (on.patches.size (), 1u);
  EXPECT_EQ (on.patches[0].members.size (), 400u); // the grid keeps every sample, its rim too

  run (off, 0, false, nullptr, kSheetBand);
  std::size_t kept = 0;
  for (const auto i : sheet)
    kept += off.labels[i] == 0u;
  EXPECT_GT (kept, sheet.size () / 2);
}

TEST (ClutterShare, ARimBesideAnUnlabelledSurfaceIsKept)
{
  // An unlabelled wall rises beside the grid's rim (a surface no plane took, as a tank beside a
  // floor): the rim samples have the wall on one side, but their plane is denser in its band.
  Scene s = gridWith ({});
  rspd_test::addRectangle (s.set, {1.0f, 0, 0.05f}, {0, 1, 0}, {0, 0, 1}, 20, 20);
  s.labels = labelSamples (s.set.size (), s.patches);
  EXPECT_EQ (run (s, 0, true), 0u);
  EXPECT_EQ (s.patches[0].members.size (), 400u);
}

TEST (ClutterShare, SameReleaseAtAnyScaleOffsetAndThreadCount)
{
  std::vector<std::uint32_t> sheet;
  Scene a = gridAndClutterSheet (sheet);
  Scene b = a;
  for (auto& p : b.set.points)
    p = p * 1000.0f + Eigen::Vector3f (1e6f, 0, 0);
  PlaneEstimate e;
  e.center = Eigen::Vector3d (1e6, 0, 0);
  e.normal = Eigen::Vector3d::UnitZ ();
  e.distance_halfwidth = 10.0;
  e.angle_halfwidth = 0.1;
  b.patches[0].setEstimate (e);
  Scene c = a;
  const std::size_t released = run (a, 1, true, nullptr, kSheetBand);
  const NeighborGraph gb = rspd_test::bruteForceGraph (b.set.points, kK);
  const std::vector<double> band_b (1, 1000.0 * kSheetBand);
  EXPECT_EQ (releaseUnsupportedMembers (b.set, gb, band_b, 0, b.patches, b.labels, true), released);
  EXPECT_EQ (run (c, 2, true, nullptr, kSheetBand), released);
  EXPECT_GE (released, sheet.size ());
  EXPECT_EQ (a.labels, b.labels);
  EXPECT_EQ (a.labels, c.labels);
}
