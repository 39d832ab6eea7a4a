/*
 * pcl_rspd: the paper's evaluation protocol (Sec. 4.2): voxel-regularized precision, recall, F1.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Scores of one detection against per-point ground truth. */
struct EvaluationResult
{
  double precision = 0.0;      ///< TP / (TP + FP), 0 when nothing was detected
  double recall = 0.0;         ///< TP / (TP + FN)
  double f1 = 0.0;             ///< harmonic mean of precision and recall
  int found = 0;               ///< ground-truth planes matched by at least one detection
  int planes = 0;              ///< ground-truth planes (distinct non-zero truth labels)
  int detected = 0;            ///< detected planes (distinct non-zero detection labels)
  int fragments = 0;           ///< extra detections matched to an already-matched plane
  int false_planes = 0;        ///< detections matched to no ground-truth plane
  std::size_t tp = 0, fp = 0, fn = 0; ///< voxel counts
};

/** \brief Evaluate \a detected against \a truth by the protocol of Sec. 4.2 (see the .cpp for the
  * exact rules): voxels of edge \a voxel_ratio times the largest extent of the finite points, grid
  * anchored at their minimum corner; a voxel belongs to every plane with a sample in it; a detection
  * matches the truth plane of largest voxel IoU provided >= 50 % of its voxels lie in it and the
  * least-squares normals (fitted about the median point) differ by <= 30 degrees.
  * \param[in] cloud positions; non-finite points are ignored
  * \param[in] truth per-point ground-truth labels (0 = no plane), cloud.size() entries
  * \param[in] detected per-point detection labels (0 = no plane), cloud.size() entries
  * \param[in] voxel_ratio voxel edge as a fraction of the largest extent
  * \throws std::invalid_argument on size mismatch or voxel_ratio <= 0
  */
EvaluationResult
evaluatePlaneDetection (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                        const std::vector<std::uint32_t>& truth,
                        const std::vector<std::uint32_t>& detected,
                        double voxel_ratio = 0.01);

} // namespace rspd
} // namespace pcl
