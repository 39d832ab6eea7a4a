/*
 * Tests of the groups of noisy small seeds (joinNoisySeeds) and of the union-find they use.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/disjoint_sets.h>
#include <pcl_rspd/seed_groups.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace pcl::rspd;

namespace
{
constexpr double kDegree = M_PI / 180.0;

/** A rough face: 1 x 1 m in z = 0, 40 x 40 samples, noise 1 cm, each normal tilted at random by
  * about 10° (as PCA normals of a rough face), cut into 4 x 4 seeds of 10 x 10 samples, each with
  * its own estimate (Eqs. 3-9). Optionally a second face, tilted by \a tilt about the y axis beyond
  * x = 1, cut the same way. */
struct Scene
{
  PointSet set;
  std::vector<PlanarPatch> seeds;
  NeighborGraph graph;
};

void
addFace (Scene& s, const Eigen::Vector3f& origin, const Eigen::Vector3f& a, const Eigen::Vector3f& b, std::uint32_t seed,
         const DetectorParameters& params)
{
  const int n = 40;
  const std::vector<std::uint32_t> added = rspd_test::addRectangle (s.set, origin, a, b, n, n, 0.01f, seed);
  std::mt19937 rng (seed + 100);
  std::normal_distribution<float> g (0.0f, 0.12f);
  for (const auto i : added)
    s.set.normals[i] = (s.set.normals[i] + Eigen::Vector3f (g (rng), g (rng), g (rng))).normalized ();
  for (int bi = 0; bi < 4; ++bi)
    for (int bj = 0; bj < 4; ++bj)
    {
      std::vector<std::uint32_t> members;
      for (int i = 10 * bi; i < 10 * bi + 10; ++i)
        for (int j = 10 * bj; j < 10 * bj + 10; ++j)
          members.push_back (added[static_cast<std::size_t> (i * n + j)]);
      PlaneEstimate e;
      ASSERT_TRUE (estimatePlane (s.set, members, params, e));
      PlanarPatch p;
      p.members = members;
      p.first_index = members.front ();
      p.setEstimate (e);
      s.seeds.push_back (p);
    }
}

DetectorParameters
parameters ()
{
  DetectorParameters p;
  p.min_patch_size = 300;
  p.small_cell_size = 20; // the pass's cell size, at which a group below ε is judged
  return p;
}

Scene
makeScene (bool second_face, double tilt = 0.0)
{
  Scene s;
  addFace (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1, parameters ());
  if (second_face)
  {
    const float c = static_cast<float> (std::cos (tilt)), sn = static_cast<float> (std::sin (tilt));
    addFace (s, {1.02f, 0, 0}, {c, 0, sn}, {0, 1, 0}, 2, parameters ());
  }
  s.graph = rspd_test::bruteForceGraph (s.set.points, 20);
  return s;
}

double
maxMnd (const std::vector<PlanarPatch>& seeds)
{
  double m = 0.0;
  for (const auto& p : seeds)
    m = std::max (m, p.mnd);
  return m;
}
} // namespace

TEST (SeedGroups, TouchingAgreeingSeedsOfARoughFaceSeedOnePlane)
{
  const Scene s = makeScene (false);
  ASSERT_EQ (s.seeds.size (), 16u);
  // The planes found are a little smoother and thinner than the face: within the ratio of 2.
  const std::vector<PlanarPatch> out = joinNoisySeeds (s.set, s.graph, parameters (), s.seeds, 0.8 * maxMnd (s.seeds), 0.03);
  ASSERT_EQ (out.size (), 1u);
  EXPECT_GE (out[0].members.size (), 1200u); // T3's three quarters of 1,600, at least
  EXPECT_GT (std::abs (out[0].normal.z ()), std::cos (2.0 * kDegree));
}

TEST (SeedGroups, GroupFarNoisierOrThickerThanThePlanesFoundSeedsNothing)
{
  const Scene s = makeScene (false);
  // Planes found five times smoother (the tank facets' case), or five times thinner (a slab of outliers).
  EXPECT_TRUE (joinNoisySeeds (s.set, s.graph, parameters (), s.seeds, 0.2 * maxMnd (s.seeds), 0.03).empty ());
  EXPECT_TRUE (joinNoisySeeds (s.set, s.graph, parameters (), s.seeds, 0.8 * maxMnd (s.seeds), 0.004).empty ());
  // The ratio is the parameter's: at 10 the smoother planes let the face in.
  DetectorParameters wide = parameters ();
  wide.noisy_group_ratio = 10.0;
  EXPECT_EQ (joinNoisySeeds (s.set, s.graph, wide, s.seeds, 0.2 * maxMnd (s.seeds), 0.03).size (), 1u);
}

TEST (SeedGroups, GroupOfFewerThanEpsilonSamplesSeedsOnlyAsALoneSeedWould)
{
  // ε above what the face holds: the group is judged at the pass's cell size, as a lone seed is (its
  // grown plane must reach ε); without lone seeds it seeds nothing.
  const Scene s = makeScene (false);
  DetectorParameters big = parameters ();
  big.min_patch_size = 2000; // more than the face holds
  const std::vector<PlanarPatch> out = joinNoisySeeds (s.set, s.graph, big, s.seeds, 0.8 * maxMnd (s.seeds), 0.03);
  ASSERT_EQ (out.size (), 1u);
  EXPECT_GE (out[0].members.size (), 1200u);
  EXPECT_GT (std::abs (out[0].normal.z ()), std::cos (2.0 * kDegree));
  big.noisy_lone_seeds = false;
  EXPECT_TRUE (joinNoisySeeds (s.set, s.graph, big, s.seeds, 0.8 * maxMnd (s.seeds), 0.03).empty ());
  // Still on the group's terms: far noisier than the planes found, it seeds nothing.
  big.noisy_lone_seeds = true;
  EXPECT_TRUE (joinNoisySeeds (s.set, s.graph, big, s.seeds, 0.2 * maxMnd (s.seeds), 0.03).empty ());
}

TEST (SeedGroups, LoneSeedSeedsAloneOnTheGroupsTermsButEpsilon)
{
  // One seed of 100 samples against ε = 300: it joins no other, and seeds as it is (its grown plane
  // must reach ε); without lone seeds, or noisier than twice the planes found, it seeds nothing.
  const Scene s = makeScene (false);
  const std::vector<PlanarPatch> one (s.seeds.begin (), s.seeds.begin () + 1);
  const std::vector<PlanarPatch> out = joinNoisySeeds (s.set, s.graph, parameters (), one, maxMnd (s.seeds), 0.03);
  ASSERT_EQ (out.size (), 1u);
  EXPECT_EQ (out[0].members, one[0].members);
  EXPECT_EQ (out[0].normal, one[0].normal);
  EXPECT_TRUE (joinNoisySeeds (s.set, s.graph, parameters (), one, 0.2 * one[0].mnd, 0.03).empty ());
  EXPECT_TRUE (joinNoisySeeds (s.set, s.graph, parameters (), one, maxMnd (s.seeds), 0.2 * one[0].mdp).empty ());
  DetectorParameters off = parameters ();
  off.noisy_lone_seeds = false;
  EXPECT_TRUE (joinNoisySeeds (s.set, s.graph, off, one, maxMnd (s.seeds), 0.03).empty ());
  // Seeds that join a group are never also lone seeds: the whole face is still one plane.
  EXPECT_EQ (joinNoisySeeds (s.set, s.graph, parameters (), s.seeds, 0.8 * maxMnd (s.seeds), 0.03).size (), 1u);
}

TEST (SeedGroups, FacesMeetingAtAnEdgeStayApart)
{
  // Two rough faces 45° apart, side by side: their seeds touch along the edge but do not agree, so
  // each face is a group of its own, and no group holds samples of both.
  const Scene s = makeScene (true, 45.0 * kDegree);
  ASSERT_EQ (s.seeds.size (), 32u);
  const std::vector<PlanarPatch> out = joinNoisySeeds (s.set, s.graph, parameters (), s.seeds, 0.8 * maxMnd (s.seeds), 0.03);
  ASSERT_EQ (out.size (), 2u);
  for (const auto& p : out)
  {
    const bool first = p.members.front () < 1600;
    for (const auto i : p.members)
      EXPECT_EQ (i < 1600, first);
  }
}

TEST (SeedGroups, SameSeedsGiveTheSameGroups)
{
  // Groups come in order of their first seed: a second run gives the same members.
  const Scene s = makeScene (true, 45.0 * kDegree);
  const std::vector<PlanarPatch> a = joinNoisySeeds (s.set, s.graph, parameters (), s.seeds, 0.8 * maxMnd (s.seeds), 0.03);
  const std::vector<PlanarPatch> b = joinNoisySeeds (s.set, s.graph, parameters (), s.seeds, 0.8 * maxMnd (s.seeds), 0.03);
  ASSERT_EQ (a.size (), b.size ());
  for (std::size_t k = 0; k < a.size (); ++k)
    EXPECT_EQ (a[k].members, b[k].members);
}

TEST (DisjointSets, GroupsDoNotDependOnTheJoinOrder)
{
  // Each set's root is its smallest element, and groups come in order of it.
  DisjointSets a (6), b (6);
  a.join (4, 1);
  a.join (1, 3);
  a.join (5, 2);
  b.join (3, 1);
  b.join (2, 5);
  b.join (3, 4);
  const std::vector<std::vector<std::uint32_t>> expected = {{0}, {1, 3, 4}, {2, 5}};
  EXPECT_EQ (a.groups (), expected);
  EXPECT_EQ (b.groups (), expected);
  EXPECT_EQ (a.find (4), 1u);
  EXPECT_EQ (b.find (5), 2u);
}

TEST (DisjointSets, FilteredGroupsCountOnlyTheKeptElements)
{
  // {0}, {1, 3, 4, 6}, {2, 5}, {7}: with 4 left out, {1, 3, 6} keeps three elements.
  DisjointSets s (8);
  s.join (4, 1);
  s.join (1, 3);
  s.join (5, 2);
  s.join (6, 4);
  const auto all = [] (std::uint32_t) { return true; };
  const auto not4 = [] (std::uint32_t i) { return i != 4; };
  using Groups = std::vector<std::vector<std::uint32_t>>;
  EXPECT_EQ (s.groups (1, all), s.groups ());
  EXPECT_EQ (s.groups (2, all), (Groups {{1, 3, 4, 6}, {2, 5}}));
  EXPECT_EQ (s.groups (3, not4), (Groups {{1, 3, 6}}));
  EXPECT_EQ (s.groups (4, not4), Groups ());
  // A set whose kept elements exclude its root still comes in order of its root.
  const auto odd = [] (std::uint32_t i) { return i % 2 == 1; };
  EXPECT_EQ (s.groups (1, odd), (Groups {{1, 3}, {5}, {7}}));
  EXPECT_EQ (s.groups (0, [] (std::uint32_t) { return false; }), Groups ());
}
