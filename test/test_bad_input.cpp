/*
 * The bad-input battery of the library: every input users really have gives either a valid result
 * or a clear error (PCL_ERROR, empty outputs), never a crash, and the caller's cloud, normals and
 * indices are unchanged afterwards. Plus determinism: run to run, thread counts, shuffled input.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/robust_plane_segmentation.h>
#include <pcl_rspd/synthetic_scenes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <map>
#include <numeric>
#include <random>
#include <set>

namespace
{
using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Normals = pcl::PointCloud<pcl::Normal>;
using Seg = pcl::RobustPlaneSegmentation<pcl::PointXYZ, pcl::Normal>;

/** Byte-exact snapshot of what the caller owns. */
struct Snapshot
{
  std::vector<unsigned char> cloud, normals;
  std::vector<pcl::index_t> indices;

  Snapshot (const Cloud::ConstPtr& c, const Normals::ConstPtr& n, const pcl::IndicesConstPtr& i)
  {
    if (c)
      cloud.assign (reinterpret_cast<const unsigned char*> (c->data ()),
                    reinterpret_cast<const unsigned char*> (c->data () + c->size ()));
    if (n)
      normals.assign (reinterpret_cast<const unsigned char*> (n->data ()),
                      reinterpret_cast<const unsigned char*> (n->data () + n->size ()));
    if (i)
      indices = *i;
  }
  bool
  operator== (const Snapshot& o) const { return cloud == o.cloud && normals == o.normals && indices == o.indices; }
};

/** Outcome of one segmentation, checked for internal consistency. */
struct Outcome
{
  bool ok = false;
  std::vector<pcl::PointIndices> planes;
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<std::uint32_t> labels;
};

Outcome
runChecked (const Cloud::Ptr& cloud, const Normals::Ptr& normals = nullptr, const pcl::IndicesPtr& indices = nullptr,
            int k = 50, unsigned threads = 0)
{
  const Snapshot before (cloud, normals, indices);
  Seg seg;
  if (cloud)
    seg.setInputCloud (cloud);
  if (normals)
    seg.setInputNormals (normals);
  if (indices)
    seg.setIndices (indices);
  seg.setNumberOfNeighbours (k);
  seg.setNumberOfThreads (threads);
  Outcome o;
  seg.segment (o.coefficients, o.planes);
  o.ok = seg.hasResult ();
  pcl::PointCloud<pcl::Label> labels;
  seg.getLabels (labels);
  for (const auto& l : labels)
    o.labels.push_back (l.label);
  EXPECT_TRUE (before == Snapshot (cloud, normals, indices)) << "the caller's data changed";
  if (!o.ok)
  {
    EXPECT_TRUE (o.planes.empty ());
    EXPECT_TRUE (o.coefficients.empty ());
    EXPECT_TRUE (o.labels.empty ());
    return o;
  }
  // A valid result: labels cover the cloud, planes are disjoint, in range, consistent with labels.
  EXPECT_EQ (o.labels.size (), cloud->size ());
  EXPECT_EQ (o.planes.size (), o.coefficients.size ());
  std::set<pcl::index_t> seen;
  for (std::size_t p = 0; p < o.planes.size (); ++p)
  {
    EXPECT_EQ (o.coefficients[p].values.size (), 4u);
    if (o.coefficients[p].values.size () != 4u)
      continue;
    for (const float v : o.coefficients[p].values)
      EXPECT_TRUE (std::isfinite (v));
    const Eigen::Vector3f n (o.coefficients[p].values[0], o.coefficients[p].values[1], o.coefficients[p].values[2]);
    EXPECT_NEAR (n.norm (), 1.0f, 1e-4f);
    for (const auto i : o.planes[p].indices)
    {
      EXPECT_TRUE (i >= 0 && static_cast<std::size_t> (i) < cloud->size ()) << i;
      if (i < 0 || static_cast<std::size_t> (i) >= cloud->size ())
        continue;
      EXPECT_TRUE (seen.insert (i).second) << "index in two planes";
      EXPECT_EQ (o.labels[i], p + 1);
      EXPECT_TRUE (std::isfinite ((*cloud)[i].x));
    }
  }
  return o;
}

Cloud::Ptr
boxCorner (int per_face, float sigma = 0.002f, std::uint32_t seed = 1)
{
  auto cloud = std::make_shared<Cloud> ();
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  std::normal_distribution<float> g (0.0f, 1.0f);
  for (int f = 0; f < 3; ++f)
    for (int i = 0; i < per_face; ++i)
    {
      float c[3] = {u (rng), u (rng), u (rng)};
      c[f] = sigma * g (rng);
      cloud->push_back (pcl::PointXYZ (c[0], c[1], c[2]));
    }
  return cloud;
}

/** Share of points whose labels agree under the best one-to-one relabeling (0 must map to 0). */
double
agreement (const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> joint;
  for (std::size_t i = 0; i < a.size (); ++i)
    ++joint[{a[i], b[i]}];
  std::vector<std::pair<std::size_t, std::pair<std::uint32_t, std::uint32_t>>> pairs;
  for (const auto& [key, count] : joint)
    pairs.push_back ({count, key});
  std::sort (pairs.rbegin (), pairs.rend ());
  std::set<std::uint32_t> used_a, used_b;
  std::size_t same = 0;
  for (const auto& [count, key] : pairs)
    if ((key.first == 0) == (key.second == 0) && !used_a.count (key.first) && !used_b.count (key.second))
    {
      used_a.insert (key.first);
      used_b.insert (key.second);
      same += count;
    }
  return static_cast<double> (same) / static_cast<double> (a.size ());
}
} // namespace

TEST (BadInput, NoCloud)
{
  EXPECT_FALSE (runChecked (nullptr).ok);
}

TEST (BadInput, EmptyCloud)
{
  EXPECT_FALSE (runChecked (std::make_shared<Cloud> ()).ok);
}

TEST (BadInput, AllNaN)
{
  auto cloud = std::make_shared<Cloud> ();
  cloud->resize (1000, pcl::PointXYZ (NAN, NAN, NAN));
  EXPECT_FALSE (runChecked (cloud).ok);
}

TEST (BadInput, SomeNaNAndInfCoordinatesAreSkipped)
{
  auto cloud = boxCorner (2000);
  for (std::size_t i = 0; i < cloud->size (); i += 7)
    (*cloud)[i].x = (i % 2) ? NAN : INFINITY;
  (*cloud)[1].y = -INFINITY;
  const Outcome o = runChecked (cloud);
  ASSERT_TRUE (o.ok);
  EXPECT_EQ (o.planes.size (), 3u);
  for (std::size_t i = 0; i < cloud->size (); i += 7)
    EXPECT_EQ (o.labels[i], 0u);
}

TEST (BadInput, NaNAndZeroLengthNormalsAreLeftOut)
{
  auto cloud = boxCorner (2000);
  auto normals = std::make_shared<Normals> ();
  for (std::size_t i = 0; i < cloud->size (); ++i)
  {
    pcl::Normal n (0, 0, 0);
    n.normal[i / 2000] = 1.0f;
    normals->push_back (n);
  }
  (*normals)[10] = pcl::Normal (NAN, 0, 1);
  (*normals)[20] = pcl::Normal (0, 0, 0);
  const Outcome o = runChecked (cloud, normals);
  ASSERT_TRUE (o.ok);
  EXPECT_EQ (o.planes.size (), 3u);
  EXPECT_EQ (o.labels[10], 0u);
  EXPECT_EQ (o.labels[20], 0u);
}

TEST (BadInput, EveryNormalZeroLengthOrNaNFails)
{
  // No point is left once those are left out: a clear error, empty outputs.
  auto cloud = boxCorner (500);
  auto zero = std::make_shared<Normals> ();
  zero->resize (cloud->size (), pcl::Normal (0, 0, 0));
  EXPECT_FALSE (runChecked (cloud, zero).ok);
  auto nan = std::make_shared<Normals> ();
  nan->resize (cloud->size (), pcl::Normal (NAN, NAN, NAN));
  EXPECT_FALSE (runChecked (cloud, nan).ok);
}

TEST (BadInput, NormalsOfAnotherSize)
{
  auto cloud = boxCorner (500);
  auto normals = std::make_shared<Normals> ();
  normals->resize (cloud->size () + 1);
  EXPECT_FALSE (runChecked (cloud, normals).ok);
}

TEST (BadInput, IndicesOutOfRange)
{
  auto cloud = boxCorner (500);
  EXPECT_FALSE (runChecked (cloud, nullptr, std::make_shared<pcl::Indices> (pcl::Indices{0, 1, 1500})).ok);
  EXPECT_FALSE (runChecked (cloud, nullptr, std::make_shared<pcl::Indices> (pcl::Indices{-3, 1, 2})).ok);
}

TEST (BadInput, RepeatedIndicesCountOnce)
{
  auto cloud = boxCorner (1000);
  auto indices = std::make_shared<pcl::Indices> ();
  for (int i = 0; i < 3000; ++i)
  {
    indices->push_back (i);
    indices->push_back (i); // every index twice, unsorted overall
  }
  std::reverse (indices->begin (), indices->end ());
  const Outcome twice = runChecked (cloud, nullptr, indices);
  const Outcome plain = runChecked (cloud);
  ASSERT_TRUE (twice.ok);
  EXPECT_EQ (twice.labels, plain.labels);
}

TEST (BadInput, FewerPointsThanK)
{
  EXPECT_FALSE (runChecked (boxCorner (10)).ok); // 30 points, k = 50
}

TEST (BadInput, ThreePoints)
{
  auto cloud = std::make_shared<Cloud> ();
  cloud->push_back ({0, 0, 0});
  cloud->push_back ({1, 0, 0});
  cloud->push_back ({0, 1, 0});
  EXPECT_FALSE (runChecked (cloud).ok);
  const Outcome o = runChecked (cloud, nullptr, nullptr, 2);
  EXPECT_FALSE (o.ok) << "k = 2 is refused by the setter (k >= 3); still no crash";
}

TEST (BadInput, TenThousandIdenticalPoints)
{
  auto cloud = std::make_shared<Cloud> ();
  cloud->resize (10000, pcl::PointXYZ (1.5f, -2.0f, 3.0f));
  const Outcome o = runChecked (cloud);
  ASSERT_TRUE (o.ok);
  EXPECT_TRUE (o.planes.empty ()) << "a single position is no plane";
}

TEST (BadInput, DuplicatedCopyOfAWholeCloud)
{
  auto cloud = boxCorner (2000);
  auto doubled = std::make_shared<Cloud> (*cloud);
  *doubled += *cloud;
  const Outcome o = runChecked (doubled);
  ASSERT_TRUE (o.ok);
  EXPECT_EQ (o.planes.size (), 3u);
  const std::size_t n = cloud->size ();
  std::size_t same = 0;
  for (std::size_t i = 0; i < n; ++i)
    same += o.labels[i] == o.labels[i + n];
  EXPECT_GE (same, n * 99 / 100) << "a point and its copy share a plane";
}

TEST (BadInput, NoiseFreePlaneIsOnePlane)
{
  auto cloud = std::make_shared<Cloud> ();
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j)
      cloud->push_back (pcl::PointXYZ (i * 0.01f, j * 0.01f, 0.0f));
  const Outcome o = runChecked (cloud);
  ASSERT_TRUE (o.ok);
  ASSERT_EQ (o.planes.size (), 1u);
  EXPECT_GE (o.planes[0].indices.size (), cloud->size () * 99 / 100);
}

TEST (BadInput, PointsOnALine)
{
  auto cloud = std::make_shared<Cloud> ();
  for (int i = 0; i < 2000; ++i)
    cloud->push_back (pcl::PointXYZ (i * 0.001f, 2 * i * 0.001f, 0.5f));
  EXPECT_TRUE (runChecked (cloud).ok); // any result is valid; no crash, no hang
}

TEST (BadInput, CloudAMillionUnitsFromTheOrigin)
{
  auto cloud = boxCorner (2000, 0.002f);
  for (auto& p : *cloud)
  {
    p.x += 1e6f;
    p.y -= 1e6f;
  }
  // float32 input is coarse here (0.06 unit steps): only a clean run is asked.
  EXPECT_TRUE (runChecked (cloud).ok);
}

TEST (BadInput, MillimetresOfAMetreSceneAndAKilometreAway)
{
  auto cloud = boxCorner (2000);
  const Outcome metres = runChecked (cloud);
  auto mm = std::make_shared<Cloud> (*cloud);
  auto far = std::make_shared<Cloud> (*cloud);
  for (std::size_t i = 0; i < cloud->size (); ++i)
  {
    (*mm)[i].getVector3fMap () *= 1000.0f;
    (*far)[i].x += 1000.0f;
  }
  const Outcome in_mm = runChecked (mm);
  const Outcome away = runChecked (far);
  ASSERT_TRUE (metres.ok && in_mm.ok && away.ok);
  EXPECT_EQ (in_mm.planes.size (), metres.planes.size ());
  EXPECT_EQ (away.planes.size (), metres.planes.size ());
  EXPECT_GE (agreement (metres.labels, in_mm.labels), 0.995);
  EXPECT_GE (agreement (metres.labels, away.labels), 0.99);
}

TEST (BadInput, HugeSinglePlane)
{
  // 10M points: 1.8 GB and ~30 s (2 cores), so it runs on request (PCL_RSPD_LARGE_TESTS=1), e.g.
  // ctest -R HugeSinglePlane with the variable set; .ci/run sets it.
  if (!std::getenv ("PCL_RSPD_LARGE_TESTS"))
    GTEST_SKIP () << "set PCL_RSPD_LARGE_TESTS=1 to run the 10M-point plane";
  auto cloud = std::make_shared<Cloud> ();
  std::mt19937 rng (3);
  std::uniform_real_distribution<float> u (0.0f, 100.0f);
  std::normal_distribution<float> g (0.0f, 0.01f);
  cloud->resize (10000000);
  for (auto& p : *cloud)
    p = pcl::PointXYZ (u (rng), u (rng), g (rng));
  const Outcome o = runChecked (cloud);
  ASSERT_TRUE (o.ok);
  ASSERT_GE (o.planes.size (), 1u);
  EXPECT_GE (o.planes[0].indices.size (), cloud->size () * 9 / 10);
}

TEST (Determinism, SameInputSameOutputBitForBit)
{
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("room");
  auto cloud = std::make_shared<Cloud> (scene.cloud);
  const Outcome a = runChecked (cloud), b = runChecked (cloud);
  EXPECT_EQ (a.labels, b.labels);
  ASSERT_EQ (a.coefficients.size (), b.coefficients.size ());
  for (std::size_t p = 0; p < a.coefficients.size (); ++p)
    EXPECT_EQ (std::memcmp (a.coefficients[p].values.data (), b.coefficients[p].values.data (), 4 * sizeof (float)), 0);
}

TEST (Determinism, OneThreadAndTwoThreadsAgreeBitForBit)
{
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("facade");
  auto cloud = std::make_shared<Cloud> (scene.cloud);
  const Outcome one = runChecked (cloud, nullptr, nullptr, 50, 1);
  const Outcome two = runChecked (cloud, nullptr, nullptr, 50, 2);
  EXPECT_EQ (one.labels, two.labels);
  ASSERT_EQ (one.coefficients.size (), two.coefficients.size ());
  for (std::size_t p = 0; p < one.coefficients.size (); ++p)
    EXPECT_EQ (std::memcmp (one.coefficients[p].values.data (), two.coefficients[p].values.data (), 4 * sizeof (float)), 0);
}

TEST (Determinism, ShuffledInputGivesTheSamePlanes)
{
  for (const char* name : {"room", "staircase", "industrial"})
  {
    const pcl::rspd::Scene scene = pcl::rspd::makeScene (name);
    std::vector<std::size_t> perm (scene.cloud.size ());
    std::iota (perm.begin (), perm.end (), 0);
    std::mt19937 rng (11);
    std::shuffle (perm.begin (), perm.end (), rng);
    auto original = std::make_shared<Cloud> (scene.cloud);
    auto shuffled = std::make_shared<Cloud> ();
    for (const auto i : perm)
      shuffled->push_back (scene.cloud[i]);
    const Outcome a = runChecked (original), b = runChecked (shuffled);
    std::vector<std::uint32_t> back (perm.size ());
    for (std::size_t j = 0; j < perm.size (); ++j)
      back[perm[j]] = b.labels[j];
    EXPECT_EQ (a.planes.size (), b.planes.size ()) << name;
    EXPECT_GE (agreement (a.labels, back), 0.99) << name;
  }
}
