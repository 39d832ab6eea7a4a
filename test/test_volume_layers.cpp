/*
 * Tests of the volume-layer check (samplesBesideBand, dropVolumeLayers), of the in-band layers
 * (countLayerSamples, isInBandLayer), of the flat layers (LayerCounts::flat_beside) and of the
 * surrounding clutter's count (clutterBesidePlane).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/patch_growth.h> // labelSamples
#include <pcl_rspd/volume_layers.h>

#include <gtest/gtest.h>

#include <random>

using namespace pcl::rspd;

namespace
{
/** 6,000 samples scattered evenly through the box 2 x 2 x 1 times \a scale (a volume of clutter;
  * normals along z) from \a seed, appended to \a set. \return those for which \a take (the
  * unscaled sample, its draw) holds. */
template <typename Take> std::vector<std::uint32_t>
scatterInBox (PointSet& set, unsigned seed, float scale, Take&& take)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  std::vector<std::uint32_t> taken;
  for (int i = 0; i < 6000; ++i)
  {
    const Eigen::Vector3f p (2.0f * u (rng), 2.0f * u (rng), u (rng));
    if (take (p, i))
      taken.push_back (static_cast<std::uint32_t> (set.points.size ()));
    set.points.push_back (scale * p);
    set.normals.push_back (Eigen::Vector3f::UnitZ ());
    set.input_indices.push_back (static_cast<pcl::index_t> (set.input_indices.size ()));
  }
  return taken;
}

/** Samples scattered evenly through a box 2 x 2 x 1 (a volume of clutter), and the plane a noisy
  * seed would make where the volume ends below: every sixth sample of the bottom 0.2 (the ones whose
  * cut neighbourhoods give normals across the end), its plane z = 0.1 and band 0.1. The layer beside
  * the band above, z in (0.2, 0.3], holds half a band's samples, three times as many as the plane. */
struct VolumeEnd
{
  PointSet set;
  std::vector<PlanarPatch> planes;
  std::vector<double> band {0.1};
  NeighborGraph graph;

  explicit VolumeEnd (float scale = 1.0f)
  {
    const std::vector<std::uint32_t> end = scatterInBox (set, 11, scale, [] (const Eigen::Vector3f& p, int i) {
      return p.z () < 0.2f && i % 6 == 0;
    });
    planes = {rspd_test::makePatch (end, scale * Eigen::Vector3d (1.0, 1.0, 0.1), {0, 0, 1}, scale * 0.1, 0.3)};
    planes[0].retested = true;
    band[0] *= scale;
    // k = 50, as the automatic k gives at this size: the footprint's cells (the neighbourhood
    // radius, 0.2) then hold a few members each, as the facade's slabs' did (8 on average).
    graph = rspd_test::bruteForceGraph (set.points, 50);
  }
};

/** A noisy face (z = 0.5 over 2 x 2, 40 x 40 samples, σ 1 cm) among 300 samples of clutter in the
  * box around it, held by a plane a noisy seed seeded, band 3 σ. */
struct NoisyFace
{
  PointSet set;
  std::vector<PlanarPatch> planes;
  std::vector<double> band {0.03};
  NeighborGraph graph;

  NoisyFace ()
  {
    const std::vector<std::uint32_t> face = rspd_test::addRectangle (set, {0, 0, 0.5f}, {2, 0, 0}, {0, 2, 0}, 40, 40, 0.01f, 3);
    std::mt19937 rng (5);
    std::uniform_real_distribution<float> u (0.0f, 1.0f);
    for (int i = 0; i < 300; ++i)
    {
      set.points.emplace_back (2.0f * u (rng), 2.0f * u (rng), u (rng));
      set.normals.push_back (Eigen::Vector3f::UnitX ());
      set.input_indices.push_back (static_cast<pcl::index_t> (set.input_indices.size ()));
    }
    planes = {rspd_test::makePatch (face, {1.0, 1.0, 0.5}, {0, 0, 1}, 0.03, 0.3)};
    planes[0].retested = true;
    graph = rspd_test::bruteForceGraph (set.points, 15);
  }
};

/** Two parallel faces \a apart (40 x 40 samples each over 2 x 2, σ 1 cm), each held by a plane
  * whose band is 3 cm. */
struct TwoFaces
{
  PointSet set;
  std::vector<PlanarPatch> planes;
  NeighborGraph graph;

  explicit TwoFaces (float apart)
  {
    const auto a = rspd_test::addRectangle (set, {0, 0, 0}, {2, 0, 0}, {0, 2, 0}, 40, 40, 0.01f, 3);
    const auto b = rspd_test::addRectangle (set, {0, 0, apart}, {2, 0, 0}, {0, 2, 0}, 40, 40, 0.01f, 4);
    graph = rspd_test::bruteForceGraph (set.points, 15);
    planes = {rspd_test::makePatch (a, {1.0, 1.0, 0.0}, {0, 0, 1}, 0.03, 0.3),
              rspd_test::makePatch (b, {1.0, 1.0, apart}, {0, 0, 1}, 0.03, 0.3)};
  }
};
} // namespace

TEST (VolumeLayers, TheEndOfAVolumeIsDenserBesideItsBandThanWithin)
{
  VolumeEnd v;
  const std::size_t beside = samplesBesideBand (v.set, v.graph, v.planes[0], v.band[0]);
  // About 600 samples in (0.2, 0.3] (those over the footprint's cells) against about 200 members.
  EXPECT_GT (beside, 2 * v.planes[0].members.size ());
  EXPECT_LT (beside, 4 * v.planes[0].members.size ());
  EXPECT_EQ (dropVolumeLayers (v.set, v.graph, v.band, 1, v.planes), 1u);
  EXPECT_TRUE (v.planes.empty ());
}

TEST (VolumeLayers, NoisyFaceAmongClutterIsKept)
{
  NoisyFace f;
  // Beside a 3 cm band, a 3 cm layer of the clutter over the face: a handful of samples.
  EXPECT_LT (samplesBesideBand (f.set, f.graph, f.planes[0], f.band[0]), f.planes[0].members.size () / 20);
  EXPECT_EQ (dropVolumeLayers (f.set, f.graph, f.band, 1, f.planes), 0u);
  EXPECT_EQ (f.planes.size (), 1u);
}

TEST (VolumeLayers, OnlyNoisySeedsPlanesAreJudged)
{
  // Two faces of a thin wall lie in each other's layer: a plane from an ordinary seed is not judged.
  VolumeEnd v;
  v.planes[0].retested = false;
  EXPECT_EQ (dropVolumeLayers (v.set, v.graph, v.band, 1, v.planes), 0u);
  v.planes[0].joined = true; // a group of thick cells is a noisy seed too
  EXPECT_EQ (dropVolumeLayers (v.set, v.graph, v.band, 1, v.planes), 1u);
}

TEST (VolumeLayers, EveryPlaneIsJudgedOnceFinal)
{
  // DetectorParameters::final_volume_layer_check: the end of a volume is dropped however seeded.
  VolumeEnd v;
  v.planes[0].retested = false;
  EXPECT_EQ (dropVolumeLayers (v.set, v.graph, v.band, 1, v.planes, true), 1u);
  EXPECT_TRUE (v.planes.empty ());
}

TEST (VolumeLayers, FacesOfAThinWallAreKeptWhenEveryPlaneIsJudged)
{
  // Two faces 5 cm apart (40 x 40 samples each over 2 x 2, σ 1 cm, bands 3 cm): each lies in the
  // layer beside the other's band, which holds about as many samples as the face, not twice.
  TwoFaces f (0.05f);
  const PointSet& set = f.set;
  const NeighborGraph& graph = f.graph;
  std::vector<PlanarPatch>& planes = f.planes;
  const std::size_t beside = samplesBesideBand (set, graph, planes[0], 0.03);
  EXPECT_GT (beside, planes[1].members.size () / 4); // the other face is there
  EXPECT_LT (beside, 2 * planes[0].members.size ());
  EXPECT_EQ (dropVolumeLayers (set, graph, {0.03, 0.03}, 1, planes, true), 0u);
  EXPECT_EQ (planes.size (), 2u);
}

namespace
{
/** A dense face (z = 0 over 2 x 2, 60 x 60 samples, σ 1 cm, band 3 cm) and 400 samples scattered
  * over it between z = 0.02 and 0.08, held by a plane through their middle whose band (6 cm) takes
  * in the upper part of the face: a layer of clutter inside the face's band. */
struct ClutterLayer
{
  PointSet set;
  std::vector<PlanarPatch> planes;
  std::vector<double> band {0.03, 0.06};
  NeighborGraph graph;

  /** \a count samples between z = 0.02 and 0.02 + \a thick, their plane through the middle with a
    * band of \a layer_band. */
  explicit ClutterLayer (int count = 400, float thick = 0.06f, double layer_band = 0.06)
  {
    band[1] = layer_band;
    const auto face = rspd_test::addRectangle (set, {0, 0, 0}, {2, 0, 0}, {0, 2, 0}, 60, 60, 0.01f, 3);
    std::mt19937 rng (7);
    std::uniform_real_distribution<float> u (0.0f, 1.0f);
    std::vector<std::uint32_t> layer;
    for (int i = 0; i < count; ++i)
    {
      layer.push_back (static_cast<std::uint32_t> (set.points.size ()));
      set.points.emplace_back (2.0f * u (rng), 2.0f * u (rng), 0.02f + thick * u (rng));
      set.normals.push_back (Eigen::Vector3f::UnitZ ());
      set.input_indices.push_back (static_cast<pcl::index_t> (set.input_indices.size ()));
    }
    planes = {rspd_test::makePatch (face, {1.0, 1.0, 0.0}, {0, 0, 1}, 0.03, 0.3),
              rspd_test::makePatch (layer, {1.0, 1.0, 0.02 + 0.5 * thick}, {0, 0, 1}, layer_band, 0.3)};
    // k = 50, as the automatic k gives at this size: the footprint's cells (the neighbourhood
    // radius, 0.13) then cover the face under the layer's scattered samples.
    graph = rspd_test::bruteForceGraph (set.points, 50);
  }

  std::vector<std::uint32_t>
  labels () const
  {
    return labelSamples (set.points.size (), planes);
  }
};
} // namespace

TEST (InBandLayers, ALayerOfClutterInsideADenserPlanesBandIsDropped)
{
  ClutterLayer c;
  const std::vector<std::uint32_t> labels = c.labels ();
  const LayerCounts layer = countLayerSamples (c.set, c.graph, c.planes[1], c.band[1], &labels, 1);
  // Within 6 cm of z = 0.05: the face's samples above z = -0.01 (84 % of 3,600) where the layer's
  // footprint covers the face.
  EXPECT_GT (layer.other_in_band, 2000u);
  EXPECT_LT (layer.other_in_band, 3300u);
  EXPECT_TRUE (isInBandLayer (layer, c.planes[1].members.size ()));
  // The layer beside its band is the face's lower tail, not twice the layer: no volume layer.
  EXPECT_EQ (layer.beside, samplesBesideBand (c.set, c.graph, c.planes[1], c.band[1]));
  EXPECT_LT (layer.beside, 2 * c.planes[1].members.size ());
  // The face holds the most within its own band; the clutter there is a tenth of it.
  const LayerCounts face = countLayerSamples (c.set, c.graph, c.planes[0], c.band[0], &labels, 0);
  EXPECT_FALSE (isInBandLayer (face, c.planes[0].members.size ()));

  std::vector<PlanarPatch> kept = c.planes;
  EXPECT_EQ (dropVolumeLayers (c.set, c.graph, c.band, 1, kept, true), 0u); // without the rule
  EXPECT_EQ (kept.size (), 2u);
  std::size_t in_band = 0;
  EXPECT_EQ (dropVolumeLayers (c.set, c.graph, c.band, 2, kept, true, 0, true, &in_band), 1u);
  EXPECT_EQ (in_band, 1u);
  ASSERT_EQ (kept.size (), 1u);
  EXPECT_EQ (kept[0].members.size (), 3600u);
  // Only the planes from `first` on are judged; and only once final (every_plane).
  std::vector<PlanarPatch> later = c.planes;
  EXPECT_EQ (dropVolumeLayers (c.set, c.graph, c.band, 1, later, true, 2, true, &in_band), 0u);
  later[1].retested = true;
  EXPECT_EQ (dropVolumeLayers (c.set, c.graph, c.band, 1, later, false, 0, true, &in_band), 0u);
  EXPECT_EQ (later.size (), 2u);
  EXPECT_EQ (in_band, 1u);
}

TEST (InBandLayers, AWideLayerOverAThinFaceIsJudgedByDensity)
{
  // 1,000 samples between z = 0.02 and 0.14, their plane at 0.08 with a band of 10 cm that takes in
  // nearly all of the face (σ 1 cm, band 3 cm): fewer than four times the layer's samples, but
  // squeezed into a band a third as thick, more than four times as dense.
  ClutterLayer c (1000, 0.12f, 0.1);
  const std::vector<std::uint32_t> labels = c.labels ();
  const LayerCounts layer = countLayerSamples (c.set, c.graph, c.planes[1], c.band[1], &labels, 1);
  EXPECT_EQ (layer.other, 0u);
  EXPECT_GT (layer.other_in_band, 2 * c.planes[1].members.size ());
  EXPECT_LT (layer.other_in_band, 4 * c.planes[1].members.size ());
  EXPECT_FALSE (isInBandLayer (layer, c.planes[1].members.size ())); // by counts
  EXPECT_TRUE (isInBandLayer (layer, c.planes[1].members.size (), c.band[1], c.band[0]));
  // A wider other band, or none known, leaves the counts.
  EXPECT_FALSE (isInBandLayer (layer, c.planes[1].members.size (), c.band[1], 0.2));
  EXPECT_FALSE (isInBandLayer (layer, c.planes[1].members.size (), c.band[1], 0.0));
  EXPECT_FALSE (isInBandLayer (layer, c.planes[1].members.size (), std::nan (""), c.band[0]));
  std::vector<PlanarPatch> kept = c.planes;
  std::size_t in_band = 0;
  EXPECT_EQ (dropVolumeLayers (c.set, c.graph, c.band, 2, kept, true, 0, true, &in_band), 1u);
  EXPECT_EQ (in_band, 1u);
  ASSERT_EQ (kept.size (), 1u);
  EXPECT_EQ (kept[0].members.size (), 3600u);
}

TEST (InBandLayers, FacesOfUnequalNoiseInsideEachOthersBandAreKept)
{
  // Two faces 2 cm apart, the second's band taken as twice the first's (a noisier face): the first
  // holds about as many samples in the second's band as the second, twice as dense, not four times.
  TwoFaces f (0.02f);
  const std::vector<std::uint32_t> labels = labelSamples (f.set.points.size (), f.planes);
  const LayerCounts c = countLayerSamples (f.set, f.graph, f.planes[1], 0.06, &labels, 1);
  EXPECT_EQ (c.other, 0u);
  EXPECT_FALSE (isInBandLayer (c, f.planes[1].members.size (), 0.06, 0.03));
  std::size_t in_band = 0;
  EXPECT_EQ (dropVolumeLayers (f.set, f.graph, {0.03, 0.06}, 1, f.planes, true, 0, true, &in_band), 0u);
  EXPECT_EQ (f.planes.size (), 2u);
}

TEST (InBandLayers, FacesOfLikeDensityInsideEachOthersBandAreKept)
{
  // Two faces 2 cm apart at σ 1 cm, bands 3 cm: each lies inside the other's band and holds about
  // as many samples there as the other.
  TwoFaces f (0.02f);
  const PointSet& set = f.set;
  const NeighborGraph& graph = f.graph;
  std::vector<PlanarPatch>& planes = f.planes;
  const std::vector<std::uint32_t> labels = labelSamples (set.points.size (), planes);
  const LayerCounts c = countLayerSamples (set, graph, planes[0], 0.03, &labels, 0);
  EXPECT_GT (c.other_in_band, planes[1].members.size () / 2);
  EXPECT_FALSE (isInBandLayer (c, planes[0].members.size ()));
  std::size_t in_band = 0;
  EXPECT_EQ (dropVolumeLayers (set, graph, {0.03, 0.03}, 1, planes, true, 0, true, &in_band), 0u);
  EXPECT_EQ (in_band, 0u);
  EXPECT_EQ (planes.size (), 2u);
}

TEST (InBandLayers, LabelsThatDoNotFitAreNotCounted)
{
  ClutterLayer c;
  const std::vector<std::uint32_t> short_labels (10, 0);
  const LayerCounts none = countLayerSamples (c.set, c.graph, c.planes[1], c.band[1], &short_labels, 1);
  EXPECT_EQ (none.other_in_band, 0u);
  EXPECT_EQ (none.beside, samplesBesideBand (c.set, c.graph, c.planes[1], c.band[1]));
  const std::vector<std::uint32_t> labels = c.labels ();
  const LayerCounts nan = countLayerSamples (c.set, c.graph, c.planes[1], std::nan (""), &labels, 1);
  EXPECT_EQ (nan.other_in_band, 0u);
  EXPECT_EQ (nan.beside, 0u);
  EXPECT_FALSE (isInBandLayer (nan, c.planes[1].members.size ()));
}

TEST (VolumeLayers, ScaleAndThreadsDoNotChangeTheCount)
{
  VolumeEnd v, mm (1000.0f);
  const std::size_t beside = samplesBesideBand (v.set, v.graph, v.planes[0], v.band[0]);
  EXPECT_EQ (samplesBesideBand (mm.set, mm.graph, mm.planes[0], mm.band[0]), beside);
  std::vector<PlanarPatch> two = {v.planes[0], v.planes[0]};
  two[1].retested = false;
  EXPECT_EQ (dropVolumeLayers (v.set, v.graph, {0.1, 0.1}, 2, two), 1u);
  ASSERT_EQ (two.size (), 1u);
  EXPECT_FALSE (two[0].retested); // the order of the planes kept is kept
}

TEST (VolumeLayers, NothingToJudgeGivesZero)
{
  VolumeEnd v;
  EXPECT_EQ (samplesBesideBand (v.set, v.graph, v.planes[0], 0.0), 0u);
  EXPECT_EQ (samplesBesideBand (v.set, v.graph, v.planes[0], std::nan ("")), 0u);
  PlanarPatch empty;
  EXPECT_EQ (samplesBesideBand (v.set, v.graph, empty, 0.1), 0u);
  std::vector<PlanarPatch> none;
  EXPECT_EQ (dropVolumeLayers (v.set, v.graph, {}, 1, none), 0u);
}

namespace
{
/** A face (z = 0 over 2 x 2, 40 x 40 samples, σ 1 cm) held by plane 0, and 4,000 samples of clutter
  * over it, between z = -0.5 and 0.5 (or 0 and 0.5 with \a one_side), that no plane holds. */
struct FaceInClutter
{
  PointSet set;
  std::vector<PlanarPatch> planes;
  std::vector<std::uint32_t> labels, open;
  NeighborGraph graph;

  explicit FaceInClutter (bool one_side)
  {
    const auto face = rspd_test::addRectangle (set, {0, 0, 0}, {2, 0, 0}, {0, 2, 0}, 40, 40, 0.01f, 3);
    std::mt19937 rng (9);
    std::uniform_real_distribution<float> u (0.0f, 1.0f);
    for (int i = 0; i < 4000; ++i)
    {
      open.push_back (static_cast<std::uint32_t> (set.points.size ()));
      const float z = one_side ? 0.5f * u (rng) : u (rng) - 0.5f;
      set.points.emplace_back (2.0f * u (rng), 2.0f * u (rng), z);
      set.normals.push_back (Eigen::Vector3f::UnitZ ());
      set.input_indices.push_back (static_cast<pcl::index_t> (set.input_indices.size ()));
    }
    planes = {rspd_test::makePatch (face, {1.0, 1.0, 0.0}, {0, 0, 1}, 0.03, 0.3)};
    labels = labelSamples (set.size (), planes);
    graph = rspd_test::bruteForceGraph (set.points, 15);
  }
};
} // namespace

TEST (SurroundingClutter, ClutterOnBothSidesIsCountedOnOneSideItIsNot)
{
  // Between 4.5 and 6 cm from the face, each side's layer holds about 4,000 · 0.015 = 60 samples of
  // the clutter: twice the lesser side, about 120. With the clutter above the face only, the side
  // below is empty: what lies on one side of a plane is other structure, no clutter.
  FaceInClutter both (false);
  const std::size_t count = clutterBesidePlane (both.set, both.graph, both.planes[0], 0.045, 0.06, both.labels, both.open, 0);
  EXPECT_GT (count, 70u);
  EXPECT_LT (count, 180u);
  FaceInClutter above (true);
  EXPECT_EQ (clutterBesidePlane (above.set, above.graph, above.planes[0], 0.045, 0.06, above.labels, above.open, 0), 0u);
}

TEST (SurroundingClutter, SamplesNextToAnotherPlaneAreItsEdgeNotClutter)
{
  FaceInClutter f (false);
  std::vector<std::uint32_t> labels = f.labels;
  // Every sample of the clutter held by a plane 1 but those offered: each offered one then has a
  // neighbour in another plane.
  std::vector<char> offered (f.set.size (), 0);
  std::vector<std::uint32_t> open;
  for (const auto i : f.open)
  {
    const double z = std::abs (f.set.points[i].z ());
    if (z >= 0.045 && z < 0.06)
    {
      open.push_back (i);
      offered[i] = 1;
    }
  }
  for (const auto i : f.open)
    if (!offered[i])
      labels[i] = 1;
  EXPECT_GT (clutterBesidePlane (f.set, f.graph, f.planes[0], 0.045, 0.06, f.labels, open, 0), 70u);
  EXPECT_EQ (clutterBesidePlane (f.set, f.graph, f.planes[0], 0.045, 0.06, labels, open, 0), 0u);
  // Nothing to judge: no members, an empty shell, labels of another size.
  PlanarPatch empty = f.planes[0];
  empty.members.clear ();
  EXPECT_EQ (clutterBesidePlane (f.set, f.graph, empty, 0.045, 0.06, f.labels, f.open, 0), 0u);
  EXPECT_EQ (clutterBesidePlane (f.set, f.graph, f.planes[0], 0.06, 0.045, f.labels, f.open, 0), 0u);
  EXPECT_EQ (clutterBesidePlane (f.set, f.graph, f.planes[0], 0.045, 0.06, {}, f.open, 0), 0u);
}

namespace
{
/** Samples scattered evenly through a box 2 x 2 x 1 (a volume of clutter) and a plane z = 0.5 that
  * holds every third sample within 0.05 of it (band 0.05): a layer inside the volume. */
struct LayerInVolume
{
  PointSet set;
  std::vector<PlanarPatch> planes;
  std::vector<double> band {0.05};
  NeighborGraph graph;

  LayerInVolume ()
  {
    const std::vector<std::uint32_t> layer = scatterInBox (set, 17, 1.0f, [] (const Eigen::Vector3f& p, int i) {
      return std::abs (p.z () - 0.5f) <= 0.05f && i % 3 == 0;
    });
    planes = {rspd_test::makePatch (layer, Eigen::Vector3d (1.0, 1.0, 0.5), {0, 0, 1}, 0.05, 0.3)};
    graph = rspd_test::bruteForceGraph (set.points, 50);
  }
};
} // namespace

TEST (FlatLayers, ALayerOfAVolumeIsDroppedWhereTheRatioAloneKeepsIt)
{
  // About 200 members; beside the band, (0.05, 0.1] on each side, about 300 samples a side over
  // the footprint, and as many again in (0.1, 0.15]: denser than the plane, flat past it.
  LayerInVolume v;
  const std::size_t members = v.planes[0].members.size ();
  const LayerCounts c = countLayerSamples (v.set, v.graph, v.planes[0], v.band[0], nullptr, 0);
  EXPECT_GT (c.beside, members);
  EXPECT_LT (c.beside, 2 * members); // the final volume layers' ratio alone keeps it
  EXPECT_GT (c.flat_beside, members);
  std::vector<PlanarPatch> kept = v.planes;
  EXPECT_EQ (dropVolumeLayers (v.set, v.graph, v.band, 1, kept, true), 0u);
  EXPECT_EQ (dropVolumeLayers (v.set, v.graph, v.band, 1, v.planes, true, 0, false, nullptr, true), 1u);
  EXPECT_TRUE (v.planes.empty ());
  // Judged only with every plane (the final check).
  LayerInVolume w;
  EXPECT_EQ (dropVolumeLayers (w.set, w.graph, w.band, 1, w.planes, false, 0, false, nullptr, true), 0u);
}

TEST (FlatLayers, FacesOfAThinWallAndANoisyFaceInClutterAreKept)
{
  // The other face of a thin wall lies beside the band, with nothing after it: not flat.
  TwoFaces f (0.05f);
  const LayerCounts c = countLayerSamples (f.set, f.graph, f.planes[0], 0.03, nullptr, 0);
  EXPECT_GT (c.beside, f.planes[0].members.size () / 2);
  EXPECT_LT (c.flat_beside, f.planes[0].members.size () / 4);
  EXPECT_EQ (dropVolumeLayers (f.set, f.graph, {0.03, 0.03}, 1, f.planes, true, 0, true, nullptr, true), 0u);
  EXPECT_EQ (f.planes.size (), 2u);
  NoisyFace n;
  EXPECT_EQ (dropVolumeLayers (n.set, n.graph, n.band, 1, n.planes, true, 0, true, nullptr, true), 0u);
}

TEST (FlatLayers, NothingToJudgeGivesZero)
{
  // A band that is zero or not a number, or a plane with no members: no layer is counted, and the
  // flat layers drop nothing.
  LayerInVolume v;
  EXPECT_EQ (countLayerSamples (v.set, v.graph, v.planes[0], 0.0, nullptr, 0).flat_beside, 0u);
  EXPECT_EQ (countLayerSamples (v.set, v.graph, v.planes[0], std::nan (""), nullptr, 0).flat_beside, 0u);
  PlanarPatch empty;
  EXPECT_EQ (countLayerSamples (v.set, v.graph, empty, 0.05, nullptr, 0).flat_beside, 0u);
  EXPECT_EQ (dropVolumeLayers (v.set, v.graph, {0.0}, 1, v.planes, true, 0, false, nullptr, true), 0u);
  EXPECT_EQ (v.planes.size (), 1u);
}
