/*
 * pcl_rspd: depth levels — clouds whose depth a structured-light or stereo camera quantized, and
 * the dither that makes the quantization error noise again (departure from the paper).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief The distinct depths of a cloud along its camera's axis, and whether they are a camera's
  * quantization (findDepthLevels). */
struct DepthLevels
{
  std::vector<double> levels;  ///< the levels' depths, increasing (empty unless quantized)
  std::vector<float> first;    ///< each level's lowest depth as a float (see findDepthLevels)
  std::size_t samples = 0;     ///< samples measured
  std::size_t on_levels = 0;   ///< samples whose level holds at least one other sample
  std::size_t distinct = 0;    ///< levels: distinct depths, those within two float steps as one
  bool quantized = false;      ///< the depths are a camera's levels: see findDepthLevels
};

/** \brief A camera's viewing axis from a cloud's sensor orientation (PCL's VIEWPOINT quaternion):
  * the z axis turned by it, as PCL's own viewpoint convention reads it. */
inline Eigen::Vector3d
viewingAxis (const Eigen::Quaternionf& orientation)
{
  return (orientation.cast<double> () * Eigen::Vector3d::UnitZ ()).normalized ();
}

/** \brief Whether the samples' depths along \a axis from \a origin take a camera's levels.
  *
  * A structured-light or stereo camera measures disparity in steps, so its depths take a few hundred
  * values (office1: 125 over 254,456 samples, 6-8 cm apart near 5 m). Every surface not square to
  * the axis becomes terraces at those depths; each terrace is exactly flat, with no spread, so it is
  * a plane of its own square to the axis, and growth stops at the next level. The depths are levels
  * when (no length is involved) at least 16 levels are taken, every sample lies in front of the
  * camera, and at least 95 % of the samples share their level with another sample. A level is a run
  * of depths, as floats, each within two float steps of the one before: the camera stored one float,
  * and recomputing it along an axis given as a float quaternion moves it by a step or two. Measured
  * depths do not repeat: a scene of horizontal floors and vertical walls seen along z, without noise,
  * repeats the floors' depths only, well under 95 % (the staircase: 62 %). Where there are more
  * samples than float depths in their range (tens of millions a few metres deep), runs form by
  * chance, a few float steps apart, and the dither moves samples by no more than that.
  * \param[in] positions samples, in the cloud's coordinates
  * \param[in] origin the camera's centre (PCL's sensor_origin_)
  * \param[in] axis the camera's unit viewing axis (PCL's sensor_orientation_ applied to +z)
  * \return the levels (filled only when quantized) and the counts */
DepthLevels
findDepthLevels (const std::vector<Eigen::Vector3d>& positions, const Eigen::Vector3d& origin, const Eigen::Vector3d& axis);

/** \brief Move each sample along its ray from \a origin to a depth drawn within its level's bin:
  * from half the gap to the level below to half the gap to the level above (the nearest gap at the
  * first and last levels), uniformly, by a hash of the sample's coordinates (the same sample gets
  * the same draw whatever the cloud's order). The quantization error becomes what it was before the
  * camera rounded it: noise along the ray, about gap / √12. A sample whose depth is no level, or on
  * or behind the camera, is left as it is. */
void
ditherDepthLevels (std::vector<Eigen::Vector3d>& positions, const Eigen::Vector3d& origin, const Eigen::Vector3d& axis,
                   const DepthLevels& levels);
} // namespace rspd
} // namespace pcl
