/*
 * pcl_rspd: tests of the exact k-NN search (dense table and compressed graph) against brute force
 * and pcl::KdTreeFLANN.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/neighbor_graph.h>

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

namespace
{
using Points = std::vector<Eigen::Vector3f>;
using pcl::rspd::NeighborGraph;
using pcl::rspd::NeighborTable;

float
dist2 (const Points& p, std::size_t i, std::size_t j)
{
  return (p[i] - p[j]).squaredNorm ();
}

// --- clouds -------------------------------------------------------------------------------

Points
uniformCube (std::size_t n, unsigned seed, const Eigen::Vector3f& scale = Eigen::Vector3f::Ones ())
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> u (-1.f, 1.f);
  Points p (n);
  for (auto& x : p)
    x = Eigen::Vector3f (u (rng), u (rng), u (rng)).cwiseProduct (scale);
  return p;
}

/** Points on the six faces of a cube of half-size 1, optionally with a little noise. */
Points
cubeFaces (std::size_t n, unsigned seed, float noise = 0.f)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> u (-1.f, 1.f);
  std::normal_distribution<float> g (0.f, 1.f);
  Points p (n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const int face = static_cast<int> (i % 6);
    Eigen::Vector3f x (u (rng), u (rng), u (rng));
    x[face / 2] = (face % 2) ? 1.f : -1.f;
    if (noise > 0.f)
      x += noise * Eigen::Vector3f (g (rng), g (rng), g (rng));
    p[i] = x;
  }
  return p;
}

/** Two crossing planes, one tilted. */
Points
twoPlanes (std::size_t n, unsigned seed)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> u (-1.f, 1.f);
  Points p (n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const float a = u (rng), b = u (rng);
    p[i] = (i % 2) ? Eigen::Vector3f (a, b, 0.f) : Eigen::Vector3f (a, 0.3f * b, 0.95f * b);
  }
  return p;
}

/** Gaussian clusters whose spreads differ by three orders of magnitude, uniform background noise
  * and one far outlier: density varies wildly across the cloud. */
Points
clustered (std::size_t n, unsigned seed)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> u (-1.f, 1.f);
  std::normal_distribution<float> g (0.f, 1.f);
  const int num_clusters = 12;
  std::vector<Eigen::Vector3f> centres;
  std::vector<float> sigma;
  for (int c = 0; c < num_clusters; ++c)
  {
    centres.emplace_back (u (rng), u (rng), u (rng));
    sigma.push_back (std::pow (10.f, -3.f + 3.f * static_cast<float> (c) / (num_clusters - 1)));
  }
  Points p (n);
  for (std::size_t i = 0; i + 1 < n; ++i)
  {
    if (i % 10 == 0)
      p[i] = Eigen::Vector3f (u (rng), u (rng), u (rng));
    else
    {
      const int c = static_cast<int> (i % num_clusters);
      p[i] = centres[c] + sigma[c] * Eigen::Vector3f (g (rng), g (rng), g (rng));
    }
  }
  p[n - 1] = Eigen::Vector3f (40.f, -30.f, 25.f);
  return p;
}

// --- checks -------------------------------------------------------------------------------

/** Rows hold distinct indices other than self, in increasing (distance, index) order. */
void
expectWellFormed (const Points& p, const NeighborTable& g)
{
  ASSERT_EQ (g.size (), p.size ());
  const int k = g.k ();
  std::vector<std::uint32_t> sorted (k);
  for (std::size_t i = 0; i < g.size (); ++i)
  {
    const std::uint32_t* r = g.neighbors (i);
    for (int t = 0; t < k; ++t)
    {
      ASSERT_LT (r[t], p.size ());
      ASSERT_NE (r[t], i) << "self in row " << i;
      if (t > 0)
      {
        const float d0 = dist2 (p, i, r[t - 1]), d1 = dist2 (p, i, r[t]);
        ASSERT_TRUE (d0 < d1 || (d0 == d1 && r[t - 1] < r[t])) << "row " << i << " position " << t;
      }
    }
    sorted.assign (r, r + k);
    std::sort (sorted.begin (), sorted.end ());
    ASSERT_TRUE (std::adjacent_find (sorted.begin (), sorted.end ()) == sorted.end ())
      << "row " << i;
  }
}

/** Exact comparison with the contract: the first k of all j != i in (distance, index) order.
  * Exact equality holds because the builder's distances are the floats squaredNorm () gives. */
void
expectEqualsBruteForce (const Points& p, const NeighborTable& g)
{
  const int k = g.k ();
  std::vector<std::pair<float, std::uint32_t>> all;
  for (std::size_t i = 0; i < p.size (); ++i)
  {
    all.clear ();
    for (std::size_t j = 0; j < p.size (); ++j)
      if (j != i)
        all.emplace_back (dist2 (p, i, j), static_cast<std::uint32_t> (j));
    std::partial_sort (all.begin (), all.begin () + k, all.end ());
    for (int t = 0; t < k; ++t)
      ASSERT_EQ (g.neighbors (i)[t], all[t].second) << "row " << i << " position " << t;
  }
}

/** FLANN sums the squares in another order: allow a few ulps, relative (the clusters' distances
  * are tiny). */
float
tolerance (float d2)
{
  return 1e-6f * d2 + 1e-30f;
}

/** Comparison with KdTreeFLANN: same sorted distances; same index sets unless the k-th distance
  * is tied with the next one. */
void
expectMatchesFlann (const Points& p, const NeighborTable& g)
{
  const int k = g.k ();
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  cloud->resize (p.size ());
  for (std::size_t i = 0; i < p.size (); ++i)
    (*cloud)[i].getVector3fMap () = p[i];
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud (cloud);

  // k + 2 so that, self removed, the (k+1)-th neighbour tells whether the k-th is tied.
  const int kq = std::min<int> (k + 2, static_cast<int> (p.size ()));
  pcl::Indices idx;
  std::vector<float> d2;
  std::vector<std::uint32_t> ours, theirs;
  std::size_t checked_sets = 0;
  for (std::size_t i = 0; i < p.size (); ++i)
  {
    ASSERT_EQ (tree.nearestKSearch ((*cloud)[i], kq, idx, d2), kq);
    // Drop self; if a duplicate of i pushed it out, drop one zero-distance entry instead.
    auto self = std::find (idx.begin (), idx.end (), static_cast<pcl::index_t> (i));
    const std::size_t drop =
      self != idx.end () ? static_cast<std::size_t> (self - idx.begin ()) : 0;
    idx.erase (idx.begin () + drop);
    d2.erase (d2.begin () + drop);

    const std::uint32_t* r = g.neighbors (i);
    for (int t = 0; t < k; ++t)
    {
      const float mine = dist2 (p, i, r[t]);
      ASSERT_NEAR (mine, d2[t], tolerance (d2[t])) << "row " << i << " position " << t;
    }
    const bool tied = static_cast<int> (d2.size ()) > k && d2[k] - d2[k - 1] <= tolerance (d2[k]);
    if (!tied)
    {
      ours.assign (r, r + k);
      theirs.assign (idx.begin (), idx.begin () + k);
      std::sort (ours.begin (), ours.end ());
      std::sort (theirs.begin (), theirs.end ());
      ASSERT_EQ (ours, theirs) << "row " << i;
      ++checked_sets;
    }
  }
  // Random clouds have essentially no ties: the set comparison must have run almost everywhere.
  EXPECT_GT (checked_sets, p.size () * 9 / 10);
}

/** The compressed graph holds each row of the table as a set, read back in increasing order. */
void
expectGraphHoldsTable (const NeighborTable& t, const NeighborGraph& g)
{
  ASSERT_EQ (g.size (), t.size ());
  ASSERT_EQ (g.k (), t.k ());
  std::vector<std::uint32_t> want (t.k ()), got (t.k ());
  for (std::size_t i = 0; i < t.size (); ++i)
  {
    std::copy (t.neighbors (i), t.neighbors (i) + t.k (), want.begin ());
    std::sort (want.begin (), want.end ());
    g.neighbors (i, got.data ());
    ASSERT_EQ (got, want) << "row " << i;
  }
}

/** The dense table, after checking that the compressed graph of the same search holds it. */
NeighborTable
build (const Points& p, int k, int threads = 2)
{
  NeighborTable g;
  EXPECT_TRUE (pcl::rspd::buildKnnTable (p, k, threads, g));
  EXPECT_EQ (g.k (), k);
  EXPECT_EQ (g.size (), p.size ());
  NeighborGraph compressed;
  EXPECT_TRUE (pcl::rspd::buildKnnGraph (p, k, threads, compressed));
  expectGraphHoldsTable (g, compressed);
  return g;
}

bool
sameGraph (const NeighborTable& a, const NeighborTable& b)
{
  if (a.size () != b.size () || a.k () != b.k ())
    return false;
  return std::equal (a.neighbors (0), a.neighbors (0) + a.size () * a.k (), b.neighbors (0));
}

} // namespace

// --- tests --------------------------------------------------------------------------------

TEST (NeighborTable, RejectsInvalidArguments)
{
  const Points p = uniformCube (10, 1);
  NeighborTable g (3, 2);
  EXPECT_FALSE (pcl::rspd::buildKnnTable (p, 0, 1, g));
  EXPECT_TRUE (g.empty ());
  g = NeighborTable (3, 2);
  EXPECT_FALSE (pcl::rspd::buildKnnTable (p, -3, 1, g));
  EXPECT_TRUE (g.empty ());
  g = NeighborTable (3, 2);
  EXPECT_FALSE (pcl::rspd::buildKnnTable (p, 10, 1, g)); // n == k
  EXPECT_TRUE (g.empty ());
  EXPECT_FALSE (pcl::rspd::buildKnnTable (p, 11, 1, g)); // n < k
  EXPECT_TRUE (g.empty ());
  EXPECT_FALSE (pcl::rspd::buildKnnTable (Points (), 1, 1, g));
  EXPECT_TRUE (g.empty ());
}

TEST (NeighborTable, SmallestCloudHoldsEveryOtherPoint)
{
  for (int k : {1, 2, 7, 50})
  {
    const Points p = uniformCube (k + 1, 2 + k);
    const NeighborTable g = build (p, k);
    expectWellFormed (p, g);
    expectEqualsBruteForce (p, g);
  }
}

TEST (NeighborTable, RandomCloudMatchesFlann)
{
  const Points p = uniformCube (20000, 3);
  for (int k : {1, 10, 50})
  {
    const NeighborTable g = build (p, k);
    expectWellFormed (p, g);
    expectMatchesFlann (p, g);
  }
}

TEST (NeighborTable, CubeFacesMatchFlann)
{
  const Points p = cubeFaces (30000, 4);
  const NeighborTable g = build (p, 50);
  expectWellFormed (p, g);
  expectMatchesFlann (p, g);

  const Points noisy = cubeFaces (20000, 5, 0.01f);
  const NeighborTable gn = build (noisy, 30);
  expectMatchesFlann (noisy, gn);
}

TEST (NeighborTable, TwoPlanesMatchFlann)
{
  const Points p = twoPlanes (30000, 6);
  const NeighborTable g = build (p, 50);
  expectWellFormed (p, g);
  expectMatchesFlann (p, g);
}

TEST (NeighborTable, AnisotropicCloudMatchesFlann)
{
  // A long, thin, flat slab: extents 100 : 1 : 0.01.
  const Points p = uniformCube (20000, 7, Eigen::Vector3f (100.f, 1.f, 0.01f));
  const NeighborTable g = build (p, 40);
  expectWellFormed (p, g);
  expectMatchesFlann (p, g);
}

TEST (NeighborTable, ClusteredCloudMatchesFlann)
{
  const Points p = clustered (30000, 8);
  const NeighborTable g = build (p, 50);
  expectWellFormed (p, g);
  expectMatchesFlann (p, g);
}

TEST (NeighborTable, SmallCloudsEqualBruteForceExactly)
{
  expectEqualsBruteForce (uniformCube (1500, 9), build (uniformCube (1500, 9), 12));
  expectEqualsBruteForce (cubeFaces (1500, 10), build (cubeFaces (1500, 10), 50));
  expectEqualsBruteForce (clustered (1500, 11), build (clustered (1500, 11), 20));
}

TEST (NeighborTable, LatticeTiesAreBrokenByIndex)
{
  // An integer lattice, shuffled: every distance is exact and massively tied, so the rows are fully
  // determined by the tie rule.
  Points p;
  for (int x = 0; x < 12; ++x)
    for (int y = 0; y < 12; ++y)
      for (int z = 0; z < 8; ++z)
        p.emplace_back (static_cast<float> (x) - 6.f, static_cast<float> (y) - 6.f,
                        static_cast<float> (z) - 4.f);
  std::shuffle (p.begin (), p.end (), std::mt19937 (12));
  for (int k : {6, 18, 26, 50})
  {
    const NeighborTable g = build (p, k);
    expectWellFormed (p, g);
    expectEqualsBruteForce (p, g);
  }
}

TEST (NeighborTable, IdenticalPointsAreNeighboursAtDistanceZero)
{
  const Points p (10000, Eigen::Vector3f (0.25f, -0.5f, 1.f));
  const int k = 50;
  const NeighborTable g = build (p, k);
  for (std::size_t i = 0; i < p.size (); ++i)
  {
    // All distances are 0, so the row is the k smallest indices other than i.
    const std::uint32_t* r = g.neighbors (i);
    std::uint32_t expected = 0;
    for (int t = 0; t < k; ++t, ++expected)
    {
      if (expected == i)
        ++expected;
      ASSERT_EQ (r[t], expected) << "row " << i;
    }
  }
}

TEST (NeighborTable, DuplicatedSamplesEqualBruteForce)
{
  // Every sample three times (the copies far apart in index), plus a run of one repeated point.
  Points p = cubeFaces (700, 13);
  const Points copy = p;
  p.insert (p.end (), copy.begin (), copy.end ());
  p.insert (p.end (), copy.begin (), copy.end ());
  p.insert (p.end (), 80, p[5]);
  for (int k : {2, 3, 30})
  {
    const NeighborTable g = build (p, k);
    expectWellFormed (p, g);
    expectEqualsBruteForce (p, g);
  }
}

TEST (NeighborTable, PointsOnALine)
{
  std::mt19937 rng (14);
  std::uniform_real_distribution<float> u (-1.f, 1.f);
  const Eigen::Vector3f dir = Eigen::Vector3f (1.f, 2.f, -0.5f).normalized ();
  Points p (3000);
  for (auto& x : p)
    x = u (rng) * dir;
  // And an axis-aligned line with evenly spaced (tied) samples.
  for (int i = 0; i < 1000; ++i)
    p.emplace_back (0.f, 0.f, 0.001f * static_cast<float> (i) - 0.5f);
  const NeighborTable g = build (p, 25);
  expectWellFormed (p, g);
  expectEqualsBruteForce (p, g);
}

TEST (NeighborTable, FlatAndDegenerateExtents)
{
  // All points on the plane z = 0, and a cloud whose z extent is a few ulps.
  Points flat = uniformCube (4000, 15, Eigen::Vector3f (1.f, 1.f, 0.f));
  expectEqualsBruteForce (flat, build (flat, 16));
  Points thin = uniformCube (3000, 16, Eigen::Vector3f (1e-3f, 1e-3f, 1e-3f));
  for (auto& x : thin)
    x[2] = 1.f + x[2] * 1e-4f;
  expectEqualsBruteForce (thin, build (thin, 10));
}

TEST (NeighborTable, FarOutliers)
{
  // A dense blob with a few samples far away on every side: their neighbours are in the blob.
  Points p = uniformCube (3000, 17, Eigen::Vector3f (0.01f, 0.01f, 0.01f));
  p.emplace_back (1000.f, 0.f, 0.f);
  p.emplace_back (-1000.f, 5.f, 0.f);
  p.emplace_back (0.f, 0.f, 500.f);
  p.emplace_back (1000.f, 0.001f, 0.f);
  const NeighborTable g = build (p, 8);
  expectWellFormed (p, g);
  expectEqualsBruteForce (p, g);
}

TEST (NeighborTable, MultiScaleClouds)
{
  // Samples whose spacing grows geometrically, around nested clusters of very different sizes:
  // the neighbours of most samples lie far outside the cells next to theirs.
  std::mt19937 rng (19);
  std::normal_distribution<float> g (0.f, 1.f);
  Points p;
  const auto gauss = [&rng, &g] () { return Eigen::Vector3f (g (rng), g (rng), g (rng)); };
  for (int i = 0; i < 150; ++i)
    p.push_back (std::pow (1.2f, static_cast<float> (i)) * gauss ().normalized ());
  for (float scale : {1e-4f, 1e-2f, 1.f, 1e2f})
    for (int i = 0; i < 300; ++i)
      p.push_back (Eigen::Vector3f (5.f, -3.f, 2.f) + scale * gauss ());
  std::shuffle (p.begin (), p.end (), rng);
  for (int k : {1, 5, 40})
  {
    const NeighborTable graph = build (p, k);
    expectWellFormed (p, graph);
    expectEqualsBruteForce (p, graph);
  }
}

TEST (NeighborTable, NeighboursBeyondTheFirstCells)
{
  // A configuration built so that the true neighbours of q lie farther from q's cell than the
  // 5x5x5 cells around it, while the cells next to it already hold enough (but farther)
  // candidates: q at one corner of a cell of side 2, a tight cluster of 24 samples at the opposite
  // corner, a few samples just past the side-4 cube around them on q's side, and one far sample
  // that sets the grid's scale (cells of side 1024 / 2^d). Whatever the builder's internal cell
  // choice, the result must equal brute force.
  std::mt19937 rng (21);
  std::uniform_real_distribution<float> u (0.f, 1e-3f);
  Points p;
  p.emplace_back (0.f, 0.f, 0.f);
  for (int i = 0; i < 23; ++i)
    p.emplace_back (u (rng), u (rng), u (rng));
  p.emplace_back (1.9f, 1.9f, 1.9f); // q
  for (int i = 0; i < 5; ++i)
    p.emplace_back (4.05f + 0.01f * static_cast<float> (i), 1.9f, 1.9f);
  p.emplace_back (1000.f, 1000.f, 1000.f);
  for (int k : {1, 3, 5})
  {
    const NeighborTable graph = build (p, k);
    EXPECT_EQ (graph.neighbors (24)[0], 25u);
    expectEqualsBruteForce (p, graph);
  }
}

TEST (NeighborTable, ManyDuplicatesAmongOtherPoints)
{
  // 50,000 copies of one position inside a cloud: their rows follow the tie rule; the other rows
  // (some of which reach the copies) equal brute force.
  const int k = 30;
  Points p = uniformCube (3000, 20);
  const Eigen::Vector3f dup = p[17];
  const std::size_t first_copy = p.size ();
  p.insert (p.end (), 50000, dup);
  // A copy with a small index, the original among the copies.
  std::swap (p[17], p[first_copy + 100]);
  const NeighborTable graph = build (p, k);

  std::vector<std::uint32_t> copies;
  for (std::size_t i = 0; i < p.size () && copies.size () <= static_cast<std::size_t> (k); ++i)
    if (p[i] == dup)
      copies.push_back (static_cast<std::uint32_t> (i));
  std::vector<std::pair<float, std::uint32_t>> all;
  for (std::size_t i = 0; i < p.size (); ++i)
  {
    const std::uint32_t* r = graph.neighbors (i);
    if (p[i] == dup)
    {
      // The k smallest indices among the other copies.
      int t = 0;
      for (std::uint32_t c : copies)
      {
        if (c == i || t == k)
          continue;
        ASSERT_EQ (r[t++], c) << "row " << i;
      }
      continue;
    }
    all.clear ();
    for (std::size_t j = 0; j < p.size (); ++j)
      if (j != i)
        all.emplace_back (dist2 (p, i, j), static_cast<std::uint32_t> (j));
    std::partial_sort (all.begin (), all.begin () + k, all.end ());
    for (int t = 0; t < k; ++t)
      ASSERT_EQ (r[t], all[t].second) << "row " << i << " position " << t;
  }
}

TEST (NeighborTable, WildOutliers)
{
  // Outliers 10^9 to 10^15 times farther than the sample spacing: the finest cells of the bounding
  // box hold the whole cloud.
  Points p = cubeFaces (3000, 22, 0.001f);
  p.emplace_back (1e9f, 0.f, 0.f);
  expectEqualsBruteForce (p, build (p, 10));
  p.emplace_back (0.f, -3e12f, 1e12f);
  p.emplace_back (0.f, 0.f, 1e12f);
  expectEqualsBruteForce (p, build (p, 40));

  // Cells of side 1 (an extent of 1.5e6 from the origin): a tight cluster at one corner of the
  // cell [10, 11)^3, q at the opposite corner, and b just outside the 3x3x3 cells around it but
  // nearer to q than the cluster.
  Points r;
  r.emplace_back (0.f, 0.f, 0.f);
  r.emplace_back (1.5e6f, 0.f, 0.f);
  std::mt19937 rng (23);
  std::uniform_real_distribution<float> u (0.f, 1e-4f);
  for (int i = 0; i < 61; ++i)
    r.emplace_back (10.f + u (rng), 10.f + u (rng), 10.f + u (rng));
  const std::uint32_t q_index = static_cast<std::uint32_t> (r.size ());
  r.emplace_back (10.999f, 10.999f, 10.999f);
  r.emplace_back (12.3f, 10.999f, 10.999f); // b
  for (int k : {1, 3})
  {
    const NeighborTable graph = build (r, k);
    EXPECT_EQ (graph.neighbors (q_index)[0], q_index + 1);
    expectEqualsBruteForce (r, graph);
  }

  // A microscopic cluster (spread 10^-12, near the origin where floats resolve it) inside a unit
  // cloud, with exact duplicates of one of its samples.
  std::normal_distribution<float> g (0.f, 1.f);
  Points q = uniformCube (2000, 24);
  for (int i = 0; i < 300; ++i)
    q.push_back (1e-12f * Eigen::Vector3f (g (rng), g (rng), g (rng)));
  q.insert (q.end (), 100, q.back ());
  std::shuffle (q.begin (), q.end (), rng);
  for (int k : {3, 30})
  {
    const NeighborTable graph = build (q, k);
    expectWellFormed (q, graph);
    expectEqualsBruteForce (q, graph);
  }
}

TEST (NeighborTable, OverwritesAGraphOfTheSameShape)
{
  const Points a = cubeFaces (5000, 25), b = uniformCube (5000, 26);
  NeighborTable reused = build (a, 12);
  ASSERT_TRUE (pcl::rspd::buildKnnTable (b, 12, 2, reused));
  EXPECT_TRUE (sameGraph (reused, build (b, 12)));
}

TEST (NeighborTable, IndependentOfThreadCount)
{
  const Points p = cubeFaces (200000, 18, 0.002f);
  NeighborTable g1, g2, g0;
  ASSERT_TRUE (pcl::rspd::buildKnnTable (p, 20, 1, g1));
  ASSERT_TRUE (pcl::rspd::buildKnnTable (p, 20, 2, g2));
  ASSERT_TRUE (pcl::rspd::buildKnnTable (p, 20, 0, g0));
  EXPECT_TRUE (sameGraph (g1, g2));
  EXPECT_TRUE (sameGraph (g1, g0));
}

TEST (NeighborGraph, CompressedGraphRejectsInvalidArguments)
{
  const Points p = uniformCube (10, 1);
  NeighborGraph g;
  EXPECT_FALSE (pcl::rspd::buildKnnGraph (p, 0, 1, g));
  EXPECT_TRUE (g.empty ());
  EXPECT_FALSE (pcl::rspd::buildKnnGraph (p, 10, 1, g)); // n == k
  EXPECT_TRUE (g.empty ());
  EXPECT_FALSE (pcl::rspd::buildKnnGraph (Points (), 1, 1, g));
  EXPECT_TRUE (g.empty ());
}

TEST (NeighborGraph, CompressedGraphIndependentOfThreadCount)
{
  const Points p = cubeFaces (100000, 18, 0.002f);
  NeighborGraph g1, g2;
  ASSERT_TRUE (pcl::rspd::buildKnnGraph (p, 20, 1, g1));
  ASSERT_TRUE (pcl::rspd::buildKnnGraph (p, 20, 2, g2));
  std::vector<std::uint32_t> a (20), b (20);
  for (std::size_t i = 0; i < p.size (); ++i)
  {
    g1.neighbors (i, a.data ());
    g2.neighbors (i, b.data ());
    ASSERT_EQ (a, b) << "row " << i;
  }
}

TEST (NeighborGraph, SpatialOrderCompressesTheGraph)
{
  // In input order the indices of a row are random; in spatial order they are nearby, which is
  // what the varint deltas need: well under 2 bytes per neighbour instead of 4 plain.
  Points p = cubeFaces (200000, 19, 0.002f);
  std::shuffle (p.begin (), p.end (), std::mt19937 (3));
  const std::vector<std::uint32_t> order = pcl::rspd::spatialOrder (p, 2);
  ASSERT_EQ (order.size (), p.size ());
  std::vector<char> seen (p.size (), 0);
  for (const auto i : order)
  {
    ASSERT_LT (i, p.size ());
    ASSERT_FALSE (seen[i]);
    seen[i] = 1;
  }
  Points sorted (p.size ());
  for (std::size_t s = 0; s < p.size (); ++s)
    sorted[s] = p[order[s]];
  const int k = 50;
  NeighborGraph g;
  ASSERT_TRUE (pcl::rspd::buildKnnGraph (sorted, k, 2, g));
  const double bytes_per_neighbour = static_cast<double> (g.memoryBytes ()) / (static_cast<double> (p.size ()) * k);
  std::printf ("compressed graph: %.2f bytes per neighbour (plain: 4)\n", bytes_per_neighbour);
  EXPECT_LT (bytes_per_neighbour, 2.0);
  // And it still holds the exact rows.
  NeighborTable t;
  ASSERT_TRUE (pcl::rspd::buildKnnTable (sorted, k, 2, t));
  expectGraphHoldsTable (t, g);
}

TEST (NeighborGraph, FromTableRoundTrips)
{
  NeighborTable t (4, 3);
  const std::uint32_t rows[4][3] = {{3, 1, 2}, {0, 2, 3}, {3, 0, 1}, {2, 1, 0}};
  for (int i = 0; i < 4; ++i)
    std::copy (rows[i], rows[i] + 3, t.row (i));
  const NeighborGraph g = NeighborGraph::fromTable (t);
  std::vector<std::uint32_t> got (3);
  g.neighbors (0, got.data ());
  EXPECT_EQ (got, (std::vector<std::uint32_t>{1, 2, 3}));
  g.neighbors (3, got.data ());
  EXPECT_EQ (got, (std::vector<std::uint32_t>{0, 1, 2}));
  std::vector<std::uint32_t> visited;
  g.forEachNeighbor (2, [&visited] (std::uint32_t j) { visited.push_back (j); });
  EXPECT_EQ (visited, (std::vector<std::uint32_t>{0, 1, 3}));
}

namespace
{
/** Rows of the flagged samples through visitKnnRows: each visited once, as the table has it. */
void
expectVisitedRowsMatchTable (const Points& p, int k, const std::vector<char>& flags, int threads)
{
  const NeighborTable table = build (p, k, threads);
  std::vector<std::uint32_t> rows (p.size () * static_cast<std::size_t> (k), 0);
  std::vector<int> visits (p.size (), 0);
  ASSERT_TRUE (pcl::rspd::visitKnnRows (p, k, threads, flags, [&] (std::uint32_t q, const std::uint32_t* row) {
    // Distinct queries per call, so each thread writes its own slots.
    ++visits[q];
    std::copy (row, row + k, rows.begin () + static_cast<std::ptrdiff_t> (q) * k);
  }));
  for (std::size_t i = 0; i < p.size (); ++i)
  {
    ASSERT_EQ (visits[i], flags[i] ? 1 : 0) << "sample " << i;
    if (flags[i])
      for (int t = 0; t < k; ++t)
        ASSERT_EQ (rows[i * k + t], table.neighbors (i)[t]) << "row " << i << " position " << t;
  }
}
} // namespace

TEST (NeighborGraph, VisitedRowsAreTheTableRowsOfTheFlaggedSamples)
{
  // A few queries (the adaptive normal scale's use), half of them, and all of them.
  const Points p = cubeFaces (20000, 31, 0.01f);
  for (const std::size_t every : {97u, 2u, 1u})
  {
    std::vector<char> flags (p.size (), 0);
    for (std::size_t i = 0; i < p.size (); i += every)
      flags[i] = 1;
    expectVisitedRowsMatchTable (p, 20, flags, 2);
    expectVisitedRowsMatchTable (p, 20, flags, 1);
  }
  // Queries inside leaves that are solved as a problem of their own (wild outliers).
  Points q = cubeFaces (3000, 32, 0.001f);
  q.emplace_back (1e9f, 0.f, 0.f);
  q.emplace_back (0.f, -3e12f, 1e12f);
  std::vector<char> flags (q.size (), 0);
  for (std::size_t i = 0; i < q.size (); i += 3)
    flags[i] = 1;
  flags.back () = 1;
  expectVisitedRowsMatchTable (q, 10, flags, 2);
}

TEST (NeighborGraph, VisitRejectsInvalidArguments)
{
  const Points p = uniformCube (10, 1);
  int visited = 0;
  const auto count = [&visited] (std::uint32_t, const std::uint32_t*) { ++visited; };
  EXPECT_FALSE (pcl::rspd::visitKnnRows (p, 0, 1, std::vector<char> (10, 1), count));
  EXPECT_FALSE (pcl::rspd::visitKnnRows (p, 10, 1, std::vector<char> (10, 1), count));
  EXPECT_FALSE (pcl::rspd::visitKnnRows (p, 3, 1, std::vector<char> (9, 1), count));
  EXPECT_EQ (visited, 0);
  EXPECT_TRUE (pcl::rspd::visitKnnRows (p, 3, 1, std::vector<char> (10, 0), count));
  EXPECT_EQ (visited, 0);
}
