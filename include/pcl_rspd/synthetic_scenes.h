/*
 * pcl_rspd: synthetic scenes with per-point plane ground truth, for tests, benchmarks and the demo.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief What a generated sample lies on. */
enum class SurfaceKind : std::uint8_t
{
  Plane = 0,   ///< a planar surface (truth label > 0)
  Curved = 1,  ///< a curved surface: cylinder, pillar, sphere, tank, pipe (truth label 0)
  Outlier = 2  ///< scattered clutter / outlier (truth label 0); in the scanned room also the
               ///< samples of a plane seen by too few rays to count as ground truth
};

/** \brief Options shared by every scene. Lengths are in the scene's own units (metres unless scaled). */
struct SceneOptions
{
  std::size_t num_points = 0;   ///< samples to generate (0: the scene's default)
  /** Gaussian noise sigma in scene units before scaling, along the surface normal (along the
    * ray for the scanned room); < 0: the scene's default. */
  double noise = -1.0;
  /** Draw the noise in every direction instead (sigma per axis), as a sensor whose error is not
    * along the normal puts samples beyond a face's edge. */
  bool isotropic_noise = false;
  /** Share of num_points that are outliers, uniform in the scene's box grown by 5 % of its
    * diagonal on each side; in [0, 1], < 0: the scene's default (0.15 facade, 0 otherwise). */
  double outlier_ratio = -1.0;
  /** Rotate by a random rotation (drawn from the seed alone) about the centre of the scene's
    * nominal bounding box. */
  bool random_rotation = false;
  double scale = 1.0;           ///< multiply every coordinate, after rotating (e.g. 1000 for mm)
  Eigen::Vector3d offset = Eigen::Vector3d::Zero (); ///< translate after rotating and scaling
  bool shuffle = true;          ///< shuffle sample order (false: generation order, by surface)
  std::uint32_t seed = 1;       ///< random seed; same seed and options give the same scene
  /** Geometry: 0 draws the documented layout below; any other value draws the scene's dimensions
    * (sizes, counts, positions, radii) from that number within the ranges makeScene documents,
    * independently of \a seed, so that detection can be checked on scenes of the same kind that
    * no default was chosen on. */
  std::uint32_t layout = 0;
  /** The scanned room only: cast the rays on a regular grid of equal azimuth and elevation steps,
    * as a laser scanner turns, instead of in uniformly random directions. Rows of samples then lie
    * farther apart than the samples along them wherever a surface is seen obliquely, and the
    * floor and ceiling near the poles are sampled densely along circles (SynPEB's clouds are such
    * scans). */
  bool scan_grid = false;
};

/** \brief A generated scene: cloud, per-point truth and per-point surface kind (same order). */
struct Scene
{
  std::string name;
  /** width = size, height = 1, is_dense; for the scanned room sensor_origin_ is the scanner. */
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::uint32_t> labels;   ///< 0 = no plane, 1..num_planes
  std::vector<SurfaceKind> kinds;      ///< what each sample lies on
  int num_planes = 0;                  ///< distinct plane labels used
};

/** \brief Names accepted by makeScene, with their defaults (points, noise sigma, planes):
  * - "cube": 1 m cube surface (100k, 0.01, 6 planes)
  * - "room": 6 x 5 x 3 m room ray-cast from one sensor position (rays in random directions, or on
  *   a scanner's grid with SceneOptions::scan_grid), with door, table, cabinet, a
  *   pillar and a ball (200k, 0.005, 12 planes; density falls with distance, occluded parts empty)
  * - "staircase": 15 steps of tread + riser (100k, 0.002, 30 planes)
  * - "facade": 20 x 10 m wall with 15 recessed windows, 15 % outliers (200k, 0.03, 16 planes)
  * - "industrial": 20 m yard, ground, walls, platform, tanks and pipes (300k, 0.005, 6 planes)
  * - "boxes": 12 x 12 m floor and wall with six boxes of rising roughness (300k, 0.002, 32 planes)
  * - "plane": one noise-free 1 x 1 square (10k, 0, 1 plane)
  *
  * With options.layout > 0 the dimensions are drawn instead (uniformly, in metres): the cube is a
  * box of edges 0.5-1.5; the staircase has 8-20 steps 0.22-0.36 deep, 0.14-0.21 high and 0.8-1.6
  * wide; the facade is 12-30 x 6-14 m with 2+ x 2+ windows of 0.9-2.0 x 1.0-2.2 m recessed
  * 0.1-0.35 m; the industrial yard is 14-26 m with walls of 4-8 m, a platform a fifth to a third of
  * the yard, tanks of radius 0.8-1.5 m and pipes of 0.05-0.3 m; the room is 4.5-8 x 4-6.5 x
  * 2.4-3.5 m with its furniture, pillar (r 0.15-0.4) and ball (r 0.2-0.45) placed in proportion and
  * the sensor 1.3-1.8 m high; the boxes are 1.0-2.0 x 0.7-1.3 m. Noise and outliers keep their
  * defaults, which are absolute. The plane scene has one layout.
  */
std::vector<std::string>
sceneNames ();

/** \brief Generate the scene \a name with exactly options.num_points samples (or the default).
  * Plane samples are drawn proportionally to area, except in the ray-cast room.
  * \throws std::invalid_argument for an unknown name or invalid options (outlier ratio > 1,
  * non-positive scale, non-finite values). */
Scene
makeScene (const std::string& name, const SceneOptions& options = SceneOptions ());

/** \brief Move a given cloud as makeScene moves a generated one: the random rotation drawn from
  * options.seed (about the centre of the finite points' bounding box) if options.random_rotation,
  * then options.scale and options.offset. Point order is kept; non-finite points stay as they are;
  * the sensor origin moves with the points. Used to check that detection does not depend on a
  * cloud's orientation, units or position (the labels of the input still apply, point for point).
  * \throws std::invalid_argument for a non-positive or non-finite scale or a non-finite offset. */
void
transformCloud (pcl::PointCloud<pcl::PointXYZ>& cloud, const SceneOptions& options);

} // namespace rspd
} // namespace pcl
