// SPDX-License-Identifier: BSD-3-Clause
/*
 * Tests of the synthetic scene generator: sizes, label bookkeeping, determinism, geometry and the
 * options.
 */

#include <pcl_rspd/synthetic_scenes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

using pcl::rspd::makeScene;
using pcl::rspd::Scene;
using pcl::rspd::SceneOptions;
using pcl::rspd::SurfaceKind;

namespace
{
/** \brief Expected default size and plane count of every scene. */
const std::map<std::string, std::pair<std::size_t, int>>&
defaults ()
{
  static const std::map<std::string, std::pair<std::size_t, int>> d = {
    {"cube", {100000, 6}},       {"room", {200000, 12}},      {"staircase", {100000, 30}},
    {"facade", {200000, 16}},    {"industrial", {300000, 6}}, {"boxes", {300000, 32}},
    {"plane", {10000, 1}}};
  return d;
}

std::size_t
countKind (const Scene& scene, SurfaceKind kind)
{
  return static_cast<std::size_t> (std::count (scene.kinds.begin (), scene.kinds.end (), kind));
}

bool
sameCloud (const Scene& a, const Scene& b)
{
  if (a.cloud.size () != b.cloud.size ())
    return false;
  for (std::size_t i = 0; i < a.cloud.size (); ++i)
    if (a.cloud[i].x != b.cloud[i].x || a.cloud[i].y != b.cloud[i].y ||
        a.cloud[i].z != b.cloud[i].z)
      return false;
  return true;
}

/** \brief Structural checks every scene must pass. */
void
checkConsistent (const Scene& scene, std::size_t expected_points)
{
  ASSERT_EQ (scene.cloud.size (), expected_points);
  EXPECT_EQ (scene.cloud.width, expected_points);
  EXPECT_EQ (scene.cloud.height, 1u);
  EXPECT_TRUE (scene.cloud.is_dense);
  ASSERT_EQ (scene.labels.size (), expected_points);
  ASSERT_EQ (scene.kinds.size (), expected_points);
  ASSERT_GE (scene.num_planes, 0);

  std::vector<std::size_t> per_label (static_cast<std::size_t> (scene.num_planes) + 1, 0);
  for (std::size_t i = 0; i < scene.cloud.size (); ++i)
  {
    const auto& p = scene.cloud[i];
    ASSERT_TRUE (std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z)) << i;
    ASSERT_LE (scene.labels[i], static_cast<std::uint32_t> (scene.num_planes)) << i;
    ++per_label[scene.labels[i]];
    // Plane samples carry a plane label and nothing else does.
    ASSERT_EQ (scene.kinds[i] == SurfaceKind::Plane, scene.labels[i] > 0) << i;
  }
  for (int l = 1; l <= scene.num_planes; ++l)
    EXPECT_GT (per_label[l], 0u) << "label " << l << " unused";
}
} // namespace

TEST (SyntheticScenes, NamesAreTheSevenScenes)
{
  const std::vector<std::string> names = pcl::rspd::sceneNames ();
  ASSERT_EQ (names.size (), defaults ().size ());
  for (const auto& n : names)
    EXPECT_EQ (defaults ().count (n), 1u) << n;
}

TEST (SyntheticScenes, UnknownNameThrows)
{
  EXPECT_THROW (makeScene ("no-such-scene"), std::invalid_argument);
  EXPECT_THROW (makeScene (""), std::invalid_argument);
}

TEST (SyntheticScenes, InvalidOptionsThrow)
{
  SceneOptions o;
  o.num_points = 100;
  o.outlier_ratio = 1.5;
  EXPECT_THROW (makeScene ("cube", o), std::invalid_argument);
  o.outlier_ratio = -1.0;
  o.scale = 0.0;
  EXPECT_THROW (makeScene ("cube", o), std::invalid_argument);
  o.scale = 1.0;
  o.noise = std::nan ("");
  EXPECT_THROW (makeScene ("cube", o), std::invalid_argument);
}

TEST (SyntheticScenes, TransformCloudMovesAsMakeSceneDoes)
{
  // A generated scene moved afterwards lands where makeScene puts it with the same options (up to
  // the rotation centre: the finite points' box here, the nominal box there, so compare shapes), and
  // NaN points stay NaN; bad options throw and leave the cloud as it was.
  SceneOptions plain;
  plain.num_points = 2000;
  Scene scene = makeScene ("cube", plain);
  scene.cloud[7].x = std::nanf ("");
  pcl::PointCloud<pcl::PointXYZ> moved = scene.cloud;
  SceneOptions o = plain;
  o.random_rotation = true;
  o.scale = 3.0;
  o.offset = Eigen::Vector3d (10, 0, 0);
  transformCloud (moved, o);
  const Scene direct = makeScene ("cube", o);
  EXPECT_TRUE (std::isnan (moved[7].x));
  for (std::size_t i = 1; i < moved.size (); i += 37)
  {
    if (i == 7)
      continue;
    const float d_moved = (moved[i].getVector3fMap () - moved[0].getVector3fMap ()).norm ();
    const float d_direct = (direct.cloud[i].getVector3fMap () - direct.cloud[0].getVector3fMap ()).norm ();
    EXPECT_NEAR (d_moved, d_direct, 1e-4f * (1.0f + d_direct)) << i;
    // The same rotation: differences between points turn alike.
    const Eigen::Vector3f a = moved[i].getVector3fMap () - moved[0].getVector3fMap ();
    const Eigen::Vector3f b = direct.cloud[i].getVector3fMap () - direct.cloud[0].getVector3fMap ();
    EXPECT_LT ((a - b).norm (), 1e-4f * (1.0f + b.norm ())) << i;
  }
  pcl::PointCloud<pcl::PointXYZ> kept = scene.cloud;
  SceneOptions bad = plain;
  bad.scale = -1.0;
  EXPECT_THROW (transformCloud (kept, bad), std::invalid_argument);
  bad.scale = 1.0;
  bad.offset = Eigen::Vector3d (std::nan (""), 0, 0);
  EXPECT_THROW (transformCloud (kept, bad), std::invalid_argument);
  EXPECT_EQ (kept[3].getVector3fMap (), scene.cloud[3].getVector3fMap ());
}

/** Every scene at its default settings, one test per scene. */
class DefaultScene : public ::testing::TestWithParam<std::string>
{};

TEST_P (DefaultScene, SizeLabelsAndPlaneCount)
{
  const std::string name = GetParam ();
  const Scene scene = makeScene (name);
  EXPECT_EQ (scene.name, name);
  checkConsistent (scene, defaults ().at (name).first);
  EXPECT_EQ (scene.num_planes, defaults ().at (name).second);
}

TEST_P (DefaultScene, ExactRequestedCount)
{
  SceneOptions o;
  o.num_points = 12345;
  o.outlier_ratio = 0.1;
  const Scene scene = makeScene (GetParam (), o);
  checkConsistent (scene, 12345);
  // round (0.1 * 12345) outliers; sparse room planes may add to them.
  EXPECT_GE (countKind (scene, SurfaceKind::Outlier), 1235u);
}

TEST_P (DefaultScene, SameSeedSameSceneOtherSeedOtherScene)
{
  SceneOptions o;
  o.num_points = 20000;
  o.seed = 7;
  o.random_rotation = true;
  const Scene a = makeScene (GetParam (), o);
  const Scene b = makeScene (GetParam (), o);
  EXPECT_TRUE (sameCloud (a, b));
  EXPECT_EQ (a.labels, b.labels);
  EXPECT_TRUE (a.kinds == b.kinds);
  EXPECT_EQ (a.num_planes, b.num_planes);

  o.seed = 8;
  const Scene c = makeScene (GetParam (), o);
  EXPECT_FALSE (sameCloud (a, c));
}

TEST_P (DefaultScene, LayoutsDrawOtherGeometryDeterministically)
{
  SceneOptions o;
  o.num_points = 20000;
  const Scene nominal = makeScene (GetParam (), o);
  o.layout = 3;
  const Scene a = makeScene (GetParam (), o);
  const Scene b = makeScene (GetParam (), o);
  checkConsistent (a, 20000);
  EXPECT_TRUE (sameCloud (a, b));
  EXPECT_EQ (a.labels, b.labels);
  // One layout for the plane; every other scene's dimensions move.
  EXPECT_EQ (sameCloud (a, nominal), GetParam () == std::string ("plane"));
  // The seed draws the samples, the layout the geometry: another seed keeps the layout's planes.
  o.seed = 2;
  const Scene c = makeScene (GetParam (), o);
  checkConsistent (c, 20000);
  if (GetParam () != std::string ("room"))  // the room's rays decide which planes count
    EXPECT_EQ (c.num_planes, a.num_planes);
}

INSTANTIATE_TEST_SUITE_P (AllScenes, DefaultScene,
                          ::testing::Values ("cube", "room", "staircase", "facade", "industrial",
                                             "boxes", "plane"));

TEST (SyntheticScenes, BoxesGetRougherFromBoxToBox)
{
  // The floor and wall carry the scene's noise, the six boxes 1, 3, 5, 7.5, 10 and 15 times it:
  // the spread of a top's heights about its mean, box by box, follows those factors.
  SceneOptions o;
  o.noise = 0.004;
  const Scene scene = makeScene ("boxes", o);
  ASSERT_EQ (scene.num_planes, 32);
  const double factor[6] = {1.0, 3.0, 5.0, 7.5, 10.0, 15.0};
  for (int box = 0; box < 6; ++box)
  {
    const std::uint32_t top = 3 + 5 * static_cast<std::uint32_t> (box) + 4; // floor 1, wall 2, then 5 faces a box
    double sum = 0.0, sum2 = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < scene.cloud.size (); ++i)
      if (scene.labels[i] == top)
      {
        sum += scene.cloud[i].z;
        sum2 += static_cast<double> (scene.cloud[i].z) * scene.cloud[i].z;
        ++n;
      }
    ASSERT_GT (n, 500u) << box;
    const double mean = sum / static_cast<double> (n);
    EXPECT_NEAR (mean, 0.8 + 0.2 * box, 0.01) << box;
    const double sigma = std::sqrt (std::max (0.0, sum2 / static_cast<double> (n) - mean * mean));
    EXPECT_NEAR (sigma, factor[box] * o.noise, 0.15 * factor[box] * o.noise) << box;
  }
}

TEST (SyntheticScenes, CubeSamplesLieOnTheirFace)
{
  SceneOptions o;
  o.noise = 0.01;
  const Scene scene = makeScene ("cube", o);
  ASSERT_EQ (scene.num_planes, 6);
  // Identify each label's face from its mean: one coordinate sits at +-0.5.
  std::vector<Eigen::Vector3d> mean (7, Eigen::Vector3d::Zero ());
  std::vector<std::size_t> count (7, 0);
  for (std::size_t i = 0; i < scene.cloud.size (); ++i)
  {
    mean[scene.labels[i]] += scene.cloud[i].getVector3fMap ().cast<double> ();
    ++count[scene.labels[i]];
  }
  std::vector<std::pair<int, double>> face (7);  // axis, side
  for (int l = 1; l <= 6; ++l)
  {
    mean[l] /= static_cast<double> (count[l]);
    int axis = 0;
    mean[l].cwiseAbs ().maxCoeff (&axis);
    face[l] = {axis, mean[l][axis] > 0.0 ? 0.5 : -0.5};
    EXPECT_NEAR (std::abs (mean[l][axis]), 0.5, 0.002) << l;
    // Uniform area sampling: each face gets a sixth of the points.
    EXPECT_NEAR (static_cast<double> (count[l]), scene.cloud.size () / 6.0, 1.0);
  }
  std::vector<bool> seen (6, false);
  for (int l = 1; l <= 6; ++l)
    seen[2 * face[l].first + (face[l].second > 0.0)] = true;
  EXPECT_EQ (std::count (seen.begin (), seen.end (), true), 6);

  double sq = 0.0;
  for (std::size_t i = 0; i < scene.cloud.size (); ++i)
  {
    const auto [axis, side] = face[scene.labels[i]];
    const double d = scene.cloud[i].getVector3fMap ()[axis] - side;
    ASSERT_LT (std::abs (d), 5.0 * o.noise) << i;
    sq += d * d;
    // In-face coordinates stay within the face.
    for (int k = 0; k < 3; ++k)
    {
      if (k != axis)
      {
        ASSERT_LE (std::abs (scene.cloud[i].getVector3fMap ()[k]), 0.5f + 1e-6f);
      }
    }
  }
  EXPECT_NEAR (std::sqrt (sq / scene.cloud.size ()), o.noise, 0.05 * o.noise);
}

TEST (SyntheticScenes, IsotropicNoiseIsDrawnInEveryDirection)
{
  // The plane scene (z = 0 over [-0.5, 0.5]^2) with σ = 1 cm per axis: off the plane as much as
  // along the normal, and along it too, so that samples lie beyond the square's edges; the ray-cast
  // room's samples leave their rays. The default draws along the normal only (see above).
  SceneOptions o;
  o.noise = 0.01;
  o.isotropic_noise = true;
  const Scene plane = makeScene ("plane", o);
  double sq_z = 0.0;
  std::size_t beyond = 0;
  for (const auto& p : plane.cloud)
  {
    sq_z += static_cast<double> (p.z) * p.z;
    beyond += std::abs (p.x) > 0.5f || std::abs (p.y) > 0.5f;
  }
  const double n = static_cast<double> (plane.cloud.size ());
  EXPECT_NEAR (std::sqrt (sq_z / n), o.noise, 0.05 * o.noise);
  // A band of 1 cm along 4 m of edge holds ~4 % of the samples, half of them pushed outwards.
  EXPECT_GT (beyond, static_cast<std::size_t> (0.01 * n));
  EXPECT_LT (beyond, static_cast<std::size_t> (0.03 * n));
  // The default and the isotropic room differ, and both keep their size and truth.
  SceneOptions r;
  r.num_points = 20000;
  const Scene along = makeScene ("room", r);
  r.isotropic_noise = true;
  const Scene around = makeScene ("room", r);
  ASSERT_EQ (along.cloud.size (), around.cloud.size ());
  EXPECT_EQ (along.num_planes, around.num_planes);
  EXPECT_NE (along.cloud[0].getVector3fMap (), around.cloud[0].getVector3fMap ());
}

TEST (SyntheticScenes, NoiseFreePlaneIsExact)
{
  const Scene scene = makeScene ("plane");
  for (const auto& p : scene.cloud)
  {
    ASSERT_EQ (p.z, 0.0f);
    ASSERT_LE (std::abs (p.x), 0.5f);
    ASSERT_LE (std::abs (p.y), 0.5f);
  }
}

TEST (SyntheticScenes, ScaleAndOffset)
{
  SceneOptions o;
  o.num_points = 5000;
  o.seed = 3;
  const Scene base = makeScene ("staircase", o);
  o.scale = 1000.0;
  o.offset = Eigen::Vector3d (100.0, -200.0, 3000.0);
  const Scene moved = makeScene ("staircase", o);
  ASSERT_EQ (moved.cloud.size (), base.cloud.size ());
  EXPECT_EQ (moved.labels, base.labels);
  for (std::size_t i = 0; i < base.cloud.size (); ++i)
  {
    const Eigen::Vector3d expect =
      1000.0 * base.cloud[i].getVector3fMap ().cast<double> () + o.offset;
    // Float rounding of the unscaled cloud, magnified by the scale.
    ASSERT_LT ((moved.cloud[i].getVector3fMap ().cast<double> () - expect).norm (), 1e-3) << i;
  }
}

TEST (SyntheticScenes, RotationIsRigidAboutTheCentre)
{
  SceneOptions o;
  o.num_points = 2000;
  const Scene base = makeScene ("cube", o);
  o.random_rotation = true;
  const Scene rotated = makeScene ("cube", o);
  ASSERT_EQ (rotated.cloud.size (), base.cloud.size ());
  EXPECT_FALSE (sameCloud (base, rotated));
  EXPECT_EQ (rotated.labels, base.labels);
  // The cube is centred on the origin: distances to it and between points are preserved.
  for (std::size_t i = 0; i + 1 < base.cloud.size (); ++i)
  {
    const Eigen::Vector3f a = base.cloud[i].getVector3fMap ();
    const Eigen::Vector3f b = base.cloud[i + 1].getVector3fMap ();
    const Eigen::Vector3f ra = rotated.cloud[i].getVector3fMap ();
    const Eigen::Vector3f rb = rotated.cloud[i + 1].getVector3fMap ();
    ASSERT_NEAR (a.norm (), ra.norm (), 1e-5f);
    ASSERT_NEAR ((a - b).norm (), (ra - rb).norm (), 1e-5f);
  }
  // Another seed gives another rotation.
  o.seed = 2;
  const Scene other = makeScene ("cube", o);
  EXPECT_FALSE (sameCloud (rotated, other));
}

TEST (SyntheticScenes, ShuffleOnlyReordersTheSamples)
{
  SceneOptions o;
  o.num_points = 3000;
  o.shuffle = false;
  const Scene ordered = makeScene ("staircase", o);
  // Generation order goes surface by surface, i.e. by label.
  EXPECT_TRUE (std::is_sorted (ordered.labels.begin (), ordered.labels.end ()));
  o.shuffle = true;
  const Scene shuffled = makeScene ("staircase", o);
  EXPECT_FALSE (std::is_sorted (shuffled.labels.begin (), shuffled.labels.end ()));

  using Row = std::tuple<float, float, float, std::uint32_t>;
  auto rows = [] (const Scene& s) {
    std::vector<Row> r;
    for (std::size_t i = 0; i < s.cloud.size (); ++i)
      r.emplace_back (s.cloud[i].x, s.cloud[i].y, s.cloud[i].z, s.labels[i]);
    std::sort (r.begin (), r.end ());
    return r;
  };
  EXPECT_EQ (rows (ordered), rows (shuffled));
}

TEST (SyntheticScenes, CurvedSurfacesInRoomAndIndustrial)
{
  for (const char* name : {"room", "industrial"})
  {
    SceneOptions o;
    o.num_points = 50000;
    const Scene scene = makeScene (name, o);
    const std::size_t curved = countKind (scene, SurfaceKind::Curved);
    EXPECT_GT (curved, scene.cloud.size () / 100) << name;
    for (std::size_t i = 0; i < scene.cloud.size (); ++i)
    {
      if (scene.kinds[i] == SurfaceKind::Curved)
      {
        ASSERT_EQ (scene.labels[i], 0u) << name;
      }
    }
  }
}

TEST (SyntheticScenes, FacadeOutlierShare)
{
  const Scene scene = makeScene ("facade");
  const double share = static_cast<double> (countKind (scene, SurfaceKind::Outlier)) /
                       static_cast<double> (scene.cloud.size ());
  EXPECT_NEAR (share, 0.15, 0.001);
  EXPECT_EQ (countKind (scene, SurfaceKind::Curved), 0u);
  for (std::size_t i = 0; i < scene.cloud.size (); ++i)
  {
    if (scene.kinds[i] == SurfaceKind::Outlier)
    {
      ASSERT_EQ (scene.labels[i], 0u);
    }
  }

  // The ratio can be changed, including to none.
  SceneOptions o;
  o.num_points = 10000;
  o.outlier_ratio = 0.0;
  EXPECT_EQ (countKind (makeScene ("facade", o), SurfaceKind::Outlier), 0u);
  o.outlier_ratio = 0.3;
  EXPECT_EQ (countKind (makeScene ("facade", o), SurfaceKind::Outlier), 3000u);
}

TEST (SyntheticScenes, RoomIsASingleScan)
{
  SceneOptions o;
  o.num_points = 50000;
  const Scene scene = makeScene ("room", o);
  const Eigen::Vector3f sensor = scene.cloud.sensor_origin_.head<3> ();
  EXPECT_TRUE (sensor.isApprox (Eigen::Vector3f (1.5f, 1.5f, 1.6f)));

  std::size_t near = 0, far = 0, behind_cabinet = 0;
  for (std::size_t i = 0; i < scene.cloud.size (); ++i)
  {
    const Eigen::Vector3f p = scene.cloud[i].getVector3fMap ();
    // Everything lies inside the room, up to noise.
    ASSERT_TRUE ((p.array () > -0.05f).all () && p.x () < 6.05f && p.y () < 5.05f &&
                 p.z () < 3.05f) << i;
    // Floor density near the sensor versus in the far corner (same 1 x 1 m area).
    if (std::abs (p.z ()) < 0.03f)
    {
      if (p.x () > 1.0f && p.x () < 2.0f && p.y () > 1.0f && p.y () < 2.0f)
        ++near;
      if (p.x () > 4.0f && p.x () < 5.0f && p.y () > 3.5f && p.y () < 4.5f)
        ++far;
    }
    // The wall y = 0 behind the cabinet (x 3.0 - 3.8, height 1.0) is occluded.
    if (p.y () < 0.03f && p.x () > 3.05f && p.x () < 3.75f && p.z () < 0.95f)
      ++behind_cabinet;
  }
  EXPECT_GT (near, 5 * far);
  EXPECT_EQ (behind_cabinet, 0u);
}

TEST (SyntheticScenes, RoomScanGridCastsItsRaysOnEqualAngleSteps)
{
  // A scanner's grid: every ray's elevation and azimuth lie on steps of one size (rows of
  // elevation over pi, columns of azimuth over 2 pi), about as many rays as the grid holds; the
  // same scene and truth bookkeeping as the random rays. Noise-free, so a sample's direction from
  // the sensor is its ray's.
  SceneOptions o;
  o.num_points = 20000;
  o.noise = 0.0;
  o.scan_grid = true;
  const Scene scene = makeScene ("room", o);
  checkConsistent (scene, 20000);
  EXPECT_GE (scene.num_planes, 10);
  const Eigen::Vector3d sensor = scene.cloud.sensor_origin_.head<3> ().cast<double> ();
  std::vector<double> elevation, azimuth;
  for (const auto& p : scene.cloud)
  {
    const Eigen::Vector3d d = (p.getVector3fMap ().cast<double> () - sensor).normalized ();
    elevation.push_back (std::asin (d.z ()));
    azimuth.push_back (std::atan2 (d.y (), d.x ()) < 0.0 ? std::atan2 (d.y (), d.x ()) + 2.0 * M_PI : std::atan2 (d.y (), d.x ()));
  }
  // The distinct values (to 1e-4 rad, far below a step of 0.03 rad) are the grid's rows and columns.
  const auto distinct = [] (std::vector<double> v) {
    std::sort (v.begin (), v.end ());
    std::vector<double> out;
    for (const double x : v)
      if (out.empty () || x - out.back () > 1e-4)
        out.push_back (x);
    return out;
  };
  const std::vector<double> rows = distinct (elevation), columns = distinct (azimuth);
  ASSERT_GE (rows.size (), 20u);
  ASSERT_GE (columns.size (), 20u);
  const double row_step = M_PI / static_cast<double> (rows.size ());
  const double column_step = 2.0 * M_PI / static_cast<double> (columns.size ());
  EXPECT_NEAR (row_step, column_step, 0.02 * row_step);
  for (std::size_t r = 0; r < rows.size (); ++r)
    EXPECT_NEAR (rows[r], -0.5 * M_PI + (static_cast<double> (r) + 0.5) * row_step, 1e-4) << r;
  for (std::size_t c = 0; c < columns.size (); ++c)
    EXPECT_NEAR (columns[c], (static_cast<double> (c) + 0.5) * column_step, 1e-4) << c;
  EXPECT_LE (scene.cloud.size (), rows.size () * columns.size ());
  EXPECT_GT (scene.cloud.size (), rows.size () * (columns.size () - 1));

  // Only the scanned room has rays to lay on a grid.
  EXPECT_THROW (makeScene ("cube", o), std::invalid_argument);
}

TEST (SyntheticScenes, SmallRoomDropsSparsePlanesConsistently)
{
  // With few rays some small planes fall under the threshold; labels must stay consecutive.
  SceneOptions o;
  o.num_points = 3000;
  const Scene scene = makeScene ("room", o);
  checkConsistent (scene, 3000);
  EXPECT_GE (scene.num_planes, 6);
  EXPECT_LE (scene.num_planes, 12);
}

TEST (SyntheticScenes, LayoutsVaryTheCounts)
{
  // Staircases of 8-20 steps (two planes each) and facades of at least 2 x 2 windows (plus the
  // wall): over a few layouts the counts differ and stay in range.
  SceneOptions o;
  o.num_points = 20000;
  std::vector<int> stairs, facades;
  for (std::uint32_t layout = 1; layout <= 6; ++layout)
  {
    o.layout = layout;
    stairs.push_back (makeScene ("staircase", o).num_planes);
    facades.push_back (makeScene ("facade", o).num_planes);
  }
  for (int n : stairs)
  {
    EXPECT_EQ (n % 2, 0);
    EXPECT_GE (n, 16);
    EXPECT_LE (n, 40);
  }
  for (int n : facades)
    EXPECT_GE (n, 5);
  EXPECT_NE (*std::min_element (stairs.begin (), stairs.end ()), *std::max_element (stairs.begin (), stairs.end ()));
  EXPECT_NE (*std::min_element (facades.begin (), facades.end ()), *std::max_element (facades.begin (), facades.end ()));
}

TEST (SyntheticScenes, LayoutBoxHasItsFacesAtItsHalfEdges)
{
  // The cube's layouts are boxes centred on the origin: every face sample lies within its noise of
  // the face's plane, and the three half edges differ.
  SceneOptions o;
  o.num_points = 6000;
  o.noise = 0.0;
  o.layout = 5;
  const Scene box = makeScene ("cube", o);
  ASSERT_EQ (box.num_planes, 6);
  std::array<float, 3> half {0.0f, 0.0f, 0.0f};
  for (const auto& p : box.cloud)
    for (int d = 0; d < 3; ++d)
      half[d] = std::max (half[d], std::abs (p.getVector3fMap ()[d]));
  for (std::size_t i = 0; i < box.cloud.size (); ++i)
  {
    const int axis = static_cast<int> ((box.labels[i] - 1) / 2);
    EXPECT_NEAR (std::abs (box.cloud[i].getVector3fMap ()[axis]), half[axis], 1e-5f) << i;
  }
  EXPECT_NE (half[0], half[1]);
  EXPECT_NE (half[1], half[2]);
}
