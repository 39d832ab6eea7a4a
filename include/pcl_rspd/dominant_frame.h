/*
 * pcl_rspd: the frame the method works in, found from the normals (orientation independence).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/point_set.h>

#include <Eigen/Core>

namespace pcl
{
namespace rspd
{
/** \brief The axes the method works along (RobustPlaneSegmentation::setDetectionFrame). */
enum class DetectionFrame
{
  InputAxes,     ///< the paper: the cloud's own coordinate axes
  DominantPlanes ///< the dominant plane orientations of the samples' normals (dominantFrame)
};

/** \brief The rotation whose rows are the dominant directions of the samples' normals.
  *
  * Two steps of the paper depend on the cloud's orientation: the octree of the split is cut along
  * the coordinate axes, and a patch's centre and normal are component-wise medians (Eqs. 3-4).
  * Both are unchanged by swapping or flipping axes (the root cube is centred on the bounding box,
  * and the median of -x is minus the median of x), so working in this frame makes the result
  * depend only on the three axes as lines, which turn with the cloud: a rotated cloud gives the
  * rotated planes. It also cuts a scene whose walls are not aligned with its coordinate axes into
  * cells that hold one wall, not a diagonal slice of two.
  *
  * The first row is the mode of the unoriented normals: the candidate direction (one of up to 256
  * normals taken at an even stride) with most of up to 16384 strided normals within 15° of it, then
  * moved by a mean shift over all normals within 15°. The second is the same among directions
  * perpendicular to the first or, if no normal is, the points' main direction in that plane. The
  * third is their cross product. No length is involved. No samples: identity.
  */
Eigen::Matrix3d
dominantFrame (const PointSet& points);

/** \brief Rotate the samples' positions and normals: p <- rotation * p (the offset is unchanged). */
void
rotateSamples (PointSet& points, const Eigen::Matrix3d& rotation, int num_threads = 0);

} // namespace rspd
} // namespace pcl
