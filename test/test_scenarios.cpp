/*
 * Scenario tests: generated scenes with per-point truth, scored by the paper's voxel metric
 * (Sec. 4.2), and the ../shared benchmark clouds where present. Floors are set a little below what
 * the faithful method measures (see README); a regression in any phase shows up here.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/plane_evaluation.h>
#include <pcl_rspd/robust_plane_segmentation.h>
#include <pcl_rspd/synthetic_scenes.h>

#include <pcl/io/pcd_io.h>

#include <pcl/features/normal_3d.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <sys/stat.h>

namespace
{
struct Detection
{
  pcl::rspd::EvaluationResult score;
  double curved_claimed = 0.0; ///< share of Curved samples labelled as a plane
  std::vector<std::uint32_t> labels;
  pcl::rspd::DetectorStatistics stats;
};

/** While one lives, every detection runs without the position planes (setPositionPlanes(false)).
  * Position planes seed many of the small faces that other departures are there for, from what those
  * leave; a test measuring one of those turns them off, or it would measure two at once (as
  * firstGridOnly does for the shifted grid and the narrowed normals). */
bool g_position_planes_off = false;
struct PositionPlanesOff
{
  PositionPlanesOff () { g_position_planes_off = true; }
  ~PositionPlanesOff () { g_position_planes_off = false; }
  PositionPlanesOff (const PositionPlanesOff&) = delete;
  PositionPlanesOff&
  operator= (const PositionPlanesOff&) = delete;
};

Detection
detect (const pcl::PointCloud<pcl::PointXYZ>& cloud, const std::vector<std::uint32_t>& truth,
        const std::vector<pcl::rspd::SurfaceKind>* kinds = nullptr, bool small_plane_seeding = true,
        pcl::rspd::NormalScale normal_scale = pcl::rspd::NormalScale::Automatic,
        const std::function<void (pcl::RobustPlaneSegmentation<pcl::PointXYZ>&)>& configure = {})
{
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setSmallPlaneSeeding (small_plane_seeding);
  seg.setNormalScale (normal_scale);
  if (g_position_planes_off)
    seg.setPositionPlanes (false);
  if (configure)
    configure (seg);
  seg.setInputCloud (std::make_shared<pcl::PointCloud<pcl::PointXYZ>> (cloud));
  pcl::PointCloud<pcl::Label> labels;
  seg.getLabels (labels);
  Detection run;
  for (const auto& l : labels)
    run.labels.push_back (l.label);
  run.stats = seg.getStatistics ();
  run.score = pcl::rspd::evaluatePlaneDetection (cloud, truth, run.labels);
  if (kinds)
  {
    std::size_t curved = 0, claimed = 0;
    for (std::size_t i = 0; i < kinds->size (); ++i)
      if ((*kinds)[i] == pcl::rspd::SurfaceKind::Curved)
      {
        ++curved;
        claimed += run.labels[i] != 0;
      }
    run.curved_claimed = curved ? static_cast<double> (claimed) / curved : 0.0;
  }
  std::printf ("    F1 %.3f  P %.3f  R %.3f  found %d/%d  detected %d  fragments %d  false %d  curved claimed %.1f %%\n",
               run.score.f1, run.score.precision, run.score.recall, run.score.found, run.score.planes,
               run.score.detected, run.score.fragments, run.score.false_planes, 100.0 * run.curved_claimed);
  return run;
}

Detection
detectScene (const std::string& name, const pcl::rspd::SceneOptions& options = {}, bool small_plane_seeding = true,
             pcl::rspd::NormalScale normal_scale = pcl::rspd::NormalScale::Automatic,
             const std::function<void (pcl::RobustPlaneSegmentation<pcl::PointXYZ>&)>& configure = {})
{
  const pcl::rspd::Scene scene = pcl::rspd::makeScene (name, options);
  const char* scale = normal_scale == pcl::rspd::NormalScale::Automatic
      ? "" : (normal_scale == pcl::rspd::NormalScale::Adaptive ? ", adaptive normal scale" : ", fixed (paper's) normal scale");
  std::printf ("    %s: %zu points, %d planes%s\n", name.c_str (), scene.cloud.size (), scene.num_planes, scale);
  return detect (scene.cloud, scene.labels, &scene.kinds, small_plane_seeding, normal_scale, configure);
}

/** PCL's PCA normals over k = 50 neighbours, as rspd_compare shares them with every method. */
pcl::PointCloud<pcl::Normal>::Ptr
pclNormals (const pcl::PointCloud<pcl::PointXYZ>& cloud)
{
  auto normals = std::make_shared<pcl::PointCloud<pcl::Normal>> ();
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud (std::make_shared<pcl::PointCloud<pcl::PointXYZ>> (cloud));
  estimation.setKSearch (50);
  estimation.compute (*normals);
  return normals;
}

using Configure = std::function<void (pcl::RobustPlaneSegmentation<pcl::PointXYZ>&)>;

/** The small-plane pass on its first grid alone, without the shifted grid and the narrowed normals of
  * what growth left (setShiftedGrid, setLeftNormalNarrowing): both seed small planes that other
  * mechanisms seed too, so a test of one of those turns them off, or it would measure two at once. */
void
firstGridOnly (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s)
{
  s.setShiftedGrid (false);
  s.setLeftNormalNarrowing (false);
}

/** The position planes without their surface parts (setPositionSurfaceParts): what the parts left
  * at a plane turned down still hold on a surface is searched again for rough faces, which finds
  * the faces of several earlier mechanisms' tests too; those turn it off, or they would measure two
  * at once. */
void
surfacePartsOff (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s)
{
  s.setPositionSurfaceParts (false);
}

/** A scene's detection on PCL's k = 50 normals (pclNormals, computed once by the caller), with its
  * curved samples scored, configured further by \a configure. */
Detection
detectOnPclNormals (const pcl::rspd::Scene& scene, const pcl::PointCloud<pcl::Normal>::Ptr& normals,
                    const Configure& configure = {})
{
  return detect (scene.cloud, scene.labels, &scene.kinds, true, pcl::rspd::NormalScale::Automatic,
                 [&] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                   s.setInputNormals (normals);
                   if (configure)
                     configure (s);
                 });
}

/** detectOnPclNormals with the caller's normals kept (setGivenNormalCheck(false)): below 100,000
  * samples the check estimates PCL's k = 50 normals again (they are of the graph's scale, coarser
  * than the automatic k), and a test of a rule for normals given at that scale would measure none. */
Detection
detectOnKeptPclNormals (const pcl::rspd::Scene& scene, const pcl::PointCloud<pcl::Normal>::Ptr& normals,
                        const Configure& configure = {})
{
  return detectOnPclNormals (scene, normals, [&] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setGivenNormalCheck (false);
    if (configure)
      configure (s);
  });
}

/** The unit plane at σ 1 cm, 100,000 points, among \a outliers (a share of the points) in its box
  * grown by 5 % of its diagonal: a slab of outliers 14 cm thick. */
pcl::rspd::SceneOptions
planeInSlab (double outliers, std::uint32_t seed = pcl::rspd::SceneOptions ().seed)
{
  pcl::rspd::SceneOptions o;
  o.num_points = 100000;
  o.noise = 0.01;
  o.outlier_ratio = outliers;
  o.seed = seed;
  return o;
}

bool
loadShared (const std::string& name, pcl::PointCloud<pcl::PointXYZ>& cloud, std::vector<std::uint32_t>& truth)
{
  const std::string base = std::string (PCL_RSPD_SHARED_DATA_DIR) + "/" + name;
  struct stat st;
  if (stat ((base + ".pcd").c_str (), &st) != 0 || stat ((base + ".gt").c_str (), &st) != 0)
    return false;
  if (pcl::io::loadPCDFile (base + ".pcd", cloud) != 0)
    return false;
  truth.resize (cloud.size ());
  std::ifstream in (base + ".gt", std::ios::binary);
  in.read (reinterpret_cast<char*> (truth.data ()), static_cast<std::streamsize> (truth.size () * 4));
  return static_cast<std::size_t> (in.gcount ()) == truth.size () * 4;
}
} // namespace

TEST (Scenario, NoisyCubeEveryFaceFound)
{
  // 1 m cube, σ = 1 % of the edge.
  const Detection r = detectScene ("cube");
  EXPECT_EQ (r.score.found, 6);
  EXPECT_EQ (r.score.false_planes, 0);
  EXPECT_GE (r.score.f1, 0.93);
}

TEST (Scenario, CubeWithNoiseAsWideAsTheNeighbourhoodNeedsTheAdaptiveNormalScale)
{
  // Issue 6 at a fifth of the cost: 200,000 samples on a unit cube with σ = 2 % of the edge put
  // the 50-neighbourhood's radius (~2.2 cm) at about σ, as a million samples at 1 % do (~1 cm).
  // The k-scale normals are then noise (the smallest-variance direction can lie in the face) and
  // no face is found; normals at the finest scale that resolves the face find all six.
  pcl::rspd::SceneOptions options;
  options.num_points = 200000;
  options.noise = 0.02;
  const Detection fixed = detectScene ("cube", options, true, pcl::rspd::NormalScale::Fixed);
  EXPECT_LT (fixed.score.found, 6);
  // 77 % of the samples are unresolved at the k-scale, so Automatic widens exactly as Adaptive.
  for (const auto scale : {pcl::rspd::NormalScale::Adaptive, pcl::rspd::NormalScale::Automatic})
  {
    const Detection widened = detectScene ("cube", options, true, scale);
    EXPECT_EQ (widened.score.found, 6);
    EXPECT_EQ (widened.score.false_planes, 0);
    EXPECT_EQ (widened.score.fragments, 0);
    EXPECT_GE (widened.score.f1, 0.90);
  }
}

TEST (Scenario, AutomaticNormalScaleLeavesScenesTheKScaleResolvesUntouched)
{
  // The facade's 15 % uniform outliers are unresolved at the k-scale, and Adaptive gives some of
  // them a wide-scale surface normal (README: F1 -0.003); most samples are resolved, so Automatic
  // keeps every k-scale normal, and the labels are those of Fixed.
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("facade");
  const Detection fixed = detect (scene.cloud, scene.labels, &scene.kinds, true, pcl::rspd::NormalScale::Fixed);
  const Detection automatic = detect (scene.cloud, scene.labels, &scene.kinds);
  EXPECT_EQ (automatic.labels, fixed.labels);
}

TEST (Scenario, NoiseFreePlaneIsOnePlaneHoldingEveryPoint)
{
  const Detection r = detectScene ("plane");
  EXPECT_EQ (r.score.detected, 1);
  std::size_t labelled = 0;
  for (const auto l : r.labels)
    labelled += l == 1;
  EXPECT_GE (labelled, r.labels.size () * 99 / 100);
}

TEST (Scenario, StaircaseOfSmallParallelPlanesEveryPlaneFound)
{
  // 15 treads and 15 risers (0.18 m high), σ = 2 mm.
  const Detection r = detectScene ("staircase");
  EXPECT_EQ (r.score.found, 30);
  EXPECT_EQ (r.score.false_planes, 0);
  // One tread stays in two parts: the coplanar-group check (M4) turns down a patch whose leading
  // plane's MDP underestimates the noise (2.1 mm for sigma = 2 mm). Recorded, not hidden.
  EXPECT_LE (r.score.fragments, 1);
  EXPECT_GE (r.score.f1, 0.991); // issue 6's target for the staircase (0.9918 measured)
}

TEST (Scenario, StaircaseEdgeSamplesKeepToTheirSide)
{
  // Within noise of a step's nose, growth gives a riser sample pushed out of the step to the tread
  // (or the reverse), which puts the tread in voxels it never enters. The edge-side rule moves
  // them: F1 0.978 -> 0.989, precision 0.980 -> 0.997 measured (0.983 -> 0.993 and 0.981 -> 0.997
  // since the final refit).
  const auto off = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setEdgeSides (false); };
  const Detection without = detectScene ("staircase", {}, true, pcl::rspd::NormalScale::Automatic, off);
  const Detection with = detectScene ("staircase");
  EXPECT_LT (without.score.f1, with.score.f1 - 0.005);
  EXPECT_LT (without.score.precision, 0.985);
  EXPECT_GE (with.score.f1, 0.986);
  EXPECT_GE (with.score.precision, 0.995);
  EXPECT_EQ (with.score.found, 30);
}

TEST (Scenario, WindowsRecessedWithinTheFacadesNoiseTakeTheirSamplesBack)
{
  // The facade at sigma = 5 cm: the windows lie 20 cm behind the wall, 4 sigma, so the two noise
  // bands (3 sigma each) overlap, and the wall, grown first, kept up to 30 % of some windows'
  // samples, scattered over them, and gave others its samples along their rims. Measured: F1 0.909,
  // 14 of 16 planes, 2 false planes without the step-side rule; 0.982 and 16 with it (0.932, 15
  // planes, 1 false, against 0.988 and 16 since the surrounding-clutter tail; 0.965 and 16 against
  // 0.997 since the connected parts' core members, fifty-fourth session).
  pcl::rspd::SceneOptions o;
  o.noise = 0.05;
  const auto off = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setStepSides (false); };
  const Detection without = detectScene ("facade", o, true, pcl::rspd::NormalScale::Automatic, off);
  const Detection with = detectScene ("facade", o);
  EXPECT_LT (without.score.f1, with.score.f1 - 0.02);
  EXPECT_LT (without.score.precision, 0.95);
  EXPECT_GE (with.score.f1, 0.99);
  EXPECT_EQ (with.score.found, 16);
  EXPECT_EQ (with.score.false_planes, 0);
}

namespace
{
/** The facade of draw_rows.py 57 (layout 938, 69,000 points, σ 4 cm isotropic, 15 % outliers):
  * ten windows recessed 10 cm, 2.5σ, within the wall's 3σ band. */
pcl::rspd::Scene
deepWindowsInNoise ()
{
  pcl::rspd::SceneOptions o;
  o.layout = 938;
  o.num_points = 69000;
  o.noise = 0.04;
  o.seed = 589;
  o.isotropic_noise = true;
  return pcl::rspd::makeScene ("facade", o);
}

/** Window samples (truth labels above the wall's, 1) that the plane holding most of the wall holds. */
std::size_t
windowSamplesInTheWall (const pcl::rspd::Scene& scene, const std::vector<std::uint32_t>& labels)
{
  std::map<std::uint32_t, std::size_t> wall;
  for (std::size_t i = 0; i < labels.size (); ++i)
    if (scene.labels[i] == 1 && labels[i] != 0)
      ++wall[labels[i]];
  const auto most = std::max_element (wall.begin (), wall.end (), [] (const auto& a, const auto& b) { return a.second < b.second; });
  std::size_t count = 0;
  for (std::size_t i = 0; i < labels.size (); ++i)
    count += scene.labels[i] > 1 && labels[i] == most->first;
  return count;
}
} // namespace

TEST (Scenario, WindowsRecessedWithinTheWallsBandAreEachSplitOffAtTheirStep)
{
  // A facade of a fresh random set (draw_rows.py 57, layout 938, 69,000 points, σ 4 cm isotropic,
  // 15 % outliers), windows recessed about 10 cm, 2.5 σ: moved 1 km, its cells seed fewer windows,
  // growth and the merges give the others to the wall, and the step split cut one region off each
  // plane per call: 8 of 10 planes, F1 0.871 (the steps are no layers' rule, which keeps a window
  // the layer merge would join to its wall, has none to keep). Called until none splits, each
  // window comes off the wall at its step: 10 of 10, 0.937.
  const pcl::rspd::Scene scene = deepWindowsInNoise ();
  pcl::PointCloud<pcl::PointXYZ> far = scene.cloud;
  pcl::rspd::SceneOptions move;
  move.offset = Eigen::Vector3d (1000.0, 0.0, 0.0);
  pcl::rspd::transformCloud (far, move);
  const Detection moved = detect (far, scene.labels);
  // Scored on the cloud as generated (the voxel grid of the original, as scripts/scores.sh).
  const pcl::rspd::EvaluationResult score = pcl::rspd::evaluatePlaneDetection (scene.cloud, scene.labels, moved.labels);
  EXPECT_EQ (score.found, 10);
  EXPECT_EQ (score.false_planes, 0);
  EXPECT_GE (moved.stats.steps_split, 3u);
  EXPECT_GT (score.f1, 0.92);
}

TEST (Scenario, DeepStepsInNoiseAreJudgedWhereTheyAreHalfMade)
{
  // Turned (rspd_make_scene --rotate --seed 2), two windows lay wholly in the wall's band. The step
  // split found their regions, but read across the regions' own border, where the neighbourhood
  // means first depart by half a σ, the jump was 0.61-0.66 of the offset (the wall's samples on
  // that border): 8 of 10 planes, F1 0.911. Read again where the step is half made, 0.81-0.88: 10
  // of 10.
  const pcl::rspd::Scene scene = deepWindowsInNoise ();
  pcl::PointCloud<pcl::PointXYZ> turned = scene.cloud;
  pcl::rspd::SceneOptions turn;
  turn.random_rotation = true;
  turn.seed = 2;
  pcl::rspd::transformCloud (turned, turn);
  const Detection d = detect (turned, scene.labels);
  const pcl::rspd::EvaluationResult score = pcl::rspd::evaluatePlaneDetection (scene.cloud, scene.labels, d.labels);
  EXPECT_EQ (score.found, 10);
  EXPECT_EQ (score.false_planes, 0);
  EXPECT_GT (score.f1, 0.95);
}

TEST (Scenario, BlocksOfWindowsThatTheWallHoldsGoToTheirWindows)
{
  // As generated, the wall's growth took blocks of its windows within its band (up to 819 of a
  // window's 1,389 samples); distance cannot give them back (the step sides' per-sample rule acts
  // only on steps deeper than the bands), the regions' medians can.
  const pcl::rspd::Scene scene = deepWindowsInNoise ();
  const auto off = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    EXPECT_TRUE (s.getStepRegions ());
    s.setStepRegions (false);
  };
  const Detection without = detect (scene.cloud, scene.labels, nullptr, true, pcl::rspd::NormalScale::Automatic, off);
  const Detection with = detect (scene.cloud, scene.labels);
  const std::size_t held_without = windowSamplesInTheWall (scene, without.labels);
  const std::size_t held_with = windowSamplesInTheWall (scene, with.labels);
  EXPECT_EQ (with.score.found, 10);
  EXPECT_GT (with.stats.step_region_moved, 0u);
  EXPECT_LT (held_with * 10, held_without * 7) << held_with << " of " << held_without;
  EXPECT_GT (with.score.f1, without.score.f1 + 0.008);
}

TEST (Scenario, DeepWindowsInNoiseGiveTheSamePlanesScaledMovedOrTurned)
{
  // The issue's invariance bar on that facade: its frame's second axis is the mode of stray
  // normals, which moves with rounding, and how much of each window the wall's band takes depends on
  // the cells. With the step regions alone, the copies ranged over 0.934-0.962 (the windows' rims:
  // the wall's tail samples beyond a window's edge in the window, 122-155 per window scaled ×1000);
  // with the step sides' majority within the bands too (twice as many neighbours in the other
  // plane), 0.970-0.976 over these four.
  const pcl::rspd::Scene scene = deepWindowsInNoise ();
  std::vector<double> f1;
  for (int copy = 0; copy < 4; ++copy)
  {
    pcl::PointCloud<pcl::PointXYZ> moved = scene.cloud;
    pcl::rspd::SceneOptions move;
    if (copy == 1)
      move.scale = 1000.0;
    else if (copy == 2)
      move.offset = Eigen::Vector3d (1000.0, 0.0, 0.0);
    else if (copy == 3)
    {
      move.random_rotation = true;
      move.seed = 2;
    }
    pcl::rspd::transformCloud (moved, move);
    const Detection d = detect (moved, scene.labels);
    const pcl::rspd::EvaluationResult score = pcl::rspd::evaluatePlaneDetection (scene.cloud, scene.labels, d.labels);
    EXPECT_EQ (score.found, 10) << copy;
    f1.push_back (score.f1);
  }
  const auto [lowest, highest] = std::minmax_element (f1.begin (), f1.end ());
  EXPECT_LT (*highest - *lowest, 0.01) << *lowest << " to " << *highest;
  EXPECT_GT (*lowest, 0.96);
}

TEST (Scenario, CubeTooNoisyForAnyCellIsSeededByGroupsOfThickCells)
{
  // The cube at σ = 3 % of its edge (the issue's is 1 %): every cell that holds one face alone is
  // too thin for T1, every cell wide enough holds three faces. Measured: no plane at all without the
  // thick-cell join (the PCL SAC loop finds 6, F1 0.875); 6 of 6, F1 0.948 with it.
  pcl::rspd::SceneOptions o;
  o.noise = 0.03;
  const auto off = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setThickCellJoin (false); };
  const Detection without = detectScene ("cube", o, true, pcl::rspd::NormalScale::Automatic, off);
  const Detection with = detectScene ("cube", o);
  EXPECT_EQ (without.score.found, 0);
  EXPECT_EQ (with.score.found, 6);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_GE (with.score.f1, 0.93);
}

TEST (Scenario, NoisyStaircaseRisersAreSeededByGroupsOfThickCells)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // The staircase at σ = 1 cm (5 times its default): a riser is 18 cm tall, and no cell that holds
  // one alone is wide enough for T1; 9 risers got no seed. Groups of thick cells seed them; a riser
  // is as narrow as a strip of cells along an edge, which only the edge's bend tells apart.
  // Measured: 21 of 30, F1 0.829 without the join; 27, 0.931 with it. The groups of noisy small
  // seeds (the nineteenth session) seed the last risers, and without the join seed them all alone:
  // both off, as before either, and the first grid alone (23 of 30 with the shifted grid).
  pcl::rspd::SceneOptions o;
  o.noise = 0.01;
  const auto off = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setThickCellJoin (false);
    s.setNoisySeedGroups (false);
    firstGridOnly (s);
  };
  const Detection without = detectScene ("staircase", o, true, pcl::rspd::NormalScale::Automatic, off);
  const Detection with = detectScene ("staircase", o);
  EXPECT_LE (without.score.found, 22);
  EXPECT_EQ (with.score.found, 30);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_GE (with.score.f1, 0.97);
}

TEST (Scenario, StaircaseWithThePapersSingleSplitMissesRisers)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // Algorithm 1 alone seeds a riser only where an ε-sample cell holds it without tread: every such
  // cell is ~35 % tread, so 8 risers are never seeded. The small-plane pass is what finds them.
  const Detection paper = detectScene ("staircase", {}, false);
  EXPECT_LT (paper.score.found, 30);
  EXPECT_GE (paper.score.found, 20);
  EXPECT_EQ (paper.score.false_planes, 0);
}

TEST (Scenario, SparseStaircaseRunsTheSmallPlanePassAtEpsilon)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // 10,000 samples: ε = 10, the paper's least, and the small-plane pass's cells cannot be smaller.
  // Split again at ε, the samples growth left (the treads taken) hold risers alone: 26 of 30 planes
  // found when the pass ran only below ε (those risers were never seeded), 29 since (measured).
  pcl::rspd::SceneOptions o;
  o.num_points = 10000;
  const Detection paper = detectScene ("staircase", o, false);
  const Detection seeded = detectScene ("staircase", o);
  EXPECT_LE (paper.score.found, 26);
  EXPECT_GE (seeded.score.found, 29);
  EXPECT_GT (seeded.score.f1, paper.score.f1 + 0.03);
  EXPECT_EQ (seeded.score.false_planes, 0);
}

TEST (Scenario, RoomWithFurnitureDoorAndCurvedClutter)
{
  // One viewpoint, density falling with distance; a door 2 cm proud of a wall; a pillar and a ball.
  const Detection r = detectScene ("room");
  EXPECT_EQ (r.score.found, 12);
  EXPECT_EQ (r.score.false_planes, 0);
  EXPECT_GE (r.score.f1, 0.995); // issue 6's target for the room (0.996 measured)
  EXPECT_LE (r.curved_claimed, 0.02); // issue 6: under 2 % of a curved surface claimed
}

TEST (Scenario, RoomsTablePanelNeedsTheRimRetest)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // The table's front panel (0.7 m tall, under the top, over the floor): every small-plane cell of
  // k + 1 samples holds a band of rim normals bent towards the top or the floor, so T3 fails; its
  // inliers, tested again, seed it. Without, on the first grid alone: 11 of 12. A second split on
  // the left samples' trimmed normals (setLeftNormalRefit, off by default), which bend at no rim,
  // seeds it as well, and so do the shifted grid with the narrowed normals (the defaults).
  const auto off = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setRimCellRetest (false);
    firstGridOnly (s);
  };
  const Detection r = detectScene ("room", {}, true, pcl::rspd::NormalScale::Automatic, off);
  EXPECT_EQ (r.score.found, 11);
  const Detection shifted = detectScene ("room", {}, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setRimCellRetest (false); });
  EXPECT_EQ (shifted.score.found, 12);
  const auto retest_off = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setRimCellRetest (false);
    s.setShiftedGrid (false);
    s.setLeftNormalRefit (true);
  };
  const Detection trimmed = detectScene ("room", {}, true, pcl::rspd::NormalScale::Automatic, retest_off);
  EXPECT_EQ (trimmed.score.found, 12);
  EXPECT_GT (trimmed.stats.small_seeds_trimmed, 0u);
}

namespace
{
/** The boxes at 100,000 points with 5 % outliers, seed 23: a row first seen in issue #6's
  * twenty-third session, where one retest and the positions alone each missed a side. */
pcl::rspd::SceneOptions
boxesWithOutliersSeed23 ()
{
  pcl::rspd::SceneOptions o;
  o.num_points = 100000;
  o.outlier_ratio = 0.05;
  o.seed = 23;
  return o;
}
} // namespace

TEST (Scenario, RimCellsAreRetestedUntilStable)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // The boxes at 100,000 points with 5 % outliers (seed 23, ε = 100): a clean box side (521
  // samples, σ 2 mm) shares its small-plane cell with a quarter of floor samples; the cell's
  // inliers, the side with its rim, fail T3 again on the side's own estimate (28 % outliers: the
  // rim's normals bend at the box's edges), and no other cell seeds the side (measured: 31 of 32
  // with one retest, F1 0.9909; 32, 0.9944, until stable). On the first grid alone: the shifted
  // grid holds the side without its floor (32 either way).
  const pcl::rspd::SceneOptions o = boxesWithOutliersSeed23 ();
  const Detection stable = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic, firstGridOnly);
  const Detection once = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic,
                                      [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                        firstGridOnly (s);
                                        EXPECT_TRUE (s.getRimRetestUntilStable ());
                                        s.setRimRetestUntilStable (false);
                                        EXPECT_FALSE (s.getRimRetestUntilStable ());
                                      });
  EXPECT_EQ (stable.score.found, 32);
  EXPECT_GE (stable.score.found, once.score.found + 1);
  EXPECT_GT (stable.score.f1, once.score.f1);
  EXPECT_EQ (stable.score.false_planes, 0);
}

TEST (Scenario, RoughBoxSidesSeedWhereOnlyTheirPositionsBend)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // The boxes at 100,000 points with 5 % outliers (seed 23) on PCL's k = 50 normals: the roughest
  // box's side (781 samples, σ 3 cm) has one small-plane seed of 76 samples that joins no other;
  // cut 60 / 16 its sides' planes are 47° apart by chance while its normals turn 3.9°. Judged on
  // positions alone it was bent at an edge and seeded nothing (measured: 31 of 32, F1 0.9849;
  // 32, 0.9942, with the normals' turn).
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("boxes", boxesWithOutliersSeed23 ());
  const auto normals = pclNormals (scene.cloud);
  const Detection turn = detectOnPclNormals (scene, normals);
  const Detection positions = detectOnPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    EXPECT_TRUE (s.getHingeNormalTurn ());
    s.setHingeNormalTurn (false);
    EXPECT_FALSE (s.getHingeNormalTurn ());
  });
  EXPECT_EQ (turn.score.found, 32);
  EXPECT_GE (turn.score.found, positions.score.found + 1);
  EXPECT_GT (turn.score.f1, positions.score.f1);
  EXPECT_EQ (turn.score.false_planes, 0);
}

TEST (Scenario, RoomsDoorNeedsTheFarMemberRelease)
{
  // The door stands 2 cm proud of its wall (about 4 σ of the wall's noise). The wall's growth takes
  // part of the door under an early estimate and never gives it back; released as far from the
  // wall's final plane, the door's own growth takes it (F1 0.992 -> 0.996 measured; 0.9944 -> 0.9981
  // since the last assignment takes samples inside a plane's band whatever their normal).
  const auto off = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setFarMemberRelease (false); };
  const Detection r = detectScene ("room", {}, true, pcl::rspd::NormalScale::Automatic, off);
  const Detection with = detectScene ("room");
  EXPECT_EQ (r.score.found, 12);
  EXPECT_GT (with.score.f1, r.score.f1 + 0.0025);
}

TEST (Scenario, UnseededDoorIsSeededByItsReleasedSamples)
{
  // With seed 2 no cell seeds the door: the wall grows over it, and the far-member release frees
  // 979 of its samples, which no plane's inlier test admits. Tested as a plane (T1-T3; T3 on their
  // inliers) they become the door; otherwise they go back to the wall (11 of 12 found, F1 0.983
  // measured, 0.995 with the released planes). Since the step split reads its jump where the step
  // is half made (the door is 4σ proud here), it splits the door off the wall too (0.997): the wall
  // keeps the door only without both.
  pcl::rspd::SceneOptions options;
  options.seed = 2;
  const Detection r = detectScene ("room", options);
  EXPECT_EQ (r.score.found, 12);
  EXPECT_GE (r.score.f1, 0.99);
  EXPECT_EQ (r.score.false_planes, 0);
  const auto back = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setReleasedPlaneSeeding (false);
    s.setStepSplit (false);
  };
  const Detection wall = detectScene ("room", options, true, pcl::rspd::NormalScale::Automatic, back);
  EXPECT_EQ (wall.score.found, 11);
  EXPECT_LT (wall.score.f1, 0.985);
  const auto split = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setReleasedPlaneSeeding (false); };
  const Detection stepped = detectScene ("room", options, true, pcl::rspd::NormalScale::Automatic, split);
  EXPECT_EQ (stepped.score.found, 12);
  EXPECT_GE (stepped.score.f1, 0.99);
}

TEST (Scenario, TrimmedNormalsReachTheRoomsLastPlane)
{
  // With trimmed-plane normals (an option, for its time) the normals at the room's edges stop
  // bending and the table's front panel is seeded as a plain cell (PCA normals: by the rim retest).
  const auto trimmed = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setNormalFit (pcl::rspd::NormalFit::TrimmedPlane);
  };
  const Detection r = detectScene ("room", {}, true, pcl::rspd::NormalScale::Automatic, trimmed);
  EXPECT_EQ (r.score.found, 12);
  EXPECT_EQ (r.score.false_planes, 0);
  EXPECT_GE (r.score.f1, 0.99);
  EXPECT_LE (r.curved_claimed, 0.02);
}

TEST (Scenario, NoisyFacadeWithOutliersAndRecessedWindows)
{
  const Detection r = detectScene ("facade");
  EXPECT_EQ (r.score.found, 16);
  EXPECT_GE (r.score.f1, 0.97);
}

TEST (Scenario, FacadeOutliersBeyondTheRimsNeedThePlaneSupport)
{
  // 15 % outliers: those in the wall's noise band beyond its edges and inside the window openings,
  // and in a window's band behind the wall, have the plane's PCA normal and lie within its band;
  // growth and the last assignment take them, each a voxel of false plane. Measured: F1 0.986 ->
  // 0.9988, precision 0.973 -> 0.9980 (0.989 with the gap rule alone, 0.9968 without the detached
  // groups), recall unchanged. Since the last assignment takes samples inside a plane's band whatever
  // their normal, the outliers within the wall's band between its members count too: precision 0.9970.
  // Since the member gaps keep the last assignment from chaining outliers in beyond the rims,
  // precision without the plane support is 0.988 (measured).
  const auto off = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setSupportCheck (false); };
  const Detection without = detectScene ("facade", {}, true, pcl::rspd::NormalScale::Automatic, off);
  const Detection with = detectScene ("facade");
  EXPECT_LT (without.score.precision, 0.992);
  EXPECT_GE (with.score.precision, 0.9965);
  EXPECT_GE (with.score.recall, without.score.recall - 0.0005);
  EXPECT_GE (with.score.f1, 0.998);
  EXPECT_EQ (with.score.found, 16);
}

TEST (Scenario, FacadeOutliersBeyondTheRimsAreNotChainedInByTheLastAssignment)
{
  // The facade in layout 103 at σ 4.29 cm (206,000 points, seed 720, 15 % outliers): the last
  // assignment's rounds chained the wall and its windows from outlier to outlier through the clutter
  // beside their rims, 1,027 outliers more than 20 cm beyond their planes (F1 0.928, precision
  // 0.867; measured by a script outside the repository). With member gaps a sample joins a plane
  // only where it lies among its members: F1 0.988, every plane found either way, none false. The
  // plane support's clutter share (sixtieth session) releases most of such a chain afterwards too
  // (0.993 without member gaps but with it): off in "without".
  pcl::rspd::SceneOptions o;
  o.layout = 103;
  o.num_points = 206000;
  o.noise = 0.0429;
  o.seed = 720;
  const Detection with = detectScene ("facade", o);
  const Detection without = detectScene ("facade", o, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                           EXPECT_TRUE (s.getMemberGaps ());
                                           s.setMemberGaps (false);
                                           EXPECT_FALSE (s.getMemberGaps ());
                                           s.setSupportClutter (false);
                                         });
  EXPECT_EQ (with.score.found, 17);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_EQ (without.score.found, 17);
  EXPECT_GT (with.score.f1, 0.98);
  EXPECT_LT (without.score.f1, 0.95);
  EXPECT_GT (with.stats.member_gap_refused, 0u);
  EXPECT_EQ (without.stats.member_gap_refused, 0u);
}

TEST (Scenario, CoplanarWindowsAreNotJoinedThroughTheOutliersInTheirBand)
{
  // A random facade (layout 8026, σ 4.25 cm, 417,000 points, 15 % outliers): its nine windows lie in
  // one plane 22 cm behind the wall, and the outliers behind the wall in their band (a median of 17
  // of their 50 nearest neighbours in that plane, against 50 for its true members) percolate. Connected parts saw the windows as one part through
  // them: one plane held all nine (F1 0.588, 1 of 10 planes found, rspd_segment at commit d0397fc).
  // A part's core samples now have a third of their neighbours in the plane, only pieces of surface
  // are parts, and members more than a hop from every part are released: 0.924, 10 of 10.
  pcl::rspd::SceneOptions o;
  o.layout = 8026;
  o.num_points = 417000;
  o.noise = 0.0425;
  o.seed = 813;
  const Detection d = detectScene ("facade", o);
  EXPECT_EQ (d.score.found, 10);
  EXPECT_EQ (d.score.false_planes, 0);
  EXPECT_EQ (d.score.fragments, 0);
  EXPECT_GT (d.score.f1, 0.9);
}

TEST (Scenario, PlaneWrappedInASlabOfOutliersHasNoPlanesOfOutliers)
{
  // A unit plane at σ 1 cm with 20 % outliers in its box grown by 5 % of its diagonal: a slab 14 cm
  // thick. Clean seeds among the outliers grew two planes beside the true one, 5,500 samples each,
  // whose bands reach its own (F1 0.790, measured with rspd_segment --final-volume-layers off; the
  // PCL SAC loop 0.805). Judged once final, each has about 13 times its samples in the layer beside
  // its band, and is dropped.
  const pcl::rspd::SceneOptions o = planeInSlab (0.2);
  const Detection with = detectScene ("plane", o);
  const Detection without = detectScene ("plane", o, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                           EXPECT_TRUE (s.getFinalVolumeLayerCheck ());
                                           s.setFinalVolumeLayerCheck (false);
                                           EXPECT_FALSE (s.getFinalVolumeLayerCheck ());
                                         });
  EXPECT_EQ (with.score.found, 1);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_GT (with.score.f1, 0.9);
  EXPECT_EQ (with.stats.final_volume_layers, 2u);
  EXPECT_GT (without.score.false_planes, 0);
  EXPECT_LT (without.score.f1, 0.85);
  EXPECT_EQ (without.stats.final_volume_layers, 0u);
}

TEST (Scenario, PlaneInASlabOfOutliersEndsItsTailWhereTheOutliersOutnumberItsNoise)
{
  // The unit plane at σ 1 cm in a slab of 20 % outliers (seed 3): beyond about 2.5 σ the outliers
  // outnumber the plane's own samples, but the clutter shell of the tail odds, which counts only
  // samples whose neighbours are mostly the plane's, undercounted them, and the plane kept the
  // outliers growth gave it out to 3-3.5 σ: F1 0.915 (measured with
  // rspd_segment --surrounding-clutter off). With the clutter counted around the plane over its
  // footprint, the tail ends near 2.5 σ and the members beyond it leave: 0.940. (The plane
  // support's clutter share releases some of them too, 0.930 without the surrounding clutter but
  // with it: off in "without".)
  const pcl::rspd::SceneOptions o = planeInSlab (0.2, 3);
  const Detection with = detectScene ("plane", o);
  const Detection without = detectScene ("plane", o, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                           EXPECT_TRUE (s.getSurroundingClutter ());
                                           s.setSurroundingClutter (false);
                                           EXPECT_FALSE (s.getSurroundingClutter ());
                                           s.setSupportClutter (false);
                                         });
  EXPECT_EQ (with.score.found, 1);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_GT (with.score.f1, 0.935);
  EXPECT_LT (without.score.f1, 0.925);
}

TEST (Scenario, PlaneInASlabOfThirtyPercentOutliersKeepsNoLayerOfThem)
{
  // The unit plane at σ 1 cm in a slab of 30 % outliers (seed 2): a plane of 1,400 outliers near
  // the slab's bottom face, whose beside layer held 1.6 times its samples (under the final volume
  // layers' ratio of 2), was kept: 2 planes, F1 0.853 (rspd_segment --flat-layers off). The slab's
  // density runs on flat past it: with the flat layers it goes, 0.917.
  const pcl::rspd::SceneOptions o = planeInSlab (0.3, 2);
  const Detection with = detectScene ("plane", o);
  const Detection without = detectScene ("plane", o, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                           s.setFlatLayers (false);
                                         });
  EXPECT_EQ (with.score.found, 1);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_GT (with.score.f1, 0.9);
  EXPECT_EQ (without.score.false_planes, 1);
  EXPECT_LT (without.score.f1, 0.88);
}

TEST (Scenario, PlaneInASlabOfFortyPercentOutliersFarAwayKeepsNoWideLayerOverIt)
{
  // The unit plane at σ 1 cm in a slab of 40 % outliers (seed 2), moved 1 km as rspd_make_scene
  // P.pcd K --offset 1000 0 0 moves it: a plane of 17,421 outliers over the slab's upper half, its
  // band 8.1 cm, kept (2 planes, F1 0.641, measured with the in-band layers comparing counts): the
  // true plane held 3.8 times its samples inside that band, under the ratio of 4, but inside a band
  // 2.5 times thinner, 9.4 times as dense. By densities it goes (0.896).
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("plane", planeInSlab (0.4, 2));
  pcl::PointCloud<pcl::PointXYZ> far = scene.cloud;
  pcl::rspd::SceneOptions move;
  move.offset = Eigen::Vector3d (1000.0, 0.0, 0.0);
  pcl::rspd::transformCloud (far, move);
  const Detection with = detect (far, scene.labels);
  const Detection without = detect (far, scene.labels, nullptr, true, pcl::rspd::NormalScale::Automatic,
                                    [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                      s.setInBandLayerCheck (false);
                                    });
  // Scored on the cloud as generated (the voxel grid of the original, as scripts/slab_grid.sh).
  const pcl::rspd::EvaluationResult score = pcl::rspd::evaluatePlaneDetection (scene.cloud, scene.labels, with.labels);
  const pcl::rspd::EvaluationResult kept = pcl::rspd::evaluatePlaneDetection (scene.cloud, scene.labels, without.labels);
  EXPECT_EQ (score.found, 1);
  EXPECT_EQ (score.false_planes, 0);
  EXPECT_GT (score.f1, 0.88);
  EXPECT_GT (with.stats.in_band_layers, 0u);
  EXPECT_GE (kept.false_planes, 1);
  EXPECT_LT (kept.f1, 0.8);
}

TEST (Scenario, PlaneInAThinSlabOfOutliersScaledHasNoLayerOfOutliersInsideItsBand)
{
  // The unit plane in a slab of outliers (10 %, seed 2) in millimetres: which outliers seed moves
  // with the coordinates' rounding, and here two planes of them grew beside the true one, spread
  // so wide that their bands took in half of it (F1 0.834). The true plane holds more than four
  // times their samples within their bands: layers inside its band, dropped (F1 0.971, as the
  // scene in metres gives).
  pcl::rspd::SceneOptions o = planeInSlab (0.1, 2);
  o.scale = 1000.0;
  const Detection with = detectScene ("plane", o);
  const Detection without = detectScene ("plane", o, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                           EXPECT_TRUE (s.getInBandLayerCheck ());
                                           s.setInBandLayerCheck (false);
                                           EXPECT_FALSE (s.getInBandLayerCheck ());
                                         });
  EXPECT_EQ (with.score.found, 1);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_GT (with.score.f1, 0.96);
  EXPECT_GE (with.stats.in_band_layers, 1u);
  EXPECT_LE (with.stats.in_band_layers, with.stats.final_volume_layers);
  EXPECT_GT (without.score.false_planes, 0);
  EXPECT_LT (without.score.f1, 0.9);
  EXPECT_EQ (without.stats.in_band_layers, 0u);
}

TEST (Scenario, PillarFacetsShowTheirBendOnceGivenTheirTails)
{
  // The room at σ 3 cm and 50,000 points (seed 41): the 0.3 m pillar's facets grow within their
  // bands, which cut off the part of the pillar that bends away, and pass the curved check before
  // the last assignment; with their tails they bend beyond chance. Measured (bash scripts/sweep.sh,
  // rspd_segment --late-curved off): 35.2 % of the curved samples claimed and one false plane
  // without the late check, 1.5 % and none with it.
  pcl::rspd::SceneOptions o;
  o.num_points = 50000;
  o.noise = 0.03;
  o.seed = 41;
  const Detection with = detectScene ("room", o);
  const Detection without = detectScene ("room", o, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                           EXPECT_TRUE (s.getLateCurvedCheck ());
                                           s.setLateCurvedCheck (false);
                                           EXPECT_FALSE (s.getLateCurvedCheck ());
                                         });
  EXPECT_LT (with.curved_claimed, 0.02);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_GE (with.stats.late_curved_planes, 1u);
  EXPECT_GT (without.curved_claimed, 0.2);
  EXPECT_EQ (without.stats.late_curved_planes, 0u);
  EXPECT_GE (with.score.found, without.score.found);
}

TEST (Scenario, FacadeWithThirtyPercentOutliersKeepsItsWindows)
{
  // 30 % outliers: in a window's band behind the wall each outlier the last assignment gave the
  // window is beside the window and the wall, so the edge rule gave the next one to the window too,
  // over the whole wall, until the reach bound (3 neighbourhood radii from the grown members).
  // Measured: F1 0.889, 14 of 16 planes, 2 false planes without the bound; 0.993 and 16 with it.
  pcl::rspd::SceneOptions o;
  o.outlier_ratio = 0.3;
  const Detection d = detectScene ("facade", o);
  EXPECT_EQ (d.score.found, 16);
  EXPECT_EQ (d.score.false_planes, 0);
  EXPECT_GE (d.score.f1, 0.99);
}

TEST (Scenario, SmallPassSeedsUpToTheNoisiestPlaneButNoLayerOfOne)
{
  // The staircase's seed 4: no cell of the split seeds one riser, and the small-plane pass's seeds
  // on it (MND 0.056-0.106 rad: its normals bend towards both edges) were all above the median
  // plane's MND (0.055): 29 of 30 planes, F1 0.979; with the noisiest plane's MND as the bound, 30
  // and 0.993. The wider bound alone gave the room's seed 3 a false plane, the strip between its
  // door and the wall 2 cm behind it (F1 0.9926): a seed most of whose samples lie in a found
  // plane's noise band is not kept (0.9972, no false plane).
  pcl::rspd::SceneOptions o;
  o.seed = 4;
  const Detection stairs = detectScene ("staircase", o);
  EXPECT_EQ (stairs.score.found, 30);
  EXPECT_GE (stairs.score.f1, 0.99);
  o.seed = 3;
  const Detection room = detectScene ("room", o);
  EXPECT_EQ (room.score.found, 12);
  EXPECT_EQ (room.score.false_planes, 0);
  EXPECT_GE (room.score.f1, 0.995);
}

TEST (Scenario, SmallPlanesAtAHundredThousandPointsNeedTrimmedNormalsForWhatGrowthLeft)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // The room at 100,000 points (seed 2): the table's front panel (396 samples, 1.2 x 0.7 m) and
  // the cabinet top (303) lie within a 50-neighbourhood's radius (~18 cm) of an edge over much of
  // their area. Their PCA normals bend there, so every small-pass cell on the panel failed T3
  // (30-45 % outliers, even on its own inliers) and the cabinet top's seeds had MND 0.88 rad: 10 of
  // 12 planes, F1 0.987. A second split of the left samples on their neighbourhoods' trimmed-plane
  // normals seeds both: 12 of 12, 0.995 (measured). With one rim retest only (the panel's cells
  // pass once their inliers are retested until stable: 11 of 12 on the PCA normals alone). On the
  // first grid alone: the shifted grid with the narrowed normals (the defaults) seeds both too.
  pcl::rspd::SceneOptions o;
  o.num_points = 100000;
  o.seed = 2;
  const auto once = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setRimRetestUntilStable (false);
    firstGridOnly (s);
  };
  const auto trimmed = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setRimRetestUntilStable (false);
    s.setShiftedGrid (false);
    s.setLeftNormalRefit (true);
  };
  const Detection before = detectScene ("room", o, true, pcl::rspd::NormalScale::Automatic, once);
  const Detection after = detectScene ("room", o, true, pcl::rspd::NormalScale::Automatic, trimmed);
  EXPECT_LE (before.score.found, 10);
  EXPECT_EQ (after.score.found, 12);
  EXPECT_EQ (after.score.false_planes, 0);
  EXPECT_GE (after.score.f1, 0.995);
  EXPECT_GT (after.stats.left_refitted, 0u);
  EXPECT_GT (after.stats.small_seeds_trimmed, 0u);
  EXPECT_EQ (before.stats.left_refitted, 0u);
}

TEST (Scenario, CabinetAtAHundredThousandPointsNeedsTheShiftedGridAndNarrowedNormals)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // The room at 100,000 points (seed 4): the automatic k reaches 50, whose neighbourhoods (~0.2 m)
  // bend most of the cabinet's 0.8 m top's and front's normals, and every small-plane cell of 51
  // samples there mixes them with the sides' leftovers: 10 of 12 planes on the first grid alone
  // (F1 0.992; measured). The shifted grid holds a cell of each face alone, and the second split on
  // the left samples' normals narrowed at the edges passes T3 there: 12 of 12 (0.998). On seeds
  // 1-12: 12 of 12 on 11 seeds with both, on 3 with the shifted grid alone, on 2 with the narrowed
  // normals alone, on 1 with neither. The edge-aware normals (every normal narrowed, cells down to
  // 16 samples where they were; off by default) find both too.
  pcl::rspd::SceneOptions o;
  o.num_points = 100000;
  o.seed = 4;
  const Detection first = detectScene ("room", o, true, pcl::rspd::NormalScale::Automatic, firstGridOnly);
  const Detection both = detectScene ("room", o);
  const Detection edge = detectScene ("room", o, true, pcl::rspd::NormalScale::Automatic,
                                      [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setEdgeAwareNormals (true); });
  EXPECT_LE (first.score.found, 10);
  EXPECT_EQ (first.stats.small_seeds_shifted, 0u);
  EXPECT_EQ (first.stats.left_refitted, 0u);
  EXPECT_EQ (both.score.found, 12);
  EXPECT_EQ (both.score.false_planes, 0);
  EXPECT_EQ (both.score.fragments, 0);
  EXPECT_GE (both.score.f1, 0.997);
  EXPECT_GT (both.stats.small_seeds_shifted, 0u);
  EXPECT_GT (both.stats.left_refitted, 0u);
  EXPECT_EQ (both.stats.edge_narrowed_normals, 0u);
  EXPECT_GT (edge.stats.edge_narrowed_normals, 0u);
  EXPECT_EQ (edge.stats.left_refitted, 0u) << "every normal is narrowed already";
  EXPECT_EQ (edge.score.found, 12);
  EXPECT_EQ (edge.score.false_planes, 0);
}

TEST (Scenario, CabinetTopAtSixtyThousandPointsIsSeededByARimCellOnNarrowedNormals)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // The room at 60,000 points (seed 5): ε = 60, k = 30. The cabinet's top (154 samples, 0.8 m) has
  // the wall, the side and the front on three of its sides; every cell of the small-plane pass
  // mixes it with their leftovers or cuts it below k + 1, and on the narrowed normals its best cell
  // (41 samples) fails T3 with a third of them bent, leaving 26 inliers of the top alone: with the
  // retest bounded at k + 1 they seeded nothing, and the top was no plane (11 of 12, F1 0.994;
  // measured). Retested down to 16, the faces narrowed normals resolve: 12 of 12.
  pcl::rspd::SceneOptions o;
  o.num_points = 60000;
  o.seed = 5;
  const Detection with = detectScene ("room", o);
  const Detection without = detectScene ("room", o, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setLeftRimRetest (false); });
  EXPECT_EQ (without.score.found, 11);
  EXPECT_EQ (with.score.found, 12);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_EQ (with.score.fragments, 0);
  EXPECT_GT (with.score.f1, without.score.f1 + 0.002);
  EXPECT_GT (with.stats.left_refitted, 0u);
}

TEST (Scenario, CabinetTopOnPclNormalsIsSeededByARimCellOnTrimmedNormals)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // The same retest on given normals: PCL's k = 50, trimmed for the small-plane pass's second split.
  // The room at 60,000 points (seed 3) left its cabinet's top in no plane with the retest bounded at
  // the pass's k + 1 (11 of 12; measured); retested down to 16 it is seeded: 12 of 12.
  pcl::rspd::SceneOptions o;
  o.num_points = 60000;
  o.seed = 3;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("room", o);
  const auto normals = pclNormals (scene.cloud);
  const Detection with = detectOnKeptPclNormals (scene, normals);
  const Detection without = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setLeftRimRetest (false);
  });
  std::printf ("    retest bounded at k + 1: %d of 12, F1 %.4f; down to 16: %d, F1 %.4f\n", without.score.found,
               without.score.f1, with.score.found, with.score.f1);
  EXPECT_EQ (without.score.found, 11);
  EXPECT_EQ (with.score.found, 12);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_EQ (with.score.fragments, 0);
  // 0.0018 since the rim bands, which take the rims of the planes around the top either way.
  EXPECT_GT (with.score.f1, without.score.f1 + 0.0015);
}

TEST (Scenario, SparseRoomsCabinetIsFoundByPosition)
{
  // The room at 20,000 points (seed 5): ε = 20, k = 15. The cabinet's side (69 samples, 0.8 x 1 m)
  // and top (59) are sampled about 10 cm apart, so a 15-neighbourhood reaches across their edges
  // over most of them: every cell of them fails T3 or is noisier than every plane found, and both
  // were left in no plane (10 of 12; measured). Their positions lie within the noise of a plane:
  // found by position among what was left, 12 of 12.
  pcl::rspd::SceneOptions o;
  o.num_points = 20000;
  o.seed = 5;
  const Detection with = detectScene ("room", o);
  const Detection without = detectScene ("room", o, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setPositionPlanes (false); });
  EXPECT_EQ (without.score.found, 10);
  EXPECT_EQ (with.score.found, 12);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_EQ (with.score.fragments, 0);
  EXPECT_EQ (with.stats.position_planes, 2u);
  EXPECT_GT (with.score.f1, without.score.f1 + 0.004);
  EXPECT_LT (with.curved_claimed, 0.02);
}

TEST (Scenario, CabinetTopOfEpsilonSamplesIsFoundByPositionAndKeepsItsRim)
{
  // The room in layout 6 (200,000 points, ε = 200): the cabinet's top, seen at a grazing angle, holds
  // 208 samples about 7 cm apart beside its front's 2,163 at 2 cm. Found by position among what was
  // left (205 samples), it was turned down twice: ε asked of the 199 its 2.5 σ trim kept, and, once
  // that asked the 3 σ support, the plane support's release of 9 rim samples (fewer than a tenth of
  // their neighbours in the top) before the ε rule, leaving 196 (11 of 12 planes; measured). ε is
  // now asked of a position plane's support and before the plane support: 12 of 12.
  pcl::rspd::SceneOptions o;
  o.layout = 6;
  const Detection d = detectScene ("room", o);
  EXPECT_EQ (d.score.found, 12);
  EXPECT_EQ (d.score.false_planes, 0);
  EXPECT_EQ (d.score.fragments, 0);
  EXPECT_GE (d.stats.position_planes, 1u);
  EXPECT_GT (d.score.f1, 0.995);
  EXPECT_LT (d.curved_claimed, 0.02);
}

TEST (Scenario, SparseStaircaseAndYardNeedTheAutomaticK)
{
  // 20,000 samples: ε = 20, and a 0.18 m riser holds ~500. With the paper's k = 50 a sample's
  // neighbourhood reaches 5-6 cm, so a riser's normals bend over most of its height: F1 0.940
  // (0.864 and 26 of 30 planes before the small-plane pass took seeds up to the noisiest plane's
  // MND); the automatic k (15 here) gives 0.992. The industrial yard's walls and platform sides at
  // 30,000 samples: 4 of 6 with k = 50 and a fixed bend share, 6 with the automatic k (measured);
  // tested against noise (setBendNoiseTest), k = 50 finds 6 too, F1 0.979 against 0.987. The small-plane pass's
  // second split on trimmed normals (setLeftNormalRefit) gains a little at k = 50 (staircase
  // 0.940 -> 0.945), far from the automatic k. Since the final refit, which takes the planes off
  // the bent normals' median, k = 50 gives 0.988 with one fragment, the automatic k 0.991 and none
  // (the refitted k = 50 run 0.989; measured).
  pcl::rspd::SceneOptions o;
  o.num_points = 30000;
  pcl::rspd::SceneOptions o20 = o;
  o20.num_points = 20000;
  const auto paper_k = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setNumberOfNeighbours (50); };
  const Detection fixed = detectScene ("staircase", o20, true, pcl::rspd::NormalScale::Automatic, paper_k);
  const Detection automatic = detectScene ("staircase", o20);
  EXPECT_LT (fixed.score.f1, automatic.score.f1);
  EXPECT_GT (fixed.score.fragments, automatic.score.fragments);
  EXPECT_EQ (automatic.score.found, 30);
  EXPECT_GE (automatic.score.f1, 0.985);
  const auto paper_k_refit = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setNumberOfNeighbours (50);
    s.setLeftNormalRefit (true);
  };
  const Detection fixed_refit = detectScene ("staircase", o20, true, pcl::rspd::NormalScale::Automatic, paper_k_refit);
  EXPECT_GT (fixed_refit.score.f1, fixed.score.f1);
  EXPECT_LT (fixed_refit.score.f1, automatic.score.f1);
  // With the caller's normals (PCL's k = 50, as rspd_compare shares them) k stays the paper's 50;
  // the small-plane pass, its cells capped at ε/2, still seeds the risers (17 of 30 without the cap).
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("staircase", o);
  const Detection given = detectOnPclNormals (scene, pclNormals (scene.cloud));
  EXPECT_GE (given.score.found, 29);
  EXPECT_GE (given.score.f1, 0.96);
  const Detection yard = detectScene ("industrial", o);
  EXPECT_EQ (yard.score.found, 6);
  // One false plane when outlier seeds were first tested again, with a fixed bend share: 85
  // samples of a pipe, 1.0 % of the curved samples; none since bends are tested against noise.
  EXPECT_EQ (yard.score.false_planes, 0);
  EXPECT_GE (yard.score.f1, 0.985);
  EXPECT_LE (yard.curved_claimed, 0.02);
  const Detection yard_fixed = detectScene ("industrial", o, true, pcl::rspd::NormalScale::Automatic, paper_k);
  EXPECT_LT (yard_fixed.score.f1, yard.score.f1);
}

TEST (Scenario, IndustrialPipesAndTanksReported)
{
  // Curved surfaces becoming planes is the paper's stated limitation (Sec. 5). Coplanar-group
  // merging stops the floor from chaining over the tanks, and the curved-surface check drops the
  // facets of pipes and tanks (issue 6: under 2 % of their points claimed).
  const Detection r = detectScene ("industrial");
  EXPECT_EQ (r.score.found, 6);
  EXPECT_EQ (r.score.false_planes, 0);
  EXPECT_GE (r.score.f1, 0.99);
  EXPECT_LE (r.curved_claimed, 0.02);
}

TEST (Scenario, CurvedSurfacesNeedOneOfTheTwoGuards)
{
  // Pipes and tanks: with neither outlier seeds dropped nor the curved-surface check, their facets
  // become planes; either guard alone keeps them out (both are on by default). The check's fold
  // ratio keeps no facet: their normals turn smoothly.
  const auto both_off = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    EXPECT_TRUE (s.getCurvedPlaneCheck ());
    s.setDropOutlierSeeds (false);
    s.setCurvedPlaneCheck (false);
  };
  const auto check_only = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setDropOutlierSeeds (false);
    EXPECT_EQ (s.getCurvedFoldRatio (), 0.5);
  };
  const Detection none = detectScene ("industrial", {}, true, pcl::rspd::NormalScale::Automatic, both_off);
  const Detection check = detectScene ("industrial", {}, true, pcl::rspd::NormalScale::Automatic, check_only);
  EXPECT_GT (none.curved_claimed, 0.3);
  EXPECT_GE (none.score.false_planes, 10);
  EXPECT_LE (check.curved_claimed, 0.02);
  EXPECT_EQ (check.score.false_planes, 0);
  EXPECT_GE (check.score.f1, 0.99);
}

TEST (Scenario, TankAndPipeFacetsUnderHeavyNoiseNeedTheNormalsTurn)
{
  // The industrial scene at σ = 3 cm (seed 3): noise is most of a facet's MND, so a tank facet
  // (quadric share 0.05, half-bend 0.12 rad against MND 0.28) and two pipe facets (MND 0.64-0.66)
  // pass the quadric's fixed bounds; their normals turn across them by more than half MND, smoothly.
  // Without the turn, a facet is a false plane (measured: two before groups of noisy seeds smaller
  // than ε could seed, one since). The rim bands extend such a facet along the surface, within its
  // band, until the late curved check drops it (measured: no false plane without the turn): they are
  // off there too, so that the turn is measured alone.
  pcl::rspd::SceneOptions options;
  options.noise = 0.03;
  options.seed = 3;
  const Detection with = detectScene ("industrial", options);
  const Detection without = detectScene ("industrial", options, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                           EXPECT_TRUE (s.getCurvedNormalTurn ());
                                           s.setCurvedNormalTurn (false);
                                           s.setRimBands (false);
                                         });
  EXPECT_GE (without.score.false_planes, 1);
  EXPECT_GT (without.curved_claimed, 0.02);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_LE (with.curved_claimed, 0.02);
  EXPECT_EQ (with.score.found, 6);
  EXPECT_GT (with.score.f1, without.score.f1);
}

TEST (Scenario, SmallPillarFacetsAreNoFoldsTheBentSplitCouldCut)
{
  // The room at σ 2 cm (seed 1): a facet of the 0.3 m pillar of about 220 samples (ε 200) bends
  // beyond chance, but its normals turn by less than √48 times their noise, so the fold ratio
  // (0.65) took it for a fold; the bent-plane split could not cut it into two sides of ε samples.
  pcl::rspd::SceneOptions options;
  options.noise = 0.02;
  options.seed = 1;
  const Detection with = detectScene ("room", options);
  // Since every plane's re-estimate is bounded at T2 that facet no longer grows into a plane either
  // (0 false planes, 0.2 % claimed, measured with the fold rule off): the bound is off here too, so
  // that the fold rule is measured alone; so are the rim bands, with which the late curved check
  // drops the facet (measured).
  const Detection without = detectScene ("room", options, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                           EXPECT_TRUE (s.getCurvedFoldTwoSides ());
                                           s.setCurvedFoldTwoSides (false);
                                           s.setBoundedReestimation (false);
                                           s.setRimBands (false);
                                         });
  EXPECT_GE (without.score.false_planes, 1);
  EXPECT_GT (without.curved_claimed, 0.1);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_LE (with.curved_claimed, 0.02);
  EXPECT_GE (with.score.found, without.score.found);
}

TEST (Scenario, ARisersPlaneOnBlurredNormalsKeepsItsEstimateWithinT2)
{
  // The staircase at 10,000 points (seed 9) on PCL's k = 50 normals, whose neighbourhoods reach
  // across a riser: every tread's normal follows the flight's slope. A riser's plane, re-estimated
  // on them, reached MND 71° (past T2's 60°) and MDP 0.17 m, then grew over 6,600 samples of the
  // flight. Bounded at T2 like noisy seeds' planes, it keeps its estimate (measured: 10 -> 29 of 30).
  pcl::rspd::SceneOptions options;
  options.num_points = 10000;
  options.seed = 9;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("staircase", options);
  const auto normals = pclNormals (scene.cloud);
  const Detection bounded = detectOnKeptPclNormals (scene, normals);
  const Detection paper = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setBoundedReestimation (false);
  });
  EXPECT_LE (paper.score.found, 12);
  EXPECT_LT (paper.score.f1, 0.5);
  EXPECT_GE (bounded.score.found, 29);
  EXPECT_GE (bounded.score.f1, 0.9);
  EXPECT_GT (bounded.stats.kept_estimates, 0u);
}

TEST (Scenario, AThinPipeFoldedOntoOnePlaneIsATube)
{
  // The industrial scene at 30,000 points (seed 5) on PCL's k = 50 normals: the first split's cells
  // along a thin vertical pipe seed a ribbon of its samples from every side (100 samples 0.22 m
  // wide, MDP 0.16 m, MND 45 degrees); its quadric explains too little to call it bent and its
  // normals point all round. As thick as half its narrow side, it is a tube.
  pcl::rspd::SceneOptions options;
  options.num_points = 30000;
  options.seed = 5;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("industrial", options);
  const auto normals = pclNormals (scene.cloud);
  const Detection with = detectOnKeptPclNormals (scene, normals);
  const Detection without = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    EXPECT_TRUE (s.getCurvedTubeCheck ());
    s.setCurvedTubeCheck (false);
  });
  EXPECT_GE (without.score.false_planes, 1);
  EXPECT_GT (without.curved_claimed, 0.01);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_GE (with.stats.curved_tubes, 1u);
  EXPECT_LE (with.curved_claimed, 0.005);
  EXPECT_EQ (with.score.found, 6);
  EXPECT_GT (with.score.f1, without.score.f1);
}

TEST (Scenario, PartsOfAPillarFacetCutAtAFoldStillBend)
{
  // The room at 20,000 points, σ 1.2 cm (seed 43), on PCL's k = 50 normals: a facet of the 0.3 m pillar
  // bends far beyond chance (share 0.88, half-bend 0.67 rad against MND 0.16), but its blurred
  // normals turn in steps, so the fold ratio kept it for the bent-plane split, which cut it in two.
  // Its parts (41 and 33 samples) bend as much; judged again, the one under 2ε = 40 goes (the other,
  // spared as a fold again, stays: one false plane fewer, not none).
  pcl::rspd::SceneOptions options;
  options.num_points = 20000;
  options.noise = 0.012;
  options.seed = 43;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("room", options);
  const auto normals = pclNormals (scene.cloud);
  const Detection with = detectOnKeptPclNormals (scene, normals);
  const Detection without = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    EXPECT_TRUE (s.getCurvedSplitParts ());
    s.setCurvedSplitParts (false);
  });
  EXPECT_GE (with.stats.curved_parts, 1u);
  EXPECT_LT (with.score.false_planes, without.score.false_planes);
  EXPECT_LT (with.curved_claimed, without.curved_claimed - 0.1);
  EXPECT_GE (with.score.found, without.score.found);
  EXPECT_GT (with.score.f1, without.score.f1);
}

TEST (Scenario, RoughBoxesOnASmoothFloorNeedTheOutlierSeedRetest)
{
  // Noise that differs from surface to surface: beside a smooth floor and wall every seed on the
  // rougher boxes is an MND outlier, dropped, and the small-plane pass takes no seed noisier than
  // the planes grown. Tested again once growth is stable (flat, not bent), they seed their faces,
  // and let the small-plane pass seed faces as noisy.
  const Detection retest = detectScene ("boxes", {}, true, pcl::rspd::NormalScale::Automatic, surfacePartsOff);
  const Detection drop = detectScene ("boxes", {}, true, pcl::rspd::NormalScale::Automatic,
                                      [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                        surfacePartsOff (s);
                                        EXPECT_TRUE (s.getOutlierSeedRetest ());
                                        s.setOutlierSeedRetest (false);
                                      });
  EXPECT_GT (retest.stats.retested_seeds, 0u);
  EXPECT_EQ (drop.stats.retested_seeds, 0u);
  EXPECT_EQ (retest.score.found, 32);
  EXPECT_LE (drop.score.found, 12);
  EXPECT_GE (retest.score.f1, 0.99);
  EXPECT_EQ (retest.score.false_planes, 0);
}

TEST (Scenario, NoisyBoxFaceNeedsTheSmallPassThickCellJoin)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // Seed 2: one face of the σ = 3 cm box (2,466 samples) shares every first-split cell with its
  // neighbours, and every small cell of it, under 0.4 m, fails T1 alone (45-72°): never seeded, 31
  // of 32 planes. Joined, eleven of those thick cells pass T1-T3 as a group (measured).
  pcl::rspd::SceneOptions o;
  o.seed = 2;
  const Detection joined = detectScene ("boxes", o);
  const Detection cells = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic,
                                       [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                         EXPECT_TRUE (s.getSmallPassThickCellJoin ());
                                         s.setSmallPassThickCellJoin (false);
                                         EXPECT_FALSE (s.getSmallPassThickCellJoin ());
                                       });
  EXPECT_GT (joined.stats.small_joined_seeds, 0u);
  EXPECT_EQ (cells.stats.small_joined_seeds, 0u);
  EXPECT_EQ (joined.score.found, 32);
  EXPECT_LE (cells.score.found, 31);
  EXPECT_GT (joined.score.f1, cells.score.f1);
  EXPECT_EQ (joined.score.false_planes, 0);
}

TEST (Scenario, RoughBoxAmidOutliersNeedsGroupsOfNoisySmallSeeds)
{
  // With 15 % outliers the root cell is wider, and every cell of the σ = 3 cm box either straddles
  // its edges (0.86 m) or fails T1 (0.43 m, 74° against 75°): no seed there, and its small seeds,
  // noisier than every plane found, are turned down one at a time (27 of 32, the whole box missed;
  // measured). Joined, they pass as the first split would have had a cell fitted the face: 31 of 32;
  // the box's top, whose cells are thick and noisier than the planes found before the pass, is
  // seeded since the thick cells follow the noisy seeds' planes (32).
  pcl::rspd::SceneOptions o;
  o.outlier_ratio = 0.15;
  const Detection groups = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic, surfacePartsOff);
  const Detection alone = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic,
                                       [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                         surfacePartsOff (s);
                                         EXPECT_TRUE (s.getNoisySeedGroups ());
                                         s.setNoisySeedGroups (false);
                                         EXPECT_FALSE (s.getNoisySeedGroups ());
                                       });
  EXPECT_GT (groups.stats.small_noisy_groups, 0u);
  EXPECT_EQ (alone.stats.small_noisy_groups, 0u);
  EXPECT_EQ (groups.score.found, 32);
  EXPECT_LE (alone.score.found, 27);
  EXPECT_GE (groups.score.f1, alone.score.f1 + 0.02);
  EXPECT_EQ (groups.score.false_planes, 0);
}

TEST (Scenario, LoneNoisySeedOfARoughBoxSideSeedsItsPlane)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // The boxes at 30,000 points (ε = 30): a noisy seed of a rough box's side that joins no other is
  // turned down without lone seeds, and the side is missed (29 of 32, F1 0.9795; measured); alone it
  // seeds the side (30 of 32, 0.9842; 31, 0.989, since the thick cells follow the noisy seeds'
  // planes), with no false plane.
  pcl::rspd::SceneOptions o;
  o.num_points = 30000;
  const Detection lone = detectScene ("boxes", o);
  const Detection grouped = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                           EXPECT_TRUE (s.getNoisyLoneSeeds ());
                                           s.setNoisyLoneSeeds (false);
                                           EXPECT_FALSE (s.getNoisyLoneSeeds ());
                                         });
  EXPECT_GE (lone.score.found, grouped.score.found + 1);
  EXPECT_GE (lone.score.found, 30);
  EXPECT_GT (lone.score.f1, grouped.score.f1);
  EXPECT_EQ (lone.score.false_planes, 0);
  EXPECT_GT (lone.stats.small_noisy_groups, grouped.stats.small_noisy_groups);
}

TEST (Scenario, NoisyStaircaseEdgesNeedTheFinalRefit)
{
  // The staircase at σ = 1 cm (seed 40): on the robust estimates, samples within 1 cm of a riser's
  // edges lay beyond the edge line of both planes there and were released (F1 0.9734, recall 0.951;
  // measured, without the edge wedges, which came later); on the least-squares planes they are kept
  // (0.9823, recall 0.968; the true planes with nearest-plane assignment give 0.985). The edge wedges
  // keep most of them on the robust estimates too (0.9803, recall 0.967), the refit still more (0.9825).
  pcl::rspd::SceneOptions o;
  o.noise = 0.01;
  o.seed = 40;
  const auto robustEstimates = [] (bool wedges) {
    return [wedges] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
      EXPECT_TRUE (s.getFinalRefit ());
      s.setFinalRefit (false);
      EXPECT_FALSE (s.getFinalRefit ());
      EXPECT_TRUE (s.getEdgeWedges ());
      s.setEdgeWedges (wedges);
      EXPECT_EQ (s.getEdgeWedges (), wedges);
    };
  };
  const Detection refit = detectScene ("staircase", o);
  const Detection robust = detectScene ("staircase", o, true, pcl::rspd::NormalScale::Automatic, robustEstimates (false));
  const Detection wedged = detectScene ("staircase", o, true, pcl::rspd::NormalScale::Automatic, robustEstimates (true));
  EXPECT_EQ (refit.score.found, 30);
  EXPECT_EQ (refit.score.false_planes, 0);
  EXPECT_GT (refit.score.f1, robust.score.f1 + 0.005);
  EXPECT_GT (refit.score.recall, robust.score.recall + 0.01);
  EXPECT_GT (wedged.score.f1, robust.score.f1 + 0.005);
  EXPECT_GT (wedged.score.recall, robust.score.recall + 0.01);
  EXPECT_GT (refit.score.f1, wedged.score.f1);
}

TEST (Scenario, IsotropicNoiseOutsideTheEdgesIsKeptByTheEdgeWedges)
{
  // The staircase with σ = 5 mm drawn in every direction (seed 3): noise across a nose puts samples
  // beyond both planes' edge lines, outside the edge, which the edge sides released (F1 0.9730,
  // recall 0.952; measured); the edge wedges give each to the plane it lies farther from (0.9776,
  // recall 0.965), with every plane found and none false either way.
  pcl::rspd::SceneOptions o;
  o.noise = 0.005;
  o.seed = 3;
  o.isotropic_noise = true;
  const Detection wedged = detectScene ("staircase", o);
  const Detection released = detectScene ("staircase", o, true, pcl::rspd::NormalScale::Automatic,
                                          [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setEdgeWedges (false); });
  EXPECT_EQ (wedged.score.found, 30);
  EXPECT_EQ (wedged.score.false_planes, 0);
  EXPECT_EQ (released.score.found, 30);
  EXPECT_GT (wedged.score.f1, released.score.f1 + 0.003);
  EXPECT_GT (wedged.score.recall, released.score.recall + 0.005);
}

TEST (Scenario, CabinetTopAmidOutliersIsSeededByASmallGroupOfNoisySeeds)
{
  // The room with 10 % outliers (seed 3, ε = 200): the cabinet top (479 samples) has two noisy seeds
  // in the small-plane pass, 117 and 68 samples, that join into a group of 185. Held to ε, the group
  // seeded nothing and the top was missed (11 of 12, F1 0.9930; measured); judged as a lone seed is,
  // it seeds the top, which grows to ε (12 of 12, 0.9958), with no false plane. On the first grid
  // alone: the shifted grid seeds the top too (12 either way).
  pcl::rspd::SceneOptions o;
  o.outlier_ratio = 0.1;
  o.seed = 3;
  const Detection small = detectScene ("room", o, true, pcl::rspd::NormalScale::Automatic,
                                       [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                         firstGridOnly (s);
                                         surfacePartsOff (s);
                                       });
  const Detection held = detectScene ("room", o, true, pcl::rspd::NormalScale::Automatic,
                                      [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                        firstGridOnly (s);
                                        surfacePartsOff (s);
                                        s.setNoisyLoneSeeds (false);
                                      });
  EXPECT_EQ (small.score.found, 12);
  EXPECT_EQ (small.score.false_planes, 0);
  EXPECT_GT (small.score.f1, 0.995);
  EXPECT_LE (held.score.found, 11);
  EXPECT_GT (small.score.f1, held.score.f1);
}

TEST (Scenario, RoughBoxesEachRougherThanTheLastClimbTheNoiseLadder)
{
  // The boxes at σ = 8 mm, 80,000 points (k = 40): six boxes at 1 to 15 times the floor's noise.
  // The first split seeds the floor, the wall and one face; the small-plane pass's noisy seeds of
  // the rougher boxes are more than twice as noisy as those, so in one step only the next box is
  // seeded (13 of 32, F1 0.815; measured); step by step the rest follow (22 of 32, 0.885), with
  // no false plane. The two roughest boxes (σ 8 and 12 cm on 1 m faces) stay unseeded.
  pcl::rspd::SceneOptions o;
  o.num_points = 80000;
  o.noise = 0.008;
  o.seed = 40;
  const Detection ladder = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic, surfacePartsOff);
  const Detection step = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic,
                                      [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                        surfacePartsOff (s);
                                        EXPECT_TRUE (s.getNoisyGroupLadder ());
                                        s.setNoisyGroupLadder (false);
                                        EXPECT_FALSE (s.getNoisyGroupLadder ());
                                      });
  EXPECT_GE (ladder.score.found, 20);
  EXPECT_GE (ladder.score.found, step.score.found + 5);
  EXPECT_GT (ladder.score.f1, step.score.f1 + 0.03);
  EXPECT_EQ (ladder.score.false_planes, 0);
  EXPECT_GT (ladder.stats.small_ladder_seeds, 0u);
  EXPECT_EQ (step.stats.small_ladder_seeds, 0u);
}

TEST (Scenario, RoughBoxesNoPlaneFoundAnchorsAreReachedByTheLaddersRungs)
{
  // A fresh random row (draw_rows.py 61, boxes layout 448, 209,000 points, σ 1.4 mm) with 10 %
  // outliers: they widen the octree's root cell, so the first split seeds only the floor and the
  // wall (MND 0.6°), the small-plane pass's seeds on the boxes are 5-9 times as noisy and all turned
  // down, and by position the ladder's first step (twice the floor's σ) turns down every rough face
  // (σ 4 mm and more) for its noise: 7 of 32 planes without the rungs (measured, F1 0.840). Each
  // step that turns a face down for its noise alone within the next step takes that step.
  pcl::rspd::SceneOptions o;
  o.layout = 448;
  o.num_points = 209000;
  o.noise = 0.0014;
  o.seed = 88;
  o.outlier_ratio = 0.1;
  const Detection rungs = detectScene ("boxes", o);
  const Detection without = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                           EXPECT_TRUE (s.getPositionLadderRungs ());
                                           s.setPositionLadderRungs (false);
                                         });
  EXPECT_EQ (rungs.score.found, 32);
  EXPECT_EQ (rungs.score.false_planes, 0);
  EXPECT_GT (rungs.score.f1, 0.99);
  EXPECT_LE (without.score.found, 8);
}

TEST (Scenario, RoughBoxesAmidTwentyPercentOutliersKeepNoSheetOfThem)
{
  // A fresh random row (draw_rows.py 64, boxes layout 204, 540,000 points, σ 2.9 mm isotropic,
  // turned, 20 % outliers), where pcl_rspd fell below RegionGrowing (0.888 against 0.903). The
  // planes of the rougher boxes took sheets of the outliers in their bands, up to metres beyond
  // their faces; the noise ladder's second step also seeded a lone cell across a rough box's top
  // and a sliver of its side (MND 59.8°, under twice the step's 34°), whose plane took 1,841
  // outliers spread over the scene and, through them, strips of the sides of a box 3 m away.
  // Released as no denser than the clutter around them (the clutter share), the sheets go: 0.974,
  // but the top keeps those strips, tilted 4.7° by them and matching no face (one false plane).
  // The final parts (the default) release what no chain of its members joins to it: 0.987, 32 of
  // 32. Judged past T2 instead (setNoisyGrownT2, off by default: very rough faces fail it too),
  // that plane goes and its top is found again. Neither the share nor the final parts: 0.888.
  pcl::rspd::SceneOptions o;
  o.layout = 204;
  o.num_points = 540000;
  o.noise = 0.0029;
  o.seed = 46;
  o.isotropic_noise = true;
  o.random_rotation = true;
  o.outlier_ratio = 0.2;
  const Detection parts = detectScene ("boxes", o);
  const Detection clutter = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                           EXPECT_TRUE (s.getFinalParts ());
                                           s.setFinalParts (false);
                                         });
  const Detection t2 = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic,
                                    [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                      EXPECT_FALSE (s.getNoisyGrownT2 ());
                                      s.setFinalParts (false);
                                      s.setNoisyGrownT2 (true);
                                    });
  const Detection neither = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                           EXPECT_TRUE (s.getSupportClutter ());
                                           s.setFinalParts (false);
                                           s.setSupportClutter (false);
                                         });
  EXPECT_EQ (parts.score.found, 32);
  EXPECT_EQ (parts.score.false_planes, 0);
  EXPECT_GT (parts.score.f1, 0.985);
  EXPECT_GT (parts.stats.clutter_released, 0u);
  EXPECT_GT (parts.stats.final_strays, 0u);
  EXPECT_EQ (parts.stats.noisy_past_t2, 0u);
  EXPECT_GT (clutter.score.f1, 0.97);
  EXPECT_LE (clutter.score.found, 31);
  EXPECT_GE (clutter.score.false_planes, 1);
  EXPECT_EQ (clutter.stats.final_strays, 0u);
  EXPECT_EQ (t2.score.found, 32);
  EXPECT_EQ (t2.score.false_planes, 0);
  EXPECT_GT (t2.score.f1, 0.985);
  EXPECT_GT (t2.stats.noisy_past_t2, 0u);
  EXPECT_LT (neither.score.f1, 0.9);
  EXPECT_GE (neither.score.false_planes, 1);
  EXPECT_EQ (neither.stats.clutter_released, 0u);
}

TEST (Scenario, RoughFaceBesideFacesFoundIsJudgedFlatWithItsBandSamples)
{
  // A fresh random row (draw_rows.py 66, boxes layout 329, 125,000 points, σ 2.5 mm isotropic, 10 %
  // outliers), where pcl_rspd found 30 of 32 against RegionGrowing's 32. The σ 3.7 cm box's side
  // and top were left to the position planes; beside the sides found, the side's samples toward
  // them lay in their bands and were left out, so the members kept at those rims stood out of the
  // face and their quadric bent beyond chance (0.034 against 0.029), which ended the search of the
  // part the side and the top shared. Judged with those band samples (the default), the side is
  // flat (0.016 against 0.021) and both are found; judged without the members in the sides' bands
  // (position_bend_slabs, the default too), so are they: either rule alone finds them.
  pcl::rspd::SceneOptions o;
  o.layout = 329;
  o.num_points = 125000;
  o.noise = 0.0025;
  o.seed = 813;
  o.isotropic_noise = true;
  o.outlier_ratio = 0.1;
  // The rim bands give the side and the top those rim samples before the position planes judge them
  // (measured: 32 of 32 with neither rule): off in the third run, so that the two rules are measured.
  const auto with = [&o] (bool band, bool slabs) {
    return detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic,
                        [band, slabs] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                          EXPECT_TRUE (s.getPositionBendBand ());
                          s.setPositionBendBand (band);
                          s.setPositionBendSlabs (slabs);
                          s.setRimBands (band || slabs);
                        });
  };
  const Detection band = with (true, false);
  const Detection slabs = with (false, true);
  const Detection members = with (false, false);
  for (const Detection* d : {&band, &slabs})
  {
    EXPECT_EQ (d->score.found, 32);
    EXPECT_EQ (d->score.false_planes, 0);
    EXPECT_GT (d->score.f1, 0.988);
  }
  EXPECT_LE (members.score.found, 30);
  EXPECT_LT (members.score.f1, 0.982);
}

TEST (Scenario, RoughTopBesideItsSidesIsJudgedFlatWithoutTheirSlabs)
{
  // A fresh random row (draw_rows.py 69 12: boxes layout 576, 185,000 points, σ 2.6 mm, turned),
  // where pcl_rspd found 31 of 32 against RegionGrowing's 32. A box's top (σ 3.9 cm, 1,277
  // samples) was left to the position planes, its four sides found; the top samples left out in
  // the sides' bands were more often those below the face, so the 841 members kept bent beyond
  // chance (0.0207 against 0.0193), with or without the band samples. Judged without its 42 members
  // in the bands of its sides, it is flat (the default): 32 of 32.
  pcl::rspd::SceneOptions o;
  o.layout = 576;
  o.num_points = 185000;
  o.noise = 0.0026;
  o.seed = 280;
  o.random_rotation = true;
  const Detection slabs = detectScene ("boxes", o);
  // The rim bands give the top its rim samples before the position planes judge it (measured: 32
  // of 32 without the slabs too): off without the slabs, so that the slabs are measured.
  const Detection members = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic,
                                         [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                           EXPECT_TRUE (s.getPositionBendSlabs ());
                                           s.setPositionBendSlabs (false);
                                           s.setRimBands (false);
                                         });
  EXPECT_EQ (slabs.score.found, 32);
  EXPECT_EQ (slabs.score.false_planes, 0);
  EXPECT_GT (slabs.score.f1, 0.993);
  EXPECT_LE (members.score.found, 31);
  EXPECT_LT (members.score.f1, 0.991);
}

TEST (Scenario, NoiseLadderClimbsOnlyOnPlanesOfEpsilonSamples)
{
  // The room with 10 % outliers (seed 2): its noisy small seeds include bits of the pillar and
  // ball, smaller than ε. Had those raised the ladder's bound, it would have climbed to the noise
  // of the pillar's facets: two false planes of its samples (measured with every seed climbing; the
  // ladder off gives none). Only seeds of ε samples raise it, and none is added.
  pcl::rspd::SceneOptions o;
  o.outlier_ratio = 0.1;
  o.seed = 2;
  const Detection ladder = detectScene ("room", o);
  const Detection step = detectScene ("room", o, true, pcl::rspd::NormalScale::Automatic,
                                      [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setNoisyGroupLadder (false); });
  EXPECT_EQ (ladder.score.false_planes, 0);
  EXPECT_EQ (ladder.score.found, 12);
  EXPECT_GE (ladder.score.f1, step.score.f1 - 0.001);
}

TEST (Scenario, DoorProudOfItsWallWithinTheNoiseIsSplitOffAtItsStep)
{
  // The room at σ = 1.5 cm (seed 1): its door, 2 cm proud of the far wall, lies within the wall's
  // noise band, and growth gives it to the wall (measured: 11 of 12 planes, F1 0.986, without the
  // step split; 12 of 12, 0.995, with it).
  pcl::rspd::SceneOptions o;
  o.noise = 0.015;
  o.seed = 1;
  const Detection split = detectScene ("room", o);
  const Detection kept = detectScene ("room", o, true, pcl::rspd::NormalScale::Automatic,
                                      [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                        EXPECT_TRUE (s.getStepSplit ());
                                        s.setStepSplit (false);
                                        EXPECT_FALSE (s.getStepSplit ());
                                      });
  EXPECT_EQ (kept.stats.steps_split, 0u);
  EXPECT_EQ (split.stats.steps_split, 1u);
  EXPECT_EQ (kept.score.found, 11);
  EXPECT_EQ (split.score.found, 12);
  EXPECT_EQ (split.score.false_planes, 0);
  EXPECT_GT (split.score.f1, kept.score.f1 + 0.005);
}

TEST (Scenario, RiserSeededAlsoByANoisySeedIsKept)
{
  // The staircase at its default size, seed 12: seven small-plane seeds on one riser, the largest
  // admitted as noisy (MND 3.9° against the planes' 3.65°, let in by a retested seed's bound) and six
  // within the bound. Merged, the riser (2,258 samples with its edge bands) was judged again as a
  // noisy seed's plane, read as bent by those bands, and dropped whole: 29 of 30 planes, F1 0.977.
  // The six ordinary seeds vouch for it now: 30 of 30, 0.991 (seeds 10 and 25 alike).
  pcl::rspd::SceneOptions o;
  o.seed = 12;
  const Detection d = detectScene ("staircase", o);
  EXPECT_EQ (d.score.found, 30);
  EXPECT_EQ (d.score.false_planes, 0);
  EXPECT_GT (d.score.f1, 0.99);
}

TEST (Scenario, StripAcrossTheDoorsEdgeIsNoPlane)
{
  // The room at seed 7 (200,000 points): the small-plane pass seeds a strip of 299 leftover samples
  // across the door's left edge, half door and half wall, before the far-member release parts the
  // door from the wall; it is scored a fragment of the door (measured: 13 planes, F1 0.9968 with the
  // check off; 12, no fragment, 0.9982 with it).
  pcl::rspd::SceneOptions o;
  o.seed = 7;
  const Detection checked = detectScene ("room", o);
  const Detection kept = detectScene ("room", o, true, pcl::rspd::NormalScale::Automatic,
                                      [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                        EXPECT_TRUE (s.getAcrossStepCheck ());
                                        s.setAcrossStepCheck (false);
                                        EXPECT_FALSE (s.getAcrossStepCheck ());
                                      });
  EXPECT_EQ (kept.stats.across_steps, 0u);
  EXPECT_EQ (checked.stats.across_steps, 1u);
  EXPECT_EQ (kept.score.fragments, 1);
  EXPECT_EQ (checked.score.fragments, 0);
  EXPECT_EQ (checked.score.found, 12);
  EXPECT_EQ (checked.score.false_planes, 0);
  EXPECT_GT (checked.score.f1, kept.score.f1 + 0.001);
}

TEST (Scenario, ThickCellsFollowTheNoisySeedsPlanes)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // The boxes at 30,000 points: noisy seeds seed the roughest box's faces, noisier than every plane
  // found before the small-plane pass; collected again up to those planes' MND, the pass's thick
  // cells seed one more face (measured: 30 of 32 without, 31 with).
  pcl::rspd::SceneOptions o;
  o.num_points = 30000;
  const Detection follow = detectScene ("boxes", o);
  const Detection before = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic,
                                        [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                          EXPECT_TRUE (s.getThickCellsFollowNoisySeeds ());
                                          s.setThickCellsFollowNoisySeeds (false);
                                          EXPECT_FALSE (s.getThickCellsFollowNoisySeeds ());
                                        });
  EXPECT_EQ (before.stats.thick_rebound, 0u);
  EXPECT_GE (follow.stats.thick_rebound, 1u);
  EXPECT_GE (follow.score.found, before.score.found + 1);
  EXPECT_GE (follow.score.found, 31);
  EXPECT_EQ (follow.score.false_planes, 0);
  EXPECT_GT (follow.score.f1, before.score.f1);
}

TEST (Scenario, LayersOfANoisyFaceAreMergedIntoOnePlane)
{
  // The room: two layers of the cabinet front's noise band (1,208 and 621 samples 4.6 mm apart) and a
  // 213-sample layer below the floor were planes of their own, fragments of the truth's planes
  // (measured: 2 fragments); merged, each face is one plane, and the door 2 cm proud of its wall
  // stays a plane of its own. Measured without the narrowed rim retest (issue #6's thirty-fourth
  // session): with it one of those layers is no plane of its own to begin with (layer merge off: 1
  // fragment; on: one layer merged, none left); the defaults' result is checked too. Without the
  // layer merge, the final volume layers drop one of those layers too (1 fragment left), and the
  // step sides within the bands (part of the step regions) hand a layer's samples, interleaved with
  // the face's, to the face, which holds twice as many of their neighbours (0 left): both off here.
  const Detection defaults = detectScene ("room");
  const Detection merged = detectScene ("room", {}, true, pcl::rspd::NormalScale::Automatic,
                                        [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setLeftRimRetest (false); });
  const Detection apart = detectScene ("room", {}, true, pcl::rspd::NormalScale::Automatic,
                                       [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                         s.setLeftRimRetest (false);
                                         EXPECT_TRUE (s.getLayerMerge ());
                                         s.setLayerMerge (false);
                                         EXPECT_FALSE (s.getLayerMerge ());
                                         s.setFinalVolumeLayerCheck (false);
                                         s.setStepRegions (false);
                                       });
  EXPECT_EQ (defaults.score.found, 12);
  EXPECT_EQ (defaults.score.fragments, 0);
  EXPECT_EQ (defaults.score.false_planes, 0);
  EXPECT_GE (defaults.stats.layers_merged, 1u);
  EXPECT_GE (apart.score.fragments, 2);
  EXPECT_EQ (apart.stats.layers_merged, 0u);
  EXPECT_EQ (merged.score.fragments, 0);
  EXPECT_GE (merged.stats.layers_merged, 2u);
  EXPECT_EQ (merged.score.found, 12);
  EXPECT_EQ (merged.score.false_planes, 0);
  EXPECT_GE (merged.score.f1, 0.997);
}

TEST (Scenario, NoPlaneEndsWithFewerThanEpsilonSamples)
{
  // The staircase at 15,000 points (seed 15, ε = 15) on PCL's k = 50 normals: a plane bent over a
  // riser and a tread was cut at the edge, and the edge and step sides then moved all but one of its
  // tread samples to the tread's other plane: a plane of one sample (measured). It is dropped. With
  // the final refit the edge sides no longer leave that plane so small; without it they still do.
  pcl::rspd::SceneOptions o;
  o.num_points = 15000;
  o.seed = 15;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("staircase", o);
  const Detection refit = detectOnKeptPclNormals (scene, pclNormals (scene.cloud));
  std::map<std::uint32_t, std::size_t> refit_size;
  for (const auto l : refit.labels)
    if (l != 0)
      ++refit_size[l];
  for (const auto& s : refit_size)
    EXPECT_GE (s.second, 15u) << "plane " << s.first;
  const Detection d = detectOnKeptPclNormals (scene, pclNormals (scene.cloud), [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setFinalRefit (false);
  });
  std::map<std::uint32_t, std::size_t> size;
  for (const auto l : d.labels)
    if (l != 0)
      ++size[l];
  ASSERT_FALSE (size.empty ());
  for (const auto& s : size)
    EXPECT_GE (s.second, 15u) << "plane " << s.first;
  EXPECT_GE (d.stats.below_epsilon, 1u);
  EXPECT_EQ (d.score.found, 30);
}

TEST (Scenario, NoisyGroupsLeaveTheFacadesOutliersAndTheTanksAlone)
{
  // Groups of turned-down seeds that are no rough face: a slab of the facade's outliers (MDP five
  // times the thickest plane's) and tank facets amid outliers (MND five times and more the noisiest
  // plane's) were seeded and grown into false planes without the ratio bound (measured).
  const auto unbounded = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    EXPECT_DOUBLE_EQ (s.getNoisySeedGroupRatio (), 2.0);
    s.setNoisySeedGroupRatio (0.5); // refused: below 1
    s.setNoisySeedGroupRatio (1e6);
    EXPECT_DOUBLE_EQ (s.getNoisySeedGroupRatio (), 1e6);
  };
  // The slab is where the outliers' box ends behind the wall: the volume-layer check, a later guard,
  // drops it too, and so do the flat layers, so both are off here to show the bound alone (with
  // either on and no bound: no false plane).
  const auto unbounded_no_volume = [&] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    unbounded (s);
    s.setVolumeLayerCheck (false);
    s.setFlatLayers (false);
  };
  const Detection facade = detectScene ("facade");
  const Detection facade_unbounded = detectScene ("facade", {}, true, pcl::rspd::NormalScale::Automatic, unbounded_no_volume);
  const Detection facade_volume = detectScene ("facade", {}, true, pcl::rspd::NormalScale::Automatic, unbounded);
  EXPECT_EQ (facade.score.false_planes, 0);
  EXPECT_GE (facade.score.f1, 0.99);
  EXPECT_GE (facade_unbounded.score.false_planes, 1);
  EXPECT_EQ (facade_volume.score.false_planes, 0);
  pcl::rspd::SceneOptions o;
  o.outlier_ratio = 0.15;
  const Detection industrial = detectScene ("industrial", o);
  const Detection industrial_unbounded = detectScene ("industrial", o, true, pcl::rspd::NormalScale::Automatic, unbounded);
  EXPECT_EQ (industrial.score.false_planes, 0);
  EXPECT_GE (industrial.score.f1, 0.99);
  EXPECT_LT (industrial.curved_claimed, 0.02);
  EXPECT_GE (industrial_unbounded.score.false_planes, 1);
}

TEST (Scenario, FacadesOutliersEndingBelowTheWallAreNoPlane)
{
  // The facade with 25 % outliers at 100,000 points (seed 23): where the outliers' box ends below
  // the wall, a retested outlier seed grew into a slab 0.9 m thick (959 samples; the layer beside
  // its band on the outliers' side held 3.4 times as many). Measured: F1 0.9285 with one false
  // plane without the volume-layer check, 0.9953 and none with it. The final volume layers, judging
  // every plane once final, drop it too (0.9956 with them alone): both off for "without", and the
  // plane support's clutter share, which releases part of the slab (0.9505 with it alone).
  pcl::rspd::SceneOptions o;
  o.num_points = 100000;
  o.outlier_ratio = 0.25;
  o.seed = 23;
  const auto off = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    EXPECT_TRUE (s.getVolumeLayerCheck ());
    s.setVolumeLayerCheck (false);
    s.setFinalVolumeLayerCheck (false);
    s.setSupportClutter (false);
  };
  const auto final_only = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setVolumeLayerCheck (false); };
  const Detection without = detectScene ("facade", o, true, pcl::rspd::NormalScale::Automatic, off);
  const Detection last = detectScene ("facade", o, true, pcl::rspd::NormalScale::Automatic, final_only);
  const Detection with = detectScene ("facade", o);
  EXPECT_GE (without.score.false_planes, 1);
  EXPECT_LT (without.score.f1, 0.95);
  EXPECT_EQ (last.score.false_planes, 0);
  EXPECT_GE (last.stats.final_volume_layers, 1u);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_EQ (with.score.found, 16);
  EXPECT_GE (with.score.f1, 0.99);
}

TEST (Scenario, RoughBoxSideOnPclNormalsNeedsTheStricterJudgeOfGrownPlanes)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // Seed 8 at 50,000 points on PCL's k = 50 normals: a side of the σ = 3 cm box (411 samples) is
  // seeded, grows to 192 samples and is judged once grown; its quadric's share of the residual,
  // 0.041, is the 0.95 quantile of a flat plane's to three digits, and at 0.95 the face is dropped
  // (31 of 32; measured). Measured with the judge on the bend alone: the normals of that face do
  // not turn, and with the normal-turn share at its default the face is kept at 0.95 too.
  pcl::rspd::SceneOptions o;
  o.seed = 8;
  o.num_points = 50000;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("boxes", o);
  const auto normals = pclNormals (scene.cloud);
  const Detection strict = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setGrownPlaneNormalTurn (0.0);
  });
  const Detection loose = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    EXPECT_DOUBLE_EQ (s.getGrownPlaneBendConfidence (), 0.975);
    s.setGrownPlaneBendConfidence (1.0); // refused: not below 1
    s.setGrownPlaneBendConfidence (0.95);
    EXPECT_DOUBLE_EQ (s.getGrownPlaneBendConfidence (), 0.95);
    s.setGrownPlaneNormalTurn (0.0);
  });
  const Detection turn = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setGrownPlaneBendConfidence (0.95);
  });
  EXPECT_EQ (strict.score.found, 32);
  EXPECT_LE (loose.score.found, 31);
  EXPECT_EQ (turn.score.found, 32);
  EXPECT_EQ (strict.score.false_planes, 0);
  EXPECT_GT (strict.score.f1, loose.score.f1);
}

TEST (Scenario, FlatBoxSideWhoseNormalsDoNotTurnIsNoBentPlane)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // Seed 16 at 40,000 points on PCL's k = 50 normals: a side of the σ = 2 cm box (439 samples) is
  // seeded by the small-plane pass and grows to 231 samples of that face alone, whose quadric bends
  // beyond the 97.5 % chance quantile (share 0.067 against 0.041) by 3.8° at the rim, more than half
  // its 5.1° MND; its normals turn by 1.1° against the quadric's 7.6° (measured): kept as flat.
  // Measured on the first grid: with the shifted grid this row finds 30 (rspd_compare; a loss the
  // README reports).
  pcl::rspd::SceneOptions o;
  o.seed = 16;
  o.num_points = 40000;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("boxes", o);
  const auto normals = pclNormals (scene.cloud);
  const Detection kept = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setShiftedGrid (false);
  });
  const Detection judged = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setShiftedGrid (false);
    EXPECT_DOUBLE_EQ (s.getGrownPlaneNormalTurn (), 0.25);
    s.setGrownPlaneNormalTurn (-1.0); // refused
    s.setGrownPlaneNormalTurn (std::numeric_limits<double>::quiet_NaN ()); // refused
    EXPECT_DOUBLE_EQ (s.getGrownPlaneNormalTurn (), 0.25);
    s.setGrownPlaneNormalTurn (0.0);
  });
  EXPECT_GE (kept.score.found, 31);
  EXPECT_LE (judged.score.found, 30);
  EXPECT_EQ (kept.score.false_planes, 0);
  EXPECT_GT (kept.score.f1, judged.score.f1);
}

TEST (Scenario, SparseStaircaseOnPclNormalsNeedsTheSmallPassThickCells)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // 10,000 samples with PCL's k = 50 normals: one riser (250 samples) never passes T1 in a cell of
  // its own; its thick cells, joined once the small-plane pass's growth is stable, seed it, where
  // their parents across its edge with a tread (bent) would have replaced them (29 -> 30 of 30, measured).
  pcl::rspd::SceneOptions o;
  o.num_points = 10000;
  // Measured without the trimmed normals for what growth left and the shifted grid, which seed that
  // riser too.
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("staircase", o);
  const auto normals = pclNormals (scene.cloud);
  const Detection joined = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setLeftNormalRefitOnGivenNormals (false);
    s.setShiftedGrid (false);
  });
  const Detection cells = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setLeftNormalRefitOnGivenNormals (false);
    s.setShiftedGrid (false);
    s.setSmallPassThickCellJoin (false);
  });
  EXPECT_EQ (joined.score.found, 30);
  EXPECT_LE (cells.score.found, 29);
  EXPECT_GT (joined.score.f1, cells.score.f1);
  EXPECT_GT (joined.stats.small_joined_seeds, 0u);
}

TEST (Scenario, SmallRoomPlanesOnPclNormalsGrowOnTheTrimmedNormalsTheyWereFoundOn)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // 30,000 samples with PCL's k = 50 normals: a table's front panel (106 samples) and a cabinet side
  // (124) are seeded on the trimmed normals of what growth left (20 and 16 samples), but on the PCA
  // normals, bent over most of them, they cannot grow and stay below ε = 30 (9 of 12; measured).
  pcl::rspd::SceneOptions o;
  o.num_points = 30000;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("room", o);
  const auto normals = pclNormals (scene.cloud);
  const Detection trimmed = detectOnKeptPclNormals (scene, normals);
  const Detection pca = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    EXPECT_TRUE (s.getTrimmedSeedGrowth ());
    s.setTrimmedSeedGrowth (false);
  });
  EXPECT_GE (trimmed.score.found, 11);
  EXPECT_LE (pca.score.found, 9);
  EXPECT_EQ (trimmed.score.false_planes, 0);
  EXPECT_GT (trimmed.score.f1, pca.score.f1 + 0.005);
}

TEST (Scenario, SparseBoxesOnPclNormalsNeedReestimationWithinT2AndTheNoisyBentSplit)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // 10,000 samples with PCL's k = 50 normals: box faces of 36-123 samples, whose normals average
  // over half a face. A noisy seed's plane re-estimated from samples of the faces around it widened
  // to MND 173° and MDP 0.81 m and held a whole box (five faces, one false plane); kept within T2,
  // its seed's face and others are found (8 -> 11 of 32, F1 0.811 -> 0.861), and noisy seeds'
  // planes grown over an edge are split into their flat sides rather than dropped (11 -> 13,
  // measured). Those measured without the trimmed normals for what growth left, which find more
  // faces still: a face lies within a neighbourhood's reach (~0.3 m) of its edges, its normals bend,
  // and T3 fails its cells; on the trimmed planes' normals of the samples growth left, the
  // small-plane pass seeds them (13 -> 18 of 32, F1 0.862 -> 0.900; RegionGrowing finds 15).
  pcl::rspd::SceneOptions o;
  o.num_points = 10000;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("boxes", o);
  const auto normals = pclNormals (scene.cloud);
  const Detection refit = detectOnKeptPclNormals (scene, normals);
  EXPECT_GE (refit.score.found, 18);
  EXPECT_EQ (refit.score.false_planes, 0);
  EXPECT_GT (refit.stats.small_seeds_trimmed, 0u);
  // The arms below, measured before the rim bands, run without them (with them and without the
  // trimmed normals 11 of 32; the default, with both, 20).
  const Detection both = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setRimBands (false);
    s.setLeftNormalRefitOnGivenNormals (false);
    EXPECT_FALSE (s.getNoisyPlaneBentSplit ()); // off by default since the eighteenth session
    s.setNoisyPlaneBentSplit (true);
    EXPECT_TRUE (s.getNoisyPlaneBentSplit ());
  });
  const Detection dropped = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setRimBands (false);
    s.setLeftNormalRefitOnGivenNormals (false);
  });
  const Detection paper = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setRimBands (false);
    s.setLeftNormalRefitOnGivenNormals (false);
    EXPECT_TRUE (s.getBoundedReestimation ());
    s.setBoundedReestimation (false);
    EXPECT_FALSE (s.getBoundedReestimation ());
    s.setNoisyPlaneBentSplit (false);
  });
  EXPECT_GE (both.score.found, 13);
  EXPECT_GE (refit.score.found, both.score.found + 5);
  EXPECT_GT (refit.score.f1, both.score.f1 + 0.03);
  EXPECT_EQ (both.stats.left_refitted, 0u);
  EXPECT_EQ (both.score.false_planes, 0);
  EXPECT_GT (both.stats.noisy_bent_planes, 0u);
  EXPECT_LE (dropped.score.found, 11);
  EXPECT_EQ (dropped.stats.noisy_bent_planes, 0u);
  EXPECT_GE (dropped.score.found, paper.score.found + 2);
  EXPECT_GT (dropped.score.f1, paper.score.f1 + 0.03);
  EXPECT_GT (dropped.stats.kept_estimates, 0u);
  EXPECT_EQ (paper.stats.kept_estimates, 0u);
}

TEST (Scenario, NoisyCubeOnPclNormalsGetsNormalsEstimatedAgain)
{
  // σ = 3 % of the edge at 100,000 points: PCL's k = 50 normals come from a ball about as wide as the
  // noise, every face's normals spread past T2, and nothing is seeded (0 of 6, measured). They
  // spread as much as the k-neighbourhoods' PCA normals of a scale that resolves no surface: they
  // are estimated again at an adaptive scale, as without them.
  pcl::rspd::SceneOptions o;
  o.noise = 0.03;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("cube", o);
  const auto normals = pclNormals (scene.cloud);
  const Detection checked = detectOnPclNormals (scene, normals);
  const Detection kept = detectOnPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    EXPECT_TRUE (s.getGivenNormalCheck ());
    s.setGivenNormalCheck (false);
    EXPECT_FALSE (s.getGivenNormalCheck ());
  });
  EXPECT_TRUE (checked.stats.given_normals_replaced);
  EXPECT_EQ (checked.score.found, 6);
  EXPECT_GE (checked.score.f1, 0.94);
  EXPECT_FALSE (kept.stats.given_normals_replaced);
  EXPECT_LE (kept.score.found, 1);
}

TEST (Scenario, SparseStaircaseOnPclNormalsThatBlurItsStepsGetsNormalsEstimatedAgain)
{
  // 5,000 samples on 30 faces: PCL's k = 50 normals span two or three steps and turn smoothly
  // towards the stair's slope, so they agree with their neighbours (no noise to the first check),
  // and every cell seeded the slope: one plane held the stair (1 of 30 found, F1 0.02, measured).
  // At the automatic k (15) most samples resolve their own face, which those normals fit worse than
  // twice its plane's residual: the detection runs as without them.
  pcl::rspd::SceneOptions o;
  o.num_points = 5000;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("staircase", o);
  const auto normals = pclNormals (scene.cloud);
  const Detection checked = detectOnPclNormals (scene, normals);
  const Detection kept = detectOnPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setGivenNormalCheck (false);
  });
  EXPECT_TRUE (checked.stats.given_normals_replaced);
  EXPECT_TRUE (checked.stats.given_normals_blurred);
  EXPECT_EQ (checked.score.found, 30);
  EXPECT_GE (checked.score.f1, 0.95);
  EXPECT_FALSE (kept.stats.given_normals_blurred);
  EXPECT_LE (kept.score.found, 5);
  EXPECT_LT (kept.score.f1, 0.5);
}

TEST (Scenario, SparseFacadeOnPclNormalsOfTheGraphsScaleGetsNormalsEstimatedAgain)
{
  // 8,000 samples: on PCL's k = 50 normals, kept, one plane held two windows' panes (87 samples
  // each, in the same plane) and another pane only in part (15 of 16 found, F1 0.979, measured). Its faces are large, so those normals are tilted off the faces the
  // automatic k (15) resolves at 12 % of the probes only, but there wherever the 50-neighbourhood's
  // PCA normals are: the detection runs as without them (16 of 16, 0.992, and one false
  // plane, as on its own normals).
  pcl::rspd::SceneOptions o;
  o.num_points = 8000;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("facade", o);
  const auto normals = pclNormals (scene.cloud);
  const Detection checked = detectOnPclNormals (scene, normals);
  const Detection kept = detectOnKeptPclNormals (scene, normals);
  EXPECT_TRUE (checked.stats.given_normals_blurred);
  EXPECT_EQ (checked.score.found, 16);
  EXPECT_LE (checked.score.false_planes, 1);
  EXPECT_LE (kept.score.found, 15);
  EXPECT_GT (checked.score.f1, kept.score.f1 + 0.005);
  std::printf ("    F1 %.4f (%d of 16) on normals estimated again, %.4f (%d) on PCL's kept\n", checked.score.f1,
               checked.score.found, kept.score.f1, kept.score.found);
}

TEST (Scenario, FacadeOnPclNormalsGetsNoSlabOfOutliersFromTrimmedNormals)
{
  // 10,000 samples, 15 % outliers, PCL's k = 50 normals: trimmed normals of scattered outliers
  // agreed by chance on a seed of 79 samples (three in four outliers, MDP 0.80 m) that ended as two
  // false planes; a seed on trimmed normals thicker than every plane found is refused (measured).
  pcl::rspd::SceneOptions o;
  o.num_points = 10000;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("facade", o);
  const Detection d = detectOnKeptPclNormals (scene, pclNormals (scene.cloud));
  EXPECT_EQ (d.score.found, 16);
  // No plane made mostly of outliers. (A strip across a window's 20 cm step, wall and window
  // samples, is scored a fragment or a false plane depending on which side holds more of its
  // voxels: a fragment before the final refit, a false plane after; measured.)
  std::map<std::uint32_t, std::pair<std::size_t, std::size_t>> outliers_of; // plane -> (outliers, members)
  for (std::size_t i = 0; i < d.labels.size (); ++i)
    if (d.labels[i] != 0)
    {
      auto& c = outliers_of[d.labels[i]];
      c.first += scene.labels[i] == 0;
      ++c.second;
    }
  for (const auto& [plane, c] : outliers_of)
    EXPECT_LT (2 * c.first, c.second) << "plane " << plane << ": " << c.first << " outliers of " << c.second;
  EXPECT_LE (d.score.false_planes, 1);
  // Without the bound on a trimmed-normal seed's MDP the slab's outliers still end in planes: the
  // precision falls from 0.986 to 0.981 (measured).
  EXPECT_GE (d.score.precision, 0.984);
  EXPECT_GT (d.stats.left_refitted, 0u);
}

TEST (Scenario, StaircaseOnPclNormalsKeepsReleasedStripsOnTheirTread)
{
  // PCL's k = 50 normals: the top riser's plane held a strip of the tread's nose (259 samples) and
  // released it; its normals bent towards the riser, the tread turned it down, and it passed T1-T3
  // as a plane of its own, tilted 22° from the tread (one false plane, measured). It lies on the
  // tread (robust σ 1.2 mm about the tread's plane, 2.6 mm about its own): no plane. The tube check
  // (setCurvedTubeCheck) drops it too, a strip as thick as half its width: off here, so that the
  // released-layer check is measured alone.
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("staircase");
  const auto normals = pclNormals (scene.cloud);
  const Detection checked = detectOnPclNormals (scene, normals);
  const Detection tube_only = detectOnPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setReleasedLayerCheck (false);
  });
  const Detection seeded = detectOnPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    EXPECT_TRUE (s.getReleasedLayerCheck ());
    s.setReleasedLayerCheck (false);
    EXPECT_FALSE (s.getReleasedLayerCheck ());
    s.setCurvedTubeCheck (false);
  });
  EXPECT_EQ (checked.score.found, 30);
  EXPECT_EQ (checked.score.false_planes, 0);
  EXPECT_EQ (tube_only.score.false_planes, 0);
  EXPECT_GE (seeded.score.false_planes, 1);
  EXPECT_GT (checked.score.f1, seeded.score.f1);
}

TEST (Scenario, SparseBoxesNeedTheBendNoiseTest)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // 30,000 samples: a box face holds 110-370 and is seeded by small cells of 15-60, noisier than
  // the smooth floor and wall, so judged flat first. A quadric fitted to 16 samples of a flat face
  // explains a quarter of their noise two times in five, and one fitted to a grown face of 127
  // samples at σ 2 cm bends by 1.7° by chance against an MND of 3.3°: a fixed share and a bend of
  // half the MND dropped faces (26 of 32); tested against what noise explains, 29 of 32 (measured;
  // 32 and 28 since rim cells are retested until stable).
  pcl::rspd::SceneOptions o;
  o.num_points = 30000;
  const Detection noise = detectScene ("boxes", o);
  const Detection share = detectScene ("boxes", o, true, pcl::rspd::NormalScale::Automatic,
                                       [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                         EXPECT_TRUE (s.getBendNoiseTest ());
                                         s.setBendNoiseTest (false);
                                         EXPECT_FALSE (s.getBendNoiseTest ());
                                       });
  EXPECT_GE (noise.score.found, 31);
  EXPECT_LE (share.score.found, 28);
  EXPECT_GE (noise.score.f1, 0.975);
  EXPECT_EQ (noise.score.false_planes, 0);
}

TEST (Scenario, SparseRoomsTableTopNeedsTheSmallSeedMndFloor)
{
  const PositionPlanesOff one_departure_at_a_time; // see PositionPlanesOff
  // 30,000 samples with PCL's k = 50 normals (as rspd_compare shares them): the table top's small
  // seed (17 samples) has an MND of 0.1°, its normals averaged over nearly the same neighbours,
  // where the room's planes have 1-2°; it grew to 25 samples, short of the 50 % that re-estimates
  // it, and stayed under ε = 30. Floored at the tightest plane's MND it grows to 39 (measured).
  // Without the trimmed normals for what growth left, whose seed of it is floored too.
  pcl::rspd::SceneOptions o;
  o.num_points = 30000;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("room", o);
  const auto normals = pclNormals (scene.cloud);
  const Detection floored = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setLeftNormalRefitOnGivenNormals (false);
  });
  const Detection own = detectOnKeptPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setLeftNormalRefitOnGivenNormals (false);
    EXPECT_TRUE (s.getSmallSeedMndFloor ());
    s.setSmallSeedMndFloor (false);
  });
  EXPECT_GE (floored.score.found, 9);
  EXPECT_LE (own.score.found, 8);
  EXPECT_GT (floored.score.f1, own.score.f1);
  EXPECT_EQ (floored.score.false_planes, 0);
}

TEST (Scenario, RotatedFacadeKeepsItsPlanes)
{
  // Rotated, the octree's cells cut the facade obliquely; one coarse cell holding wall, recessed
  // windows and outliers passed T1-T3 with MND 51° and, grown and merged, made the whole scene one
  // plane (0 of 16 found). Dropping seeds whose MND is an outlier among all seeds prevents it.
  const Detection base = detectScene ("facade");
  pcl::rspd::SceneOptions turned;
  turned.random_rotation = true;
  const Detection rotated = detectScene ("facade", turned);
  EXPECT_EQ (rotated.score.found, 16);
  EXPECT_NEAR (rotated.score.f1, base.score.f1, 0.02);
}

TEST (Scenario, TurnedSceneGivesTheSamePlanes)
{
  // In the dominant-plane frame (the default) the octree's cells and the medians of Eqs. 3-4 turn
  // with the cloud, so three random rotations of the room and of the staircase label their points
  // as the original does: scored against the original's truth and positions, F1 within 0.005.
  // In the cloud's own axes (the paper), a rotated facade scores lower for some rotations (0.799
  // against 0.995 at rotation seed 1; at seed 3 it was 0.989 against 0.994 until the surrounding-
  // clutter tail made the two agree, 0.9955 each; it also lost planes before the small-plane pass
  // took seeds up to the noisiest plane's MND).
  for (const char* name : {"room", "staircase"})
  {
    const pcl::rspd::Scene scene = pcl::rspd::makeScene (name);
    const Detection base = detect (scene.cloud, scene.labels);
    for (std::uint32_t seed : {11u, 12u, 13u})
    {
      pcl::PointCloud<pcl::PointXYZ> turned = scene.cloud;
      pcl::rspd::SceneOptions o;
      o.random_rotation = true;
      o.seed = seed;
      pcl::rspd::transformCloud (turned, o);
      const Detection run = detect (turned, scene.labels);
      const pcl::rspd::EvaluationResult on_original =
        pcl::rspd::evaluatePlaneDetection (scene.cloud, scene.labels, run.labels);
      EXPECT_NEAR (on_original.f1, base.score.f1, 0.005) << name << ", rotation seed " << seed;
      EXPECT_EQ (on_original.found, base.score.found) << name << ", rotation seed " << seed;
    }
  }
  const pcl::rspd::Scene facade = pcl::rspd::makeScene ("facade");
  pcl::PointCloud<pcl::PointXYZ> turned = facade.cloud;
  pcl::rspd::SceneOptions o;
  o.random_rotation = true;
  o.seed = 1;
  pcl::rspd::transformCloud (turned, o);
  const auto axes = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setDetectionFrame (pcl::rspd::DetectionFrame::InputAxes);
  };
  const Detection planes = detect (turned, facade.labels);
  const Detection input_axes = detect (turned, facade.labels, nullptr, true, pcl::rspd::NormalScale::Automatic, axes);
  EXPECT_EQ (planes.score.found, 16);
  EXPECT_LT (input_axes.score.f1, planes.score.f1 - 0.002);
}

TEST (Scenario, ScaledAndShiftedSceneGivesTheSameScore)
{
  const Detection base = detectScene ("facade");
  pcl::rspd::SceneOptions mm;
  mm.scale = 1000.0;
  const Detection scaled = detectScene ("facade", mm);
  pcl::rspd::SceneOptions far;
  far.offset = Eigen::Vector3d (1000.0, 1000.0, 0.0);
  const Detection shifted = detectScene ("facade", far);
  EXPECT_NEAR (scaled.score.f1, base.score.f1, 0.01);
  EXPECT_NEAR (shifted.score.f1, base.score.f1, 0.01);
  EXPECT_EQ (scaled.score.found, base.score.found);
  EXPECT_EQ (shifted.score.found, base.score.found);
}

TEST (SharedData, SynPebTest100)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::uint32_t> truth;
  if (!loadShared ("synpeb_test100", cloud, truth))
    GTEST_SKIP () << "../shared/data not present";
  const Detection r = detect (cloud, truth);
  EXPECT_GE (r.score.found, 9);
  EXPECT_GE (r.score.f1, 0.95);
}

namespace
{
/** Folded plates: \a rows x \a cols sheets, each of two or three 0.3-0.6 m faces (0.4-0.7 m long)
  * that fold by 20-40 degrees, turned about z at random; uniform samples, Gaussian noise \a sigma
  * along each face's normal, truth 1..K per face, no other surface. Dense enough (about 30,000
  * samples per square metre) that k = 50 neighbourhoods are about as wide as 2 cm of noise. */
void
foldedPlates (int rows, int cols, std::size_t samples, float sigma, std::uint32_t seed,
              pcl::PointCloud<pcl::PointXYZ>& cloud, std::vector<std::uint32_t>& truth)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<double> u (0.0, 1.0);
  struct Face
  {
    Eigen::Vector3d o, a, b;
  };
  std::vector<Face> faces;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
    {
      const Eigen::Matrix3d turn = Eigen::AngleAxisd (M_PI * u (rng), Eigen::Vector3d::UnitZ ()).toRotationMatrix ();
      const Eigen::Vector3d origin (1.6 * c, 1.8 * r, 0.3);
      const double length = 0.4 + 0.3 * u (rng);
      double tilt = 20.0 * u (rng);
      Eigen::Vector3d p = Eigen::Vector3d::Zero ();
      const int count = u (rng) < 0.5 ? 2 : 3;
      for (int f = 0; f < count; ++f)
      {
        const double t = tilt * M_PI / 180.0, w = 0.3 + 0.3 * u (rng);
        const Eigen::Vector3d a (w * std::cos (t), 0.0, w * std::sin (t));
        faces.push_back ({origin + turn * p, turn * a, turn * Eigen::Vector3d (0.0, length, 0.0)});
        p += a;
        tilt += (u (rng) < 0.5 ? -1.0 : 1.0) * (20.0 + 20.0 * u (rng));
      }
    }
  double total = 0.0;
  for (const auto& f : faces)
    total += f.a.cross (f.b).norm ();
  std::normal_distribution<double> g (0.0, sigma);
  for (std::size_t k = 0; k < faces.size (); ++k)
  {
    const Face& f = faces[k];
    const Eigen::Vector3d n = f.a.cross (f.b).normalized ();
    const auto m = static_cast<std::size_t> (static_cast<double> (samples) * f.a.cross (f.b).norm () / total);
    for (std::size_t i = 0; i < m; ++i)
    {
      const Eigen::Vector3d q = f.o + u (rng) * f.a + u (rng) * f.b + g (rng) * n;
      cloud.push_back (pcl::PointXYZ (static_cast<float> (q.x ()), static_cast<float> (q.y ()), static_cast<float> (q.z ())));
      truth.push_back (static_cast<std::uint32_t> (k + 1));
    }
  }
}
} // namespace

TEST (Scenario, FoldedPlatesNeedTheBentPlaneSplit)
{
  // With 2.5 cm of noise a k-neighbourhood's PCA normal is mostly noise, MND is wide, and growth
  // carries a plane over a fold of 20-40 degrees onto the next face (as on synpeb_pc01's boxes).
  // Measured over seeds 1-4 at 1.5, 2 and 2.5 cm: the split never loses, and gains most here
  // (seed 1: 20 -> 27 of 31 faces found, F1 0.608 -> 0.790).
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::uint32_t> truth;
  foldedPlates (3, 4, 250000, 0.025f, 1, cloud, truth);
  const Detection bent = detect (cloud, truth);
  const auto unbent = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setBentPlaneSplit (false); };
  const Detection whole = detect (cloud, truth, nullptr, true, pcl::rspd::NormalScale::Automatic, unbent);
  EXPECT_GE (bent.score.found, whole.score.found + 5);
  EXPECT_GE (bent.score.f1, whole.score.f1 + 0.12);
  EXPECT_LE (bent.score.false_planes, whole.score.false_planes);
  // At 5 mm of noise normals resolve the folds, and the split changes nothing.
  cloud.clear ();
  truth.clear ();
  foldedPlates (3, 4, 250000, 0.005f, 1, cloud, truth);
  const Detection clean = detect (cloud, truth);
  const Detection clean_whole = detect (cloud, truth, nullptr, true, pcl::rspd::NormalScale::Automatic, unbent);
  EXPECT_EQ (clean.labels, clean_whole.labels);
  EXPECT_GE (clean.score.f1, 0.95);
}

TEST (Scenario, NoisyFoldsNeedTheEdgesTheNormalsConfirm)
{
  // At 3 cm of noise on faces 0.3-0.6 m wide two planes lower the positions' σ by less than the
  // bend test asks (0.8) on many folds, and a plane grown over the fold holds both faces; the
  // normals turn there by 20-40° in one step and confirm the edge (isEdgeTheNormalsConfirm). Seeds
  // 1-4 at σ = 2-3.5 cm (measured): found up on 12 of 16, F1 up by 0.006-0.084 on all 16; this one
  // 25 -> 29 of 32 faces, 0.770 -> 0.848.
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::uint32_t> truth;
  foldedPlates (3, 4, 250000, 0.03f, 2, cloud, truth);
  const Detection on = detect (cloud, truth);
  const Detection off = detect (cloud, truth, nullptr, true, pcl::rspd::NormalScale::Automatic,
                                [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                  EXPECT_TRUE (s.getBentNormalEdges ());
                                  s.setBentNormalEdges (false);
                                  EXPECT_FALSE (s.getBentNormalEdges ());
                                });
  EXPECT_GE (on.score.found, off.score.found + 3);
  EXPECT_GE (on.score.f1, off.score.f1 + 0.05);
  EXPECT_LE (on.score.false_planes, off.score.false_planes);
}

TEST (Scenario, FoldsAreNoCurvedSurfaces)
{
  // Planes grown over the folds of noisy folded plates bend, and a quadric explains much of their
  // residual, as on a curved surface; but their normals turn in steps at the edges, not smoothly,
  // and the curved-surface check leaves them to the bent-plane split (fold ratio 0.5). Without that
  // test every plane the quadric calls curved is dropped.
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::uint32_t> truth;
  foldedPlates (3, 4, 250000, 0.025f, 1, cloud, truth);
  const Detection folds = detect (cloud, truth);
  const auto any_bend = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setCurvedFoldRatio (std::numeric_limits<double>::infinity ());
    EXPECT_EQ (s.getCurvedFoldRatio (), std::numeric_limits<double>::infinity ());
  };
  const Detection dropped = detect (cloud, truth, nullptr, true, pcl::rspd::NormalScale::Automatic, any_bend);
  const auto unchecked = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setCurvedPlaneCheck (false); };
  const Detection off = detect (cloud, truth, nullptr, true, pcl::rspd::NormalScale::Automatic, unchecked);
  EXPECT_EQ (folds.labels, off.labels);
  EXPECT_LE (dropped.score.found, folds.score.found - 5);
}

TEST (Scenario, NoisyPillarIsNoPlane)
{
  // At σ = 2 cm the room's 0.3 m pillar grows into planes that pass every test of the paper; the
  // curved-surface check drops them: their samples bend and their normals turn smoothly. Unchecked,
  // on the first grid alone (3 false planes; 2 with the shifted grid, curved samples claimed 63 %).
  pcl::rspd::SceneOptions options;
  options.noise = 0.02;
  const auto unchecked = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setCurvedPlaneCheck (false);
    firstGridOnly (s);
  };
  const Detection off = detectScene ("room", options, true, pcl::rspd::NormalScale::Automatic, unchecked);
  const Detection on = detectScene ("room", options);
  EXPECT_GT (off.curved_claimed, 0.5);
  EXPECT_GE (off.score.false_planes, 3);
  EXPECT_LT (on.curved_claimed, 0.2);
  EXPECT_LE (on.score.false_planes, 1);
  EXPECT_GE (on.score.f1, off.score.f1 + 0.004);
}

TEST (SharedData, SynPebPc01)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::uint32_t> truth;
  if (!loadShared ("synpeb_pc01", cloud, truth))
    GTEST_SKIP () << "../shared/data not present";
  // Noisy (1 cm RMS), 60 mostly small planes: the paper's method finds 11 (the authors' code 10),
  // 16 with the small-plane pass; coplanar-group merging keeps facets of the faceted objects apart.
  // Its planes follow no dominant frame, and the score depends on where the octree's cells fall:
  // in the file's own axes 0.825 (40 found), 0.733-0.770 for three random rotations (README); in the
  // dominant-plane frame 0.723 (37) whatever the rotation. Its two largest planes are coplanar,
  // 13 cm apart; samples of the facets crossing the gap join both and carry M1 across, and only the
  // connected-parts split keeps them two planes (0.730 -> 0.828, 37 -> 38 found, measured). Its
  // boxes' faces (1-2 cm noise on 0.3-0.7 m faces) give PCA normals so noisy that MND reaches 30-70
  // degrees: growth carries a plane over edges of 19-42 degrees onto the next face, and only the
  // bent-plane split separates them (0.828 -> 0.909, 38 -> 51 found, measured). Such a plane's band
  // also covered the rest of a box face, whose seed the small-plane pass took for a layer of its
  // noise until a bent plane the seed bends away from stopped counting (isBandLayer: 0.916 -> 0.922,
  // 51 -> 52). Two such planes cut at their edges left one face in two parts until the parts of
  // split planes that are one face were joined again (joinSplitFaces: fragments 9 -> 2). Noisy seeds'
  // planes grown over an edge split rather than dropped gave 0.922 -> 0.923 (fragments 2 -> 4; off
  // by default since the eighteenth session: 0.922). Two faces of 271 and 452 samples beside noisier
  // faces at 24°, whose growth stopped short of ε and whose strips along the edge the neighbours'
  // bands held, need the small-plane completion (53 -> 55 found, 0.931 -> 0.938, measured). Two
  // faces 40° apart at σ 1.4-2 cm, 0.33-0.38 m wide, held by one plane (and one 24° from two
  // neighbours, half held by each), whose two planes lower the positions' σ to 0.80-0.86 only, are
  // split where the normals confirm the edge (isEdgeTheNormalsConfirm: 55 -> 56, 0.940 -> 0.948).
  const Detection r = detect (cloud, truth);
  EXPECT_GE (r.score.found, 56);
  EXPECT_GE (r.score.f1, 0.945);
  EXPECT_LE (r.score.fragments, 4);
  const Detection positions = detect (cloud, truth, nullptr, true, pcl::rspd::NormalScale::Automatic,
                                      [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) { s.setBentNormalEdges (false); });
  EXPECT_LE (positions.score.found, 55);
  EXPECT_LT (positions.score.f1, 0.944);
  const Detection uncompleted = detect (cloud, truth, nullptr, true, pcl::rspd::NormalScale::Automatic,
                                        [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                          EXPECT_TRUE (s.getSmallPlaneCompletion ());
                                          s.setSmallPlaneCompletion (false);
                                        });
  EXPECT_LE (uncompleted.score.found, 54); // 53 before the edges the normals confirm
  // Both bent splits off: the later one on every plane, and the one on noisy seeds' planes before
  // they are judged flat (0.85 and 40 found before the small-plane completion, 0.870 and 44 with it,
  // whose faces beside noisier planes those planes' wider bands then cover more of; measured).
  const auto unbent = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setBentPlaneSplit (false);
    s.setNoisyPlaneBentSplit (false);
  };
  const Detection bent = detect (cloud, truth, nullptr, true, pcl::rspd::NormalScale::Automatic, unbent);
  EXPECT_LT (bent.score.f1, 0.89);
  EXPECT_LE (bent.score.found, 45);
  const auto whole = [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    s.setBentPlaneSplit (false);
    s.setNoisyPlaneBentSplit (false);
    s.setConnectedParts (false);
    s.setFinalParts (false); // which would split them at the end instead (0.876, measured)
  };
  const Detection merged = detect (cloud, truth, nullptr, true, pcl::rspd::NormalScale::Automatic, whole);
  EXPECT_LT (merged.score.f1, 0.79); // 0.76 before the small-plane completion, 0.772 with it
}

TEST (SharedData, SynPebPc01OnPclNormalsNeedsBentSidesWithinTheirPlanesMnd)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::uint32_t> truth;
  if (!loadShared ("synpeb_pc01", cloud, truth))
    GTEST_SKIP () << "../shared/data not present";
  // On PCL's k = 50 normals (as rspd_compare shares them) MND reaches 70° on planes over two box
  // faces; each side, as noisy, failed T2 (60°) and the plane stayed whole: 47 of 60, F1 0.888.
  // Sides held to the MND of the plane they were cut from: 52, 0.915 (measured; 53, 0.926 with the
  // shifted grid, and 47, 0.897 with it but without the bound: measured without it here; with the
  // edge corners of issue #6's thirty-eighth session 52, 0.928 and 47, 0.905).
  pcl::rspd::Scene scene;
  scene.cloud = cloud;
  scene.labels = truth;
  for (const auto t : truth)
    scene.kinds.push_back (t > 0 ? pcl::rspd::SurfaceKind::Plane : pcl::rspd::SurfaceKind::Outlier);
  const auto normals = pclNormals (scene.cloud);
  const Detection bounded = detectOnPclNormals (scene, normals);
  const Detection paper = detectOnPclNormals (scene, normals, [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
    EXPECT_TRUE (s.getBentSideParentMnd ());
    s.setBentSideParentMnd (false);
    EXPECT_FALSE (s.getBentSideParentMnd ());
    s.setShiftedGrid (false);
    s.setBentNormalEdges (false); // which split one more of those planes (0.918, measured)
  });
  EXPECT_GE (bounded.score.found, 52);
  EXPECT_GE (bounded.score.f1, 0.91);
  EXPECT_EQ (bounded.score.false_planes, 0);
  EXPECT_LE (paper.score.found, 48);
  EXPECT_LT (paper.score.f1, 0.915);
}

TEST (SharedData, CgalBuildingPseudoTruth)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::uint32_t> truth;
  if (!loadShared ("cgal_building", cloud, truth))
    GTEST_SKIP () << "../shared/data not present";
  const Detection r = detect (cloud, truth); // pseudo ground truth: a smoke test, not a score to chase
  EXPECT_GE (r.score.found, 10);
}

TEST (Scenario, ScannersRingsBelowItsHeadAreTheFloors)
{
  // A room scanned on a scanner's grid (scripts/scan_grid_rows.txt, layout 315, 212,000 points,
  // turned): below the sensor its rows close into rings, 1,195 samples within centimetres whose
  // nearest neighbours are each other. No growth reaches them; the position planes found them as a
  // plane, which lies on the floor: seen through the edges into it (liesOnNeighbourPlane), it is no
  // fragment, and it gives the floor those samples (position_join_beside) instead of a hole.
  pcl::rspd::SceneOptions o;
  o.scan_grid = true;
  o.layout = 315;
  o.num_points = 212000;
  o.noise = 0.0041;
  o.seed = 131;
  o.random_rotation = true;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("room", o);
  const auto with = [&scene] (bool join) {
    return detect (scene.cloud, scene.labels, nullptr, true, pcl::rspd::NormalScale::Automatic,
                   [join] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                     EXPECT_TRUE (s.getPositionJoinBeside ());
                     s.setPositionJoinBeside (join);
                   });
  };
  const auto left = [&scene] (const Detection& d) { // samples of a plane that no plane holds
    std::size_t n = 0;
    for (std::size_t i = 0; i < d.labels.size (); ++i)
      n += scene.labels[i] != 0 && d.labels[i] == 0;
    return n;
  };
  const Detection joined = with (true);
  const Detection apart = with (false);
  for (const Detection* d : {&joined, &apart})
  {
    EXPECT_EQ (d->score.found, 12);
    EXPECT_EQ (d->score.fragments, 0);
    EXPECT_EQ (d->score.false_planes, 0);
  }
  EXPECT_GE (left (apart), left (joined) + 1000);
  EXPECT_GE (joined.score.f1, apart.score.f1);
}


namespace
{
/** Flat-topped tanks: a square ground (truth 1) of side \a side and \a tanks vertical cylinders
  * standing on it, radius 0.8-1.3 m, 3-6 m tall, each with a flat round top (truth 2, 3, ...); their
  * walls are curved (truth 0). Samples uniform by area (none under a tank), Gaussian noise \a sigma
  * along each surface's normal. */
void
flatTopTanks (int tanks, double side, std::size_t samples, float sigma, std::uint32_t seed,
              pcl::PointCloud<pcl::PointXYZ>& cloud, std::vector<std::uint32_t>& truth)
{
  std::mt19937 rng (seed);
  std::uniform_real_distribution<double> u (0.0, 1.0);
  std::normal_distribution<double> g (0.0, sigma);
  struct Tank
  {
    double x, y, r, h;
  };
  std::vector<Tank> all;
  for (int t = 0; t < tanks; ++t)
    all.push_back ({side * (t + 0.5) / tanks, side * (0.3 + 0.4 * u (rng)), 0.8 + 0.5 * u (rng), 3.0 + 3.0 * u (rng)});
  double area = side * side;
  for (const auto& t : all)
    area += 2.0 * M_PI * t.r * t.h; // the tops make up for the ground under them
  const auto add = [&] (const Eigen::Vector3d& q, std::uint32_t label) {
    cloud.push_back (pcl::PointXYZ (static_cast<float> (q.x ()), static_cast<float> (q.y ()), static_cast<float> (q.z ())));
    truth.push_back (label);
  };
  const auto count = [&] (double a) { return static_cast<std::size_t> (static_cast<double> (samples) * a / area); };
  for (std::size_t i = 0, n = count (side * side); i < n; ++i)
  {
    const double x = side * u (rng), y = side * u (rng);
    std::uint32_t label = 1;
    for (std::size_t t = 0; t < all.size (); ++t)
      if (std::hypot (x - all[t].x, y - all[t].y) < all[t].r)
        label = static_cast<std::uint32_t> (t + 2); // under the tank: its top's sample instead
    add (Eigen::Vector3d (x, y, label == 1 ? g (rng) : all[label - 2].h + g (rng)), label);
  }
  for (const auto& t : all)
    for (std::size_t i = 0, n = count (2.0 * M_PI * t.r * t.h); i < n; ++i)
    {
      const double a = 2.0 * M_PI * u (rng), r = t.r + g (rng);
      add (Eigen::Vector3d (t.x + r * std::cos (a), t.y + r * std::sin (a), t.h * u (rng)), 0);
    }
}

/** Share of the samples of truth plane \a plane that its likeliest label holds. */
double
recallOf (const std::vector<std::uint32_t>& truth, const std::vector<std::uint32_t>& labels, std::uint32_t plane)
{
  std::map<std::uint32_t, std::size_t> held;
  std::size_t total = 0;
  for (std::size_t i = 0; i < truth.size (); ++i)
    if (truth[i] == plane)
    {
      ++total;
      if (labels[i] != 0)
        ++held[labels[i]];
    }
  std::size_t best = 0;
  for (const auto& h : held)
    best = std::max (best, h.second);
  return total ? static_cast<double> (best) / static_cast<double> (total) : 0.0;
}
} // namespace

TEST (Scenario, FlatTankTopsKeepTheirRimBands)
{
  // A top's samples within a neighbourhood of its rim have the wall below in their neighbourhoods,
  // their normals tilt and growth leaves them; "most of their neighbours members" never holds across
  // that ring. With the rim bands the tops are whole; the walls stay no plane's.
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::uint32_t> truth;
  flatTopTanks (3, 12.0, 100000, 0.005f, 1, cloud, truth);
  std::vector<pcl::rspd::SurfaceKind> kinds;
  for (const auto t : truth)
    kinds.push_back (t == 0 ? pcl::rspd::SurfaceKind::Curved : pcl::rspd::SurfaceKind::Plane);
  const Detection with = detect (cloud, truth, &kinds);
  const Detection without = detect (cloud, truth, &kinds, true, pcl::rspd::NormalScale::Automatic,
                                    [] (pcl::RobustPlaneSegmentation<pcl::PointXYZ>& s) {
                                      EXPECT_TRUE (s.getRimBands ());
                                      s.setRimBands (false);
                                      EXPECT_FALSE (s.getRimBands ());
                                    });
  EXPECT_EQ (with.score.found, 4);
  EXPECT_EQ (with.score.false_planes, 0);
  EXPECT_LE (with.curved_claimed, 0.02);
  EXPECT_GT (with.score.f1, without.score.f1);
  for (std::uint32_t top = 2; top <= 4; ++top)
  {
    std::printf ("    top %u: %.3f of its samples in one plane (rim bands off: %.3f)\n", top,
                 recallOf (truth, with.labels, top), recallOf (truth, without.labels, top));
    EXPECT_GE (recallOf (truth, with.labels, top), 0.95);
  }
}
