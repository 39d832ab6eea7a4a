/*
 * pcl_rspd: the pipeline of Sec. 3 on prepared data: split, then grow and merge until stable.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/neighbor_graph.h>
#include <pcl_rspd/point_set.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Every constant of the method, with the paper's values as defaults. Angles in radians. */
struct DetectorParameters
{
  /** \brief ε: a cell with fewer samples is neither split nor tested, and a patch smaller than
    * this after outlier removal is dropped (Sec. 3.1). Resolved by the caller (>= 3). */
  std::size_t min_patch_size = 10;
  /** \brief α of Eqs. 6 and 9: interval half-width in MADs. */
  double alpha = 3.0;
  /** \brief T1: the angle between F and N must exceed this (75°). */
  double min_distance_angle = 75.0 * 3.14159265358979323846 / 180.0;
  /** \brief T2: MND must stay under this (60°). */
  double max_normal_deviation = 60.0 * 3.14159265358979323846 / 180.0;
  /** \brief T3: a cell with this share of outliers or more is rejected (25 %). */
  double max_outlier_ratio = 0.25;
  /** \brief Sec. 3.5: a patch grown by more than this share since its last estimate is re-estimated. */
  double update_growth_ratio = 0.5;
  /** \brief Departure (zero spread): the distance interval's half-width is at least this fraction
    * of the patch's in-plane extent, so a noise-free plane (MAD = 0) still passes and grows. 0 = paper. */
  double distance_floor_ratio = 1e-6;
  /** \brief Departure (zero spread): the normal-deviation interval's half-width is at least this
    * angle (radians); float rounding of exact normals stays below it. 0 = paper. */
  double normal_deviation_floor = 1e-3;
  /** \brief Departure (sign ambiguity): flip each normal into the hemisphere of the cell's dominant
    * direction before the component-wise median of Eq. 4. false = the paper's plain median. */
  bool align_normals = true;
  /** \brief Departure (small planes): once grow-merge is stable, split the samples no patch holds
    * again with cells down to this many samples (0 = off, the paper), keep the new seeds whose MND
    * is no larger than the largest MND of the planes already found, grow-merge again, and drop every
    * plane still smaller than ε. Seeds a plane whose ε-sized cells always mix with a neighbour. */
  std::size_t small_cell_size = 0;
  /** \brief Safety cap on grow-merge iterations (Sec. 3.5); hitting it is logged. */
  int max_iterations = 100;
  /** \brief Octree depth cap: subdivision also stops where all samples of a cell coincide. */
  int max_octree_depth = 24;
  /** \brief OpenMP threads (0 = OpenMP's default). Output does not depend on it. */
  int num_threads = 0;
};

/** \brief One detected plane, in the internal (centred) frame. */
struct DetectedPatch
{
  std::vector<std::uint32_t> members; ///< internal sample indices, ascending
  Eigen::Vector3d center = Eigen::Vector3d::Zero (); ///< C: component-wise median (Eq. 3), centred frame
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ (); ///< N: unit normal (Eq. 4)
  double mdp = 0.0; ///< maximum distance to plane
  double mnd = 0.0; ///< maximum normal deviation (radians)
};

/** \brief Counters of one run, for logs and tests. */
struct DetectorStatistics
{
  std::size_t cells_tested = 0;      ///< planarity tests run during the split
  std::size_t seed_patches = 0;      ///< patches the split produced
  int iterations = 0;                ///< grow-merge iterations
  std::size_t reestimations = 0;     ///< Sec. 3.5 updates
  std::size_t merges = 0;            ///< patches absorbed by merging
  std::size_t small_seeds = 0;       ///< seeds of the small-cell pass kept
  bool hit_iteration_cap = false;
  double prepare_seconds = 0.0;      ///< valid samples, centring, spatial order (wall time)
  double graph_seconds = 0.0;        ///< building the k-NN graph (wall time)
  std::size_t graph_bytes = 0;       ///< memory held by the compressed k-NN graph
  double normals_seconds = 0.0;      ///< estimating normals (0 when given)
  double split_seconds = 0.0;        ///< split phase
  double grow_merge_seconds = 0.0;   ///< grow-merge iterations
  double output_seconds = 0.0;       ///< plane outputs: indices, labels, centroids, hulls, rectangles
};

/** \brief Run split (Sec. 3.1), then grow (3.3) and merge (3.4) until stable (3.5).
  * \param[in] points valid samples with normals
  * \param[in] graph their k-NN graph
  * \param[in] params constants
  * \param[out] patches planes, largest first (ties: lowest member index)
  * \param[out] stats counters (may be null)
  */
void
detectPlanes (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
              std::vector<DetectedPatch>& patches, DetectorStatistics* stats = nullptr);

} // namespace rspd
} // namespace pcl
