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
  Outlier = 2  ///< scattered clutter / outlier (truth label 0)
};

/** \brief Options shared by every scene. Lengths are in the scene's own units (metres unless scaled). */
struct SceneOptions
{
  std::size_t num_points = 0;   ///< samples to generate (0: the scene's default)
  double noise = -1.0;          ///< Gaussian noise sigma along the surface normal (< 0: scene default)
  double outlier_ratio = -1.0;  ///< share of uniform outliers added (< 0: scene default)
  bool random_rotation = false; ///< apply a random rotation about the scene's centre
  double scale = 1.0;           ///< multiply every coordinate (e.g. 1000 for millimetres)
  Eigen::Vector3d offset = Eigen::Vector3d::Zero (); ///< translate after scaling/rotating
  bool shuffle = true;          ///< shuffle sample order (unorganized cloud)
  std::uint32_t seed = 1;       ///< random seed; same seed and options give the same scene
};

/** \brief A generated scene: cloud, per-point truth and per-point surface kind (same order). */
struct Scene
{
  std::string name;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::uint32_t> labels;   ///< 0 = no plane, 1..num_planes
  std::vector<SurfaceKind> kinds;      ///< what each sample lies on
  int num_planes = 0;                  ///< distinct plane labels used
};

/** \brief Names accepted by makeScene: "cube", "room", "staircase", "facade", "industrial",
  * "plane" (one noise-free square). */
std::vector<std::string>
sceneNames ();

/** \brief Generate the scene \a name. \throws std::invalid_argument for an unknown name. */
Scene
makeScene (const std::string& name, const SceneOptions& options = SceneOptions ());

} // namespace rspd
} // namespace pcl
