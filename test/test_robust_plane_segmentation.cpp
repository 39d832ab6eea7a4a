/*
 * Tests of pcl::RobustPlaneSegmentation: PCL conventions, failure paths, outputs, invariances.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/robust_plane_segmentation.h>
#include <pcl_rspd/impl/robust_plane_segmentation.hpp> // detail::convexHull2D

#include <pcl/search/kdtree.h>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>

namespace
{
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

/** Three faces of a unit box corner (x = 0, y = 0, z = 0 planes), σ = 2 mm unless given, with
  * truth 1..3. */
Cloud::Ptr
boxCorner (int per_face = 3000, std::vector<int>* truth = nullptr, std::uint32_t seed = 1, float sigma = 0.002f)
{
  auto cloud = std::make_shared<Cloud> ();
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  std::normal_distribution<float> g (0.0f, sigma);
  for (int f = 0; f < 3; ++f)
    for (int i = 0; i < per_face; ++i)
    {
      float c[3] = {u (rng), u (rng), u (rng)};
      c[f] = g (rng);
      cloud->push_back (pcl::PointXYZ (c[0], c[1], c[2]));
      if (truth)
        truth->push_back (f + 1);
    }
  return cloud;
}

/** The exact unit normal of each boxCorner point, from its truth label (1..3: x, y, z). */
pcl::PointCloud<pcl::Normal>::Ptr
exactNormals (const std::vector<int>& truth)
{
  auto normals = std::make_shared<pcl::PointCloud<pcl::Normal>> ();
  for (const int t : truth)
  {
    pcl::Normal n (0, 0, 0);
    n.normal[t - 1] = 1.0f;
    normals->push_back (n);
  }
  return normals;
}

/** Share of points whose labels agree up to a relabeling (best one-to-one by majority). */
double
agreement (const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> joint;
  for (std::size_t i = 0; i < a.size (); ++i)
    ++joint[{a[i], b[i]}];
  std::map<std::uint32_t, std::pair<std::uint32_t, std::size_t>> best;
  for (const auto& [key, count] : joint)
    if (count > best[key.first].second)
      best[key.first] = {key.second, count};
  std::size_t same = 0;
  for (const auto& [la, pick] : best)
    same += pick.second;
  return static_cast<double> (same) / a.size ();
}

std::vector<std::uint32_t>
labelsOf (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& seg)
{
  pcl::PointCloud<pcl::Label> l;
  seg.getLabels (l);
  std::vector<std::uint32_t> out;
  for (const auto& x : l)
    out.push_back (x.label);
  return out;
}
} // namespace

TEST (RobustPlaneSegmentation, SegmentWithoutCloudFailsWithEmptyOutput)
{
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  std::vector<pcl::ModelCoefficients> c (1);
  std::vector<pcl::PointIndices> i (1);
  seg.segment (c, i);
  EXPECT_TRUE (c.empty ());
  EXPECT_TRUE (i.empty ());
  EXPECT_FALSE (seg.hasResult ());
  EXPECT_EQ (seg.getColoredCloud (), nullptr);
}

TEST (RobustPlaneSegmentation, SegmentEmptyCloud)
{
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (std::make_shared<Cloud> ());
  pcl::PointIndices inl;
  pcl::ModelCoefficients co;
  inl.indices = {1, 2};
  seg.segment (inl, co);
  EXPECT_TRUE (inl.indices.empty ());
  EXPECT_TRUE (co.values.empty ());
}

TEST (RobustPlaneSegmentation, SegmentAllNaNCloud)
{
  auto cloud = std::make_shared<Cloud> ();
  for (int i = 0; i < 100; ++i)
    cloud->push_back (pcl::PointXYZ (NAN, NAN, NAN));
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  std::vector<pcl::ModelCoefficients> c;
  std::vector<pcl::PointIndices> i;
  seg.segment (c, i);
  EXPECT_TRUE (i.empty ());
  pcl::PointCloud<pcl::Label> labels;
  seg.getLabels (labels);
  EXPECT_TRUE (labels.empty ());
}

TEST (RobustPlaneSegmentation, SegmentWithDifferentNormalAndCloudSize)
{
  auto cloud = boxCorner (200);
  auto normals = std::make_shared<pcl::PointCloud<pcl::Normal>> ();
  normals->resize (cloud->size () - 1);
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  seg.setInputNormals (normals);
  std::vector<pcl::ModelCoefficients> c;
  std::vector<pcl::PointIndices> i;
  seg.segment (c, i);
  EXPECT_TRUE (i.empty ());
}

TEST (RobustPlaneSegmentation, SegmentWithIndicesOutOfRange)
{
  auto cloud = boxCorner (200);
  auto idx = std::make_shared<pcl::Indices> (pcl::Indices{0, 1, static_cast<pcl::index_t> (cloud->size ())});
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  seg.setIndices (idx);
  std::vector<pcl::ModelCoefficients> c;
  std::vector<pcl::PointIndices> i;
  seg.segment (c, i);
  EXPECT_TRUE (i.empty ());
  idx->back () = -1;
  seg.setIndices (idx);
  seg.segment (c, i);
  EXPECT_TRUE (i.empty ());
}

TEST (RobustPlaneSegmentation, SegmentWithFewerPointsThanK)
{
  auto cloud = boxCorner (10); // 30 points
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  seg.setNumberOfNeighbours (50);
  std::vector<pcl::ModelCoefficients> c;
  std::vector<pcl::PointIndices> i;
  seg.segment (c, i);
  EXPECT_TRUE (i.empty ());
  EXPECT_FALSE (seg.hasResult ());
  seg.setNumberOfNeighbours (10); // now enough
  seg.segment (c, i);
  EXPECT_TRUE (seg.hasResult ());
  EXPECT_EQ (seg.getNumberOfNeighboursUsed (), 10);
  seg.setNumberOfNeighbours (0); // automatic: 15 (ε = 10), enough for 30 points too
  EXPECT_EQ (seg.getNumberOfNeighbours (), 0);
  seg.segment (c, i);
  EXPECT_TRUE (seg.hasResult ());
  EXPECT_EQ (seg.getNumberOfNeighboursUsed (), 15);
  auto tiny = boxCorner (5); // 15 points: not more than the automatic k
  seg.setInputCloud (tiny);
  seg.segment (c, i);
  EXPECT_TRUE (i.empty ());
  EXPECT_FALSE (seg.hasResult ());
}

TEST (RobustPlaneSegmentation, AutomaticNumberOfNeighboursIsHalfEpsilonBetween15And50)
{
  EXPECT_EQ (pcl::rspd::automaticNumberOfNeighbours (10), 15);
  EXPECT_EQ (pcl::rspd::automaticNumberOfNeighbours (31), 15);
  EXPECT_EQ (pcl::rspd::automaticNumberOfNeighbours (50), 25);
  EXPECT_EQ (pcl::rspd::automaticNumberOfNeighbours (99), 49);
  EXPECT_EQ (pcl::rspd::automaticNumberOfNeighbours (100), 50);
  EXPECT_EQ (pcl::rspd::automaticNumberOfNeighbours (1000), 50);

  // The default: ε = 0.1 % of the valid points; the paper's 50 from 100,000 on; a k set wins.
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  EXPECT_EQ (seg.getNumberOfNeighbours (), 0);
  EXPECT_EQ (seg.getNumberOfNeighboursUsed (), 0);
  seg.setInputCloud (boxCorner (10000)); // 30,000 points: ε = 30
  std::vector<pcl::ModelCoefficients> c;
  std::vector<pcl::PointIndices> i;
  seg.segment (c, i);
  EXPECT_EQ (seg.getNumberOfNeighboursUsed (), 15);
  seg.setMinPatchSize (80);
  seg.segment (c, i);
  EXPECT_EQ (seg.getNumberOfNeighboursUsed (), 40);
  seg.setNumberOfNeighbours (50);
  seg.segment (c, i);
  EXPECT_EQ (seg.getNumberOfNeighboursUsed (), 50);

  // With the caller's normals, whose scale is theirs, automatic means the paper's 50.
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> given;
  const auto cloud = boxCorner (10000);
  auto normals = std::make_shared<pcl::PointCloud<pcl::Normal>> ();
  for (const auto& p : *cloud)
  {
    // The box corner's faces are x = 0, y = 0 and z = 0.
    const float ax = std::abs (p.x), ay = std::abs (p.y), az = std::abs (p.z);
    normals->push_back (ax <= ay && ax <= az ? pcl::Normal (1, 0, 0) : (ay <= az ? pcl::Normal (0, 1, 0) : pcl::Normal (0, 0, 1)));
  }
  given.setInputCloud (cloud);
  given.setInputNormals (normals);
  given.segment (c, i);
  EXPECT_EQ (given.getNumberOfNeighboursUsed (), 50);
  EXPECT_EQ (i.size (), 3u);
}

TEST (RobustPlaneSegmentation, SegmentWithWrongParametersKeepsOldValues)
{
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setNumberOfNeighbours (2);
  EXPECT_EQ (seg.getNumberOfNeighbours (), 0);
  seg.setNumberOfNeighbours (-1);
  EXPECT_EQ (seg.getNumberOfNeighbours (), 0);
  seg.setMinPatchSizeRatio (-1.0);
  EXPECT_DOUBLE_EQ (seg.getMinPatchSizeRatio (), 0.001);
  seg.setMaxOutlierRatio (2.0);
  EXPECT_DOUBLE_EQ (seg.getMaxOutlierRatio (), 0.25);
  seg.setMinDistanceTestAngle (2.0);
  EXPECT_NEAR (seg.getMinDistanceTestAngle (), 75.0 * M_PI / 180.0, 1e-12);
  EXPECT_NEAR (seg.getMaxNormalDeviation (), 60.0 * M_PI / 180.0, 1e-12);
  EXPECT_DOUBLE_EQ (seg.getAlpha (), 3.0);
}

TEST (RobustPlaneSegmentation, NonPlaneModelIsRefused)
{
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (boxCorner (300));
  seg.setModelType (pcl::SACMODEL_CYLINDER);
  pcl::PointIndices inl;
  pcl::ModelCoefficients co;
  seg.segment (inl, co);
  EXPECT_TRUE (inl.indices.empty ());
  seg.setModelType (pcl::SACMODEL_PLANE);
  seg.segment (inl, co);
  EXPECT_FALSE (inl.indices.empty ());
}

TEST (RobustPlaneSegmentation, SwapsInForSacSegmentation)
{
  // The setters a SACSegmentation pipeline calls compile and are harmless.
  auto cloud = boxCorner (2000);
  cloud->header.frame_id = "scanner";
  cloud->header.stamp = 42;
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setOptimizeCoefficients (true);
  seg.setModelType (pcl::SACMODEL_PLANE);
  seg.setMethodType (pcl::SAC_RANSAC);
  seg.setDistanceThreshold (0.01);
  seg.setMaxIterations (1000);
  seg.setProbability (0.99);
  seg.setInputCloud (cloud);
  pcl::PointIndices inliers;
  pcl::ModelCoefficients coefficients;
  seg.segment (inliers, coefficients);
  ASSERT_EQ (coefficients.values.size (), 4u);
  EXPECT_GT (inliers.indices.size (), 1500u);
  EXPECT_EQ (inliers.header.frame_id, "scanner");
  EXPECT_EQ (coefficients.header.stamp, 42u);
  const Eigen::Vector3f n (coefficients.values[0], coefficients.values[1], coefficients.values[2]);
  EXPECT_NEAR (n.norm (), 1.0f, 1e-5f);
}

TEST (RobustPlaneSegmentation, FindsTheThreeFacesWithConsistentOutputs)
{
  std::vector<int> truth;
  auto cloud = boxCorner (3000, &truth);
  cloud->sensor_origin_ = Eigen::Vector4f (2, 2, 2, 0);
  const Cloud before = *cloud;
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> indices;
  seg.segment (coefficients, indices);
  ASSERT_EQ (indices.size (), 3u);
  const auto labels = labelsOf (seg);
  ASSERT_EQ (labels.size (), cloud->size ());
  for (std::size_t p = 0; p < indices.size (); ++p)
  {
    if (p > 0)
      EXPECT_GE (indices[p - 1].indices.size (), indices[p].indices.size ()) << "largest first";
    EXPECT_GT (indices[p].indices.size (), 2400u);
    EXPECT_TRUE (std::is_sorted (indices[p].indices.begin (), indices[p].indices.end ()));
    // Each plane lies on one face (up to the few samples right at an edge, within MDP of both
    // faces); the normal points towards the sensor origin (2, 2, 2).
    std::map<int, int> faces;
    for (const auto i : indices[p].indices)
    {
      ++faces[truth[i]];
      EXPECT_EQ (labels[i], p + 1);
    }
    const auto face = std::max_element (faces.begin (), faces.end (),
                                        [] (const auto& a, const auto& b) { return a.second < b.second; })->first;
    EXPECT_GE (faces[face], static_cast<int> (indices[p].indices.size () * 99 / 100));
    const auto& v = coefficients[p].values;
    EXPECT_GT (v[0] * 2 + v[1] * 2 + v[2] * 2 + v[3], 0.0f);
    EXPECT_NEAR (std::abs (v[face - 1]), 1.0f, 0.01f);
    EXPECT_NEAR (v[3], 0.0f, 0.01f);
    const pcl::RobustPlane& plane = seg.getPlanes ()[p];
    EXPECT_GT (plane.mdp, 0.0);
    EXPECT_LT (plane.mdp, 0.02);
    EXPECT_GE (plane.hull.size (), 4u);
    // A unit face. PCA normals bend within a few spacings of the edges, where growth stops; the
    // last assignment pass gives those samples to the face they are nearest, so the plane reaches
    // the edges (without it, about 0.95: see FinalAssignmentReachesTheEdges).
    EXPECT_NEAR (plane.rect_size[0], 1.0, 0.02);
    EXPECT_NEAR (plane.rect_size[1], 1.0, 0.02);
    EXPECT_LE (plane.rect_size[1], plane.rect_size[0]);
    EXPECT_NEAR (plane.centroid[face - 1], 0.0, 0.01);
  }
  // The caller's cloud is untouched.
  ASSERT_EQ (before.size (), cloud->size ());
  for (std::size_t i = 0; i < before.size (); ++i)
    EXPECT_TRUE (before[i].x == (*cloud)[i].x && before[i].y == (*cloud)[i].y && before[i].z == (*cloud)[i].z);
  // A coloured cloud for viewing.
  const auto colored = seg.getColoredCloud ();
  ASSERT_TRUE (colored);
  EXPECT_EQ (colored->size (), cloud->size ());
}

TEST (RobustPlaneSegmentation, IndicesRestrictTheDetectionAndNaNPointsAreSkipped)
{
  std::vector<int> truth;
  auto cloud = boxCorner (3000, &truth);
  (*cloud)[5].x = NAN;
  (*cloud)[7].z = INFINITY;
  auto idx = std::make_shared<pcl::Indices> ();
  for (std::size_t i = 0; i < cloud->size (); ++i)
    if (truth[i] != 2)
      idx->push_back (static_cast<pcl::index_t> (i));
  idx->push_back (idx->front ()); // a repeated index is ignored
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  seg.setIndices (idx);
  std::vector<pcl::ModelCoefficients> c;
  std::vector<pcl::PointIndices> ind;
  seg.segment (c, ind);
  ASSERT_EQ (ind.size (), 2u);
  for (const auto& pi : ind)
    for (const auto i : pi.indices)
    {
      EXPECT_NE (truth[i], 2);
      EXPECT_NE (i, 5);
      EXPECT_NE (i, 7);
    }
  EXPECT_EQ (seg.getValidIndices ().size (), 6000u - 2u);
}

TEST (RobustPlaneSegmentation, OwnNeighbourGraphAgreesWithKdTreeSearch)
{
  auto cloud = boxCorner (2000);
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> a, b;
  a.setInputCloud (cloud);
  b.setInputCloud (cloud);
  b.setSearchMethod (std::make_shared<pcl::search::KdTree<pcl::PointXYZ>> ());
  const auto la = labelsOf (a), lb = labelsOf (b);
  EXPECT_GE (agreement (la, lb), 0.999);
}

TEST (RobustPlaneSegmentation, FinalAssignmentReachesTheEdges)
{
  std::vector<int> truth;
  auto cloud = boxCorner (3000, &truth);
  std::size_t labelled[3] = {0, 0, 0};
  double extent[3] = {0, 0, 0};
  int run = 0;
  for (const auto mode : {pcl::rspd::FinalAssignment::None, pcl::rspd::FinalAssignment::Edges, pcl::rspd::FinalAssignment::All})
  {
    pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
    seg.setInputCloud (cloud);
    seg.setNormalFit (pcl::rspd::NormalFit::Pca); // the bands of bent PCA normals are the point here (default)
    seg.setNumberOfNeighbours (50); // the paper's k: at 9000 points the automatic 15 bends little
    seg.setFinalAssignment (mode);
    EXPECT_EQ (seg.getFinalAssignment (), mode);
    std::vector<pcl::ModelCoefficients> c;
    std::vector<pcl::PointIndices> ind;
    seg.segment (c, ind);
    ASSERT_EQ (ind.size (), 3u);
    for (const auto& pi : ind)
      labelled[run] += pi.indices.size ();
    extent[run] = seg.getPlanes ()[0].rect_size[1];
    ++run;
  }
  // The paper stops short of the edges; the pass fills the bands of bent normals. Nearly every
  // sample left out is next to two faces here, so All adds only a handful to Edges (the outer rims).
  EXPECT_LT (extent[0], 0.98);
  EXPECT_GT (extent[1], 0.99);
  EXPECT_GT (labelled[1], labelled[0] + 150);
  EXPECT_GE (labelled[1], 9000u * 99 / 100);
  EXPECT_GE (labelled[2], labelled[1]);
  EXPECT_LE (labelled[2], labelled[1] + 20);
}

TEST (RobustPlaneSegmentation, TailsAssignmentTakesThePlanesNoiseTailOnly)
{
  // A plane with Gaussian noise (σ = 1 % of its side) and clutter above and below it. Growth's band
  // (median + α MAD of |d|) is about 2.45 σ, so a few % of the plane stay out; Tails takes those
  // within 4 robust σ whose normals agree, and no clutter sample farther than that.
  auto cloud = std::make_shared<Cloud> ();
  std::mt19937 rng (3);
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  std::normal_distribution<float> noise (0.0f, 0.01f);
  const int on_plane = 20000;
  for (int i = 0; i < on_plane; ++i)
    cloud->push_back (pcl::PointXYZ (u (rng), u (rng), noise (rng)));
  for (int i = 0; i < 600; ++i)
    cloud->push_back (pcl::PointXYZ (u (rng), u (rng), 0.4f * u (rng) - 0.2f));
  std::size_t taken[2] = {0, 0}, clutter_far[2] = {0, 0};
  double tail_max = 0.0;
  std::vector<std::uint32_t> edges_label;
  int run = 0;
  for (const auto mode : {pcl::rspd::FinalAssignment::Edges, pcl::rspd::FinalAssignment::Tails})
  {
    pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
    seg.setInputCloud (cloud);
    seg.setFinalAssignment (mode);
    EXPECT_EQ (seg.getFinalAssignment (), mode);
    const auto labels = labelsOf (seg);
    ASSERT_EQ (seg.getPlanes ().size (), 1u);
    for (int i = 0; i < static_cast<int> (labels.size ()); ++i)
    {
      if (labels[i] == 0)
        continue;
      const float z = std::abs ((*cloud)[i].z);
      if (i < on_plane)
        ++taken[run];
      else if (z > 0.045f)
        ++clutter_far[run];
      if (run == 1 && edges_label[i] == 0)
        tail_max = std::max (tail_max, static_cast<double> (z));
    }
    if (run == 0)
      edges_label = labels;
    else
      for (std::size_t i = 0; i < labels.size (); ++i)
        EXPECT_TRUE (edges_label[i] == 0 || labels[i] == edges_label[i]) << i; // only adds
    ++run;
  }
  EXPECT_LT (taken[0], on_plane * 99u / 100u);
  EXPECT_GT (taken[1], taken[0] + on_plane / 200u);
  EXPECT_LE (tail_max, 0.045); // 4.5 σ: 4 σ plus the estimates' error
  EXPECT_EQ (clutter_far[1], clutter_far[0]);
}

TEST (RobustPlaneSegmentation, TailOddsEndTheTailInClutterAndKeepItOnACleanPlane)
{
  // A plane with Gaussian noise (σ = 1 % of its side) in clutter dense enough (3,000 samples over
  // ±20 σ) to outnumber its noise beyond about 3.1 σ: with tail odds the last assignment takes far
  // fewer clutter samples at 3.5-4.5 σ than the 4 σ tail does, and loses few of the plane's own.
  // Without clutter the tail is the 4 σ one: the labels are the same either way. The plane
  // support's clutter share is off: it releases a few more of the plane's own tail samples where the
  // tail ends (46 rather than the 40 allowed below, with the odds on).
  const float sigma = 0.01f;
  const int on_plane = 20000;
  auto clean = std::make_shared<Cloud> ();
  std::mt19937 rng (5);
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  std::normal_distribution<float> noise (0.0f, sigma);
  for (int i = 0; i < on_plane; ++i)
    clean->push_back (pcl::PointXYZ (u (rng), u (rng), noise (rng)));
  auto cluttered = std::make_shared<Cloud> (*clean);
  for (int i = 0; i < 3000; ++i)
    cluttered->push_back (pcl::PointXYZ (u (rng), u (rng), 40.0f * sigma * (u (rng) - 0.5f)));

  const auto run = [] (const std::shared_ptr<Cloud>& cloud, bool odds) {
    pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
    seg.setInputCloud (cloud);
    seg.setTailOdds (odds);
    EXPECT_EQ (seg.getTailOdds (), odds);
    seg.setSupportClutter (false);
    return labelsOf (seg);
  };
  const auto clean_labels = run (clean, true);
  EXPECT_EQ (clean_labels, run (clean, false));
  EXPECT_EQ (*std::max_element (clean_labels.begin (), clean_labels.end ()), 1u);

  // (The clutter may hold a plane of its own, by position; only the plane's tail is counted.)
  std::size_t own[2] = {0, 0}, far_clutter[2] = {0, 0};
  for (const bool odds : {false, true})
  {
    const auto labels = run (cluttered, odds);
    std::map<std::uint32_t, int> votes;
    for (int i = 0; i < on_plane; ++i)
      ++votes[labels[i]];
    const auto plane = std::max_element (votes.begin (), votes.end (), [] (const auto& a, const auto& b) {
                         return a.second < b.second; })->first;
    ASSERT_NE (plane, 0u);
    for (int i = 0; i < static_cast<int> (labels.size ()); ++i)
    {
      if (labels[i] != plane)
        continue;
      const float z = std::abs ((*cluttered)[i].z) / sigma;
      if (i < on_plane)
        ++own[odds];
      else if (z > 3.5f && z <= 4.5f)
        ++far_clutter[odds];
    }
  }
  EXPECT_GT (far_clutter[0], 10u);
  EXPECT_LT (2 * far_clutter[1], far_clutter[0]);
  EXPECT_GE (own[1] + on_plane / 500u, own[0]); // 0.2 %: the tail beyond 3.1 σ holds 0.19 %
}

TEST (RobustPlaneSegmentation, TailsAssignmentTakesSamplesInsideThePlaneWhateverTheirNormal)
{
  // A noisy plane whose given normals are exact but for every 20th sample's, which lies in the plane.
  // Growth rejects those by their normal; inside the plane's band (MDP) Tails takes them back, since
  // most of their neighbours are members; beyond it the normal must still agree, so those stay out.
  auto cloud = std::make_shared<Cloud> ();
  auto normals = std::make_shared<pcl::PointCloud<pcl::Normal>> ();
  std::mt19937 rng (5);
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  std::normal_distribution<float> noise (0.0f, 0.005f);
  const int n = 20000;
  for (int i = 0; i < n; ++i)
  {
    cloud->push_back (pcl::PointXYZ (u (rng), u (rng), noise (rng)));
    normals->push_back (i % 20 == 0 ? pcl::Normal (1.0f, 0.0f, 0.0f) : pcl::Normal (0.0f, 0.0f, 1.0f));
  }
  std::size_t bent_taken[2] = {0, 0}, bent_far_taken = 0, bent = 0, bent_far = 0;
  int run = 0;
  for (const auto mode : {pcl::rspd::FinalAssignment::Edges, pcl::rspd::FinalAssignment::Tails})
  {
    pcl::RobustPlaneSegmentation<pcl::PointXYZ, pcl::Normal> seg;
    seg.setInputCloud (cloud);
    seg.setInputNormals (normals);
    seg.setFinalAssignment (mode);
    std::vector<pcl::ModelCoefficients> c;
    std::vector<pcl::PointIndices> ind;
    seg.segment (c, ind);
    ASSERT_EQ (ind.size (), 1u);
    const double mdp = seg.getPlanes ()[0].mdp;
    std::vector<char> in (n, 0);
    for (const auto i : ind[0].indices)
      in[i] = 1;
    for (int i = 0; i < n; i += 20)
    {
      const bool far = std::abs ((*cloud)[i].z) > 1.1 * mdp;
      if (run == 0)
      {
        ++bent;
        bent_far += far;
      }
      bent_taken[run] += in[i];
      if (run == 1 && far)
        bent_far_taken += in[i];
    }
    ++run;
  }
  EXPECT_LT (bent_taken[0], bent / 20);        // growth and Edges leave them out
  EXPECT_GT (bent_taken[1], bent * 95 / 100);  // Tails takes those inside the band back
  EXPECT_GT (bent_far, 5u);
  EXPECT_EQ (bent_far_taken, 0u);              // and none in the tail
}

TEST (RobustPlaneSegmentation, NoiseFreeCornerWithTrimmedNormalsKeepsEveryFace)
{
  // Exact normals put most seeds' MND at the normal-deviation floor (MAD = 0); one face whose
  // normals round 1e-4 rad differently was then all "outlier seeds" and lost. The outlier limit is
  // widened by the floor.
  auto cloud = std::make_shared<Cloud> ();
  std::mt19937 rng (1);
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  for (int f = 0; f < 3; ++f)
    for (int i = 0; i < 2000; ++i)
    {
      float c[3] = {u (rng), u (rng), u (rng)};
      c[f] = 0.0f;
      cloud->push_back (pcl::PointXYZ (c[0], c[1], c[2]));
    }
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  seg.setNormalFit (pcl::rspd::NormalFit::TrimmedPlane);
  EXPECT_EQ (seg.getNormalFit (), pcl::rspd::NormalFit::TrimmedPlane);
  std::vector<pcl::ModelCoefficients> c;
  std::vector<pcl::PointIndices> ind;
  seg.segment (c, ind);
  ASSERT_EQ (ind.size (), 3u);
  for (const auto& pi : ind)
    EXPECT_GE (pi.indices.size (), 1900u);
  EXPECT_GT (seg.getTrimmedNormalStatistics ().refined, 0u);
}

TEST (RobustPlaneSegmentation, GivenNormalsAreUsed)
{
  std::vector<int> truth;
  auto cloud = boxCorner (2000, &truth);
  auto normals = std::make_shared<pcl::PointCloud<pcl::Normal>> ();
  for (std::size_t i = 0; i < cloud->size (); ++i)
  {
    pcl::Normal n (0, 0, 0);
    n.normal[truth[i] - 1] = (i % 2) ? 1.0f : -1.0f; // exact, with random signs
    normals->push_back (n);
  }
  (*normals)[3].normal_x = NAN; // left out
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  seg.setInputNormals (normals);
  std::vector<pcl::ModelCoefficients> c;
  std::vector<pcl::PointIndices> ind;
  seg.segment (c, ind);
  ASSERT_EQ (ind.size (), 3u);
  EXPECT_EQ (seg.getValidIndices ().size (), 5999u);
  for (const auto& pi : ind)
    EXPECT_GT (pi.indices.size (), 1900u); // exact normals: nearly every sample joins
}

TEST (RobustPlaneSegmentation, PassTimesNameEachPassOnceAndSumToTheGrowMergeStage)
{
  auto cloud = boxCorner (3000, nullptr);
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  std::vector<pcl::ModelCoefficients> c;
  std::vector<pcl::PointIndices> ind;
  seg.segment (c, ind);
  ASSERT_EQ (ind.size (), 3u);
  const auto& st = seg.getStatistics ();
  ASSERT_FALSE (st.pass_seconds.empty ());
  EXPECT_EQ (st.pass_seconds.front ().first, "grow-merge");
  std::set<std::string> names;
  double sum = 0.0;
  for (const auto& pass : st.pass_seconds)
  {
    EXPECT_TRUE (names.insert (pass.first).second) << pass.first << " listed twice";
    EXPECT_GE (pass.second, 0.0);
    sum += pass.second;
  }
  for (const char* pass : {"small planes", "step split", "edge sides", "plane support"})
    EXPECT_EQ (names.count (pass), 1u) << pass;
  // The laps partition the stage: their sum is its time, up to the clock reads between them.
  EXPECT_LE (sum, st.grow_merge_seconds + 1e-6);
  EXPECT_GE (sum, 0.5 * st.grow_merge_seconds);
  // A second run starts the list again.
  const std::size_t passes = st.pass_seconds.size ();
  seg.setInputCloud (cloud); // a new input: detected again, not cached
  seg.segment (c, ind);
  EXPECT_EQ (seg.getStatistics ().pass_seconds.size (), passes);
}

TEST (RobustPlaneSegmentation, LeftNormalsAreTrimmedForGivenNormalsNarrowedForOwnAndSwitchable)
{
  // 60,000 samples: ε = 60, so the small-plane pass (cells down to 30) runs.
  std::vector<int> truth;
  auto cloud = boxCorner (20000, &truth);
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  EXPECT_FALSE (seg.getLeftNormalRefit ());
  EXPECT_TRUE (seg.getLeftNormalNarrowing ());
  EXPECT_TRUE (seg.getShiftedGrid ());
  seg.setInputCloud (cloud);
  std::vector<pcl::ModelCoefficients> c;
  std::vector<pcl::PointIndices> on, off;
  seg.setLeftNormalRefit (true);
  EXPECT_TRUE (seg.getLeftNormalRefit ());
  seg.segment (c, on);
  ASSERT_EQ (on.size (), 3u);
  EXPECT_GT (seg.getStatistics ().left_refitted, 0u); // the edge bands growth left
  // Without the trimmed refit, the normals the k-neighbourhoods' PCA gave are narrowed at the edges
  // for the second split (setLeftNormalNarrowing, on by default); exact planes: no seed more.
  seg.setLeftNormalRefit (false);
  seg.segment (c, off);
  ASSERT_EQ (off.size (), 3u);
  EXPECT_GT (seg.getStatistics ().left_refitted, 0u);
  seg.setLeftNormalNarrowing (false);
  EXPECT_FALSE (seg.getLeftNormalNarrowing ());
  std::vector<pcl::PointIndices> none;
  seg.segment (c, none);
  ASSERT_EQ (none.size (), 3u);
  EXPECT_EQ (seg.getStatistics ().left_refitted, 0u);
  EXPECT_EQ (seg.getStatistics ().small_seeds_trimmed, 0u);
  for (std::size_t p = 0; p < none.size (); ++p)
    EXPECT_EQ (none[p].indices, off[p].indices);
  seg.setLeftNormalNarrowing (true);
  // Not with trimmed normals everywhere.
  seg.setLeftNormalRefit (true);
  seg.setNormalFit (pcl::rspd::NormalFit::TrimmedPlane);
  seg.segment (c, off);
  ASSERT_EQ (off.size (), 3u);
  EXPECT_EQ (seg.getStatistics ().left_refitted, 0u);
  seg.setNormalFit (pcl::rspd::NormalFit::Pca);
  // The caller's normals have a switch of their own, on by default, whatever setLeftNormalRefit says.
  const auto normals = exactNormals (truth);
  seg.setInputNormals (normals);
  seg.setLeftNormalRefit (false);
  EXPECT_TRUE (seg.getLeftNormalRefitOnGivenNormals ());
  seg.segment (c, on);
  ASSERT_EQ (on.size (), 3u);
  EXPECT_GT (seg.getStatistics ().left_refitted, 0u);
  seg.setLeftNormalRefit (true);
  seg.setLeftNormalRefitOnGivenNormals (false);
  EXPECT_FALSE (seg.getLeftNormalRefitOnGivenNormals ());
  seg.segment (c, off);
  ASSERT_EQ (off.size (), 3u);
  EXPECT_EQ (seg.getStatistics ().left_refitted, 0u);
  for (std::size_t p = 0; p < on.size (); ++p) // exact normals: the refit seeds nothing more
    EXPECT_EQ (on[p].indices, off[p].indices);
}

TEST (RobustPlaneSegmentation, EdgeAwareNormalsAreOffByDefaultAndOnlyForEstimatedPcaNormals)
{
  // 60,000 samples: k = 30, so prefixes of 15 to 30 neighbours are tried.
  std::vector<int> truth;
  auto cloud = boxCorner (20000, &truth);
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  EXPECT_FALSE (seg.getEdgeAwareNormals ());
  seg.setInputCloud (cloud);
  std::vector<pcl::ModelCoefficients> c;
  std::vector<pcl::PointIndices> off, on, on_again;
  seg.segment (c, off);
  ASSERT_EQ (off.size (), 3u);
  EXPECT_EQ (seg.getStatistics ().edge_narrowed_normals, 0u);
  seg.setEdgeAwareNormals (true);
  EXPECT_TRUE (seg.getEdgeAwareNormals ());
  seg.segment (c, on);
  ASSERT_EQ (on.size (), 3u);
  const std::size_t narrowed = seg.getStatistics ().edge_narrowed_normals;
  EXPECT_GT (narrowed, 0u); // the samples near the corner's three edges
  EXPECT_LT (narrowed, cloud->size () / 10);
  // Per sample: the thread count changes nothing.
  seg.setNumberOfThreads (1);
  seg.segment (c, on_again);
  EXPECT_EQ (seg.getStatistics ().edge_narrowed_normals, narrowed);
  ASSERT_EQ (on_again.size (), on.size ());
  for (std::size_t p = 0; p < on.size (); ++p)
    EXPECT_EQ (on[p].indices, on_again[p].indices);
  // Not with trimmed normals, nor with the caller's.
  seg.setNormalFit (pcl::rspd::NormalFit::TrimmedPlane);
  seg.segment (c, off);
  EXPECT_EQ (seg.getStatistics ().edge_narrowed_normals, 0u);
  seg.setNormalFit (pcl::rspd::NormalFit::Pca);
  const auto normals = exactNormals (truth);
  seg.setInputNormals (normals);
  seg.segment (c, off);
  ASSERT_EQ (off.size (), 3u);
  EXPECT_EQ (seg.getStatistics ().edge_narrowed_normals, 0u);
}

TEST (RobustPlaneSegmentation, DeterministicAcrossRunsAndThreads)
{
  auto cloud = boxCorner (3000);
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> one, two;
  one.setInputCloud (cloud);
  one.setNumberOfThreads (1);
  two.setInputCloud (cloud);
  two.setNumberOfThreads (2);
  std::vector<pcl::ModelCoefficients> c1, c2;
  std::vector<pcl::PointIndices> i1, i2;
  one.segment (c1, i1);
  two.segment (c2, i2);
  ASSERT_EQ (i1.size (), i2.size ());
  for (std::size_t p = 0; p < i1.size (); ++p)
  {
    EXPECT_EQ (i1[p].indices, i2[p].indices);
    EXPECT_EQ (c1[p].values, c2[p].values);
  }
}

TEST (RobustPlaneSegmentation, AdaptiveNormalScaleOnlyWhereTheNoiseSwampsTheNeighbourhood)
{
  // σ = 2 mm with 3000 samples per face: the k-neighbourhoods resolve the faces, so the option
  // changes nothing. σ = 1 cm with 20,000 per face and k = 10 (neighbourhood radius ~1.3 cm, the
  // regime of a million-sample unit cube with 1 % noise at k = 50): it widens most samples.
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> fixed, adaptive;
  fixed.setNumberOfNeighbours (50); // the paper's k, as the comment's radii assume
  adaptive.setNumberOfNeighbours (50);
  EXPECT_EQ (adaptive.getNormalScale (), pcl::rspd::NormalScale::Automatic); // the default
  fixed.setNormalScale (pcl::rspd::NormalScale::Fixed);
  adaptive.setNormalScale (pcl::rspd::NormalScale::Adaptive);
  EXPECT_EQ (adaptive.getNormalScale (), pcl::rspd::NormalScale::Adaptive);
  auto quiet = boxCorner (3000);
  fixed.setInputCloud (quiet);
  adaptive.setInputCloud (quiet);
  EXPECT_GE (agreement (labelsOf (fixed), labelsOf (adaptive)), 0.99);
  EXPECT_TRUE (fixed.getNormalScaleStatistics ().samples_per_scale.empty ());
  EXPECT_LE (adaptive.getNormalScaleStatistics ().widened (), 30u); // the corner's samples
  ASSERT_FALSE (adaptive.getNormalScaleStatistics ().samples_per_scale.empty ());
  EXPECT_EQ (adaptive.getNormalScaleStatistics ().samples_per_scale[0] + adaptive.getNormalScaleStatistics ().widened (),
             9000u);
  // Automatic: the k-scale resolves most samples, so nothing is widened and the labels are Fixed's.
  adaptive.setNormalScale (pcl::rspd::NormalScale::Automatic);
  EXPECT_EQ (labelsOf (adaptive), labelsOf (fixed));
  EXPECT_FALSE (adaptive.getNormalScaleStatistics ().widened_scales);
  EXPECT_EQ (adaptive.getNormalScaleStatistics ().widened (), 0u);
  adaptive.setNormalScale (pcl::rspd::NormalScale::Adaptive);

  auto noisy = boxCorner (20000, nullptr, 2, 0.01f);
  adaptive.setInputCloud (noisy);
  adaptive.setNumberOfNeighbours (10);
  adaptive.setNumberOfThreads (1);
  const auto one_thread = labelsOf (adaptive);
  const std::size_t widened = adaptive.getNormalScaleStatistics ().widened ();
  EXPECT_GT (widened, 30000u);
  adaptive.setNumberOfThreads (2);
  adaptive.setNormalScale (pcl::rspd::NormalScale::Adaptive); // invalidates: computed again
  EXPECT_EQ (labelsOf (adaptive), one_thread);
  EXPECT_EQ (adaptive.getNormalScaleStatistics ().widened (), widened);
  // Most samples are unresolved at the k-scale: Automatic widens as Adaptive does.
  adaptive.setNormalScale (pcl::rspd::NormalScale::Automatic);
  EXPECT_EQ (labelsOf (adaptive), one_thread);
  EXPECT_TRUE (adaptive.getNormalScaleStatistics ().widened_scales);

  // Given normals are used as they are.
  auto normals = std::make_shared<pcl::PointCloud<pcl::Normal>> ();
  for (std::size_t i = 0; i < noisy->size (); ++i)
    normals->push_back (pcl::Normal (0.f, 0.f, 1.f));
  adaptive.setInputNormals (normals);
  labelsOf (adaptive);
  EXPECT_TRUE (adaptive.hasResult ());
  EXPECT_TRUE (adaptive.getNormalScaleStatistics ().samples_per_scale.empty ());
}

TEST (RobustPlaneSegmentation, ResultIsCachedUntilAnInputChanges)
{
  auto cloud = boxCorner (1000);
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  std::vector<pcl::ModelCoefficients> c;
  std::vector<pcl::PointIndices> i;
  seg.segment (c, i);
  const pcl::RobustPlane* first = seg.getPlanes ().data ();
  seg.segment (c, i);
  EXPECT_EQ (seg.getPlanes ().data (), first) << "second call reuses the cached planes";
  seg.setMinPatchSize (50);
  seg.segment (c, i);
  EXPECT_EQ (seg.getResolvedMinPatchSize (), 50u);
}

TEST (RobustPlaneSegmentation, ScaleOffsetAndRotationDoNotChangeThePlanes)
{
  auto cloud = boxCorner (3000);
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  const auto base = labelsOf (seg);
  const Eigen::Matrix3f rot = (Eigen::AngleAxisf (0.7f, Eigen::Vector3f (1, 2, 3).normalized ())).toRotationMatrix ();
  // The same planes whatever the units, position or orientation. Memberships agree but for a few
  // edge samples: the corner's three faces tie for the dominant normal direction, so float rounding
  // of the scaled normals can change the order of the frame's axes, hence the order the seeds are
  // found in, and the face an ambiguous edge sample joins (0.993 for mm, 1.0 rotated).
  struct Variant { const char* name; float scale; Eigen::Vector3f offset; bool rotate; double min_agreement; };
  for (const Variant& v : {Variant{"mm", 1000.0f, Eigen::Vector3f::Zero (), false, 0.99},
                           Variant{"1 km away", 1.0f, Eigen::Vector3f (1000, -1000, 500), false, 0.99},
                           Variant{"rotated", 1.0f, Eigen::Vector3f::Zero (), true, 0.99}})
  {
    auto moved = std::make_shared<Cloud> ();
    for (const auto& p : *cloud)
    {
      Eigen::Vector3f q = p.getVector3fMap () * v.scale;
      if (v.rotate)
        q = rot * q;
      q += v.offset;
      moved->push_back (pcl::PointXYZ (q.x (), q.y (), q.z ()));
    }
    pcl::RobustPlaneSegmentation<pcl::PointXYZ> s2;
    s2.setInputCloud (moved);
    const auto l2 = labelsOf (s2);
    EXPECT_GE (agreement (base, l2), v.min_agreement) << v.name;
    EXPECT_EQ (*std::max_element (l2.begin (), l2.end ()), 3u) << v.name;
  }
}

TEST (RobustPlaneSegmentation, OtherPointTypesAreInstantiated)
{
  auto cloud = boxCorner (1000);
  auto rgb = std::make_shared<pcl::PointCloud<pcl::PointXYZRGB>> ();
  for (const auto& p : *cloud)
  {
    pcl::PointXYZRGB q;
    q.x = p.x; q.y = p.y; q.z = p.z;
    rgb->push_back (q);
  }
  pcl::RobustPlaneSegmentation<pcl::PointXYZRGB, pcl::PointNormal> seg;
  seg.setInputCloud (rgb);
  std::vector<pcl::ModelCoefficients> c;
  std::vector<pcl::PointIndices> i;
  seg.segment (c, i);
  EXPECT_EQ (i.size (), 3u);
}

TEST (RobustPlaneSegmentation, ConvexHullOfManyPointsIsTheHull)
{
  // Above 64 points the hull drops points inside the octagon of extremes before sorting: the
  // result must still be the convex hull: convex, counter-clockwise, made of input points, and
  // holding every input point.
  std::mt19937 rng (5);
  std::normal_distribution<double> g (0.0, 1.0);
  for (const std::size_t n : {65u, 1000u, 20000u})
  {
    std::vector<Eigen::Vector2d> pts (n);
    for (auto& p : pts)
      p = Eigen::Vector2d (3.0 * g (rng), g (rng));
    const std::vector<Eigen::Vector2d> hull = pcl::rspd::detail::convexHull2D (pts);
    ASSERT_GE (hull.size (), 3u);
    const auto cross = [] (const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
      return (a.x () - o.x ()) * (b.y () - o.y ()) - (a.y () - o.y ()) * (b.x () - o.x ());
    };
    for (std::size_t e = 0; e < hull.size (); ++e)
    {
      const Eigen::Vector2d& a = hull[e];
      const Eigen::Vector2d& b = hull[(e + 1) % hull.size ()];
      EXPECT_GT (cross (a, b, hull[(e + 2) % hull.size ()]), 0.0) << "convex, counter-clockwise";
      EXPECT_NE (std::find (pts.begin (), pts.end (), a), pts.end ()) << "a vertex is an input point";
      for (const auto& p : pts)
        ASSERT_GE (cross (a, b, p), -1e-9) << "every point inside, n = " << n;
    }
  }
}

TEST (RobustPlaneSegmentation, CurvedFoldRatioRefusesWhatIsNotPositive)
{
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  EXPECT_TRUE (seg.getCurvedPlaneCheck ());
  EXPECT_DOUBLE_EQ (seg.getCurvedFoldRatio (), 0.5);
  for (const double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN ()})
  {
    seg.setCurvedFoldRatio (bad); // refused with PCL_ERROR
    EXPECT_DOUBLE_EQ (seg.getCurvedFoldRatio (), 0.5) << bad;
  }
  seg.setCurvedFoldRatio (std::numeric_limits<double>::infinity ()); // every curved plane dropped
  EXPECT_EQ (seg.getCurvedFoldRatio (), std::numeric_limits<double>::infinity ());
}

TEST (RobustPlaneSegmentation, EverySwitchRoundTripsThroughItsGetter)
{
  // Each on/off switch of the API, flipped and flipped back, reads back what was set, and no other
  // switch moves with it (a setter writing the wrong field would show here, not in a scene).
  using Seg = pcl::RobustPlaneSegmentation<pcl::PointXYZ>;
  struct Switch
  {
    const char* name;
    void (Seg::*set) (bool);
    bool (Seg::*get) () const;
  };
#define RSPD_SWITCH(n) Switch{#n, &Seg::set##n, &Seg::get##n}
  const std::vector<Switch> switches{
    RSPD_SWITCH (AlignNormalsBeforeMedian),
    RSPD_SWITCH (SmallPlaneSeeding),
    RSPD_SWITCH (LeftNormalRefit),
    RSPD_SWITCH (LeftNormalNarrowing),
    RSPD_SWITCH (ShiftedGrid),
    RSPD_SWITCH (LeftNormalRefitOnGivenNormals),
    RSPD_SWITCH (TrimmedSeedGrowth),
    RSPD_SWITCH (GivenNormalCheck),
    RSPD_SWITCH (DepthLevelDither),
    RSPD_SWITCH (RimCellRetest),
    RSPD_SWITCH (RimRetestUntilStable),
    RSPD_SWITCH (LeftRimRetest),
    RSPD_SWITCH (PositionPlanes),
    RSPD_SWITCH (TailOdds),
    RSPD_SWITCH (SurroundingClutter),
    RSPD_SWITCH (MemberGaps),
    RSPD_SWITCH (RimBands),
    RSPD_SWITCH (HingeNormalTurn),
    RSPD_SWITCH (FarMemberRelease),
    RSPD_SWITCH (ReleasedPlaneSeeding),
    RSPD_SWITCH (ReleasedLayerCheck),
    RSPD_SWITCH (BentSideParentMnd),
    RSPD_SWITCH (ConnectedParts),
    RSPD_SWITCH (BentPlaneSplit),
    RSPD_SWITCH (LayerMerge),
    RSPD_SWITCH (LayerSteps),
    RSPD_SWITCH (StepSplit),
    RSPD_SWITCH (AcrossStepCheck),
    RSPD_SWITCH (EdgeSides),
    RSPD_SWITCH (EdgeCorners),
    RSPD_SWITCH (EdgeWedges),
    RSPD_SWITCH (ThickCellJoin),
    RSPD_SWITCH (StepSides),
    RSPD_SWITCH (StepRegions),
    RSPD_SWITCH (SupportCheck),
    RSPD_SWITCH (SupportClutter),
    RSPD_SWITCH (FinalParts),
    RSPD_SWITCH (NoisyGrownT2),
    RSPD_SWITCH (FinalRefit),
    RSPD_SWITCH (CoplanarMerge),
    RSPD_SWITCH (DropOutlierSeeds),
    RSPD_SWITCH (OutlierSeedRetest),
    RSPD_SWITCH (SmallPlaneCompletion),
    RSPD_SWITCH (VolumeLayerCheck),
    RSPD_SWITCH (FinalVolumeLayerCheck),
    RSPD_SWITCH (InBandLayerCheck),
    RSPD_SWITCH (FlatLayers),
    RSPD_SWITCH (CurvedPlaneCheck),
    RSPD_SWITCH (LateCurvedCheck),
    RSPD_SWITCH (CurvedNormalTurn),
    RSPD_SWITCH (CurvedFoldTwoSides),
    RSPD_SWITCH (CurvedTubeCheck),
    RSPD_SWITCH (CurvedSplitParts),
    RSPD_SWITCH (SmallSeedMndFloor),
    RSPD_SWITCH (BoundedReestimation),
    RSPD_SWITCH (NoisyPlaneBentSplit),
    RSPD_SWITCH (SmallPassThickCellJoin),
    RSPD_SWITCH (NoisySeedGroups),
    RSPD_SWITCH (NoisyLoneSeeds),
    RSPD_SWITCH (NoisyGroupLadder),
    RSPD_SWITCH (PositionSurfaceParts),
    RSPD_SWITCH (PositionSurfaceNormals),
    RSPD_SWITCH (PositionBendBand),
    RSPD_SWITCH (PositionBendSlabs),
    RSPD_SWITCH (PositionJoinBeside),
    RSPD_SWITCH (PositionSurfaceLadder),
    RSPD_SWITCH (PositionLadderRungs),
    RSPD_SWITCH (ThickCellsFollowNoisySeeds),
    RSPD_SWITCH (BendNoiseTest),
    RSPD_SWITCH (EdgeAwareNormals),
  };
#undef RSPD_SWITCH
  Seg seg;
  const auto state = [&] {
    std::vector<bool> s;
    for (const Switch& w : switches)
      s.push_back ((seg.*w.get) ());
    return s;
  };
  const std::vector<bool> defaults = state ();
  for (std::size_t i = 0; i < switches.size (); ++i)
  {
    const Switch& w = switches[i];
    (seg.*w.set) (!defaults[i]);
    std::vector<bool> expected = defaults;
    expected[i] = !defaults[i];
    EXPECT_EQ (state (), expected) << w.name;
    (seg.*w.set) (defaults[i]);
    EXPECT_EQ (state (), defaults) << w.name;
  }
}

TEST (RobustPlaneSegmentation, NoisyGroupRatioBendConfidenceAndNormalTurnRefuseBadValues)
{
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  const double nan = std::numeric_limits<double>::quiet_NaN ();
  const double inf = std::numeric_limits<double>::infinity ();
  const double ratio = seg.getNoisySeedGroupRatio ();
  for (const double bad : {0.5, -1.0, nan, inf})
  {
    seg.setNoisySeedGroupRatio (bad); // refused with PCL_ERROR
    EXPECT_DOUBLE_EQ (seg.getNoisySeedGroupRatio (), ratio) << bad;
  }
  seg.setNoisySeedGroupRatio (3.0);
  EXPECT_DOUBLE_EQ (seg.getNoisySeedGroupRatio (), 3.0);
  const double confidence = seg.getGrownPlaneBendConfidence ();
  for (const double bad : {0.0, 1.0, -0.5, nan})
  {
    seg.setGrownPlaneBendConfidence (bad);
    EXPECT_DOUBLE_EQ (seg.getGrownPlaneBendConfidence (), confidence) << bad;
  }
  seg.setGrownPlaneBendConfidence (0.9);
  EXPECT_DOUBLE_EQ (seg.getGrownPlaneBendConfidence (), 0.9);
  const double turn = seg.getGrownPlaneNormalTurn ();
  for (const double bad : {-0.1, nan, inf})
  {
    seg.setGrownPlaneNormalTurn (bad);
    EXPECT_DOUBLE_EQ (seg.getGrownPlaneNormalTurn (), turn) << bad;
  }
  seg.setGrownPlaneNormalTurn (0.0); // judged on the positions' bend alone
  EXPECT_DOUBLE_EQ (seg.getGrownPlaneNormalTurn (), 0.0);
  EXPECT_EQ (seg.getNormalScale (), pcl::rspd::NormalScale::Automatic);
  seg.setNormalScale (pcl::rspd::NormalScale::Fixed);
  EXPECT_EQ (seg.getNormalScale (), pcl::rspd::NormalScale::Fixed);
}
