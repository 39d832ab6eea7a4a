/*
 * pcl_rspd: tests of normal estimation: PCA over the k-neighbourhoods, and the adaptive scale that
 * widens them where noise along the normal swamps them.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/neighbor_graph.h>
#include <pcl_rspd/normal_estimation.h>
#include <pcl_rspd/synthetic_scenes.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace
{
using Points = std::vector<Eigen::Vector3f>;
constexpr double kDegree = M_PI / 180.0;

/** Points in the order the class stores them (spatial), which the adaptive scale relies on. */
Points
inSpatialOrder (const Points& p)
{
  const std::vector<std::uint32_t> order = pcl::rspd::spatialOrder (p, 2);
  Points sorted (p.size ());
  for (std::size_t i = 0; i < p.size (); ++i)
    sorted[i] = p[order[i]];
  return sorted;
}

/** n samples uniform on the square [-0.5, 0.5]^2 in the plane z = 0, Gaussian noise of \a sigma along
  * z, centred on the origin and in spatial order. */
Points
noisySquare (std::size_t n, float sigma, unsigned seed)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> u (-0.5f, 0.5f);
  std::normal_distribution<float> g (0.f, sigma);
  Points p (n);
  for (auto& x : p)
    x = Eigen::Vector3f (u (rng), u (rng), sigma > 0.f ? g (rng) : 0.f);
  return inSpatialOrder (p);
}

/** Median angle between the normals and the z axis, over the samples away from the square's border
  * (where any neighbourhood is one-sided), in degrees. */
double
medianErrorDegrees (const Points& p, const Points& normals, const Eigen::Vector3f& truth = Eigen::Vector3f::UnitZ (),
                    float inner = 0.4f)
{
  std::vector<double> a;
  for (std::size_t i = 0; i < p.size (); ++i)
    if (std::abs (p[i].x ()) < inner && std::abs (p[i].y ()) < inner)
      a.push_back (std::acos (std::min (1.0, std::abs (static_cast<double> (normals[i].dot (truth))))) / kDegree);
  std::nth_element (a.begin (), a.begin () + a.size () / 2, a.end ());
  return a[a.size () / 2];
}

/** n samples uniform in the cube [-half, half]^3 (a volume, no surface), in spatial order. */
Points
filledCube (std::size_t n, float half, unsigned seed)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> u (-half, half);
  Points p (n);
  for (auto& x : p)
    x = Eigen::Vector3f (u (rng), u (rng), u (rng));
  return inSpatialOrder (p);
}

struct Estimates
{
  Points fixed;
  Points adaptive;
  pcl::rspd::NormalScaleStatistics stats;
};

Estimates
estimateBoth (const Points& p, int k, int threads = 2)
{
  pcl::rspd::NeighborGraph graph;
  EXPECT_TRUE (pcl::rspd::buildKnnGraph (p, k, threads, graph));
  Estimates e;
  pcl::rspd::estimateNormals (p, graph, threads, e.fixed);
  pcl::rspd::estimateAdaptiveScaleNormals (p, graph, threads, e.adaptive, &e.stats);
  EXPECT_EQ (e.adaptive.size (), p.size ());
  const std::size_t total =
    std::accumulate (e.stats.samples_per_scale.begin (), e.stats.samples_per_scale.end (), std::size_t (0));
  EXPECT_EQ (total, p.size ());
  EXPECT_EQ (e.stats.widened () + e.stats.samples_per_scale[0], p.size ());
  EXPECT_LE (e.stats.unresolved, e.stats.samples_per_scale[0]);
  std::printf ("    %zu samples: %zu from a wider scale, %zu unresolved, per scale:", p.size (), e.stats.widened (),
               e.stats.unresolved);
  for (const auto c : e.stats.samples_per_scale)
    std::printf (" %zu", c);
  std::printf ("\n");
  return e;
}
} // namespace

TEST (NormalEstimation, IsotropicRatioQuantileIsReproducibleAndOrdered)
{
  const double q = pcl::rspd::isotropicEigenRatioQuantile (50, 0.05);
  EXPECT_NEAR (q, 0.58, 0.02); // an independent simulation (20,000 draws) gave 0.581
  EXPECT_EQ (q, pcl::rspd::isotropicEigenRatioQuantile (50, 0.05));
  // More samples fill the ball more evenly; a higher quantile is a larger ratio.
  EXPECT_LT (pcl::rspd::isotropicEigenRatioQuantile (20, 0.05), q);
  EXPECT_LT (q, pcl::rspd::isotropicEigenRatioQuantile (100, 0.05));
  EXPECT_LT (q, pcl::rspd::isotropicEigenRatioQuantile (50, 0.5));
  EXPECT_EQ (pcl::rspd::isotropicEigenRatioQuantile (1, 0.05), 0.0);
  EXPECT_EQ (pcl::rspd::isotropicEigenRatioQuantile (50, 0.0), 0.0);
  EXPECT_EQ (pcl::rspd::isotropicEigenRatioQuantile (50, 1.0), 0.0);
}

TEST (NormalEstimation, ResolvedSurfacesKeepTheKScaleNormals)
{
  // Noise-free, and noise 1/30 of the neighbourhood's radius: the k-scale resolves every sample
  // but perhaps a few at the square's corners, and those are the only normals that may change.
  for (const float sigma : {0.f, 0.001f})
  {
    const Points p = noisySquare (20000, sigma, 1);
    const Estimates e = estimateBoth (p, 50);
    EXPECT_LE (e.stats.widened (), 20u);
    std::size_t changed = 0;
    for (std::size_t i = 0; i < p.size (); ++i)
      changed += e.adaptive[i] != e.fixed[i];
    EXPECT_LE (changed, e.stats.widened ());
  }
}

TEST (NormalEstimation, NoiseAsWideAsTheNeighbourhoodIsResolvedAtAWiderScale)
{
  // 20,000 samples on a unit square: the 50-neighbourhood's radius is ~0.028, below the noise
  // (0.04), so the k-scale normals are mostly noise, as on a million-sample unit cube with 1 % noise
  // (radius ~0.01).
  const Points p = noisySquare (20000, 0.04f, 2);
  const Estimates e = estimateBoth (p, 50);
  const double fixed = medianErrorDegrees (p, e.fixed), adaptive = medianErrorDegrees (p, e.adaptive);
  std::printf ("    median error: k-scale %.1f deg, adaptive scale %.1f deg\n", fixed, adaptive);
  EXPECT_GT (fixed, 30.0);
  EXPECT_LT (adaptive, 15.0);
  EXPECT_GT (e.stats.widened (), p.size () / 2);
  EXPECT_LT (e.stats.unresolved, p.size () / 100);
}

TEST (NormalEstimation, PassesMostNeighboursDoNotShareAreWidenedToo)
{
  // Same regime: most k-neighbourhoods fill a slab as thick as they are wide, and the 5 %-level test
  // still passes a share of them; such a sample, with most neighbours unresolved, is widened like
  // them instead of keeping its noise-dominated normal (which then fails its plane's MND).
  const Points p = noisySquare (20000, 0.04f, 3);
  const Estimates e = estimateBoth (p, 50);
  std::size_t inner = 0, bad = 0;
  for (std::size_t i = 0; i < p.size (); ++i)
    if (std::abs (p[i].x ()) < 0.4f && std::abs (p[i].y ()) < 0.4f)
    {
      ++inner;
      bad += std::abs (e.adaptive[i].z ()) < std::cos (30.0 * kDegree);
    }
  std::printf ("    passes most neighbours do not share: %zu; inner samples off by > 30 deg: %zu of %zu\n",
               e.stats.chance_resolved, bad, inner);
  EXPECT_GT (e.stats.chance_resolved, 0u);
  EXPECT_LE (e.stats.chance_resolved, e.stats.unresolved_at_k);
  EXPECT_LT (bad, inner / 25); // 313 of 12,813 measured; 803 without the rule
}

TEST (NormalEstimation, AdaptiveScaleIsIndependentOfThreadCount)
{
  const Points p = noisySquare (30000, 0.03f, 3);
  const Estimates one = estimateBoth (p, 30, 1), two = estimateBoth (p, 30, 2);
  EXPECT_TRUE (one.adaptive == two.adaptive);
  EXPECT_EQ (one.stats.samples_per_scale, two.stats.samples_per_scale);
}

TEST (NormalEstimation, AdaptiveScaleDoesNotDependOnUnitsOrOrientation)
{
  const Points p = noisySquare (20000, 0.03f, 4);
  const Estimates base = estimateBoth (p, 50);

  // A power of two scales every float operation exactly: the same normals, bit for bit.
  Points binary (p.size ());
  for (std::size_t i = 0; i < p.size (); ++i)
    binary[i] = 1024.f * p[i];
  const Estimates b = estimateBoth (binary, 50);
  EXPECT_TRUE (b.adaptive == base.adaptive);
  EXPECT_EQ (b.stats.samples_per_scale, base.stats.samples_per_scale);

  // Millimetres and a rotation change the spatial order, hence which samples represent a scale:
  // the same result statistically.
  const Eigen::Matrix3f r = Eigen::AngleAxisf (0.7f, Eigen::Vector3f (1.f, 2.f, 3.f).normalized ()).toRotationMatrix ();
  Points turned (p.size ());
  for (std::size_t i = 0; i < p.size (); ++i)
    turned[i] = 1000.f * (r * p[i]);
  turned = inSpatialOrder (turned);
  const Estimates t = estimateBoth (turned, 50);
  Points back (p.size ());
  for (std::size_t i = 0; i < p.size (); ++i)
    back[i] = r.transpose () * turned[i] / 1000.f;
  Points normals_back (p.size ());
  for (std::size_t i = 0; i < p.size (); ++i)
    normals_back[i] = r.transpose () * t.adaptive[i];
  const double e_base = medianErrorDegrees (p, base.adaptive), e_turned = medianErrorDegrees (back, normals_back);
  std::printf ("    median error: %.2f deg, in mm and turned %.2f deg\n", e_base, e_turned);
  EXPECT_NEAR (e_turned, e_base, 1.5);
  EXPECT_NEAR (static_cast<double> (t.stats.widened ()), static_cast<double> (base.stats.widened ()), 0.03 * p.size ());
}

TEST (NormalEstimation, VolumeWithoutSurfaceIsAccountedFor)
{
  // A uniformly filled cube has no surface at any scale: no normal is meaningful, but every sample
  // still gets a unit normal, and the counts add up (checked in estimateBoth).
  const Points p = filledCube (20000, 1.f, 5);
  const Estimates e = estimateBoth (p, 30);
  for (const auto& n : e.adaptive)
    ASSERT_NEAR (n.norm (), 1.f, 1e-5f);
  EXPECT_GT (e.stats.unresolved, 0u);
}

TEST (NormalEstimation, AutomaticScaleWidensOnlyWhenMostSamplesAreUnresolved)
{
  // A noise-swamped square (most samples unresolved at the k-scale): the same as Adaptive. The same
  // square with a quarter of its samples replaced by uniform outliers above it, at a noise the k-scale
  // resolves: the outliers are unresolved, but the median sample is not, so nothing is widened.
  const Points noisy = noisySquare (20000, 0.04f, 6);
  const Estimates e = estimateBoth (noisy, 50);
  pcl::rspd::NeighborGraph graph;
  ASSERT_TRUE (pcl::rspd::buildKnnGraph (noisy, 50, 2, graph));
  Points automatic;
  pcl::rspd::NormalScaleStatistics st;
  pcl::rspd::estimateAdaptiveScaleNormals (noisy, graph, 2, automatic, &st, true);
  EXPECT_TRUE (automatic == e.adaptive);
  EXPECT_TRUE (st.widened_scales);
  EXPECT_EQ (st.samples_per_scale, e.stats.samples_per_scale);

  std::mt19937 rng (7);
  std::uniform_real_distribution<float> u (-0.5f, 0.5f);
  Points mixed = noisySquare (15000, 0.001f, 8);
  for (int i = 0; i < 5000; ++i)
    mixed.emplace_back (u (rng), u (rng), 0.5f + u (rng));
  mixed = inSpatialOrder (mixed);
  const Estimates m = estimateBoth (mixed, 50);
  ASSERT_TRUE (pcl::rspd::buildKnnGraph (mixed, 50, 2, graph));
  pcl::rspd::estimateAdaptiveScaleNormals (mixed, graph, 2, automatic, &st, true);
  EXPECT_GT (st.unresolved_at_k, 1000u);
  EXPECT_LT (2 * st.unresolved_at_k, mixed.size ());
  EXPECT_FALSE (st.widened_scales);
  EXPECT_EQ (st.widened (), 0u);
  EXPECT_EQ (st.unresolved, st.unresolved_at_k);
  EXPECT_TRUE (automatic == m.fixed);
  EXPECT_GT (m.stats.widened (), 0u); // Adaptive does widen some of the outliers
}

namespace
{
/** The 50-NN graph of \a p and its PCA normals, as a caller at k = 50 would give them. */
struct KScale
{
  pcl::rspd::NeighborGraph graph;
  Points normals;
};

KScale
kScale (const Points& p)
{
  KScale k;
  EXPECT_TRUE (pcl::rspd::buildKnnGraph (p, 50, 2, k.graph));
  pcl::rspd::estimateNormals (p, k.graph, 2, k.normals);
  return k;
}
} // namespace

TEST (NormalEstimation, GivenNormalsThatAreNoiseAtTheKScaleAreTold)
{
  // Noise as wide as the 50-neighbourhood (above): PCA normals at that k are noise, and normals
  // given as exactly those are told apart from normals of a wider scale (here exact, spread 0).
  const Points p = noisySquare (20000, 0.04f, 2);
  const KScale k = kScale (p);
  const pcl::rspd::NeighborGraph& graph = k.graph;
  const Points& k_scale = k.normals;
  pcl::rspd::GivenNormalCheck check;
  EXPECT_TRUE (pcl::rspd::givenNormalsAreNoise (p, graph, 2, k_scale, &check));
  EXPECT_GT (2 * check.unresolved, check.probes);
  EXPECT_GE (check.given_spread, check.neighbourhood_spread);
  std::printf ("    k-scale normals: %zu of %zu probes unresolved, spread %.1f deg against %.1f deg\n",
               check.unresolved, check.probes, check.given_spread / kDegree, check.neighbourhood_spread / kDegree);
  const Points exact (p.size (), Eigen::Vector3f::UnitZ ());
  EXPECT_FALSE (pcl::rspd::givenNormalsAreNoise (p, graph, 2, exact, &check));
  EXPECT_EQ (check.given_spread, 0.0);
  // One thread or two: the same answer and figures.
  pcl::rspd::GivenNormalCheck one;
  EXPECT_TRUE (pcl::rspd::givenNormalsAreNoise (p, graph, 1, k_scale, &one));
  pcl::rspd::givenNormalsAreNoise (p, graph, 2, k_scale, &check);
  EXPECT_EQ (one.given_spread, check.given_spread);
  EXPECT_EQ (one.neighbourhood_spread, check.neighbourhood_spread);
}

namespace
{
/** A generated scene at \a n samples, in spatial order; \a truth: each sample's face normal (its
  * face's least-squares plane; +Z for samples of no plane). */
Points
sparseScene (const std::string& name, std::size_t n, Points& truth)
{
  pcl::rspd::SceneOptions o;
  o.num_points = n;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene (name, o);
  Points raw;
  for (const auto& q : scene.cloud)
    raw.push_back (q.getVector3fMap ());
  std::vector<Eigen::Vector3f> face (static_cast<std::size_t> (scene.num_planes) + 1, Eigen::Vector3f::UnitZ ());
  for (int l = 1; l <= scene.num_planes; ++l)
  {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
    std::size_t m = 0;
    for (std::size_t i = 0; i < raw.size (); ++i)
      if (scene.labels[i] == static_cast<std::uint32_t> (l))
      {
        mean += raw[i].cast<double> ();
        ++m;
      }
    mean /= static_cast<double> (m);
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero ();
    for (std::size_t i = 0; i < raw.size (); ++i)
      if (scene.labels[i] == static_cast<std::uint32_t> (l))
      {
        const Eigen::Vector3d d = raw[i].cast<double> () - mean;
        cov += d * d.transpose ();
      }
    face[static_cast<std::size_t> (l)] = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (cov).eigenvectors ().col (0).cast<float> ();
  }
  const std::vector<std::uint32_t> order = pcl::rspd::spatialOrder (raw, 2);
  Points sorted (raw.size ());
  truth.resize (raw.size ());
  for (std::size_t i = 0; i < raw.size (); ++i)
  {
    sorted[i] = raw[order[i]];
    truth[i] = face[scene.labels[order[i]]];
  }
  return sorted;
}

/** The generated staircase (30 faces) at 5,000 samples, a few hundred a face (sparseScene). */
Points
sparseStairs (Points& truth)
{
  return sparseScene ("staircase", 5000, truth);
}
} // namespace

TEST (NormalEstimation, GivenNormalsThatBlurTheFacesAFinerScaleResolvesAreTold)
{
  // PCA normals over 50 neighbours span two or three steps and turn towards the stair's slope; at
  // 15 neighbours most samples resolve their own face, which those normals fit worse than twice its
  // plane's residual. The faces' own normals fit them.
  Points truth;
  const Points p = sparseStairs (truth);
  const KScale k = kScale (p);
  pcl::rspd::GivenNormalCheck check;
  EXPECT_TRUE (pcl::rspd::givenNormalsBlurFaces (p, k.graph, 15, 2, k.normals, &check));
  EXPECT_EQ (check.fine_k, 15);
  EXPECT_EQ (check.probes, p.size ());
  EXPECT_GT (2 * check.fine_resolved, check.probes);
  EXPECT_GT (2 * check.fine_tilted, check.fine_resolved);
  std::printf ("    k = 50 normals against 15-neighbourhoods: %zu of %zu resolved probes tilted\n", check.fine_tilted,
               check.fine_resolved);
  // Nor is a stair's noise, as PCA normals at that noise give it, mistaken for a tilt.
  pcl::rspd::GivenNormalCheck exact;
  EXPECT_FALSE (pcl::rspd::givenNormalsBlurFaces (p, k.graph, 15, 2, truth, &exact));
  EXPECT_LT (4 * exact.fine_tilted, exact.fine_resolved);
  // One thread or two: the same counts.
  pcl::rspd::GivenNormalCheck one;
  EXPECT_TRUE (pcl::rspd::givenNormalsBlurFaces (p, k.graph, 15, 1, k.normals, &one));
  EXPECT_EQ (one.fine_resolved, check.fine_resolved);
  EXPECT_EQ (one.fine_tilted, check.fine_tilted);
  EXPECT_EQ (one.graph_tilted, check.graph_tilted);
  EXPECT_EQ (one.graph_and_given_tilted, check.graph_and_given_tilted);
  // No finer scale than the graph's, or bad input: no check.
  EXPECT_FALSE (pcl::rspd::givenNormalsBlurFaces (p, k.graph, 50, 2, k.normals));
  EXPECT_FALSE (pcl::rspd::givenNormalsBlurFaces (p, k.graph, 15, 2, Points (3, Eigen::Vector3f::UnitZ ())));
}

TEST (NormalEstimation, GivenNormalsOfTheGraphsScaleAreToldWhereFewSamplesLieNearAnEdge)
{
  // The facade at 8,000 samples: its faces are large, so 50-neighbourhood PCA normals are tilted off
  // the faces 15-neighbourhoods resolve at a few of the probes only (near edges and in the windows'
  // recesses), but there at nearly every one where that 50-neighbourhood's normal is: they are of
  // that scale. Normals of the finer scale and the faces' own are kept.
  Points truth;
  const Points p = sparseScene ("facade", 8000, truth);
  const KScale k = kScale (p);
  pcl::rspd::GivenNormalCheck check;
  EXPECT_TRUE (pcl::rspd::givenNormalsBlurFaces (p, k.graph, 15, 2, k.normals, &check));
  EXPECT_GT (2 * check.fine_resolved, check.probes);
  EXPECT_LT (4 * check.fine_tilted, check.fine_resolved); // the first test alone keeps them
  EXPECT_GT (check.graph_tilted, 0u);
  EXPECT_GT (2 * check.graph_and_given_tilted, check.graph_tilted);
  std::printf ("    k = 50 normals: %zu of %zu resolved probes tilted, %zu of the %zu where the 50-neighbourhood's are\n",
               check.fine_tilted, check.fine_resolved, check.graph_and_given_tilted, check.graph_tilted);
  pcl::rspd::GivenNormalCheck exact;
  EXPECT_FALSE (pcl::rspd::givenNormalsBlurFaces (p, k.graph, 15, 2, truth, &exact));
  EXPECT_EQ (exact.graph_tilted, check.graph_tilted);
  EXPECT_LT (2 * exact.graph_and_given_tilted, exact.graph_tilted);
  pcl::rspd::NeighborGraph fine_graph;
  ASSERT_TRUE (pcl::rspd::buildKnnGraph (p, 15, 2, fine_graph));
  Points fine;
  pcl::rspd::estimateNormals (p, fine_graph, 2, fine);
  pcl::rspd::GivenNormalCheck finer;
  EXPECT_FALSE (pcl::rspd::givenNormalsBlurFaces (p, k.graph, 15, 2, fine, &finer));
  EXPECT_EQ (finer.graph_and_given_tilted, 0u);
}

TEST (NormalEstimation, GivenNormalsOfAResolvedSurfaceAreKept)
{
  // Noise 1/30 of the neighbourhood's radius: the k-scale resolves the surface, and the caller's
  // normals are trusted whatever they are. Bad input: no check.
  const Points p = noisySquare (20000, 0.001f, 1);
  const KScale k = kScale (p);
  const pcl::rspd::NeighborGraph& graph = k.graph;
  const Points& k_scale = k.normals;
  pcl::rspd::GivenNormalCheck check;
  EXPECT_FALSE (pcl::rspd::givenNormalsAreNoise (p, graph, 2, k_scale, &check));
  EXPECT_LT (2 * check.unresolved, check.probes);
  EXPECT_EQ (check.neighbourhood_spread, 0.0); // not measured
  EXPECT_FALSE (pcl::rspd::givenNormalsAreNoise (p, graph, 2, Points (3), &check));
  EXPECT_FALSE (pcl::rspd::givenNormalsAreNoise (Points (), graph, 2, Points (), &check));
}

namespace
{
/** A fold: face A in z = 0 (x in [-1, 0]) and face B in x = 0 (z in [0, 1]), y in [-0.5, 0.5], n
  * samples in all, Gaussian noise of \a sigma along each face's normal, in spatial order. */
Points
fold (std::size_t n, float sigma, unsigned seed)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> u (0.f, 1.f);
  std::normal_distribution<float> g (0.f, sigma);
  Points p (n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const float a = u (rng), y = u (rng) - 0.5f, e = sigma > 0.f ? g (rng) : 0.f;
    p[i] = i % 2 == 0 ? Eigen::Vector3f (-a, y, e) : Eigen::Vector3f (e, y, a);
  }
  return inSpatialOrder (p);
}

/** Median angle (degrees) to +Z of the normals of face A's samples whose distance to the edge lies
  * in [near, far) and that are away from the y rims. */
double
bandErrorDegrees (const Points& p, const Points& normals, float near, float far)
{
  std::vector<double> a;
  for (std::size_t i = 0; i < p.size (); ++i)
    if (std::abs (p[i].z ()) < 0.02f && p[i].x () <= -near && p[i].x () > -far && std::abs (p[i].y ()) < 0.3f)
      a.push_back (std::acos (std::min (1.0, std::abs (static_cast<double> (normals[i].z ())))) / kDegree);
  std::nth_element (a.begin (), a.begin () + a.size () / 2, a.end ());
  return a[a.size () / 2];
}

struct Narrowed
{
  Points pca, narrowed;
  std::size_t count = 0;
};

Narrowed
narrowBoth (const Points& p, int k, int threads = 2)
{
  pcl::rspd::NeighborGraph graph;
  EXPECT_TRUE (pcl::rspd::buildKnnGraph (p, k, threads, graph));
  Narrowed r;
  pcl::rspd::estimateNormals (p, graph, threads, r.pca);
  r.narrowed = r.pca;
  r.count = pcl::rspd::narrowNormalsAtEdges (p, graph, threads, 15, r.narrowed);
  return r;
}
} // namespace

TEST (EdgeNormals, SamplesNearAnEdgeGetTheirFacesNormal)
{
  // 4,000 samples on 2 m²: a 50-neighbourhood reaches about 9 cm, a 15-neighbourhood about 5 cm.
  // Between the two from the edge, the k-normal leans towards face B; the narrowed one does not.
  const Points p = fold (4000, 1e-4f, 1);
  const Narrowed r = narrowBoth (p, 50);
  const double pca = bandErrorDegrees (p, r.pca, 0.05f, 0.08f), narrowed = bandErrorDegrees (p, r.narrowed, 0.05f, 0.08f);
  std::printf ("    5-8 cm from the edge: k-normals %.2f deg off, narrowed %.2f deg; %zu of %zu narrowed\n", pca,
               narrowed, r.count, p.size ());
  EXPECT_GT (pca, 5.0);
  EXPECT_LT (narrowed, 1.0);
  // Farther than a k-neighbourhood from the edge, a normal changes only by chance (a few samples whose
  // spread crosses the ratio and whose normals differ by more than their noise), and then by noise.
  std::size_t far = 0, changed = 0;
  for (std::size_t i = 0; i < p.size (); ++i)
    if (p[i].x () < -0.15f && std::abs (p[i].y ()) < 0.35f)
    {
      ++far;
      if (r.narrowed[i] == r.pca[i])
        continue;
      ++changed;
      EXPECT_LT (std::acos (std::min (1.0, std::abs (static_cast<double> (r.narrowed[i].dot (r.pca[i]))))) / kDegree, 0.5);
    }
  EXPECT_LT (changed, far / 50);
}

TEST (EdgeNormals, OnASubsetOnlyItsSamplesAreNarrowed)
{
  // The small-plane pass narrows the normals of the samples growth left alone: each sample's result
  // is the one the whole cloud's narrowing gives it, and the others keep their k-normals.
  const Points p = fold (4000, 1e-4f, 1);
  const Narrowed all = narrowBoth (p, 50);
  pcl::rspd::NeighborGraph graph;
  ASSERT_TRUE (pcl::rspd::buildKnnGraph (p, 50, 2, graph));
  std::vector<std::uint32_t> subset;
  for (std::uint32_t i = 0; i < p.size (); i += 3)
    subset.push_back (i);
  Points normals = all.pca;
  std::vector<char> flags;
  const std::size_t count = pcl::rspd::narrowNormalsAtEdges (p, graph, 2, 15, normals, &flags, &subset);
  EXPECT_GT (count, 0u);
  std::size_t flagged = 0;
  for (std::uint32_t i = 0; i < p.size (); ++i)
  {
    const bool in = i % 3 == 0;
    EXPECT_EQ (normals[i], in ? all.narrowed[i] : all.pca[i]) << i;
    if (!in)
      EXPECT_EQ (flags[i], 0) << i;
    flagged += flags[i] != 0;
  }
  EXPECT_EQ (flagged, count);
}

TEST (EdgeNormals, NoiseAloneKeepsTheKNormals)
{
  // One noisy face, no edge (noise a third of a 50-neighbourhood's radius): a narrower normal is only
  // a noisier one, and the k-normal stands but where both tests pass by chance (1.4 %, measured).
  const Points p = noisySquare (20000, 0.01f, 5);
  const Narrowed r = narrowBoth (p, 50);
  std::printf ("    %zu of %zu narrowed; median error %.2f -> %.2f deg\n", r.count, p.size (),
               medianErrorDegrees (p, r.pca), medianErrorDegrees (p, r.narrowed));
  EXPECT_LT (r.count, p.size () / 50);
  EXPECT_NEAR (medianErrorDegrees (p, r.narrowed), medianErrorDegrees (p, r.pca), 0.15);
}

TEST (EdgeNormals, VolumeWithoutSurfaceIsNotNarrowed)
{
  // Samples filling a cube: a 15-neighbourhood resolves a surface only by chance (the resolution
  // test's 5 % level), and only such a sample can be narrowed.
  const Points p = filledCube (5000, 0.5f, 6);
  const Narrowed r = narrowBoth (p, 50);
  std::printf ("    %zu of %zu narrowed\n", r.count, p.size ());
  EXPECT_LT (r.count, p.size () / 20);
}

TEST (EdgeNormals, IndependentOfThreadCountUnitsAndOrientation)
{
  const Points p = fold (6000, 0.002f, 7);
  const Narrowed one = narrowBoth (p, 40, 1), two = narrowBoth (p, 40, 2);
  EXPECT_TRUE (one.narrowed == two.narrowed);
  EXPECT_EQ (one.count, two.count);
  // A power of two scales every float operation exactly.
  Points binary (p.size ());
  for (std::size_t i = 0; i < p.size (); ++i)
    binary[i] = 1024.f * p[i];
  const Narrowed b = narrowBoth (binary, 40);
  EXPECT_TRUE (b.narrowed == one.narrowed);
  // Millimetres, turned: the same share narrowed and the same accuracy near the edge.
  const Eigen::Matrix3f rot = Eigen::AngleAxisf (0.9f, Eigen::Vector3f (3.f, -1.f, 2.f).normalized ()).toRotationMatrix ();
  Points turned (p.size ());
  for (std::size_t i = 0; i < p.size (); ++i)
    turned[i] = 1000.f * (rot * p[i]);
  const Narrowed t = narrowBoth (turned, 40);
  Points normals_back (p.size ());
  for (std::size_t i = 0; i < p.size (); ++i)
    normals_back[i] = rot.transpose () * t.narrowed[i];
  std::printf ("    narrowed %zu, turned in mm %zu\n", one.count, t.count);
  EXPECT_NEAR (static_cast<double> (t.count), static_cast<double> (one.count), 0.02 * one.count);
  EXPECT_NEAR (bandErrorDegrees (p, normals_back, 0.04f, 0.07f), bandErrorDegrees (p, one.narrowed, 0.04f, 0.07f), 0.5);
}

TEST (EdgeNormals, NothingToDoWithoutANarrowerPrefix)
{
  const Points p = fold (2000, 1e-4f, 8);
  pcl::rspd::NeighborGraph graph;
  ASSERT_TRUE (pcl::rspd::buildKnnGraph (p, 15, 1, graph));
  Points normals;
  pcl::rspd::estimateNormals (p, graph, 1, normals);
  const Points before = normals;
  EXPECT_EQ (pcl::rspd::narrowNormalsAtEdges (p, graph, 1, 15, normals), 0u); // k = k_min
  EXPECT_EQ (pcl::rspd::narrowNormalsAtEdges (p, graph, 1, 1, normals), 0u);  // k_min < 2
  Points wrong_size (3);
  EXPECT_EQ (pcl::rspd::narrowNormalsAtEdges (p, graph, 1, 10, wrong_size), 0u);
  EXPECT_TRUE (normals == before);
}
