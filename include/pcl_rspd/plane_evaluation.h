/*
 * pcl_rspd: the paper's evaluation protocol (Sec. 4.2): voxel-regularized precision, recall, F1.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <array>
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
  * \param[in] grid_phase per axis, the fraction of a voxel edge by which the grid's origin lies
  *            below the minimum corner, each in [0, 1); zero (the default) is the paper's grid
  * \throws std::invalid_argument on size mismatch, voxel_ratio <= 0 or a phase outside [0, 1)
  */
EvaluationResult
evaluatePlaneDetection (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                        const std::vector<std::uint32_t>& truth,
                        const std::vector<std::uint32_t>& detected,
                        double voxel_ratio = 0.01,
                        const std::array<double, 3>& grid_phase = {0.0, 0.0, 0.0});

/** \brief The \a index-th grid phase of a fixed sequence for evaluatePlaneDetection: index 0 is
  * the paper's grid (no shift), the others spread evenly over [0, 1)^3 (the R3 low-discrepancy
  * sequence, frac(index / g^k) with g the plastic number), so any caller gets the same phases.
  *
  * Why: where a plane's noise band or rim lies close to a voxel boundary, the few samples on the
  * far side decide whether a voxel counts, and F1 moves with the grid's position alone (the
  * facade's labels over 16 phases, `rspd_evaluate --phases 16`: 0.975 to 0.999). Scores over several phases separate that from
  * the detection.
  */
std::array<double, 3>
gridPhase (std::size_t index);

/** \brief F1 and planes found over several grid phases of one labelling. */
struct PhaseScores
{
  std::size_t phases = 0; ///< grids scored: gridPhase (0) .. gridPhase (phases - 1)
  double f1_median = 0.0; ///< median F1 (mean of the two middle ones for an even count)
  double f1_min = 0.0;    ///< lowest F1
  double f1_max = 0.0;    ///< highest F1
  int found_min = 0;      ///< fewest ground-truth planes found
};

/** \brief evaluatePlaneDetection on the grids gridPhase (0) .. gridPhase (\a phases - 1).
  * \throws std::invalid_argument as evaluatePlaneDetection, or when \a phases is 0
  */
PhaseScores
evaluateOverGridPhases (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                        const std::vector<std::uint32_t>& truth,
                        const std::vector<std::uint32_t>& detected,
                        double voxel_ratio, std::size_t phases);

} // namespace rspd
} // namespace pcl
