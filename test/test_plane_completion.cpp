/*
 * Tests of small-plane completion (completeSmallPlanes).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "test_helpers.h"

#include <pcl_rspd/plane_completion.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace pcl::rspd;

namespace
{
constexpr double kPi = 3.14159265358979323846;

/** A noisy face A (z = 0 over 1 x 1 m, 40 x 40 samples, σ 1 cm) and a clean face B (σ 1 mm) that
  * rises from A's edge x = 1 at 24° for 0.4 m (16 rows of 40 samples, 2.5 cm apart). As the
  * small-plane pass leaves them: A holds its own samples and B's first four rows (within 4 cm of A's
  * plane, the strip A's wider band took), B's rows 4 and 5 are in no plane, and B (its seed grown
  * short of its rim) holds rows 6-15, 400 samples, with a tilted estimate. ε = 560. */
struct FacesAtAnEdge
{
  PointSet set;
  std::vector<std::uint32_t> a_samples, b_samples;
  std::vector<PlanarPatch> planes;
  NeighborGraph graph;
  DetectorParameters params;

  explicit FacesAtAnEdge (float scale = 1.0f, float b_noise = 0.001f)
  {
    const float angle = static_cast<float> (24.0 * kPi / 180.0);
    const Eigen::Vector3f rise (std::cos (angle), 0.0f, std::sin (angle));
    a_samples = rspd_test::addRectangle (set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 40, 40, 0.01f, 3);
    b_samples = rspd_test::addRectangle (set, {1, 0, 0}, 0.4f * rise, {0, 1, 0}, 16, 40, b_noise, 4);
    for (auto& p : set.points)
      p *= scale;
    std::vector<std::uint32_t> a_members = a_samples, b_members;
    for (int row = 0; row < 16; ++row)
      for (int j = 0; j < 40; ++j)
      {
        const std::uint32_t s = b_samples[static_cast<std::size_t> (row * 40 + j)];
        if (row < 4)
          a_members.push_back (s);
        else if (row >= 6)
          b_members.push_back (s);
      }
    std::sort (a_members.begin (), a_members.end ());
    // B's estimate tilted by 5°, as a median of normals bent over A's neighbourhoods leaves it.
    const Eigen::Vector3d b_normal = Eigen::AngleAxisd (5.0 * kPi / 180.0, Eigen::Vector3d::UnitY ()) *
                                     rise.cast<double> ().cross (Eigen::Vector3d::UnitY ()).normalized ();
    planes = {rspd_test::makePatch (a_members, scale * Eigen::Vector3d (0.5, 0.5, 0.0), {0, 0, 1}, scale * 0.03, 0.5),
              rspd_test::makePatch (b_members, scale * (Eigen::Vector3d (1.0, 0.5, 0.0) + 0.25 * rise.cast<double> ()),
                                    b_normal, scale * 0.01, 2.0 * kPi / 180.0)};
    graph = rspd_test::bruteForceGraph (set.points, 15);
    params.min_patch_size = 560;
  }

  /** How many of \a samples \a plane holds. */
  std::size_t
  held (std::size_t plane, const std::vector<std::uint32_t>& samples) const
  {
    const auto& m = planes[plane].members;
    return static_cast<std::size_t> (std::count_if (samples.begin (), samples.end (), [&] (std::uint32_t s) {
      return std::binary_search (m.begin (), m.end (), s);
    }));
  }
};
} // namespace

TEST (PlaneCompletion, SmallFaceTakesItsStripBackFromTheNoisierFaceAndReachesEpsilon)
{
  FacesAtAnEdge f;
  EXPECT_EQ (completeSmallPlanes (f.set, f.graph, f.params, f.planes), 1u);
  ASSERT_EQ (f.planes.size (), 2u); // nothing is removed here
  EXPECT_GE (f.planes[1].members.size (), f.params.min_patch_size);
  // B's rows 1-5 are B's again (row 0, within 1 cm of A's plane, is as near to A relative to A's
  // band); A keeps its own samples but a few within B's band where the faces meet.
  EXPECT_GE (f.held (1, f.b_samples), 575u);
  EXPECT_LE (f.held (1, f.a_samples), 10u);
  EXPECT_GE (f.held (0, f.a_samples), 1590u);
  EXPECT_TRUE (f.planes[1].retested); // completed by position: judged flat once grown
  EXPECT_FALSE (f.planes[0].retested);
  EXPECT_TRUE (std::is_sorted (f.planes[1].members.begin (), f.planes[1].members.end ()));
  EXPECT_EQ (f.planes[1].first_index, f.planes[1].members.front ());
}

TEST (PlaneCompletion, PlaneThatStaysShortOfEpsilonTakesNothing)
{
  FacesAtAnEdge f;
  f.params.min_patch_size = 700; // B's surface holds 640 samples
  const std::vector<PlanarPatch> before = f.planes;
  EXPECT_EQ (completeSmallPlanes (f.set, f.graph, f.params, f.planes), 0u);
  EXPECT_EQ (f.planes[0].members, before[0].members);
  EXPECT_EQ (f.planes[1].members, before[1].members);
}

TEST (PlaneCompletion, NoisySeedsAndSeedsUnderHalfOfEpsilonAreNotCompleted)
{
  FacesAtAnEdge noisy;
  noisy.planes[1].retested = true; // a noisy or shifted-grid seed's plane: judged once grown instead
  EXPECT_EQ (completeSmallPlanes (noisy.set, noisy.graph, noisy.params, noisy.planes), 0u);

  FacesAtAnEdge small;
  small.params.min_patch_size = 801; // B's 400 members are under half of it
  EXPECT_EQ (completeSmallPlanes (small.set, small.graph, small.params, small.planes), 0u);
  small.params.min_patch_size = 800; // half of it, but B's surface holds 640 samples
  EXPECT_EQ (completeSmallPlanes (small.set, small.graph, small.params, small.planes), 0u);
  small.params.min_patch_size = 560;
  EXPECT_EQ (completeSmallPlanes (small.set, small.graph, small.params, small.planes), 1u);
}

TEST (PlaneCompletion, NothingIsTakenFromAPlaneWithinItsNormalSpread)
{
  // B's MND wider than the 24° between the faces: A's samples could be B's own surface's (a layer of
  // one face), so B takes only the free rows 4-5 and stays short of ε.
  FacesAtAnEdge f;
  f.planes[1].mnd = 30.0 * kPi / 180.0;
  f.planes[1].cos_mnd = std::cos (f.planes[1].mnd);
  EXPECT_EQ (completeSmallPlanes (f.set, f.graph, f.params, f.planes), 0u);
  f.params.min_patch_size = 470; // the free rows alone: 400 + 80 (a few beyond 3 σ)
  EXPECT_EQ (completeSmallPlanes (f.set, f.graph, f.params, f.planes), 1u);
  EXPECT_EQ (f.held (0, f.b_samples), 160u); // A keeps B's first four rows
}

TEST (PlaneCompletion, NothingIsTakenFromAQuieterPlane)
{
  // A as quiet as B: the strip is not a wider band's, and B takes only the free rows.
  FacesAtAnEdge f;
  for (const auto s : f.a_samples)
    f.set.points[s].z () *= 0.05f;
  f.params.min_patch_size = 560;
  EXPECT_EQ (completeSmallPlanes (f.set, f.graph, f.params, f.planes), 0u);
}

TEST (PlaneCompletion, ScaleAndThreadsDoNotChangeTheResult)
{
  FacesAtAnEdge m, mm (1000.0f), two;
  two.params.num_threads = 2;
  m.params.num_threads = 1;
  EXPECT_EQ (completeSmallPlanes (m.set, m.graph, m.params, m.planes), 1u);
  EXPECT_EQ (completeSmallPlanes (mm.set, mm.graph, mm.params, mm.planes), 1u);
  EXPECT_EQ (completeSmallPlanes (two.set, two.graph, two.params, two.planes), 1u);
  EXPECT_EQ (mm.planes[1].members, m.planes[1].members);
  EXPECT_EQ (two.planes[1].members, m.planes[1].members);
  EXPECT_EQ (two.planes[0].members, m.planes[0].members);
}

TEST (PlaneCompletion, NoCandidateLeavesEverythingAlone)
{
  FacesAtAnEdge f;
  f.params.min_patch_size = 400; // every plane already holds ε
  const std::vector<PlanarPatch> before = f.planes;
  EXPECT_EQ (completeSmallPlanes (f.set, f.graph, f.params, f.planes), 0u);
  EXPECT_EQ (f.planes[1].members, before[1].members);
  std::vector<PlanarPatch> none;
  EXPECT_EQ (completeSmallPlanes (f.set, f.graph, f.params, none), 0u);
}

TEST (PlaneCompletion, FaceFlatToRoundingIsNoNoisyFace)
{
  // B noise-free: its band is float rounding, far under 1 % of its 2.5 cm spacing (a depth
  // camera's level looks so), and it is not completed.
  FacesAtAnEdge exact (1.0f, 0.0f);
  EXPECT_EQ (completeSmallPlanes (exact.set, exact.graph, exact.params, exact.planes), 0u);
  FacesAtAnEdge quiet (1.0f, 0.0005f); // 2 % of the spacing in σ: a face
  EXPECT_EQ (completeSmallPlanes (quiet.set, quiet.graph, quiet.params, quiet.planes), 1u);
}

TEST (PlaneCompletion, LayerOfAFoundPlaneIsNotCompleted)
{
  // One noisy face (σ 1 cm, 40 x 40 samples over 1 x 1 m): A holds every other column, the rest is
  // in no plane but a block of 10 x 40 that B holds. B completed by the free columns would be a
  // layer of A's band, every member beside a sample of A.
  PointSet set;
  const std::vector<std::uint32_t> face = rspd_test::addRectangle (set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 40, 40, 0.01f, 3);
  std::vector<std::uint32_t> a, b;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j)
    {
      const std::uint32_t s = face[static_cast<std::size_t> (i * 40 + j)];
      if (i % 2 == 0)
        a.push_back (s);
      else if (i < 20)
        b.push_back (s);
    }
  std::vector<PlanarPatch> planes = {rspd_test::makePatch (a, {0.5, 0.5, 0.0}, {0, 0, 1}, 0.03, 0.5),
                                     rspd_test::makePatch (b, {0.25, 0.5, 0.0}, {0, 0, 1}, 0.03, 0.5)};
  const NeighborGraph graph = rspd_test::bruteForceGraph (set.points, 15);
  DetectorParameters params;
  params.min_patch_size = 700; // B's 400 and the 400 free samples of the other half
  EXPECT_EQ (completeSmallPlanes (set, graph, params, planes), 0u);
  EXPECT_EQ (planes[1].members.size (), 400u);
}
