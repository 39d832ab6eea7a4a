/*
 * Tests of the trimmed-plane normals (pcl::rspd::refineNormalsTrimmed).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/neighbor_graph.h>
#include <pcl_rspd/normal_estimation.h>
#include <pcl_rspd/robust_normals.h>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace pcl::rspd;

namespace
{
double
angleTo (const Eigen::Vector3f& n, const Eigen::Vector3f& truth)
{
  return std::acos (std::min (1.0f, std::abs (n.normalized ().dot (truth))));
}

/** A sample set's k = 50 graph, its PCA normals, and those normals refined by trimmed planes. */
struct BothFits
{
  NeighborGraph graph;
  std::vector<Eigen::Vector3f> pca, trimmed;
  TrimmedNormalStatistics stats;
};

BothFits
fitBoth (const PointSet& s)
{
  BothFits f;
  f.graph = rspd_test::bruteForceGraph (s.points, 50);
  estimateNormals (s.points, f.graph, 1, f.pca);
  f.trimmed = f.pca;
  refineNormalsTrimmed (s.points, f.graph, 1, f.trimmed, &f.stats);
  return f;
}

/** A roof: two 1 x 1 faces meeting at 90° along the y axis, σ = 2 mm; face[i] = 0 or 1. */
PointSet
roof (std::vector<int>& face)
{
  PointSet s;
  const auto a = rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 60, 60, 0.002f, 1);
  const auto b = rspd_test::addRectangle (s, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 60, 60, 0.002f, 2);
  face.assign (s.size (), 0);
  for (const auto i : b)
    face[i] = 1;
  (void) a;
  return s;
}
} // namespace

TEST (TrimmedNormals, NormalsNearAnEdgeBelongToOneFace)
{
  // PCA normals within a neighbourhood radius of the edge bend towards the other face; the trimmed
  // plane takes the sample's own face.
  std::vector<int> face;
  PointSet s = roof (face);
  const BothFits fits = fitBoth (s);
  const auto& pca = fits.pca;
  const auto& trimmed = fits.trimmed;
  const TrimmedNormalStatistics& stats = fits.stats;
  EXPECT_GT (stats.refined, s.size () * 9 / 10);
  const Eigen::Vector3f truth[2] = {Eigen::Vector3f::UnitZ (), Eigen::Vector3f::UnitX ()};
  std::size_t near = 0, pca_bent = 0, trimmed_bent = 0;
  for (std::size_t i = 0; i < s.size (); ++i)
  {
    const Eigen::Vector3f& p = s.points[i];
    if (std::max (p.x (), p.z ()) > 0.06f) // within ~ a neighbourhood radius of the edge
      continue;
    ++near;
    pca_bent += angleTo (pca[i], truth[face[i]]) > 10.0 * M_PI / 180.0;
    trimmed_bent += angleTo (trimmed[i], truth[face[i]]) > 10.0 * M_PI / 180.0;
  }
  ASSERT_GT (near, 200u);
  // Measured: 301 of 480 PCA normals more than 10° off their face, 86 trimmed ones (those within a
  // few sample spacings of the edge, where the two faces fit the nearest half alike).
  EXPECT_GT (pca_bent, near / 2) << "PCA normals bend at the edge";
  EXPECT_LT (trimmed_bent, near / 4) << "trimmed normals mostly do not";
  EXPECT_LT (3 * trimmed_bent, pca_bent);
}

TEST (TrimmedNormals, FlatNoisySurfaceKeepsPcaAccuracy)
{
  // Reweighting gives back most of the efficiency trimming costs: on one noisy plane the trimmed
  // normals' median angle to the truth is 0.042 rad against PCA's 0.033 (a cost: noisy normals
  // widen MND), and less than 1.5 times PCA's.
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 80, 80, 0.005f, 3);
  const BothFits fits = fitBoth (s);
  const auto& pca = fits.pca;
  const auto& trimmed = fits.trimmed;
  std::vector<double> a, b;
  for (std::size_t i = 0; i < s.size (); ++i)
  {
    a.push_back (angleTo (pca[i], Eigen::Vector3f::UnitZ ()));
    b.push_back (angleTo (trimmed[i], Eigen::Vector3f::UnitZ ()));
  }
  std::nth_element (a.begin (), a.begin () + a.size () / 2, a.end ());
  std::nth_element (b.begin (), b.begin () + b.size () / 2, b.end ());
  EXPECT_LT (b[b.size () / 2], 1.5 * a[a.size () / 2]);
}

TEST (TrimmedNormals, ScanLinesKeepTheirPcaNormal)
{
  // Samples on parallel lines 10x farther apart than the samples along them: a trimmed half can be
  // one line, whose plane is undetermined about it. Such samples keep the PCA normal.
  PointSet s;
  for (int line = 0; line < 12; ++line)
    for (int j = 0; j < 400; ++j)
    {
      s.points.emplace_back (0.0025f * j, 0.025f * line, 0.0f);
      s.normals.push_back (Eigen::Vector3f::UnitZ ());
      s.input_indices.push_back (static_cast<pcl::index_t> (s.input_indices.size ()));
    }
  const BothFits fits = fitBoth (s);
  const auto& pca = fits.pca;
  const auto& trimmed = fits.trimmed;
  const TrimmedNormalStatistics& stats = fits.stats;
  std::size_t off = 0;
  for (std::size_t i = 0; i < s.size (); ++i)
    off += angleTo (trimmed[i], Eigen::Vector3f::UnitZ ()) > 1e-3;
  EXPECT_EQ (off, 0u);
  EXPECT_GT (stats.collinear, 0u) << "the scan-line guard is what kept them";
}

TEST (TrimmedNormals, SameResultForAnyThreadCountAndTurnedCloud)
{
  std::vector<int> face;
  PointSet s = roof (face);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 50);
  std::vector<Eigen::Vector3f> base, one, two;
  estimateNormals (s.points, g, 1, base);
  one = base;
  two = base;
  refineNormalsTrimmed (s.points, g, 1, one);
  refineNormalsTrimmed (s.points, g, 2, two);
  EXPECT_EQ (one, two);
  // Turned: the same normals, turned (a few samples may pick the other face where both fit alike).
  const Eigen::Matrix3f r = Eigen::AngleAxisf (0.9f, Eigen::Vector3f (1, -2, 0.5f).normalized ()).toRotationMatrix ();
  PointSet t = s;
  for (auto& p : t.points)
    p = r * p;
  std::vector<Eigen::Vector3f> turned;
  estimateNormals (t.points, g, 1, turned);
  refineNormalsTrimmed (t.points, g, 1, turned);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < s.size (); ++i)
    differ += angleTo (turned[i], r * one[i]) > 1e-3;
  EXPECT_LT (differ, s.size () / 200);
}

TEST (TrimmedNormals, TooFewNeighboursOrMismatchedSizesChangeNothing)
{
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 10, 10, 0.0f, 1);
  const NeighborGraph g = rspd_test::bruteForceGraph (s.points, 2);
  std::vector<Eigen::Vector3f> n (s.size (), Eigen::Vector3f::UnitX ());
  refineNormalsTrimmed (s.points, g, 1, n);
  for (const auto& v : n)
    EXPECT_EQ (v, Eigen::Vector3f::UnitX ());
  const NeighborGraph g50 = rspd_test::bruteForceGraph (s.points, 50);
  std::vector<Eigen::Vector3f> short_normals (3, Eigen::Vector3f::UnitX ());
  refineNormalsTrimmed (s.points, g50, 1, short_normals);
  EXPECT_EQ (short_normals.size (), 3u);
}

TEST (TrimmedNormals, ASubsetRefitsOnlyItsOwnSamplesAndAsAWholeRunWould)
{
  // The detector refits only the samples growth left (DetectorParameters::left_normal_refit).
  std::vector<int> face;
  const PointSet s = roof (face);
  const BothFits f = fitBoth (s);
  std::vector<std::uint32_t> subset;
  for (std::uint32_t i = 0; i < s.size (); i += 7)
    subset.push_back (i);
  std::vector<Eigen::Vector3f> part = f.pca;
  TrimmedNormalStatistics stats;
  refineNormalsTrimmed (s.points, f.graph, 2, part, &stats, &subset);
  std::size_t changed = 0;
  for (std::uint32_t i = 0; i < s.size (); ++i)
  {
    const bool in_subset = i % 7 == 0;
    EXPECT_EQ (part[i], in_subset ? f.trimmed[i] : f.pca[i]) << i;
    changed += part[i] != f.pca[i];
  }
  EXPECT_GT (changed, 0u);
  EXPECT_LE (stats.refined, subset.size ());
  EXPECT_GE (stats.refined, changed);
  // An empty subset changes nothing.
  std::vector<Eigen::Vector3f> none = f.pca;
  const std::vector<std::uint32_t> empty;
  refineNormalsTrimmed (s.points, f.graph, 1, none, nullptr, &empty);
  EXPECT_EQ (none, f.pca);
}
