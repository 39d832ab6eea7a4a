/*
 * Tests of the plane curvature measure (measureCurvature), of the share of a flat plane's noise a
 * quadric explains by chance (chanceBendShare), and of the flat and curved tests built on them.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/plane_curvature.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>

using namespace pcl::rspd;

namespace
{
/** Samples on a cylinder of radius r around the y axis, arc of +-half_arc radians about +z (pi: all
  * round), \a length long, Gaussian noise along the radius; exact normals. */
std::vector<std::uint32_t>
addCylinderArc (PointSet& s, double r, double half_arc, int n, float noise, std::uint32_t seed = 1, double length = 1.0)
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
    s.points.push_back (radius * normal + Eigen::Vector3f (0, static_cast<float> (length * u (rng)), 0));
    s.normals.push_back (normal);
    s.input_indices.push_back (static_cast<pcl::index_t> (s.input_indices.size ()));
  }
  return added;
}

/** n samples uniform on a w x l rectangle in the plane z = 0, Gaussian noise sigma along z. */
std::vector<std::uint32_t>
addNoisyRectangle (PointSet& s, double w, double l, int n, float sigma, std::mt19937& rng)
{
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  std::normal_distribution<float> g (0.0f, sigma);
  std::vector<std::uint32_t> added;
  for (int i = 0; i < n; ++i)
  {
    added.push_back (static_cast<std::uint32_t> (s.points.size ()));
    s.points.emplace_back (static_cast<float> (w) * u (rng), static_cast<float> (l) * u (rng), g (rng));
    s.normals.emplace_back (0.0f, 0.0f, 1.0f);
    s.input_indices.push_back (static_cast<pcl::index_t> (s.input_indices.size ()));
  }
  return added;
}

/** A patch holding \a members with the given MDP and MND (its plane does not matter to the tests). */
PlanarPatch
patchOf (const std::vector<std::uint32_t>& members, double mdp, double mnd)
{
  PlanarPatch p;
  p.members = members;
  p.mdp = mdp;
  p.mnd = mnd;
  p.cos_mnd = std::cos (mnd);
  return p;
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

TEST (Curvature, ChanceShareFollowsTheSampleCount)
{
  // Quantiles of Beta(3/2, (n-6)/2).
  EXPECT_NEAR (chanceBendShare (16, 0.99), 0.663, 0.005);
  EXPECT_NEAR (chanceBendShare (50, 0.99), 0.225, 0.005);
  EXPECT_NEAR (chanceBendShare (200, 0.99), 0.057, 0.002);
  EXPECT_GT (chanceBendShare (50, 0.999), chanceBendShare (50, 0.99));
  EXPECT_EQ (chanceBendShare (6, 0.99), 1.0);  // nothing can be told
  EXPECT_EQ (chanceBendShare (500, 0.0), 0.0); // no test: a fixed share alone
}

TEST (Curvature, FlatNoiseExceedsTheChanceShareAsOftenAsItsConfidenceSays)
{
  // 1,000 flat noisy patches of 20 and of 60 samples: the chance share at 99 % is exceeded about
  // once in a hundred, at 95 % (the default) about once in twenty; the fixed quarter calls a
  // quarter of the 20-sample patches bent.
  std::mt19937 rng (7);
  for (const int n : {20, 60})
  {
    int beyond99 = 0, beyond95 = 0, beyond_quarter = 0;
    for (int t = 0; t < 1000; ++t)
    {
      PointSet s;
      const auto m = addNoisyRectangle (s, 1.5, 1.0, n, 0.01f, rng);
      const PlaneCurvature c = measureCurvature (s, m);
      beyond99 += c.share >= chanceBendShare (n, 0.99);
      beyond95 += c.share >= chanceBendShare (n, 0.95);
      beyond_quarter += c.share >= 0.25;
    }
    std::printf ("    %d samples, of 1000: %d beyond the 99 %% chance share, %d beyond the 95 %%, %d beyond a quarter\n",
                 n, beyond99, beyond95, beyond_quarter);
    EXPECT_LE (beyond99, 25) << n << " samples";
    EXPECT_GE (beyond99, 2) << n << " samples";
    EXPECT_LE (beyond95, 80) << n << " samples";
    EXPECT_GE (beyond95, 25) << n << " samples";
    if (n == 20)
      EXPECT_GE (beyond_quarter, 200);
  }
  EXPECT_EQ (DetectorParameters ().bend_confidence, 0.95);
}

TEST (FlatPatch, NoisyFaceWhoseChanceBendExceedsHalfItsMndIsFlat)
{
  // A grown face of 127 samples at σ 2 cm: its quadric bends by chance; with an MND below twice
  // that bend, the fixed share's rule calls it bent, the noise test flat.
  std::mt19937 rng (3);
  PointSet s;
  const auto m = addNoisyRectangle (s, 1.5, 1.0, 127, 0.02f, rng);
  const PlaneCurvature c = measureCurvature (s, m);
  ASSERT_GT (c.half_bend, 0.0);
  ASSERT_LT (c.share, chanceBendShare (127, DetectorParameters ().bend_confidence));
  const PlanarPatch face = patchOf (m, 0.05, 1.5 * c.half_bend);
  DetectorParameters params;
  EXPECT_TRUE (isFlatPatch (s, params, face, true));
  EXPECT_TRUE (isFlatPatch (s, params, face, false));
  params.bend_confidence = 0.0;
  EXPECT_FALSE (isFlatPatch (s, params, face, true));
  EXPECT_TRUE (isFlatPatch (s, params, face, false)); // a seed is not judged by its bend
}

TEST (FlatPatch, TubeSampledAllRoundIsNoPlane)
{
  // A pipe 0.3 m across, 4 m long, 120 samples: no quadric over its plane explains it (the share is
  // one noise gives), but its noise band is as wide as half its narrow side.
  PointSet s;
  const auto m = addCylinderArc (s, 0.15, M_PI, 120, 0.005f, 1, 4.0);
  const PlaneCurvature c = measureCurvature (s, m);
  EXPECT_LT (c.share, chanceBendShare (120, DetectorParameters ().bend_confidence));
  EXPECT_NEAR (c.minor_extent, 0.3, 0.03);
  const PlanarPatch tube = patchOf (m, 0.16, 40.0 * M_PI / 180.0);
  DetectorParameters params;
  EXPECT_FALSE (isFlatPatch (s, params, tube, true));
  // A plane as long, 0.3 m wide, with a noise band of 2 cm is flat.
  std::mt19937 rng (5);
  PointSet p;
  const auto strip = addNoisyRectangle (p, 4.0, 0.3, 120, 0.008f, rng);
  EXPECT_TRUE (isFlatPatch (p, params, patchOf (strip, 0.02, 0.1), true));
}

TEST (FlatPatch, TubeStandingOnAPlaneIsNoPlane)
{
  // The same pipe holding three samples of the ground it stands on, which lie in its band on one side
  // beyond it: they stretch its narrow side's range from 0.3 to 0.65 m, but not the inner 95 % of
  // its samples, and it stays a tube (a pipe on a plant's ground, 429 samples and 6 strays, was kept
  // as a plane when the narrow side was the range).
  PointSet s;
  auto m = addCylinderArc (s, 0.15, M_PI, 120, 0.005f, 1, 4.0);
  for (const float x : {0.25f, 0.35f, 0.5f})
  {
    m.push_back (static_cast<std::uint32_t> (s.points.size ()));
    s.points.emplace_back (x, 0.01f, 0.0f);
    s.normals.emplace_back (0.0f, 0.0f, 1.0f);
    s.input_indices.push_back (static_cast<pcl::index_t> (s.input_indices.size ()));
  }
  const PlaneCurvature c = measureCurvature (s, m);
  EXPECT_NEAR (c.minor_extent, 0.3, 0.03);
  // A tube's MDP (median + 3 MAD of |d|) is 1.4-1.8 times its radius: 0.2 here, against half the
  // narrow side, 0.16 (0.33 by the range).
  DetectorParameters params;
  EXPECT_FALSE (isFlatPatch (s, params, patchOf (m, 0.2, 40.0 * M_PI / 180.0), true));
  // A strip 0.3 m wide keeps its width: the inner 95 % of a uniform strip, scaled back.
  std::mt19937 rng (5);
  PointSet p;
  const auto strip = addNoisyRectangle (p, 4.0, 0.3, 400, 0.008f, rng);
  EXPECT_NEAR (measureCurvature (p, strip).minor_extent, 0.3, 0.015);
}

TEST (FlatPatch, CylinderArcIsBentEitherWay)
{
  // A 40° arc of a cylinder, 2,000 samples: its bend explains most of the residual and turns the
  // normal by 20°, more than half an MND of 25°.
  PointSet s;
  const auto m = addCylinderArc (s, 1.0, 20.0 * M_PI / 180.0, 2000, 0.002f);
  const PlanarPatch arc = patchOf (m, 0.02, 25.0 * M_PI / 180.0);
  DetectorParameters params;
  EXPECT_FALSE (isFlatPatch (s, params, arc, true));
  EXPECT_FALSE (isFlatPatch (s, params, arc, false));
  EXPECT_TRUE (isCurvedPatch (measureCurvature (s, m), arc.mnd, params));
  params.bend_confidence = 0.0;
  EXPECT_FALSE (isFlatPatch (s, params, arc, true));
  EXPECT_TRUE (isCurvedPatch (measureCurvature (s, m), arc.mnd, params));
}

TEST (FlatPatch, CurvedCheckIgnoresABendNoiseExplains)
{
  // 16 flat noisy samples whose quadric explains more than a quarter of their residual by chance:
  // the curved check with a fixed share calls them curved, tested against noise it does not.
  std::mt19937 rng (11);
  for (int t = 0; t < 200; ++t)
  {
    PointSet s;
    const auto m = addNoisyRectangle (s, 1.0, 1.0, 16, 0.01f, rng);
    const PlaneCurvature c = measureCurvature (s, m);
    if (!(c.share >= 0.3 && c.share < chanceBendShare (16, DetectorParameters ().bend_confidence) && c.half_bend > 0.0))
      continue;
    DetectorParameters params;
    EXPECT_FALSE (isCurvedPatch (c, c.half_bend, params));
    params.bend_confidence = 0.0;
    EXPECT_TRUE (isCurvedPatch (c, c.half_bend, params));
    return;
  }
  FAIL () << "no 16-sample flat patch with a chance share above 0.3 in 200 draws";
}

namespace
{
/** Adds n samples on faces folded about lines parallel to the y axis: face f spans x' in
  * [f w, (f + 1) w] along its own direction, each face turned by \a fold radians from the one before;
  * exact positions, normals with Gaussian noise of \a normal_noise radians about the face's normal. */
std::vector<std::uint32_t>
addFoldedFaces (PointSet& s, int faces, double w, double fold, int n, double normal_noise, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u (0.0, 1.0);
  std::normal_distribution<double> g (0.0, normal_noise);
  std::vector<std::uint32_t> added;
  Eigen::Vector2d start (0.0, 0.0); // (x, z) where each face starts
  for (int f = 0; f < faces; ++f)
  {
    const double a = f * fold;
    const Eigen::Vector2d dir (std::cos (a), std::sin (a)), nrm (-std::sin (a), std::cos (a));
    for (int i = 0; i < n / faces; ++i)
    {
      const Eigen::Vector2d p = start + w * u (rng) * dir;
      const double t = g (rng);
      const Eigen::Vector2d q = std::cos (t) * nrm + std::sin (t) * dir;
      added.push_back (static_cast<std::uint32_t> (s.points.size ()));
      s.points.emplace_back (static_cast<float> (p.x ()), static_cast<float> (u (rng)), static_cast<float> (p.y ()));
      s.normals.emplace_back (static_cast<float> (q.x ()), 0.0f, static_cast<float> (q.y ()));
      s.input_indices.push_back (static_cast<pcl::index_t> (s.input_indices.size ()));
    }
    start += w * dir;
  }
  return added;
}
} // namespace

TEST (NormalTurnRatio, SmoothOnACurvedSurfaceAndStepwiseOverAFold)
{
  // A cylinder's arc turns its normals in proportion to the position: far below 1/2.
  PointSet arc;
  const auto a = addCylinderArc (arc, 1.0, 0.3, 2000, 0.001f);
  EXPECT_LT (normalTurnRatio (arc, a, measureCurvature (arc, a)), 0.05);
  // Two faces 30° apart: one step, at least 1; three faces over two 20° edges, normal noise 0.1 rad:
  // (σ² + Δ²/12) / (σ² + Δ²/6) = 0.66 (less where the outer faces' positions, projected onto the
  // plane, shrink: about 1/2 without noise).
  std::mt19937 rng (4);
  PointSet two;
  const auto b = addFoldedFaces (two, 2, 0.5, 30.0 * M_PI / 180.0, 2000, 0.05, rng);
  EXPECT_GE (normalTurnRatio (two, b, measureCurvature (two, b)), 1.0);
  PointSet three;
  const auto c = addFoldedFaces (three, 3, 0.4, 20.0 * M_PI / 180.0, 3000, 0.1, rng);
  const double r3 = normalTurnRatio (three, c, measureCurvature (three, c));
  EXPECT_GT (r3, 0.5);
  EXPECT_LT (r3, 1.0);
  // Many narrow faces approach the arc again (a faceted curved surface): below 1/2.
  PointSet many;
  const auto d = addFoldedFaces (many, 8, 0.15, 6.0 * M_PI / 180.0, 4000, 0.02, rng);
  EXPECT_LT (normalTurnRatio (many, d, measureCurvature (many, d)), 0.5);
}

TEST (NormalTurnRatio, NoisyNormalsOnAnArcStayBelowHalfWhileTheTurnExceedsSevenTimesTheNoise)
{
  // The arc turns the normal by 0.6 rad across it: σ² / (σ² + 0.6²/48) is 0.25 for normal noise of
  // 0.05 rad (0.6 rad is 12 σ) and 0.57 for 0.1 rad (6 σ, within the √48 ≈ 7 σ a fold can mimic).
  const auto ratioAt = [] (float sigma) {
    std::mt19937 rng (2);
    std::normal_distribution<float> g (0.0f, sigma);
    PointSet arc;
    const auto a = addCylinderArc (arc, 1.0, 0.3, 3000, 0.002f);
    for (auto& n : arc.normals)
      n = Eigen::AngleAxisf (g (rng), Eigen::Vector3f::UnitY ()) * n;
    return std::make_pair (normalTurnRatio (arc, a, measureCurvature (arc, a)), arc);
  };
  const auto quiet = ratioAt (0.05f);
  EXPECT_GT (quiet.first, 0.18);
  EXPECT_LT (quiet.first, 0.32);
  const double noisy = ratioAt (0.1f).first;
  EXPECT_GT (noisy, 0.5);
  EXPECT_LT (noisy, 0.65);
  PointSet arc = quiet.second;
  std::vector<std::uint32_t> a (arc.points.size ());
  std::iota (a.begin (), a.end (), 0u);
  const double r = quiet.first;
  // Unoriented normals (half of them flipped) give the same ratio.
  for (std::size_t i = 0; i < arc.normals.size (); i += 2)
    arc.normals[i] = -arc.normals[i];
  EXPECT_NEAR (normalTurnRatio (arc, a, measureCurvature (arc, a)), r, 1e-9);
}

TEST (NormalTurnRatio, TooFewSamplesOrNoBendCannotBeMeasured)
{
  PointSet arc;
  const auto a = addCylinderArc (arc, 1.0, 0.3, 11, 0.001f);
  EXPECT_EQ (normalTurnRatio (arc, a, measureCurvature (arc, a)), HUGE_VAL);
  std::mt19937 rng (3);
  PointSet flat;
  const auto f = addNoisyRectangle (flat, 1.0, 1.0, 500, 0.0f, rng);
  EXPECT_EQ (normalTurnRatio (flat, f, measureCurvature (flat, f)), HUGE_VAL); // no residual, no direction
}

TEST (NormalTurnAcross, AnArcsNormalsTurnWithItAFlatFacesDoNot)
{
  // An arc of 0.6 rad: its normals turn by about that much across it, as its quadric does.
  PointSet arc;
  const auto a = addCylinderArc (arc, 1.0, 0.3, 3000, 0.002f);
  const PlaneCurvature ca = measureCurvature (arc, a);
  const double turn = normalTurnAcross (arc, a, ca);
  EXPECT_NEAR (turn, 0.6, 0.06);
  EXPECT_NEAR (turn, 2.0 * ca.half_bend, 0.1);
  // A flat face with noisy positions and true normals: the quadric bends by chance, the normals by
  // nothing, whatever the draw.
  std::mt19937 rng (5);
  int measured = 0;
  for (int draw = 0; draw < 20; ++draw)
  {
    PointSet flat;
    const auto f = addNoisyRectangle (flat, 1.5, 1.0, 200, 0.02f, rng);
    const PlaneCurvature cf = measureCurvature (flat, f);
    if (cf.samples == 0)
      continue;
    ++measured;
    EXPECT_GT (cf.half_bend, 0.0);
    EXPECT_LT (normalTurnAcross (flat, f, cf), 1e-6);
  }
  EXPECT_EQ (measured, 20);
  // Too few samples: not measured.
  PointSet few;
  const auto s = addCylinderArc (few, 1.0, 0.3, 11, 0.001f);
  EXPECT_EQ (normalTurnAcross (few, s, measureCurvature (few, s)), HUGE_VAL);
}

TEST (CurvedByNormals, ANoisyArcWhoseNormalsTurnByHalfItsMndIsCurvedAFlatFaceIsNot)
{
  // A pillar's facet under noise a large part of its bend (radius 0.3 m, 0.29 m across, σ 2 cm):
  // the quadric explains less than a quarter of the residual, yet more than chance, and MND is the
  // noise's, so isCurvedPatch's fixed bounds keep it; its normals turn by 1 rad across it.
  DetectorParameters params;
  int judged = 0;
  for (std::uint32_t seed = 1; seed <= 40 && judged < 5; ++seed)
  {
    PointSet s;
    const auto m = addCylinderArc (s, 0.3, 0.5, 1000, 0.02f, seed, 2.5);
    const PlaneCurvature c = measureCurvature (s, m);
    if (!(c.share < params.min_curvature_share && c.share > chanceBendShare (c.samples, params.curved_turn_confidence)))
      continue;
    ++judged;
    const double mnd = 0.8; // noisy normals: a spread wider than the turn
    const double turn = normalTurnAcross (s, m, c);
    EXPECT_NEAR (turn, 1.0, 0.1);
    EXPECT_FALSE (isCurvedPatch (c, mnd, params)) << "share " << c.share;
    EXPECT_TRUE (isCurvedByNormals (c, turn, mnd, params)) << "share " << c.share;
    // Normals that turn by less than half MND show nothing beyond the quadric.
    EXPECT_FALSE (isCurvedByNormals (c, turn, 2.0 * turn + 0.01, params));
  }
  EXPECT_EQ (judged, 5) << "too few draws with a share between chance (99.9 %) and a quarter";
  // A flat face: its quadric bends by chance at most, its normals do not turn.
  std::mt19937 rng (3);
  int flat_judged = 0;
  for (int draw = 0; draw < 40; ++draw)
  {
    PointSet flat;
    const auto f = addNoisyRectangle (flat, 2.5, 0.3, 1000, 0.02f, rng);
    const PlaneCurvature cf = measureCurvature (flat, f);
    if (cf.samples == 0)
      continue;
    ++flat_judged;
    EXPECT_FALSE (isCurvedByNormals (cf, normalTurnAcross (flat, f, cf), 0.05, params));
  }
  EXPECT_EQ (flat_judged, 40);
  // A sparse face's normals turn across it by its rims (the boxes at 10,000 points on PCL's k = 50
  // normals: 1.2-2.1 rad, MND 0.7-1.7) and one face in twenty bends beyond chance at 95 %: the
  // normals' path asks for a share beyond chance at 99.9 %.
  PlaneCurvature sparse;
  sparse.samples = 100;
  sparse.share = 0.5 * (chanceBendShare (100, 0.95) + chanceBendShare (100, params.curved_turn_confidence));
  EXPECT_FALSE (isCurvedByNormals (sparse, 2.0, 1.0, params));
  sparse.share = 1.05 * chanceBendShare (100, params.curved_turn_confidence);
  EXPECT_TRUE (isCurvedByNormals (sparse, 2.0, 1.0, params));
  // Not measured: never curved.
  EXPECT_FALSE (isCurvedByNormals (PlaneCurvature (), 1.0, 0.1, params));
  PointSet arc;
  const auto a = addCylinderArc (arc, 0.3, 0.5, 1000, 0.02f, 1, 2.5);
  EXPECT_FALSE (isCurvedByNormals (measureCurvature (arc, a), HUGE_VAL, 0.1, params));
}
