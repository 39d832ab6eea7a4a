/*
 * Tests of the band-layer test of the small-plane pass (isBandLayer) and of a released group lying
 * on a neighbouring plane (liesOnNeighbourPlane), and of the merge of grown planes that are layers of
 * one plane's band (mergeBandLayers).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/band_layers.h>
#include <pcl_rspd/patch_growth.h>
#include <pcl_rspd/plane_refit.h>
#include <pcl_rspd/robust_statistics.h>

#include <gtest/gtest.h>

#include <functional>
#include <random>

#include <algorithm>
#include <cmath>

using namespace pcl::rspd;

namespace
{
/** A wall: the plane z = 0, 1 x 1 m, 40 x 40 samples, noise 3 mm, and one plane holding it whose
  * noise band is \a band. A face of 20 x 20 samples on 0.3 x 0.3 m, noise \a face_noise, tilted by
  * \a tilt about the y axis (rising along x), either over the wall's middle and raised by \a lift,
  * or beside it (\a beside: from the wall's edge x = 1 on, meeting it there). As where a plane grew
  * into a face, the plane also holds every other sample of the face (a checkerboard); the seed is
  * the rest. */
struct Scene
{
  PointSet set;
  std::vector<PlanarPatch> planes;
  std::vector<double> band;
  std::vector<std::uint32_t> labels;
  PlanarPatch seed;
  NeighborGraph graph;
};

Scene
makeScene (double tilt, double lift, float face_noise, double band, bool beside)
{
  Scene s;
  std::vector<std::uint32_t> held = rspd_test::addRectangle (s.set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 40, 40, 0.003f, 1);
  const float c = static_cast<float> (std::cos (tilt)), sn = static_cast<float> (std::sin (tilt));
  const Eigen::Vector3f origin = beside ? Eigen::Vector3f (1.0f, 0.35f, 0.0f)
                                        : Eigen::Vector3f (0.35f, 0.35f, static_cast<float> (lift));
  const Eigen::Vector3f along (0, 0.3f, 0), across (0.3f * c, 0, 0.3f * sn);
  const int n = 20;
  const std::vector<std::uint32_t> face = rspd_test::addRectangle (s.set, origin, along, across, n, n, face_noise, 2);
  std::vector<std::uint32_t> seed_members;
  for (std::size_t k = 0; k < face.size (); ++k)
    ((k / n + k % n) % 2 == 0 ? held : seed_members).push_back (face[k]);
  std::sort (held.begin (), held.end ());
  s.planes = {rspd_test::makePatch (held, {0.5, 0.5, 0}, {0, 0, 1}, 0.01, 0.1)};
  s.band = {band};
  s.labels.assign (s.set.points.size (), kNoPatch);
  for (const auto i : held)
    s.labels[i] = 0;
  const Eigen::Vector3f middle = origin + 0.5f * along + 0.5f * across;
  s.seed = rspd_test::makePatch (seed_members, middle.cast<double> (), along.cross (across).normalized ().cast<double> (),
                                 0.01, 0.1);
  s.graph = rspd_test::bruteForceGraph (s.set.points, 20);
  return s;
}

constexpr double kDegree = M_PI / 180.0;

DetectorParameters
parameters ()
{
  DetectorParameters p;
  p.min_patch_size = 50;
  return p;
}
} // namespace

TEST (BandLayer, ParallelLayerWithinAPlanesBandIsALayer)
{
  // The samples between a door 2 cm proud of its wall and the wall: parallel, inside its 3 cm band.
  const Scene s = makeScene (0.0, 0.01, 0.003f, 0.03, false);
  EXPECT_TRUE (isBandLayer (s.set, s.graph, parameters (), s.planes, s.band, s.labels, s.seed));
}

TEST (BandLayer, ParallelLayerBeyondThePlanesBandIsNoLayer)
{
  const Scene s = makeScene (0.0, 0.05, 0.003f, 0.03, false);
  EXPECT_FALSE (isBandLayer (s.set, s.graph, parameters (), s.planes, s.band, s.labels, s.seed));
}

TEST (BandLayer, FaceBesideAPlaneBentOntoItIsNoLayer)
{
  // The plane grew across the edge onto a face 30° away and holds half of it: two planes meeting at
  // an edge explain its members, and its band (20 cm, widened by that face) covers the rest. The
  // seed's own plane explains its samples far better than the wall's, at more than 15°: a face.
  const Scene s = makeScene (30.0 * kDegree, 0.0, 0.003f, 0.2, true);
  bool beside = false;
  EXPECT_FALSE (isBandLayer (s.set, s.graph, parameters (), s.planes, s.band, s.labels, s.seed, &beside));
  EXPECT_TRUE (beside);
  // Without the samples of the face, the same plane is flat: the seed, out of its band's reach
  // but along the edge, is no layer either, and not by that rule.
  Scene t = makeScene (30.0 * kDegree, 0.0, 0.003f, 0.2, true);
  t.planes[0].members.erase (std::remove_if (t.planes[0].members.begin (), t.planes[0].members.end (),
                                             [] (std::uint32_t i) { return i >= 1600; }),
                             t.planes[0].members.end ());
  for (std::size_t i = 1600; i < t.labels.size (); ++i)
    t.labels[i] = kNoPatch;
  EXPECT_FALSE (isBandLayer (t.set, t.graph, parameters (), t.planes, t.band, t.labels, t.seed, &beside));
  EXPECT_FALSE (beside);
}

TEST (BandLayer, ParallelLayerInABentPlanesBandIsStillALayer)
{
  // The bent plane of FaceBesideAPlaneBentOntoItIsNoLayer, and over its wall a layer 1 cm above it
  // (a door's rim), half of it held by the plane: the layer's own plane explains it better than the
  // wall's, but it is parallel, so the wall's band holds it.
  Scene s = makeScene (30.0 * kDegree, 0.0, 0.003f, 0.2, true);
  const std::vector<std::uint32_t> layer =
      rspd_test::addRectangle (s.set, {0.35f, 0.35f, 0.01f}, {0.3f, 0, 0}, {0, 0.3f, 0}, 20, 20, 0.002f, 3);
  s.labels.resize (s.set.points.size (), kNoPatch);
  s.seed.members.clear ();
  for (std::size_t k = 0; k < layer.size (); ++k)
    if ((k / 20 + k % 20) % 2 == 0)
    {
      s.planes[0].members.push_back (layer[k]);
      s.labels[layer[k]] = 0;
    }
    else
      s.seed.members.push_back (layer[k]);
  s.seed.center = Eigen::Vector3d (0.5, 0.5, 0.01);
  s.seed.normal = Eigen::Vector3d::UnitZ ();
  s.graph = rspd_test::bruteForceGraph (s.set.points, 20);
  bool beside = true;
  EXPECT_TRUE (isBandLayer (s.set, s.graph, parameters (), s.planes, s.band, s.labels, s.seed, &beside));
  EXPECT_FALSE (beside);
}

TEST (BandLayer, TiltedSeedOverAFlatPlaneIsALayer)
{
  // The same face over the wall, the plane holding half of it: no edge explains the plane (a
  // curved surface's next facet looks like this), so its band claims the seed.
  const Scene s = makeScene (30.0 * kDegree, 0.0, 0.003f, 0.2, false);
  bool beside = true;
  EXPECT_TRUE (isBandLayer (s.set, s.graph, parameters (), s.planes, s.band, s.labels, s.seed, &beside));
  EXPECT_FALSE (beside);
}

TEST (BandLayer, GentleTiltBesideTheEdgeIsStillALayer)
{
  // 10°: below 90° minus T1's 75°, which T1 itself accepts as one plane.
  const Scene s = makeScene (10.0 * kDegree, 0.0, 0.003f, 0.2, true);
  EXPECT_TRUE (isBandLayer (s.set, s.graph, parameters (), s.planes, s.band, s.labels, s.seed));
}

TEST (BandLayer, NoisySeedThatItsOwnPlaneDoesNotExplainBetterIsALayer)
{
  // Beside the edge at 30°, but with noise (15 cm) that dwarfs the tilt's spread over the seed: its
  // own plane does not lower the σ to 0.8 of the wall's, so the wall's band (50 cm) still claims it.
  const Scene s = makeScene (30.0 * kDegree, 0.0, 0.15f, 0.5, true);
  EXPECT_TRUE (isBandLayer (s.set, s.graph, parameters (), s.planes, s.band, s.labels, s.seed));
}

TEST (BandLayer, EmptySeedIsNoLayer)
{
  Scene s = makeScene (0.0, 0.01, 0.003f, 0.03, false);
  s.seed.members.clear ();
  EXPECT_FALSE (isBandLayer (s.set, s.graph, parameters (), s.planes, s.band, s.labels, s.seed));
}

namespace
{
/** A tread: the plane z = 0 on 1 x 0.9 m (40 x 36 samples, noise 2 mm), held by one plane, and a
  * strip along its nose, x from 1 on, 4 x 36 samples on 0.1 x 0.9 m, lowered by \a drop, none held:
  * the candidate, its center on the strip and its normal tilted by \a tilt about the y axis. */
struct Strip
{
  PointSet set;
  std::vector<PlanarPatch> planes;
  std::vector<std::uint32_t> labels;
  PlanarPatch candidate;
  NeighborGraph graph;
};

Strip
makeStrip (double tilt, float drop)
{
  Strip s;
  const std::vector<std::uint32_t> tread =
      rspd_test::addRectangle (s.set, {0, 0, 0}, {0.975f, 0, 0}, {0, 0.9f, 0}, 40, 36, 0.002f, 1);
  const std::vector<std::uint32_t> strip =
      rspd_test::addRectangle (s.set, {1.0f, 0, -drop}, {0.075f, 0, 0}, {0, 0.9f, 0}, 4, 36, 0.002f, 2);
  s.planes = {rspd_test::makePatch (tread, {0.5, 0.45, 0}, {0, 0, 1}, 0.01, 0.05)};
  s.labels.assign (s.set.points.size (), kNoPatch);
  for (const auto i : tread)
    s.labels[i] = 0;
  s.candidate = rspd_test::makePatch (strip, {1.04, 0.45, -drop}, {std::sin (tilt), 0, std::cos (tilt)}, 0.01, 0.3);
  s.graph = rspd_test::bruteForceGraph (s.set.points, 20);
  return s;
}
} // namespace

TEST (NeighbourPlane, StripAlongANoseWithABentNormalLiesOnTheTread)
{
  // The staircase's top tread on PCL's k = 50 normals: released along the nose, the strip's median
  // normal tilted 22°; the tread's plane fits its positions better than its own.
  const Strip s = makeStrip (22.0 * kDegree, 0.0f);
  EXPECT_TRUE (liesOnNeighbourPlane (s.set, s.graph, s.planes, s.labels, s.candidate));
  // Its own plane right: as close to the tread's, which counts for the tread.
  const Strip flat = makeStrip (0.0, 0.0f);
  EXPECT_TRUE (liesOnNeighbourPlane (flat.set, flat.graph, flat.planes, flat.labels, flat.candidate));
}

TEST (NeighbourPlane, APieceOfThePlaneBesideFittedToItselfLiesOnItWithinTheError)
{
  // The strip on the tread's plane, its own plane fitted to its members by least squares: that fit
  // is closer to them than the tread's (fitted to them, it takes some of their noise), by less
  // than twice the standard error of their robust σ. A room scanned on a grid left such a piece
  // (the ceiling around the zenith) to the position planes, which kept it as a plane of its own.
  Strip s = makeStrip (0.0, 0.0f);
  ASSERT_TRUE (leastSquaresPlane (s.set, s.candidate.members, {}, Eigen::Vector3d::Zero (), s.candidate.center,
                                  s.candidate.normal));
  const auto sigmaAbout = [&] (const Eigen::Vector3d& c, const Eigen::Vector3d& n) {
    std::vector<double> d;
    for (const auto i : s.candidate.members)
      d.push_back (std::abs ((s.set.points[i].cast<double> () - c).dot (n)));
    return kMadScale * medianInPlace (d);
  };
  const double own = sigmaAbout (s.candidate.center, s.candidate.normal);
  const double tread = sigmaAbout (s.planes[0].center, s.planes[0].normal);
  ASSERT_LT (own, tread); // without the error, its own plane would win
  EXPECT_TRUE (liesOnNeighbourPlane (s.set, s.graph, s.planes, s.labels, s.candidate));
  // Lowered by 2.5 σ, it lies off the tread, however its plane was fitted.
  Strip low = makeStrip (0.0, 0.005f);
  ASSERT_TRUE (leastSquaresPlane (low.set, low.candidate.members, {}, Eigen::Vector3d::Zero (), low.candidate.center,
                                  low.candidate.normal));
  EXPECT_FALSE (liesOnNeighbourPlane (low.set, low.graph, low.planes, low.labels, low.candidate));
}

TEST (NeighbourPlane, RecessedStripLiesOnItsOwnPlane)
{
  // A window 5 cm behind its wall: the wall's plane is 25 times farther than its own noise.
  const Strip s = makeStrip (0.0, 0.05f);
  EXPECT_FALSE (liesOnNeighbourPlane (s.set, s.graph, s.planes, s.labels, s.candidate));
}

namespace
{
/** The tread of makeStrip without its strip, and a dense patch over its middle, 10 x 10 samples on
  * 1 x 1 cm (noise 2 mm, raised by \a lift), none held: the candidate, its plane parallel to the
  * tread's. The patch's 20 nearest of each member are members, as a scanner's rings below its head
  * are each other's: no member has a neighbour the tread holds, but the tread's samples around it
  * count members among theirs. */
Strip
makeClosedPatch (float lift)
{
  Strip s;
  const std::vector<std::uint32_t> tread =
      rspd_test::addRectangle (s.set, {0, 0, 0}, {0.975f, 0, 0}, {0, 0.9f, 0}, 40, 36, 0.002f, 1);
  // Centred between four of the tread's samples (spacing 2.4-2.5 cm).
  const std::vector<std::uint32_t> patch =
      rspd_test::addRectangle (s.set, {0.4825f, 0.445f, lift}, {0.01f, 0, 0}, {0, 0.01f, 0}, 10, 10, 0.002f, 3);
  s.planes = {rspd_test::makePatch (tread, {0.5, 0.45, 0}, {0, 0, 1}, 0.01, 0.05)};
  s.labels.assign (s.set.points.size (), kNoPatch);
  for (const auto i : tread)
    s.labels[i] = 0;
  s.candidate = rspd_test::makePatch (patch, {0.4875, 0.45, lift}, {0, 0, 1}, 0.01, 0.3);
  s.graph = rspd_test::bruteForceGraph (s.set.points, 20);
  return s;
}

/** Whether some member of \a s's candidate has a neighbour a plane holds. */
bool
anyEdgeOut (const Strip& s)
{
  bool out = false;
  for (const auto i : s.candidate.members)
    s.graph.forEachNeighbor (i, [&] (std::uint32_t j) { out = out || s.labels[j] != kNoPatch; });
  return out;
}
} // namespace

TEST (NeighbourPlane, AClosedPatchIsSeenFromTheSamplesAroundIt)
{
  // On the tread: found through the edges into it.
  const Strip on = makeClosedPatch (0.0f);
  ASSERT_FALSE (anyEdgeOut (on)); // the case: closed under the graph
  EXPECT_TRUE (liesOnNeighbourPlane (on.set, on.graph, on.planes, on.labels, on.candidate));
  // 2 cm over it (10 σ): the same edges, but off the tread's plane.
  const Strip off = makeClosedPatch (0.02f);
  ASSERT_FALSE (anyEdgeOut (off));
  EXPECT_FALSE (liesOnNeighbourPlane (off.set, off.graph, off.planes, off.labels, off.candidate));
  // No plane held around it: nothing to lie on.
  Strip alone = makeClosedPatch (0.0f);
  alone.labels.assign (alone.labels.size (), kNoPatch);
  EXPECT_FALSE (liesOnNeighbourPlane (alone.set, alone.graph, alone.planes, alone.labels, alone.candidate));
}

TEST (NeighbourPlane, NoPlaneBesideOrNoMembers)
{
  Strip s = makeStrip (22.0 * kDegree, 0.0f);
  std::vector<std::uint32_t> none (s.labels.size (), kNoPatch);
  EXPECT_FALSE (liesOnNeighbourPlane (s.set, s.graph, s.planes, none, s.candidate));
  s.candidate.members.clear ();
  EXPECT_FALSE (liesOnNeighbourPlane (s.set, s.graph, s.planes, s.labels, s.candidate));
}

namespace
{
/** Two planes over a 1 x 1 m face (z = 0, 40 x 40 samples, noise 5 mm) for the layer merge: one holds
  * the samples above z = 0, the other those below, each estimated on its own members (Eqs. 3-9), as
  * two seeds of one noisy face grow into two layers of its band.
  * Optionally a third plane C, 20 x 20 samples on 0.4 x 0.4 m at height \a c_lift over the face's
  * middle, tilted by \a c_tilt about the y axis (C never joins a plane of the face). */
struct LayerScene
{
  PointSet set;
  std::vector<PlanarPatch> planes;
  NeighborGraph graph;
};

PlanarPatch
estimatedPatch (const PointSet& set, std::vector<std::uint32_t> members)
{
  std::sort (members.begin (), members.end ());
  PlaneEstimate e;
  EXPECT_TRUE (estimatePlane (set, members, parameters (), e));
  PlanarPatch p;
  p.members = std::move (members);
  p.first_index = p.members.front ();
  p.setEstimate (e);
  return p;
}

LayerScene
makeLayers (bool with_c = false, double c_lift = 0.0, double c_tilt = 0.0)
{
  LayerScene s;
  const std::vector<std::uint32_t> face = rspd_test::addRectangle (s.set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 40, 40, 0.005f, 7);
  std::vector<std::uint32_t> a, b;
  for (const auto i : face)
    (s.set.points[i].z () > 0.0f ? a : b).push_back (i);
  s.planes = {estimatedPatch (s.set, b), estimatedPatch (s.set, a)};
  if (with_c)
  {
    const float c = static_cast<float> (std::cos (c_tilt)), sn = static_cast<float> (std::sin (c_tilt));
    const std::vector<std::uint32_t> third = rspd_test::addRectangle (
        s.set, {0.3f, 0.3f, static_cast<float> (c_lift)}, {0.4f * c, 0, 0.4f * sn}, {0, 0.4f, 0}, 20, 20, 0.002f, 8);
    s.planes.push_back (estimatedPatch (s.set, third));
  }
  s.graph = rspd_test::bruteForceGraph (s.set.points, 20);
  return s;
}

std::vector<std::uint32_t>
labelsOf (const LayerScene& s)
{
  std::vector<std::uint32_t> labels (s.set.points.size (), kNoPatch);
  for (std::uint32_t p = 0; p < s.planes.size (); ++p)
    for (const auto i : s.planes[p].members)
      labels[i] = p;
  return labels;
}

/** Each plane's noise band as the detector measures it: max(MDP, 3 robust σ of its members). */
std::vector<double>
bandsOf (const LayerScene& s)
{
  std::vector<double> band;
  for (const auto& p : s.planes)
  {
    std::vector<double> d;
    for (const auto i : p.members)
      d.push_back (std::abs ((s.set.points[i].cast<double> () - p.center).dot (p.normal)));
    std::nth_element (d.begin (), d.begin () + d.size () / 2, d.end ());
    band.push_back (std::max (p.mdp, 3.0 * 1.4826 * d[d.size () / 2]));
  }
  return band;
}

/** The two planes \a scene builds stay apart under the layer merge's defaults, and merge into one
  * with \a off (the rule that keeps them apart) applied to the parameters. */
void
expectApartUnless (const std::function<LayerScene ()>& scene, const std::function<void (DetectorParameters&)>& off)
{
  LayerScene s = scene ();
  EXPECT_EQ (mergeBandLayers (s.set, s.graph, parameters (), bandsOf (s), s.planes, labelsOf (s)), 0u);
  EXPECT_EQ (s.planes.size (), 2u);
  LayerScene without = scene ();
  DetectorParameters p = parameters ();
  off (p);
  EXPECT_EQ (mergeBandLayers (without.set, without.graph, p, bandsOf (without), without.planes, labelsOf (without)), 1u);
  EXPECT_EQ (without.planes.size (), 1u);
}
} // namespace

TEST (BandLayerMerge, TwoLayersOfOneNoisyFaceBecomeOnePlane)
{
  LayerScene s = makeLayers ();
  // Each layer sits on its own side of the face, a noise σ or so from the other.
  const double apart = std::abs ((s.planes[1].center - s.planes[0].center).dot (s.planes[0].normal));
  EXPECT_GT (apart, 0.004);
  EXPECT_EQ (mergeBandLayers (s.set, s.graph, parameters (), bandsOf (s), s.planes, labelsOf (s)), 1u);
  ASSERT_EQ (s.planes.size (), 1u);
  EXPECT_EQ (s.planes[0].members.size (), 1600u);
  // Estimated again on both layers: back on the face.
  EXPECT_LT (std::abs (s.planes[0].center.z ()), 0.0015);
  EXPECT_GT (std::abs (s.planes[0].normal.z ()), std::cos (1.0 * kDegree));
  // Nothing more to merge.
  EXPECT_EQ (mergeBandLayers (s.set, s.graph, parameters (), bandsOf (s), s.planes, labelsOf (s)), 0u);
}

TEST (BandLayerMerge, ALayerOfClutterInsideTheFacesBandIsNotJoinedToIt)
{
  // 100 samples scattered over the face between 5 and 20 mm above it: among its samples, within its
  // band (the median 12 mm), but a layer whose own band holds more than ten times its samples of
  // the face. Joined, it would widen the face's band into the clutter
  // (DetectorParameters::in_band_layer_check); without the rule it is joined.
  const auto scene = [] {
    LayerScene s;
    const std::vector<std::uint32_t> face = rspd_test::addRectangle (s.set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 40, 40, 0.005f, 7);
    std::mt19937 rng (3);
    std::uniform_real_distribution<float> u (0.0f, 1.0f);
    std::vector<std::uint32_t> layer;
    for (int i = 0; i < 100; ++i)
    {
      layer.push_back (static_cast<std::uint32_t> (s.set.points.size ()));
      s.set.points.emplace_back (u (rng), u (rng), 0.005f + 0.015f * u (rng));
      s.set.normals.push_back (Eigen::Vector3f::UnitZ ());
      s.set.input_indices.push_back (static_cast<pcl::index_t> (s.set.input_indices.size ()));
    }
    s.planes = {estimatedPatch (s.set, face), estimatedPatch (s.set, layer)};
    s.graph = rspd_test::bruteForceGraph (s.set.points, 50); // footprint cells that cover the face
    return s;
  };
  expectApartUnless (scene, [] (DetectorParameters& p) { p.in_band_layer_check = false; });
}

TEST (BandLayerMerge, PlaneOffTheBandOrTiltedOutOfItStays)
{
  // A plate 4 cm over the face's middle: among its samples, but far beyond its band.
  {
    LayerScene s = makeLayers (true, 0.04, 0.0);
    const std::vector<double> band = bandsOf (s);
    s.planes.erase (s.planes.begin () + 1); // the face as one plane, and the plate
    std::vector<double> two = {band[0], band[2]};
    EXPECT_EQ (mergeBandLayers (s.set, s.graph, parameters (), two, s.planes, labelsOf (s)), 0u);
    EXPECT_EQ (s.planes.size (), 2u);
  }
  // A face crossing the plane at 4° through its middle, normals noisy enough for M2 (MND 10°):
  // most of its samples lie within the band (the median does), its rims 2 cm off, beyond it.
  {
    LayerScene s = makeLayers (true, -0.2 * std::sin (4.0 * kDegree), 4.0 * kDegree);
    s.planes.erase (s.planes.begin () + 1);
    for (auto& p : s.planes)
    {
      p.mnd = 10.0 * kDegree;
      p.cos_mnd = std::cos (p.mnd);
    }
    const std::vector<double> band = bandsOf (s);
    std::vector<double> d;
    for (const auto i : s.planes[1].members)
      d.push_back (std::abs ((s.set.points[i].cast<double> () - s.planes[0].center).dot (s.planes[0].normal)));
    std::nth_element (d.begin (), d.begin () + d.size () / 2, d.end ());
    ASSERT_LT (d[d.size () / 2], band[0]); // the median test alone would merge it
    EXPECT_EQ (mergeBandLayers (s.set, s.graph, parameters (), band, s.planes, labelsOf (s)), 0u);
    EXPECT_EQ (s.planes.size (), 2u);
  }
}

TEST (BandLayerMerge, PlaneBesideALargerOneStays)
{
  // Two coplanar halves of a face, each estimated on its own: they touch along one line only, so
  // fewer than half of either's members border the other (M1-M4's business, not a layer's).
  LayerScene s;
  const std::vector<std::uint32_t> face = rspd_test::addRectangle (s.set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 40, 40, 0.005f, 7);
  std::vector<std::uint32_t> left, right;
  for (const auto i : face)
    (s.set.points[i].x () < 0.45f ? left : right).push_back (i);
  s.planes = {estimatedPatch (s.set, right), estimatedPatch (s.set, left)};
  s.graph = rspd_test::bruteForceGraph (s.set.points, 20);
  EXPECT_EQ (mergeBandLayers (s.set, s.graph, parameters (), bandsOf (s), s.planes, labelsOf (s)), 0u);
  EXPECT_EQ (s.planes.size (), 2u);
}

TEST (BandLayerMerge, AWindowRecessedWithinItsWallsBandIsAStepNotALayer)
{
  // A 1 x 1 m wall (z = 0, noise 5 mm) with a 0.4 x 0.4 m window 1 cm deep (2 σ) in its middle, on
  // one 40 x 40 grid. The wall's plane holds the window samples nearer than 5 mm, as a wall's band
  // takes the near half of a window's; the window's plane holds the rest. Every window member has a
  // wall neighbour and lies within the wall's band, but the window's samples average 1 cm off the
  // two planes' joint plane: a step, kept apart (DetectorParameters::layer_steps); without the rule
  // the layer merge joins it to the wall.
  const auto scene = [] {
    LayerScene s;
    std::mt19937 rng (11);
    std::normal_distribution<float> g (0.0f, 0.005f);
    std::vector<std::uint32_t> wall, window;
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 40; ++j)
      {
        const float x = (i + 0.5f) / 40.0f, y = (j + 0.5f) / 40.0f;
        const bool inside = x > 0.3f && x < 0.7f && y > 0.3f && y < 0.7f;
        const float z = (inside ? 0.01f : 0.0f) + g (rng);
        const auto index = static_cast<std::uint32_t> (s.set.points.size ());
        s.set.points.emplace_back (x, y, z);
        s.set.normals.push_back (Eigen::Vector3f::UnitZ ());
        s.set.input_indices.push_back (static_cast<pcl::index_t> (index));
        (inside && z >= 0.005f ? window : wall).push_back (index);
      }
    s.planes = {estimatedPatch (s.set, wall), estimatedPatch (s.set, window)};
    s.graph = rspd_test::bruteForceGraph (s.set.points, 20);
    return s;
  };
  expectApartUnless (scene, [] (DetectorParameters& p) { p.layer_steps = false; });
}
