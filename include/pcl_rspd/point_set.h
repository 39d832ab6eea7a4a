/*
 * pcl_rspd: the valid samples of a cloud, centred, as the phases of the method see them.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl/types.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief The valid samples (finite, within the caller's indices) of an input cloud.
  *
  * Positions are centred in double precision on the middle of their bounding box and then stored
  * as float, so a scene 1 km from the origin is treated exactly as the same scene at the origin.
  * Every phase (split, grow, merge) works on internal indices 0..size()-1 into these arrays;
  * \a input_indices maps them back to the caller's cloud.
  */
struct PointSet
{
  std::vector<Eigen::Vector3f> points;       ///< centred positions
  std::vector<Eigen::Vector3f> normals;      ///< unit normals (unoriented); same size as points
  std::vector<pcl::index_t> input_indices;   ///< internal index -> index in the input cloud
  /** \brief Per sample, whether its normal was narrowed to one face at an edge
    * (narrowNormalsAtEdges); empty when that did not run. */
  std::vector<char> narrowed;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero (); ///< input position = point + offset

  /** \brief Number of valid samples. */
  std::size_t
  size () const { return points.size (); }
};

} // namespace rspd
} // namespace pcl
