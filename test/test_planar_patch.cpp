/*
 * Tests of the robust planarity test (Sec. 3.2): T1, T2, T3, zero spread, and the paper's Sec. 4.4
 * noise experiment (Table 5).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/planar_patch.h>

#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

#include <numeric>
#include <random>

using namespace pcl::rspd;

namespace
{
std::vector<std::uint32_t>
allSamples (const PointSet& s)
{
  std::vector<std::uint32_t> v (s.size ());
  std::iota (v.begin (), v.end (), 0u);
  return v;
}

DetectorParameters
params (std::size_t eps = 10)
{
  DetectorParameters p;
  p.min_patch_size = eps;
  return p;
}

/** PCA eigenvalue ratio τ = λ_min / λ_max (Eq. 1). */
double
pcaRatio (const PointSet& s)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
  for (const auto& p : s.points)
    mean += p.cast<double> ();
  mean /= s.size ();
  Eigen::Matrix3d c = Eigen::Matrix3d::Zero ();
  for (const auto& p : s.points)
    c += (p.cast<double> () - mean) * (p.cast<double> () - mean).transpose ();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es (c);
  return es.eigenvalues ()[0] / es.eigenvalues ()[2];
}

/** Sec. 4.4: 10,000 samples on a 1 x 1 plane with exact normals, plus p (fraction of 10,000)
  * outliers at random positions on the plane shifted along the normal by G(0, sigma), with random
  * normals. */
PointSet
noiseExperiment (double p, double sigma, std::uint32_t seed = 7)
{
  PointSet s;
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  std::normal_distribution<float> g (0.0f, static_cast<float> (sigma));
  for (int i = 0; i < 10000; ++i)
  {
    s.points.emplace_back (u (rng), u (rng), 0.0f);
    s.normals.emplace_back (0.0f, 0.0f, 1.0f);
  }
  const int outliers = static_cast<int> (std::lround (p * 10000));
  std::normal_distribution<float> dir (0.0f, 1.0f);
  for (int i = 0; i < outliers; ++i)
  {
    s.points.emplace_back (u (rng), u (rng), g (rng));
    Eigen::Vector3f n (dir (rng), dir (rng), dir (rng));
    s.normals.push_back (n.normalized ());
  }
  s.input_indices.resize (s.points.size ());
  std::iota (s.input_indices.begin (), s.input_indices.end (), 0);
  return s;
}
} // namespace

TEST (PlanarityTest, NoiseExperimentMdpAndMndStayAtZeroSpreadWhilePcaRatioRises)
{
  // The paper's Table 5: MDP and MND do not move with p and sigma; τ goes 0.07 -> 0.19 -> 0.49.
  const double ps[3] = {0.125, 0.25, 0.5};
  const double sigmas[3] = {0.125, 0.25, 0.5};
  double last_tau = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const PointSet s = noiseExperiment (ps[i], sigmas[i]);
    const PlanarityResult r = robustPlanarityTest (s, allSamples (s), params ());
    const DetectorParameters prm = params ();
    // Zero spread: the floors, exactly.
    EXPECT_NEAR (r.estimate.normal.z (), 1.0, 1e-9);
    EXPECT_DOUBLE_EQ (r.estimate.distance_median, 0.0);
    EXPECT_DOUBLE_EQ (r.estimate.mdp (), prm.distance_floor_ratio * std::max (r.estimate.width, r.estimate.length));
    EXPECT_DOUBLE_EQ (r.estimate.mnd (), prm.normal_deviation_floor);
    const double tau = pcaRatio (s);
    std::printf ("    p = %.3f, sigma = %.3f: MDP %.2g, MND %.2g rad, PCA tau %.3f, outliers %.3f\n", ps[i], sigmas[i],
                 r.estimate.mdp (), r.estimate.mnd (), tau, r.outlier_ratio);
    EXPECT_GT (tau, last_tau) << "p = " << ps[i];
    last_tau = tau;
    // T3: p of 10,000 outliers is p / (1 + p) of the samples: 11 %, 20 %, 33 %.
    const double share = ps[i] / (1.0 + ps[i]);
    EXPECT_NEAR (r.outlier_ratio, share, 0.005);
    if (share < 0.25)
    {
      EXPECT_EQ (r.verdict, PlanarityVerdict::Planar);
      EXPECT_EQ (r.inliers.size (), 10000u); // exactly the plane's samples are kept
      for (const auto idx : r.inliers)
        EXPECT_LT (idx, 10000u);
    }
    else
      EXPECT_EQ (r.verdict, PlanarityVerdict::TooManyOutliers);
  }
  EXPECT_GT (last_tau, 0.1);
}

TEST (PlanarityTest, DistanceTestRejectsCurvedPatchAndAcceptsFlatOneOfSameSize)
{
  // Same 1 x 1 footprint: a flat patch, and a cylindrical one (radius 0.6) with exact normals.
  PointSet flat, curved;
  rspd_test::addRectangle (flat, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 40, 40, 0.002f);
  const float r = 0.6f;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j)
    {
      const float x = (i + 0.5f) / 40 - 0.5f, y = (j + 0.5f) / 40;
      const float z = std::sqrt (r * r - x * x) - r;
      curved.points.emplace_back (x, y, z);
      curved.normals.push_back (Eigen::Vector3f (x, 0, z + r).normalized ());
    }
  curved.input_indices.resize (curved.points.size ());
  const PlanarityResult rf = robustPlanarityTest (flat, allSamples (flat), params ());
  const PlanarityResult rc = robustPlanarityTest (curved, allSamples (curved), params ());
  EXPECT_EQ (rf.verdict, PlanarityVerdict::Planar);
  EXPECT_GT (rf.distance_angle, 75.0 * M_PI / 180.0);
  EXPECT_EQ (rc.verdict, PlanarityVerdict::FailedDistance);
  EXPECT_LT (rc.distance_angle, 75.0 * M_PI / 180.0);
}

TEST (PlanarityTest, DistanceTestUsesInPlaneExtentWhateverTheOrientation)
{
  // A long thin flat strip rotated 30° about z: w and l come from the in-plane principal axes.
  PointSet strip;
  const Eigen::Vector3f a (std::cos (0.5236f) * 2.0f, std::sin (0.5236f) * 2.0f, 0.0f);
  const Eigen::Vector3f b (-std::sin (0.5236f) * 0.1f, std::cos (0.5236f) * 0.1f, 0.0f);
  rspd_test::addRectangle (strip, {0, 0, 0}, a, b, 200, 10);
  const PlanarityResult r = robustPlanarityTest (strip, allSamples (strip), params ());
  EXPECT_NEAR (std::max (r.estimate.width, r.estimate.length), 2.0 * 199.0 / 200.0, 1e-3);
  EXPECT_NEAR (std::min (r.estimate.width, r.estimate.length), 0.1 * 9.0 / 10.0, 1e-3);
}

TEST (PlanarityTest, NormalTestRejectsScatteredNormals)
{
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 30, 30);
  std::mt19937 rng (3);
  std::normal_distribution<float> g (0.0f, 1.0f);
  // Normals tilted from the plane's by up to 85° in every direction: N stays right (symmetric
  // spread), so T1 passes and only T2 can reject.
  PointSet noisy = s;
  std::uniform_real_distribution<float> tilt (0.0f, 85.0f * static_cast<float> (M_PI) / 180.0f);
  std::uniform_real_distribution<float> azimuth (0.0f, 2.0f * static_cast<float> (M_PI));
  for (auto& n : noisy.normals)
  {
    const float t = tilt (rng), a = azimuth (rng);
    n = Eigen::Vector3f (std::sin (t) * std::cos (a), std::sin (t) * std::sin (a), std::cos (t));
  }
  PointSet mild = s;
  for (auto& n : mild.normals)
    n = (n + 0.05f * Eigen::Vector3f (g (rng), g (rng), g (rng))).normalized (); // a few degrees off
  const PlanarityResult rn = robustPlanarityTest (noisy, allSamples (noisy), params ());
  const PlanarityResult rm = robustPlanarityTest (mild, allSamples (mild), params ());
  EXPECT_EQ (rn.verdict, PlanarityVerdict::FailedNormal);
  EXPECT_GE (rn.estimate.mnd (), 60.0 * M_PI / 180.0);
  EXPECT_EQ (rm.verdict, PlanarityVerdict::Planar);
  EXPECT_LT (rm.estimate.mnd (), 20.0 * M_PI / 180.0);
}

TEST (PlanarityTest, OutlierTestDecidesAtTwentyFivePercent)
{
  // 76 % / 74 % exact plane samples; the rest 0.3 above it (normals exact, so only D flags them).
  for (const int outliers : {24, 26})
  {
    PointSet s;
    rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 10, 100 - outliers);
    rspd_test::addRectangle (s, {0, 0, 0.3f}, {1, 0, 0}, {0, 1, 0}, 10, outliers);
    const PlanarityResult r = robustPlanarityTest (s, allSamples (s), params ());
    EXPECT_NEAR (r.outlier_ratio, outliers / 100.0, 1e-9);
    if (outliers == 24)
    {
      EXPECT_EQ (r.verdict, PlanarityVerdict::Planar);
      EXPECT_EQ (r.inliers.size (), 760u); // the accepted patch drops its outliers
    }
    else
    {
      EXPECT_EQ (r.verdict, PlanarityVerdict::TooManyOutliers);
      EXPECT_TRUE (r.inliers.empty ());
    }
  }
}

TEST (PlanarityTest, PatchSmallerThanEpsilonAfterOutlierRemovalIsDropped)
{
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 10, 8);
  rspd_test::addRectangle (s, {0, 0, 0.3f}, {1, 0, 0}, {0, 1, 0}, 10, 2);
  EXPECT_EQ (robustPlanarityTest (s, allSamples (s), params (80)).verdict, PlanarityVerdict::Planar);
  EXPECT_EQ (robustPlanarityTest (s, allSamples (s), params (81)).verdict, PlanarityVerdict::TooSmall);
}

TEST (PlanarityTest, NoiseFreePlanePassesWithFloorsAndTheyScaleWithTheData)
{
  for (const float scale : {1.0f, 1000.0f, 0.001f})
  {
    PointSet s;
    rspd_test::addRectangle (s, {0, 0, 0}, {scale, 0, 0}, {0, scale, 0}, 20, 20);
    const PlanarityResult r = robustPlanarityTest (s, allSamples (s), params ());
    EXPECT_EQ (r.verdict, PlanarityVerdict::Planar) << scale;
    EXPECT_EQ (r.inliers.size (), 400u);
    EXPECT_NEAR (r.estimate.mdp () / scale, 1e-6 * 0.95, 1e-9) << "floor relative to the extent";
  }
}

TEST (PlanarityTest, PaperLetterWithoutFloorsGivesZeroSpread)
{
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 20, 20);
  DetectorParameters p = params ();
  p.distance_floor_ratio = 0.0;
  p.normal_deviation_floor = 0.0;
  PlaneEstimate e;
  ASSERT_TRUE (estimatePlane (s, allSamples (s), p, e));
  EXPECT_EQ (e.mdp (), 0.0);
  EXPECT_EQ (e.mnd (), 0.0);
}

TEST (PlanarityTest, SplitNormalSignsDoNotSkewTheMedianNormal)
{
  // Half of the normals flipped: the plain component-wise median collapses towards 0; aligning
  // them into the dominant hemisphere first recovers N.
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 20, 20);
  const Eigen::Vector3f n = Eigen::Vector3f (0.3f, 0.2f, 1.0f).normalized ();
  for (std::size_t i = 0; i < s.size (); ++i)
    s.normals[i] = (i % 2) ? n : Eigen::Vector3f (-n);
  DetectorParameters p = params ();
  PlaneEstimate aligned;
  ASSERT_TRUE (estimatePlane (s, allSamples (s), p, aligned));
  EXPECT_NEAR (std::abs (aligned.normal.dot (n.cast<double> ())), 1.0, 1e-6);
  p.align_normals = false;
  PlaneEstimate plain;
  EXPECT_FALSE (estimatePlane (s, allSamples (s), p, plain) && std::abs (plain.normal.dot (n.cast<double> ())) > 0.999);
}

TEST (PlanarityTest, DegenerateInputIsRejectedNotCrashed)
{
  PointSet s;
  for (int i = 0; i < 50; ++i)
  {
    s.points.emplace_back (1.0f, 2.0f, 3.0f);
    s.normals.emplace_back (0.0f, 0.0f, 1.0f);
  }
  s.input_indices.resize (50);
  const PlanarityResult r = robustPlanarityTest (s, allSamples (s), params ());
  EXPECT_NE (r.verdict, PlanarityVerdict::Planar); // zero extent: T1 cannot pass
  EXPECT_EQ (robustPlanarityTest (s, {}, params ()).verdict, PlanarityVerdict::Degenerate);
}

TEST (PlanarPatch, InlierConditionUsesDistanceAndAngle)
{
  PlanarPatch p;
  PlaneEstimate e;
  e.center = Eigen::Vector3d::Zero ();
  e.normal = Eigen::Vector3d::UnitZ ();
  e.distance_halfwidth = 0.1;
  e.angle_halfwidth = 10.0 * M_PI / 180.0;
  p.setEstimate (e);
  EXPECT_TRUE (p.isInlier ({5, 5, 0.0999f}, {0, 0, -1}));
  EXPECT_FALSE (p.isInlier ({0, 0, 0.11f}, {0, 0, 1}));
  EXPECT_TRUE (p.isInlier ({0, 0, 0}, Eigen::Vector3f (std::sin (0.17f), 0, std::cos (0.17f))));
  EXPECT_FALSE (p.isInlier ({0, 0, 0}, Eigen::Vector3f (std::sin (0.18f), 0, std::cos (0.18f))));
}
