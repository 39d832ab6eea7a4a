/*
 * Tests of the bent-plane split (departure, fitHinge and splitBentPlanes).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/bent_planes.h>
#include <pcl_rspd/plane_curvature.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <set>

using namespace pcl::rspd;

namespace
{
constexpr float kDegree = static_cast<float> (M_PI / 180.0);

/** A roof: two faces meeting along the y axis, each tilted by half of the dihedral angle from
  * z = 0, Gaussian noise along each face's normal; faces[0] at x < 0, faces[1] at x > 0. */
struct Roof
{
  PointSet set;
  std::vector<std::uint32_t> faces[2];
};

/** A roof of two faces \a width across and \a length along their edge (the y axis), meeting at
  * \a dihedral, Gaussian noise \a noise along each face's normal, exact normals. */
Roof
makeRoofSized (float dihedral, float noise, float width, float length, int across, int along, std::uint32_t seed = 1)
{
  Roof r;
  const float h = 0.5f * dihedral;
  const Eigen::Vector3f right (width * std::cos (h), 0.0f, -width * std::sin (h));
  const Eigen::Vector3f left (-width * std::cos (h), 0.0f, -width * std::sin (h));
  const Eigen::Vector3f on (0.0f, length, 0.0f);
  r.faces[0] = rspd_test::addRectangle (r.set, {0, 0, 0}, on, left, along, across, noise, seed);
  r.faces[1] = rspd_test::addRectangle (r.set, {0, 0, 0}, right, on, across, along, noise, seed + 1);
  return r;
}

/** The roof of 0.4 x 0.6 m faces, nu x nv samples a face. */
Roof
makeRoof (float dihedral, float noise, int nu = 40, int nv = 60, std::uint32_t seed = 1)
{
  return makeRoofSized (dihedral, noise, 0.4f, 0.6f, nu, nv, seed);
}

std::vector<PlanarPatch>
onePlane (std::size_t n)
{
  return rspd_test::onePatchOfAll (n, 0.05, 0.5);
}


/** Samples of \a face that ended in a patch other than the one holding most of them, all of them and
  * those farther than \a band from the plane x = 0 (the roofs' edge). */
std::pair<std::size_t, std::size_t>
strays (const PointSet& set, const std::vector<PlanarPatch>& patches, const std::vector<std::uint32_t>& face,
        float band = 0.05f)
{
  const std::set<std::uint32_t> f (face.begin (), face.end ());
  std::size_t best = 0;
  for (std::size_t l = 1; l < patches.size (); ++l)
  {
    std::size_t a = 0, b = 0;
    for (const auto i : patches[l].members)
      a += f.count (i);
    for (const auto i : patches[best].members)
      b += f.count (i);
    if (a > b)
      best = l;
  }
  std::pair<std::size_t, std::size_t> n (0, 0);
  const std::set<std::uint32_t> home (patches[best].members.begin (), patches[best].members.end ());
  for (const auto i : face)
    if (!home.count (i))
    {
      ++n.first;
      n.second += std::abs (set.points[i].x ()) > band ? 1 : 0;
    }
  return n;
}
} // namespace

TEST (BentPlanes, HingeFindsTheEdgeOfARoof)
{
  const Roof r = makeRoof (30.0f * kDegree, 0.005f);
  std::vector<std::uint32_t> all (r.set.size ());
  for (std::uint32_t i = 0; i < all.size (); ++i)
    all[i] = i;
  HingeFit fit;
  ASSERT_TRUE (fitHinge (r.set, all, fit));
  EXPECT_NEAR (fit.angle, 30.0 * kDegree, 1.0 * kDegree);
  EXPECT_NEAR (fit.split_sigma, 0.005, 0.001);  // each side: its own noise
  EXPECT_GT (fit.single_sigma, 4.0 * fit.split_sigma); // one plane: the bend
  // The cut runs along the edge: each side holds one face, but for samples within noise of both
  // planes (less than 3 σ / sin 30° = 3 cm from the edge).
  for (int s = 0; s < 2; ++s)
  {
    std::size_t off = 0, far = 0, positive = 0;
    for (const auto i : fit.parts[s])
      positive += r.set.points[i].x () > 0 ? 1 : 0;
    const float sign = 2 * positive > fit.parts[s].size () ? 1.0f : -1.0f;
    for (const auto i : fit.parts[s])
      if (sign * r.set.points[i].x () < 0)
      {
        ++off;
        far += std::abs (r.set.points[i].x ()) > 0.03f ? 1 : 0;
      }
    EXPECT_EQ (far, 0u);
    EXPECT_LE (off, fit.parts[s].size () / 20);
  }
}

TEST (BentPlanes, AHingeNeedsTheNormalsToTurnToo)
{
  // A roof whose faces' normals turn with them is bent at an edge; the same positions with normals
  // that do not turn (a flat noisy face whose cut sides tilt by chance) are not, unless positions
  // alone decide (DetectorParameters::hinge_normal_turn off).
  Roof r = makeRoof (40.0f * kDegree, 0.005f);
  std::vector<std::uint32_t> all (r.set.size ());
  std::iota (all.begin (), all.end (), 0u);
  DetectorParameters p = rspd_test::unitParameters ();
  EXPECT_TRUE (p.hinge_normal_turn);
  EXPECT_TRUE (bentAtAnEdge (r.set, all, p));
  // Normals turned by 10° only (under T1's 15°), with signs mixed as PCA leaves them.
  for (std::uint32_t i = 0; i < r.set.size (); ++i)
  {
    const float t = (r.set.points[i].x () > 0 ? 5.0f : -5.0f) * kDegree;
    r.set.normals[i] = Eigen::Vector3f (std::sin (t), 0.0f, std::cos (t)) * (i % 3 == 0 ? -1.0f : 1.0f);
  }
  EXPECT_FALSE (bentAtAnEdge (r.set, all, p));
  p.hinge_normal_turn = false;
  EXPECT_TRUE (bentAtAnEdge (r.set, all, p));
  // Turned by 30°: a hinge again.
  p.hinge_normal_turn = true;
  for (std::uint32_t i = 0; i < r.set.size (); ++i)
  {
    const float t = (r.set.points[i].x () > 0 ? 15.0f : -15.0f) * kDegree;
    r.set.normals[i] = Eigen::Vector3f (std::sin (t), 0.0f, std::cos (t));
  }
  EXPECT_TRUE (bentAtAnEdge (r.set, all, p));
}

TEST (BentPlanes, RoofHeldByOnePlaneIsSplitIntoItsFaces)
{
  const Roof r = makeRoof (30.0f * kDegree, 0.01f);
  std::vector<PlanarPatch> patches = onePlane (r.set.size ());
  std::vector<char> split;
  EXPECT_EQ (splitBentPlanes (r.set, rspd_test::unitParameters (), patches, &split), 1u);
  ASSERT_EQ (patches.size (), 2u);
  EXPECT_EQ (split, std::vector<char> ({1, 1}));
  // Its faces are no face shared by two planes.
  const NeighborGraph graph = rspd_test::bruteForceGraph (r.set.points, 20);
  std::vector<PlanarPatch> joined = patches;
  EXPECT_EQ (joinSplitFaces (r.set, graph, rspd_test::unitParameters (), joined, split), 0u);
  EXPECT_EQ (joined.size (), 2u);
  // Samples change face only within noise of both planes (3 σ / sin 30° = 6 cm of the edge).
  for (const auto& face : r.faces)
  {
    const auto n = strays (r.set, patches, face, 0.06f);
    EXPECT_EQ (n.second, 0u);
    EXPECT_LE (n.first, face.size () / 20);
  }
  for (const auto& p : patches)
  {
    EXPECT_TRUE (std::is_sorted (p.members.begin (), p.members.end ()));
    EXPECT_EQ (p.first_index, p.members.front ());
    EXPECT_NEAR (std::abs (p.normal.z ()), std::cos (15.0 * kDegree), 0.02); // estimated again
  }
  EXPECT_EQ (patches[0].members.size () + patches[1].members.size (), r.set.size ());
}

TEST (BentPlanes, FlatNoisyPlanesAreKeptWhole)
{
  // Flat squares of several sizes and noise levels: two planes only fit noise.
  for (const int n : {12, 30, 100})
    for (const float noise : {0.002f, 0.02f, 0.05f})
    {
      PointSet s;
      rspd_test::addRectangle (s, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, n, n, noise, 7);
      std::vector<PlanarPatch> patches = onePlane (s.size ());
      EXPECT_EQ (splitBentPlanes (s, rspd_test::unitParameters (), patches), 0u) << n << " " << noise;
      EXPECT_EQ (patches.size (), 1u);
    }
}

TEST (BentPlanes, BendWithinT1sSlopeIsKeptWhole)
{
  // 10 degrees: two planes explain the samples far better than one, but T1 would accept the bend
  // within one planar cell (90 - 75 = 15 degrees).
  const Roof r = makeRoof (10.0f * kDegree, 0.002f);
  std::vector<PlanarPatch> patches = onePlane (r.set.size ());
  EXPECT_EQ (splitBentPlanes (r.set, rspd_test::unitParameters (), patches), 0u);
  // 20 degrees is an edge.
  const Roof r20 = makeRoof (20.0f * kDegree, 0.002f);
  patches = onePlane (r20.set.size ());
  EXPECT_EQ (splitBentPlanes (r20.set, rspd_test::unitParameters (), patches), 1u);
}

TEST (BentPlanes, FaceSmallerThanEpsilonStaysWithThePlane)
{
  // 8 x 6 = 48 samples on the second face, ε = 50.
  PointSet s;
  rspd_test::addRectangle (s, {0, 0, 0}, {0, 0.6f, 0}, {-0.4f, 0, 0}, 60, 40, 0.002f, 1);
  const float a = 40.0f * kDegree;
  rspd_test::addRectangle (s, {0, 0, 0}, {0.08f * std::cos (a), 0, 0.08f * std::sin (a)}, {0, 0.6f, 0}, 8, 6, 0.002f, 2);
  std::vector<PlanarPatch> patches = onePlane (s.size ());
  EXPECT_EQ (splitBentPlanes (s, rspd_test::unitParameters (), patches), 0u);
  EXPECT_EQ (patches[0].members.size (), s.size ());
}

TEST (BentPlanes, ThreeFacesAreSplitIntoThree)
{
  // A folded strip: faces at 0, 30 and 60 degrees about parallel edges. The best single cut runs
  // through the middle face, and its sides, 1.5 faces each, fail T3: each is split again and the
  // middle face's halves are joined.
  PointSet s;
  std::vector<std::uint32_t> faces[3];
  Eigen::Vector3f o (0, 0, 0);
  for (int f = 0; f < 3; ++f)
  {
    const float a = 30.0f * f * kDegree;
    const Eigen::Vector3f step (0.4f * std::cos (a), 0.0f, 0.4f * std::sin (a));
    faces[f] = rspd_test::addRectangle (s, o, step, {0, 0.6f, 0}, 40, 60, 0.004f, 3 + f);
    o += step;
  }
  std::vector<PlanarPatch> patches = onePlane (s.size ());
  EXPECT_EQ (splitBentPlanes (s, rspd_test::unitParameters (), patches), 2u);
  ASSERT_EQ (patches.size (), 3u);
  for (const auto& face : faces)
    EXPECT_LE (strays (s, patches, face).first, face.size () / 20);
}

TEST (BentPlanes, ResultDoesNotDependOnTheThreadCount)
{
  const Roof a = makeRoof (25.0f * kDegree, 0.01f), b = makeRoof (35.0f * kDegree, 0.01f, 30, 50, 5);
  PointSet s = a.set;
  std::vector<PlanarPatch> p1 = onePlane (a.set.size ());
  // A second roof, far away, held by a second plane.
  std::vector<std::uint32_t> second;
  for (std::size_t i = 0; i < b.set.size (); ++i)
  {
    second.push_back (static_cast<std::uint32_t> (s.size ()));
    s.points.push_back (b.set.points[i] + Eigen::Vector3f (5, 0, 0));
    s.normals.push_back (b.set.normals[i]);
    s.input_indices.push_back (static_cast<pcl::index_t> (s.input_indices.size ()));
  }
  p1.push_back (rspd_test::makePatch (second, {5, 0, 0}, {0, 0, 1}, 0.05, 0.5));
  std::vector<PlanarPatch> p2 = p1;
  EXPECT_EQ (splitBentPlanes (s, rspd_test::unitParameters (1), p1), 2u);
  EXPECT_EQ (splitBentPlanes (s, rspd_test::unitParameters (2), p2), 2u);
  ASSERT_EQ (p1.size (), p2.size ());
  for (std::size_t l = 0; l < p1.size (); ++l)
    EXPECT_EQ (p1[l].members, p2[l].members);
}

TEST (BentPlanes, SetsThatDetermineNoTwoPlanesAreRefused)
{
  // Fewer than six samples, samples on one line, and coincident samples: no hinge, and the split
  // leaves such a plane (and an empty list) alone.
  PointSet s;
  for (int i = 0; i < 200; ++i)
  {
    s.points.emplace_back (0.01f * i, 0.0f, 0.0f); // a line
    s.normals.push_back (Eigen::Vector3f::UnitZ ());
    s.input_indices.push_back (i);
  }
  for (int i = 0; i < 100; ++i)
  {
    s.points.emplace_back (5.0f, 5.0f, 5.0f); // one point, repeated
    s.normals.push_back (Eigen::Vector3f::UnitZ ());
    s.input_indices.push_back (200 + i);
  }
  std::vector<std::uint32_t> line (200), same (100), few {0, 1, 2, 3, 4};
  for (std::uint32_t i = 0; i < 200; ++i)
    line[i] = i;
  for (std::uint32_t i = 0; i < 100; ++i)
    same[i] = 200 + i;
  HingeFit fit;
  EXPECT_FALSE (fitHinge (s, few, fit));
  EXPECT_FALSE (fitHinge (s, line, fit));
  EXPECT_FALSE (fitHinge (s, same, fit));
  std::vector<PlanarPatch> patches {rspd_test::makePatch (line, {0, 0, 0}, {0, 0, 1}, 0.05, 0.5),
                                    rspd_test::makePatch (same, {5, 5, 5}, {0, 0, 1}, 0.05, 0.5)};
  EXPECT_EQ (splitBentPlanes (s, rspd_test::unitParameters (), patches), 0u);
  EXPECT_EQ (patches[0].members, line);
  EXPECT_EQ (patches[1].members, same);
  std::vector<PlanarPatch> none;
  EXPECT_EQ (splitBentPlanes (s, rspd_test::unitParameters (), none), 0u);
}

namespace
{
/** Two planes over the halves of one 0.8 x 0.6 m square (x < 0 and x >= 0, 80 x 60 samples, noise
  * \a noise), the right half raised by \a step and turned by \a turn about the y axis, each plane
  * estimated on its own samples; a gap of \a gap between them. */
struct Halves
{
  PointSet set;
  std::vector<PlanarPatch> planes;
  NeighborGraph graph;
};

Halves
makeHalves (float noise, float step, float turn, float gap = 0.0f)
{
  Halves h;
  const std::vector<std::uint32_t> left =
      rspd_test::addRectangle (h.set, {-0.4f, 0, 0}, {0.4f, 0, 0}, {0, 0.6f, 0}, 40, 60, noise, 11);
  const Eigen::Vector3f across (0.4f * std::cos (turn), 0, 0.4f * std::sin (turn));
  const std::vector<std::uint32_t> right =
      rspd_test::addRectangle (h.set, {gap, 0, step}, across, {0, 0.6f, 0}, 40, 60, noise, 12);
  for (const auto* half : {&left, &right})
  {
    PlaneEstimate e;
    EXPECT_TRUE (estimatePlane (h.set, *half, rspd_test::unitParameters (), e));
    PlanarPatch p;
    p.members = *half;
    p.first_index = half->front ();
    p.setEstimate (e);
    h.planes.push_back (std::move (p));
  }
  h.graph = rspd_test::bruteForceGraph (h.set.points, 20);
  return h;
}
} // namespace

TEST (BentPlanes, FaceSharedByTwoSplitPlanesIsJoinedAgain)
{
  Halves h = makeHalves (0.01f, 0.0f, 0.0f);
  EXPECT_EQ (joinSplitFaces (h.set, h.graph, rspd_test::unitParameters (), h.planes, {1, 1}), 1u);
  ASSERT_EQ (h.planes.size (), 1u);
  EXPECT_EQ (h.planes[0].members.size (), h.set.size ());
  EXPECT_TRUE (std::is_sorted (h.planes[0].members.begin (), h.planes[0].members.end ()));
  EXPECT_EQ (h.planes[0].first_index, 0u);
  // One part of a split plane is enough; neither is not.
  Halves one = makeHalves (0.01f, 0.0f, 0.0f);
  EXPECT_EQ (joinSplitFaces (one.set, one.graph, rspd_test::unitParameters (), one.planes, {0, 1}), 1u);
  Halves none = makeHalves (0.01f, 0.0f, 0.0f);
  EXPECT_EQ (joinSplitFaces (none.set, none.graph, rspd_test::unitParameters (), none.planes, {0, 0}), 0u);
  EXPECT_EQ (joinSplitFaces (none.set, none.graph, rspd_test::unitParameters (), none.planes, {}), 0u); // a short list
  Halves short_list = makeHalves (0.01f, 0.0f, 0.0f);
  EXPECT_EQ (joinSplitFaces (short_list.set, short_list.graph, rspd_test::unitParameters (), short_list.planes, {1}), 1u);
  EXPECT_EQ (none.planes.size (), 2u);
  // Nor is a part of a split plane elsewhere.
  const std::vector<std::uint32_t> far =
      rspd_test::addRectangle (none.set, {5, 0, 0}, {0.3f, 0, 0}, {0, 0.3f, 0}, 10, 10, 0.01f, 13);
  none.planes.push_back (rspd_test::makePatch (far, {5.15, 0.15, 0}, {0, 0, 1}, 0.03, 0.3));
  none.graph = rspd_test::bruteForceGraph (none.set.points, 20);
  EXPECT_EQ (joinSplitFaces (none.set, none.graph, rspd_test::unitParameters (), none.planes, {0, 0, 1}), 0u);
  EXPECT_EQ (none.planes.size (), 3u);
}

TEST (BentPlanes, FacesAtAnEdgeAStepOrAGapStayApart)
{
  // A 30° edge (normals beyond T1's 15°), a step of 5 σ (a hinge fit explains it), and a gap of
  // 10 cm (no graph edge between the halves).
  Halves edge = makeHalves (0.005f, 0.0f, 30.0f * kDegree);
  EXPECT_EQ (joinSplitFaces (edge.set, edge.graph, rspd_test::unitParameters (), edge.planes, {1, 1}), 0u);
  // 25° under 8 cm of noise: a hinge fit no longer tells the faces apart, their normals do.
  Halves noisy = makeHalves (0.08f, 0.0f, 25.0f * kDegree);
  HingeFit fit;
  std::vector<std::uint32_t> all (noisy.set.size ());
  std::iota (all.begin (), all.end (), 0u);
  ASSERT_TRUE (fitHinge (noisy.set, all, fit));
  EXPECT_GT (fit.split_sigma, 0.8 * fit.single_sigma);
  EXPECT_EQ (joinSplitFaces (noisy.set, noisy.graph, rspd_test::unitParameters (), noisy.planes, {1, 1}), 0u);
  Halves step = makeHalves (0.005f, 0.025f, 0.0f);
  EXPECT_EQ (joinSplitFaces (step.set, step.graph, rspd_test::unitParameters (), step.planes, {1, 1}), 0u);
  Halves gap = makeHalves (0.005f, 0.0f, 0.0f, 0.1f);
  EXPECT_EQ (joinSplitFaces (gap.set, gap.graph, rspd_test::unitParameters (), gap.planes, {1, 1}), 0u);
  EXPECT_EQ (gap.planes.size (), 2u);
}

TEST (BentPlanes, NoisySeedsPlaneOverAnEdgeIsSplitIntoFlatSides)
{
  // A noisy seed's plane grown over a 40° roof is no flat plane; its two sides are.
  Roof roof = makeRoof (40.0f * kDegree, 0.005f);
  auto planes = onePlane (roof.set.size ());
  planes[0].retested = true;
  EXPECT_EQ (splitBentNoisyPlanes (roof.set, rspd_test::unitParameters (), planes), 1u);
  ASSERT_EQ (planes.size (), 2u);
  for (const auto& plane : planes)
  {
    EXPECT_TRUE (plane.retested);
    EXPECT_TRUE (std::is_sorted (plane.members.begin (), plane.members.end ()));
    std::size_t on_face0 = 0;
    for (const auto i : plane.members)
      on_face0 += std::binary_search (roof.faces[0].begin (), roof.faces[0].end (), i);
    const std::size_t most = std::max (on_face0, plane.members.size () - on_face0);
    EXPECT_GE (most, plane.members.size () * 95 / 100);
    EXPECT_GE (most, roof.faces[0].size () * 90 / 100);
  }
  // The planes the split seeded are left to the bent-plane split; a flat roof is no bend.
  auto seeded = onePlane (roof.set.size ());
  EXPECT_EQ (splitBentNoisyPlanes (roof.set, rspd_test::unitParameters (), seeded), 0u);
  EXPECT_EQ (seeded.size (), 1u);
  Roof flat = makeRoof (0.0f, 0.005f);
  auto flat_plane = onePlane (flat.set.size ());
  flat_plane[0].retested = true;
  EXPECT_EQ (splitBentNoisyPlanes (flat.set, rspd_test::unitParameters (), flat_plane), 0u);
}

TEST (BentPlanes, NoisySeedsPlaneOnACylinderIsNotSplit)
{
  // A 120° arc of a 0.3 m cylinder: two chords explain it better than one plane, but each still
  // bends, so the plane is left to the judgement that drops it.
  PointSet s;
  std::mt19937 rng (3);
  std::normal_distribution<float> noise (0.0f, 0.001f);
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j)
    {
      const float a = (-60.0f + 120.0f * (i + 0.5f) / 60.0f) * kDegree;
      const Eigen::Vector3f radial (std::sin (a), 0.0f, std::cos (a));
      s.points.push_back ((0.3f + noise (rng)) * radial + Eigen::Vector3f (0.0f, 0.6f * (j + 0.5f) / 60.0f, 0.0f));
      s.normals.push_back (radial);
      s.input_indices.push_back (static_cast<pcl::index_t> (s.input_indices.size ()));
    }
  HingeFit fit;
  ASSERT_TRUE (fitHinge (s, onePlane (s.size ())[0].members, fit));
  EXPECT_TRUE (isBend (fit, rspd_test::unitParameters ()));
  auto planes = onePlane (s.size ());
  planes[0].retested = true;
  EXPECT_FALSE (isFlatPatch (s, rspd_test::unitParameters (), planes[0], true));
  EXPECT_EQ (splitBentNoisyPlanes (s, rspd_test::unitParameters (), planes), 0u);
  EXPECT_EQ (planes.size (), 1u);
}

TEST (BentPlanes, SidesAsNoisyAsTheirPlaneArePlanesPastT2)
{
  // A 40° roof whose normals are as noisy as PCL's k = 50 ones on synpeb_pc01: the whole plane's MND
  // past T2's 60° (re-estimation tests nothing again), each side's past it too but below the
  // whole's. Held to T2 at 60°, neither side is a plane and the roof stays whole; held to the MND
  // of the plane they come from, it is split (DetectorParameters::bent_side_parent_mnd).
  Roof r = makeRoof (40.0f * kDegree, 0.005f);
  std::mt19937 rng (7);
  std::normal_distribution<float> jitter (0.0f, 0.35f);
  for (auto& n : r.set.normals)
    n = (n + Eigen::Vector3f (jitter (rng), jitter (rng), jitter (rng))).normalized ();
  DetectorParameters p = rspd_test::unitParameters ();
  PlaneEstimate whole, side;
  ASSERT_TRUE (estimatePlane (r.set, onePlane (r.set.size ())[0].members, p, whole));
  ASSERT_TRUE (estimatePlane (r.set, r.faces[0], p, side));
  std::printf ("    MND whole %.1f°, one side %.1f°\n", whole.mnd () / kDegree, side.mnd () / kDegree);
  EXPECT_GT (side.mnd (), p.max_normal_deviation);
  EXPECT_LT (side.mnd (), whole.mnd ());
  std::vector<PlanarPatch> bounded = onePlane (r.set.size ());
  EXPECT_EQ (splitBentPlanes (r.set, p, bounded), 1u);
  EXPECT_EQ (bounded.size (), 2u);
  p.bent_side_parent_mnd = false;
  std::vector<PlanarPatch> paper = onePlane (r.set.size ());
  EXPECT_EQ (splitBentPlanes (r.set, p, paper), 0u);
  EXPECT_EQ (paper.size (), 1u);
}

namespace
{
/** An arc of a cylinder of \a radius about the y axis, \a span wide, \a length long, Gaussian noise
  * \a noise along the radius, exact (radial) normals. */
PointSet
makeArc (float radius, float span, float length, float noise, int across, int along)
{
  PointSet s;
  std::mt19937 rng (5);
  std::normal_distribution<float> g (0.0f, noise);
  for (int i = 0; i < across; ++i)
    for (int j = 0; j < along; ++j)
    {
      const float a = span * ((i + 0.5f) / across - 0.5f);
      const Eigen::Vector3f radial (std::sin (a), 0.0f, std::cos (a));
      s.points.push_back ((radius + g (rng)) * radial + Eigen::Vector3f (0.0f, length * (j + 0.5f) / along, 0.0f));
      s.normals.push_back (radial);
      s.input_indices.push_back (static_cast<pcl::index_t> (s.input_indices.size ()));
    }
  return s;
}

std::vector<std::uint32_t>
allOf (const PointSet& s)
{
  std::vector<std::uint32_t> all (s.size ());
  std::iota (all.begin (), all.end (), 0u);
  return all;
}
} // namespace

TEST (BentPlanes, EdgeTheNormalsConfirmSplitsARoofTooNoisyForThePositions)
{
  // Two faces 40° apart whose noise is a large part of their width (as synpeb_pc01's boxes): two
  // planes lower the positions' σ by less than the bend test asks (0.8), and by more than half
  // its share of the variance (0.906); the normals turn by 40°, in one step.
  const Roof r = makeRoofSized (40.0f * kDegree, 0.03f, 0.2f, 1.0f, 30, 100);
  HingeFit fit;
  ASSERT_TRUE (fitHinge (r.set, allOf (r.set), fit));
  const double ratio = fit.split_sigma / fit.single_sigma;
  std::printf ("    sigma ratio %.3f, sides %.1f° apart\n", ratio, fit.angle / kDegree);
  DetectorParameters p = rspd_test::unitParameters ();
  ASSERT_GT (ratio, p.bent_sigma_ratio);
  ASSERT_LT (ratio, std::sqrt (0.5 * (1.0 + p.bent_sigma_ratio * p.bent_sigma_ratio)));
  EXPECT_FALSE (isBend (fit, p));
  EXPECT_TRUE (p.bent_normal_edges);
  EXPECT_TRUE (isEdgeTheNormalsConfirm (r.set, fit, p));
  std::vector<PlanarPatch> patches = onePlane (r.set.size ());
  EXPECT_EQ (splitBentPlanes (r.set, p, patches), 1u);
  ASSERT_EQ (patches.size (), 2u);
  for (const auto& face : r.faces)
  {
    const auto n = strays (r.set, patches, face, 0.15f);
    EXPECT_EQ (n.second, 0u);
    EXPECT_LE (n.first, face.size () / 10);
  }
  // The positions alone (the option off): one plane.
  p.bent_normal_edges = false;
  EXPECT_FALSE (isEdgeTheNormalsConfirm (r.set, fit, p));
  patches = onePlane (r.set.size ());
  EXPECT_EQ (splitBentPlanes (r.set, p, patches), 0u);
  EXPECT_EQ (patches.size (), 1u);
}

TEST (BentPlanes, NormalsThatTurnLessThanT1sSlopeConfirmNoEdge)
{
  // The same positions, the normals turned by 10° across the edge (under T1's 15°): no edge.
  Roof r = makeRoofSized (40.0f * kDegree, 0.03f, 0.2f, 1.0f, 30, 100);
  for (std::uint32_t i = 0; i < r.set.size (); ++i)
  {
    const float t = (r.set.points[i].x () > 0 ? 5.0f : -5.0f) * kDegree;
    r.set.normals[i] = Eigen::Vector3f (std::sin (t), 0.0f, std::cos (t)) * (i % 3 == 0 ? -1.0f : 1.0f);
  }
  HingeFit fit;
  ASSERT_TRUE (fitHinge (r.set, allOf (r.set), fit));
  EXPECT_FALSE (isEdgeTheNormalsConfirm (r.set, fit, rspd_test::unitParameters ()));
  std::vector<PlanarPatch> patches = onePlane (r.set.size ());
  EXPECT_EQ (splitBentPlanes (r.set, rspd_test::unitParameters (), patches), 0u);
  // Zero-length normals on one side: no direction to confirm anything, no edge.
  for (const auto i : r.faces[1])
    r.set.normals[i].setZero ();
  EXPECT_FALSE (isEdgeTheNormalsConfirm (r.set, fit, rspd_test::unitParameters ()));
}

TEST (BentPlanes, NormalsTurningSteadilyConfirmNoEdge)
{
  // A 90° arc of a 0.3 m cylinder at σ = 4 cm (as noisy as the room's pillar at σ = 3 cm seen
  // over fewer samples): two chords 45° apart explain its positions as they do a noisy roof's, and
  // its normals turn as much, but steadily: a curved surface, no edge.
  const PointSet arc = makeArc (0.3f, 90.0f * kDegree, 1.0f, 0.04f, 40, 80);
  HingeFit fit;
  ASSERT_TRUE (fitHinge (arc, allOf (arc), fit));
  const double ratio = fit.split_sigma / fit.single_sigma;
  std::printf ("    sigma ratio %.3f, sides %.1f° apart\n", ratio, fit.angle / kDegree);
  const DetectorParameters p = rspd_test::unitParameters ();
  ASSERT_GT (fit.angle, 0.5 * M_PI - p.min_distance_angle);
  ASSERT_GT (ratio, p.bent_sigma_ratio);
  ASSERT_LT (ratio, std::sqrt (0.5 * (1.0 + p.bent_sigma_ratio * p.bent_sigma_ratio)));
  EXPECT_FALSE (isEdgeTheNormalsConfirm (arc, fit, p));
  std::vector<PlanarPatch> patches = onePlane (arc.size ());
  EXPECT_EQ (splitBentPlanes (arc, p, patches), 0u);
}
