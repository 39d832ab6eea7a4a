/*
 * pcl_rspd: RobustPlaneSegmentation — input checks, neighbourhoods, and outputs around the
 * non-template pipeline (pcl::rspd::detectPlanes).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/normal_estimation.h>
#include <pcl_rspd/plane_colors.h>
#include <pcl_rspd/robust_plane_segmentation.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>

namespace pcl
{
namespace rspd
{
namespace detail
{
/** Convex hull of 2D points (Andrew's monotone chain), counter-clockwise, collinear points dropped. */
inline std::vector<Eigen::Vector2d>
convexHull2D (std::vector<Eigen::Vector2d> pts)
{
  if (pts.size () > 64)
  {
    // Akl-Toussaint: the points extreme in 8 directions span a convex octagon inside the hull; what
    // lies strictly inside it cannot be a hull vertex. On a dense plane that drops nearly every
    // point before the O(m log m) sort (the sort was most of the output time on large planes).
    const Eigen::Vector2d dirs[8] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
    Eigen::Vector2d ext[8];
    double best[8];
    std::fill (best, best + 8, -HUGE_VAL);
    for (const auto& p : pts)
      for (int d = 0; d < 8; ++d)
      {
        const double v = p.dot (dirs[d]);
        if (v > best[d])
        {
          best[d] = v;
          ext[d] = p;
        }
      }
    std::vector<Eigen::Vector2d> poly; // counter-clockwise: support points by increasing angle
    for (const auto& e : ext)
      if (poly.empty () || e != poly.back ())
        poly.push_back (e);
    while (poly.size () > 1 && poly.front () == poly.back ())
      poly.pop_back ();
    if (poly.size () >= 3)
    {
      const auto inside = [&poly] (const Eigen::Vector2d& p) {
        for (std::size_t e = 0; e < poly.size (); ++e)
        {
          const Eigen::Vector2d& a = poly[e];
          const Eigen::Vector2d& b = poly[(e + 1) % poly.size ()];
          if (!((b.x () - a.x ()) * (p.y () - a.y ()) - (b.y () - a.y ()) * (p.x () - a.x ()) > 0.0))
            return false;
        }
        return true;
      };
      pts.erase (std::remove_if (pts.begin (), pts.end (), inside), pts.end ());
    }
  }
  std::sort (pts.begin (), pts.end (), [] (const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x () < b.x () || (a.x () == b.x () && a.y () < b.y ());
  });
  pts.erase (std::unique (pts.begin (), pts.end ()), pts.end ());
  if (pts.size () < 3)
    return pts;
  auto cross = [] (const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a.x () - o.x ()) * (b.y () - o.y ()) - (a.y () - o.y ()) * (b.x () - o.x ());
  };
  std::vector<Eigen::Vector2d> hull (2 * pts.size ());
  std::size_t h = 0;
  for (std::size_t i = 0; i < pts.size (); ++i)
  {
    while (h >= 2 && cross (hull[h - 2], hull[h - 1], pts[i]) <= 0)
      --h;
    hull[h++] = pts[i];
  }
  for (std::size_t i = pts.size () - 1, lower = h + 1; i-- > 0;)
  {
    while (h >= lower && cross (hull[h - 2], hull[h - 1], pts[i]) <= 0)
      --h;
    hull[h++] = pts[i];
  }
  hull.resize (h - 1);
  return hull;
}
} // namespace detail
} // namespace rspd

template <typename PointT, typename NormalT>
RobustPlaneSegmentation<PointT, NormalT>::RobustPlaneSegmentation ()
  : model_type_ (pcl::SACMODEL_PLANE), method_type_ (pcl::SAC_RANSAC)
{}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setInputCloud (const PointCloudConstPtr& cloud)
{
  PCLBase<PointT>::setInputCloud (cloud);
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setIndices (const IndicesPtr& indices)
{
  PCLBase<PointT>::setIndices (indices);
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setIndices (const IndicesConstPtr& indices)
{
  PCLBase<PointT>::setIndices (indices);
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setIndices (const PointIndicesConstPtr& indices)
{
  PCLBase<PointT>::setIndices (indices);
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setIndices (std::size_t row_start, std::size_t col_start,
                                                      std::size_t nb_rows, std::size_t nb_cols)
{
  PCLBase<PointT>::setIndices (row_start, col_start, nb_rows, nb_cols);
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setInputNormals (const NormalsConstPtr& normals)
{
  normals_ = normals;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setSearchMethod (const SearchPtr& search)
{
  search_ = search;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setNumberOfNeighbours (int k)
{
  if (k < 3 && k != 0)
  {
    PCL_ERROR ("[pcl::%s::setNumberOfNeighbours] k must be at least 3, or 0 for automatic (got %d); keeping %d\n",
               getClassName ().c_str (), k, k_);
    return;
  }
  k_ = k;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setMinPatchSizeRatio (double ratio)
{
  if (!(ratio > 0.0 && ratio <= 1.0))
  {
    PCL_ERROR ("[pcl::%s::setMinPatchSizeRatio] the ratio must be in (0, 1] (got %g); keeping %g\n",
               getClassName ().c_str (), ratio, min_patch_ratio_);
    return;
  }
  min_patch_ratio_ = ratio;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setMinPatchSize (std::size_t min_size)
{
  if (min_size != 0 && min_size < 3)
  {
    PCL_ERROR ("[pcl::%s::setMinPatchSize] a patch needs at least 3 samples (got %zu); keeping %zu\n",
               getClassName ().c_str (), min_size, min_patch_size_);
    return;
  }
  min_patch_size_ = min_size;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setNumberOfThreads (unsigned int threads)
{
  params_.num_threads = static_cast<int> (threads);
  // The output does not depend on the thread count: the cache stays valid.
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setMinDistanceTestAngle (double radians)
{
  if (!(radians > 0.0 && radians < M_PI / 2.0))
  {
    PCL_ERROR ("[pcl::%s::setMinDistanceTestAngle] the angle must be in (0, pi/2) radians (got %g)\n",
               getClassName ().c_str (), radians);
    return;
  }
  params_.min_distance_angle = radians;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setMaxNormalDeviation (double radians)
{
  if (!(radians > 0.0 && radians <= M_PI / 2.0))
  {
    PCL_ERROR ("[pcl::%s::setMaxNormalDeviation] the angle must be in (0, pi/2] radians (got %g)\n",
               getClassName ().c_str (), radians);
    return;
  }
  params_.max_normal_deviation = radians;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setMaxOutlierRatio (double ratio)
{
  if (!(ratio > 0.0 && ratio <= 1.0))
  {
    PCL_ERROR ("[pcl::%s::setMaxOutlierRatio] the ratio must be in (0, 1] (got %g)\n", getClassName ().c_str (), ratio);
    return;
  }
  params_.max_outlier_ratio = ratio;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setAlpha (double alpha)
{
  if (!(alpha > 0.0 && std::isfinite (alpha)))
  {
    PCL_ERROR ("[pcl::%s::setAlpha] alpha must be positive (got %g)\n", getClassName ().c_str (), alpha);
    return;
  }
  params_.alpha = alpha;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setDistanceFloorRatio (double ratio)
{
  if (!(ratio >= 0.0 && ratio < 1.0))
  {
    PCL_ERROR ("[pcl::%s::setDistanceFloorRatio] the ratio must be in [0, 1) (got %g)\n", getClassName ().c_str (), ratio);
    return;
  }
  params_.distance_floor_ratio = ratio;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setNormalDeviationFloor (double radians)
{
  if (!(radians >= 0.0 && radians < M_PI / 2.0))
  {
    PCL_ERROR ("[pcl::%s::setNormalDeviationFloor] the angle must be in [0, pi/2) (got %g)\n",
               getClassName ().c_str (), radians);
    return;
  }
  params_.normal_deviation_floor = radians;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setAlignNormalsBeforeMedian (bool align)
{
  params_.align_normals = align;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setSmallPlaneSeeding (bool enable)
{
  small_plane_seeding_ = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setLeftNormalRefit (bool enable)
{
  left_normal_refit_ = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setLeftNormalNarrowing (bool enable)
{
  left_normal_narrowing_ = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setShiftedGrid (bool enable)
{
  shifted_grid_ = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setLeftNormalRefitOnGivenNormals (bool enable)
{
  given_normals_left_refit_ = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setGivenNormalCheck (bool enable)
{
  given_normal_check_ = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setRimCellRetest (bool enable)
{
  params_.rim_cell_retest = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setRimRetestUntilStable (bool enable)
{
  params_.rim_retest_until_stable = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setLeftRimRetest (bool enable)
{
  params_.left_rim_retest = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setPositionPlanes (bool enable)
{
  params_.position_planes = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setPositionSurfaceParts (bool enable)
{
  params_.position_surface_parts = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setPositionBendBand (bool enable)
{
  params_.position_bend_band = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setPositionBendSlabs (bool enable)
{
  params_.position_bend_slabs = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setPositionJoinBeside (bool enable)
{
  params_.position_join_beside = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setPositionSurfaceNormals (bool enable)
{
  params_.position_surface_normals = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setPositionSurfaceLadder (bool enable)
{
  params_.position_surface_ladder = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setPositionLadderRungs (bool enable)
{
  params_.position_ladder_rungs = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setTailOdds (bool enable)
{
  params_.tail_odds = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setSurroundingClutter (bool enable)
{
  params_.surrounding_clutter = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setMemberGaps (bool enable)
{
  params_.member_gaps = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setRimBands (bool enable)
{
  params_.rim_bands = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setHingeNormalTurn (bool enable)
{
  params_.hinge_normal_turn = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setFarMemberRelease (bool enable)
{
  params_.release_far_members = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setReleasedPlaneSeeding (bool enable)
{
  params_.seed_released_planes = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setReleasedLayerCheck (bool enable)
{
  params_.released_layer_check = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setBentSideParentMnd (bool enable)
{
  params_.bent_side_parent_mnd = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setBentNormalEdges (bool enable)
{
  params_.bent_normal_edges = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setConnectedParts (bool enable)
{
  params_.connected_parts = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setLayerMerge (bool enable)
{
  params_.layer_merge = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setLayerSteps (bool enable)
{
  params_.layer_steps = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setStepSplit (bool enable)
{
  params_.step_split = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setAcrossStepCheck (bool enable)
{
  params_.across_step_check = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setBentPlaneSplit (bool enable)
{
  params_.bent_plane_split = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setEdgeSides (bool enable)
{
  params_.edge_sides = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setEdgeCorners (bool enable)
{
  params_.edge_corners = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setEdgeWedges (bool enable)
{
  params_.edge_wedges = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setThickCellJoin (bool enable)
{
  params_.join_thick_cells = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setStepSides (bool enable)
{
  params_.step_sides = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setStepRegions (bool enable)
{
  params_.step_regions = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setSupportCheck (bool enable)
{
  params_.support_check = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setSupportClutter (bool enable)
{
  params_.support_clutter = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setFinalParts (bool enable)
{
  params_.final_parts = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setFinalRefit (bool enable)
{
  params_.final_refit = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setCoplanarMerge (bool enable)
{
  params_.coplanar_merge = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setEdgeAwareNormals (bool enable)
{
  edge_aware_normals_ = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setNormalFit (pcl::rspd::NormalFit fit)
{
  normal_fit_ = fit;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setDetectionFrame (pcl::rspd::DetectionFrame frame)
{
  detection_frame_ = frame;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setDropOutlierSeeds (bool enable)
{
  params_.drop_outlier_seeds = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setOutlierSeedRetest (bool enable)
{
  params_.retest_outlier_seeds = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setSmallPlaneCompletion (bool enable)
{
  params_.small_plane_completion = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setVolumeLayerCheck (bool enable)
{
  params_.volume_layer_check = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setFinalVolumeLayerCheck (bool enable)
{
  params_.final_volume_layer_check = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setInBandLayerCheck (bool enable)
{
  params_.in_band_layer_check = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setFlatLayers (bool enable)
{
  params_.flat_layers = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setTrimmedSeedGrowth (bool enable)
{
  params_.trimmed_seed_growth = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setLateCurvedCheck (bool enable)
{
  params_.late_curved_check = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setCurvedPlaneCheck (bool enable)
{
  params_.curved_plane_check = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setDepthLevelDither (bool enable)
{
  depth_level_dither_ = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setCurvedFoldTwoSides (bool enable)
{
  params_.curved_fold_two_sides = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setCurvedTubeCheck (bool enable)
{
  params_.curved_tube_check = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setCurvedSplitParts (bool enable)
{
  params_.curved_split_parts = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setCurvedNormalTurn (bool enable)
{
  params_.curved_normal_turn = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setCurvedFoldRatio (double ratio)
{
  if (!(ratio > 0.0)) // NaN too
  {
    PCL_ERROR ("[pcl::%s::setCurvedFoldRatio] the ratio must be positive (got %g)\n", getClassName ().c_str (), ratio);
    return;
  }
  params_.curved_fold_ratio = ratio;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setSmallSeedMndFloor (bool enable)
{
  params_.small_seed_mnd_floor = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setBoundedReestimation (bool enable)
{
  params_.bounded_reestimation = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setNoisyPlaneBentSplit (bool enable)
{
  params_.noisy_bent_split = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setSmallPassThickCellJoin (bool enable)
{
  params_.small_cell_thick_join = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setNoisySeedGroups (bool enable)
{
  params_.noisy_seed_groups = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setThickCellsFollowNoisySeeds (bool enable)
{
  params_.thick_cells_follow_noisy_seeds = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setNoisyLoneSeeds (bool enable)
{
  params_.noisy_lone_seeds = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setNoisyGroupLadder (bool enable)
{
  params_.noisy_group_ladder = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setNoisyGrownT2 (bool enable)
{
  params_.noisy_grown_t2 = enable;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setNoisySeedGroupRatio (double ratio)
{
  if (!(ratio >= 1.0 && std::isfinite (ratio)))
  {
    PCL_ERROR ("[pcl::%s::setNoisySeedGroupRatio] the ratio must be finite and at least 1 (got %g)\n",
               getClassName ().c_str (), ratio);
    return;
  }
  params_.noisy_group_ratio = ratio;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setBendNoiseTest (bool enable)
{
  params_.bend_confidence = enable ? pcl::rspd::DetectorParameters ().bend_confidence : 0.0;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setGrownPlaneBendConfidence (double confidence)
{
  if (!(confidence > 0.0 && confidence < 1.0))
  {
    PCL_ERROR ("[pcl::%s::setGrownPlaneBendConfidence] the confidence must be in (0, 1) (got %g)\n",
               getClassName ().c_str (), confidence);
    return;
  }
  params_.judge_bend_confidence = confidence;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setGrownPlaneNormalTurn (double share)
{
  if (!(share >= 0.0) || !std::isfinite (share))
  {
    PCL_ERROR ("[pcl::%s::setGrownPlaneNormalTurn] the share must be finite and at least 0 (got %g)\n",
               getClassName ().c_str (), share);
    return;
  }
  params_.judge_normal_turn = share;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setFinalAssignment (pcl::rspd::FinalAssignment mode)
{
  params_.final_assignment = mode;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setNormalScale (pcl::rspd::NormalScale scale)
{
  normal_scale_ = scale;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setMaxGrowMergeIterations (int iterations)
{
  if (iterations < 1)
  {
    PCL_ERROR ("[pcl::%s::setMaxGrowMergeIterations] need at least 1 (got %d)\n", getClassName ().c_str (), iterations);
    return;
  }
  params_.max_iterations = iterations;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setModelType (int model)
{
  model_type_ = model;
  invalidate ();
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setMethodType (int method)
{
  method_type_ = method;
  PCL_DEBUG ("[pcl::%s::setMethodType] ignored: the method is deterministic\n", getClassName ().c_str ());
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setDistanceThreshold (double threshold)
{
  distance_threshold_ = threshold;
  PCL_DEBUG ("[pcl::%s::setDistanceThreshold] ignored: each plane's MDP is estimated from the data\n",
             getClassName ().c_str ());
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setMaxIterations (int)
{
  PCL_DEBUG ("[pcl::%s::setMaxIterations] ignored: no random sampling (see setMaxGrowMergeIterations)\n",
             getClassName ().c_str ());
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setProbability (double)
{
  PCL_DEBUG ("[pcl::%s::setProbability] ignored: no random sampling\n", getClassName ().c_str ());
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setOptimizeCoefficients (bool)
{
  PCL_DEBUG ("[pcl::%s::setOptimizeCoefficients] ignored: coefficients are least-squares planes of the "
             "inliers (setFinalRefit) or the robust estimate\n",
             getClassName ().c_str ());
}

template <typename PointT, typename NormalT> bool
RobustPlaneSegmentation<PointT, NormalT>::prepareSamples ()
{
  const std::string class_name = getClassName ();
  const char* name = class_name.c_str ();
  if (!input_)
  {
    PCL_ERROR ("[pcl::%s::segment] no input cloud was given\n", name);
    return false;
  }
  switch (model_type_)
  {
    case pcl::SACMODEL_PLANE:
    case pcl::SACMODEL_PERPENDICULAR_PLANE:
    case pcl::SACMODEL_PARALLEL_PLANE:
    case pcl::SACMODEL_NORMAL_PLANE:
    case pcl::SACMODEL_NORMAL_PARALLEL_PLANE:
      break;
    default:
      PCL_ERROR ("[pcl::%s::segment] only plane models are supported (model type %d)\n", name, model_type_);
      return false;
  }
  const std::size_t cloud_size = input_->size ();
  if (cloud_size == 0)
  {
    PCL_ERROR ("[pcl::%s::segment] the input cloud is empty\n", name);
    return false;
  }
  if (normals_ && normals_->size () != cloud_size)
  {
    PCL_ERROR ("[pcl::%s::segment] the normals hold %zu points but the cloud %zu\n", name, normals_->size (),
               cloud_size);
    return false;
  }

  // The samples to work on: the caller's indices (checked, sorted, repeats dropped) or all points.
  std::vector<pcl::index_t> candidates;
  if (indices_)
  {
    candidates.assign (indices_->begin (), indices_->end ());
    for (const auto i : candidates)
      if (i < 0 || static_cast<std::size_t> (i) >= cloud_size)
      {
        PCL_ERROR ("[pcl::%s::segment] index %d is out of range (the cloud holds %zu points)\n", name,
                   static_cast<int> (i), cloud_size);
        return false;
      }
    std::sort (candidates.begin (), candidates.end ());
    const std::size_t before = candidates.size ();
    candidates.erase (std::unique (candidates.begin (), candidates.end ()), candidates.end ());
    if (candidates.size () != before)
      PCL_DEBUG ("[pcl::%s::segment] %zu repeated indices ignored\n", name, before - candidates.size ());
  }
  else
  {
    candidates.resize (cloud_size);
    for (std::size_t i = 0; i < cloud_size; ++i)
      candidates[i] = static_cast<pcl::index_t> (i);
  }

  // Valid samples: finite positions (NaN must never reach the octree or the search) and, when the
  // caller gave normals, a finite non-zero normal.
  std::size_t bad_normals = 0;
  points_ = pcl::rspd::PointSet ();
  points_.input_indices.reserve (candidates.size ());
  Eigen::Vector3d lo = Eigen::Vector3d::Constant (HUGE_VAL), hi = Eigen::Vector3d::Constant (-HUGE_VAL);
  for (const auto i : candidates)
  {
    const PointT& p = (*input_)[i];
    if (!std::isfinite (p.x) || !std::isfinite (p.y) || !std::isfinite (p.z))
      continue;
    if (normals_)
    {
      const NormalT& n = (*normals_)[i];
      const double len2 = double (n.normal_x) * n.normal_x + double (n.normal_y) * n.normal_y + double (n.normal_z) * n.normal_z;
      if (!std::isfinite (len2) || !(len2 > 0.0))
      {
        ++bad_normals;
        continue;
      }
    }
    points_.input_indices.push_back (i);
    const Eigen::Vector3d q (p.x, p.y, p.z);
    lo = lo.cwiseMin (q);
    hi = hi.cwiseMax (q);
  }
  if (bad_normals > 0)
    PCL_WARN ("[pcl::%s::segment] %zu points with a NaN or zero-length normal were left out\n", name, bad_normals);
  const std::size_t n = points_.input_indices.size ();
  if (n == 0)
  {
    PCL_ERROR ("[pcl::%s::segment] no valid point: every point is non-finite%s\n", name,
               bad_normals > 0 ? " or has a NaN or zero-length normal" : "");
    return false;
  }
  params_.min_patch_size = min_patch_size_ > 0
      ? min_patch_size_
      : std::max<std::size_t> (10, static_cast<std::size_t> (std::ceil (min_patch_ratio_ * static_cast<double> (n))));
  // Automatic k: ε/2 between 15 and 50 for the normals estimated here; with the caller's normals,
  // whose scale is unknown, the paper's 50 (measured with PCL's k = 50 normals: the 30,000-point
  // facade 0.987 with a 50-graph, 0.935 with a 15-graph).
  k_used_ = k_ > 0 ? k_ : (normals_ ? pcl::rspd::kPaperNeighbours : pcl::rspd::automaticNumberOfNeighbours (params_.min_patch_size));
  if (n <= static_cast<std::size_t> (k_used_))
  {
    PCL_ERROR ("[pcl::%s::segment] %zu valid points: need more than k = %d\n", name, n, k_used_);
    return false;
  }

  // Centre in double precision before any statistic: a scene 1 km from the origin keeps its
  // float resolution and gives the same planes as at the origin.
  points_.offset = 0.5 * (lo + hi);
  points_.points.resize (n);
  for (std::size_t s = 0; s < n; ++s)
  {
    const PointT& p = (*input_)[points_.input_indices[s]];
    points_.points[s] = (Eigen::Vector3d (p.x, p.y, p.z) - points_.offset).cast<float> ();
  }
  if (depth_level_dither_)
  {
    // Departure (setDepthLevelDither): depths a camera quantized are drawn again within their bins.
    std::vector<Eigen::Vector3d> positions (n);
    for (std::size_t s = 0; s < n; ++s)
    {
      const PointT& p = (*input_)[points_.input_indices[s]];
      positions[s] = Eigen::Vector3d (p.x, p.y, p.z);
    }
    const Eigen::Vector3d origin = input_->sensor_origin_.template head<3> ().template cast<double> ();
    const Eigen::Vector3d axis = pcl::rspd::viewingAxis (input_->sensor_orientation_);
    const pcl::rspd::DepthLevels levels = pcl::rspd::findDepthLevels (positions, origin, axis);
    if (levels.quantized)
    {
      pcl::rspd::ditherDepthLevels (positions, origin, axis, levels);
      for (std::size_t s = 0; s < n; ++s)
        points_.points[s] = (positions[s] - points_.offset).template cast<float> ();
      stats_.depth_levels = levels.distinct;
    }
    PCL_DEBUG ("[pcl::%s::segment] depth levels: %zu distinct depths, %zu of %zu samples share theirs: %s\n", name,
               levels.distinct, levels.on_levels, levels.samples, levels.quantized ? "dithered" : "not quantized");
  }
  // Samples in spatial (Morton) order: the k-NN graph's rows then hold nearby indices and
  // compress to a third (neighbor_graph.h), and every phase walks memory in spatial order. It also
  // makes the internal order, hence every tie-break, independent of the order of the input.
  {
    const std::vector<std::uint32_t> order = pcl::rspd::spatialOrder (points_.points, params_.num_threads);
    std::vector<Eigen::Vector3f> sorted (n);
    std::vector<pcl::index_t> sorted_indices (n);
    for (std::size_t s = 0; s < n; ++s)
    {
      sorted[s] = points_.points[order[s]];
      sorted_indices[s] = points_.input_indices[order[s]];
    }
    points_.points.swap (sorted);
    points_.input_indices.swap (sorted_indices);
  }
  use_given_normals_ = normals_ != nullptr;
  if (use_given_normals_)
  {
    points_.normals.resize (n);
    for (std::size_t s = 0; s < n; ++s)
    {
      const NormalT& nn = (*normals_)[points_.input_indices[s]];
      points_.normals[s] = Eigen::Vector3d (nn.normal_x, nn.normal_y, nn.normal_z).normalized ().cast<float> ();
    }
  }
  setNeighbourDependentParameters ();
  params_.left_normal_narrow = false; // set once the normals are known (prepareNeighbourhoods)
  params_.shifted_small_grid = shifted_grid_;
  return true;
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::setNeighbourDependentParameters ()
{
  // The small-plane pass's cells: down to a neighbourhood, k + 1 samples, but no larger than ε/2
  // (at least 10, the paper's least ε); with k + 1 > ε (k = 50 under 51,000 points, as with the
  // caller's normals) the pass would not run at all: rspd_compare's 30,000-point staircase on PCL's
  // k = 50 normals found 17 of 30 planes without it, 29 with it.
  params_.small_cell_size = small_plane_seeding_
      ? std::min<std::size_t> (static_cast<std::size_t> (k_used_ + 1), std::max<std::size_t> (10, params_.min_patch_size / 2))
      : 0;
  // Trimmed normals need no second fit; the caller's normals have a switch of their own.
  params_.left_normal_refit = use_given_normals_ ? given_normals_left_refit_
                                                 : left_normal_refit_ && normal_fit_ == pcl::rspd::NormalFit::Pca;
}

template <typename PointT, typename NormalT> bool
RobustPlaneSegmentation<PointT, NormalT>::prepareNeighbourhoods ()
{
  const std::string class_name = getClassName ();
  const char* name = class_name.c_str ();
  const std::size_t n = points_.size ();
  const auto t0 = std::chrono::steady_clock::now ();
  // The k_used_-nearest-neighbour graph, with the caller's search method if one was set.
  const auto buildGraph = [&] () -> bool {
    if (search_)
    {
      // pcl::KdTreeFLANN splits its nodes at (min + max) / 2 in float; beyond half the float range
      // that sum overflows and FLANN aborts on an assertion (fuzz/regressions/README.md). Refuse.
      const float limit = 0.5f * std::numeric_limits<float>::max ();
      for (const auto i : points_.input_indices)
      {
        const PointT& p = (*input_)[i];
        if (!(std::abs (p.x) < limit && std::abs (p.y) < limit && std::abs (p.z) < limit))
        {
          PCL_ERROR ("[pcl::%s::segment] point %d has a coordinate beyond +-%g, which the search method "
                     "cannot index\n", name, static_cast<int> (i), static_cast<double> (limit));
          return false;
        }
      }
      // The caller's search structure, over the valid samples only.
      auto valid = std::make_shared<pcl::Indices> (points_.input_indices.begin (), points_.input_indices.end ());
      search_->setInputCloud (input_, valid);
      std::vector<std::uint32_t> to_internal (input_->size (), std::numeric_limits<std::uint32_t>::max ());
      for (std::size_t s = 0; s < n; ++s)
        to_internal[points_.input_indices[s]] = static_cast<std::uint32_t> (s);
      graph_ = pcl::rspd::NeighborGraph (n, k_used_);
      bool short_answer = false;
      const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (n);
  #pragma omp parallel num_threads(pcl::rspd::resolveThreads (params_.num_threads))
      {
        pcl::rspd::NeighborGraph::Appender appender (graph_);
        pcl::Indices nn;
        std::vector<float> d2;
        std::vector<std::pair<float, std::uint32_t>> found;
        std::vector<std::uint32_t> row (static_cast<std::size_t> (k_used_));
  #pragma omp for schedule(dynamic, 256)
        for (std::ptrdiff_t s = 0; s < count; ++s)
        {
          search_->nearestKSearch ((*input_)[points_.input_indices[s]], k_used_ + 1, nn, d2);
          found.clear ();
          for (std::size_t j = 0; j < nn.size () && j < d2.size (); ++j)
          {
            if (nn[j] < 0 || static_cast<std::size_t> (nn[j]) >= to_internal.size ())
              continue;
            const std::uint32_t t = to_internal[nn[j]];
            if (t != std::numeric_limits<std::uint32_t>::max () && t != static_cast<std::uint32_t> (s))
              found.emplace_back (d2[j], t);
          }
          std::sort (found.begin (), found.end ()); // by distance, ties by index: deterministic
          found.erase (std::unique (found.begin (), found.end (),
                                    [] (const std::pair<float, std::uint32_t>& a, const std::pair<float, std::uint32_t>& b) {
                                      return a.second == b.second;
                                    }),
                       found.end ());
          if (found.size () < static_cast<std::size_t> (k_used_))
          {
  #pragma omp atomic write
            short_answer = true;
            // Every row must be set before the graph is read: fill with what there is.
            for (int j = 0; j < k_used_; ++j)
              row[j] = found.empty () ? static_cast<std::uint32_t> (s == 0 ? 1 : 0) : found[j % found.size ()].second;
          }
          else
            for (int j = 0; j < k_used_; ++j)
              row[j] = found[j].second;
          appender.setRow (static_cast<std::size_t> (s), row.data ());
        }
      }
      if (short_answer)
      {
        PCL_ERROR ("[pcl::%s::segment] the search method returned fewer than k = %d neighbours\n", name, k_used_);
        return false;
      }
    }
    else if (!pcl::rspd::buildKnnGraph (points_.points, k_used_, params_.num_threads, graph_))
    {
      PCL_ERROR ("[pcl::%s::segment] could not build the %d-nearest-neighbour graph\n", name, k_used_);
      return false;
    }
    return true;
  };
  if (!buildGraph ())
    return false;
  given_normal_check_stats_ = pcl::rspd::GivenNormalCheck ();
  if (use_given_normals_ && given_normal_check_ && normal_scale_ == pcl::rspd::NormalScale::Automatic && k_ == 0)
  {
    const int fine_k = pcl::rspd::automaticNumberOfNeighbours (params_.min_patch_size);
    if (fine_k < k_used_ && pcl::rspd::givenNormalsBlurFaces (points_.points, graph_, fine_k, params_.num_threads,
                                                              points_.normals, &given_normal_check_stats_))
    {
      // The caller's normals blur the faces the automatic k resolves (setGivenNormalCheck): the
      // detection goes on as without them, on the automatic k's graph and normals estimated here.
      PCL_DEBUG ("[pcl::%s::segment] the given normals blur the faces %d-neighbourhoods resolve (%zu of %zu "
                 "resolved probes tilted): estimated again at k = %d\n", name, fine_k,
                 given_normal_check_stats_.fine_tilted, given_normal_check_stats_.fine_resolved, fine_k);
      use_given_normals_ = false;
      stats_.given_normals_replaced = true;
      stats_.given_normals_blurred = true;
      k_used_ = fine_k;
      setNeighbourDependentParameters ();
      if (!buildGraph ())
        return false;
    }
  }
  const auto t1 = std::chrono::steady_clock::now ();
  stats_.graph_seconds = std::chrono::duration<double> (t1 - t0).count ();
  stats_.graph_bytes = graph_.memoryBytes ();
  if (use_given_normals_ && given_normal_check_ && normal_scale_ == pcl::rspd::NormalScale::Automatic &&
      pcl::rspd::givenNormalsAreNoise (points_.points, graph_, params_.num_threads, points_.normals,
                                       &given_normal_check_stats_))
  {
    // The caller's normals are noise at this scale (setGivenNormalCheck): estimated here instead, at
    // the finest scale that resolves a surface, as without them.
    pcl::rspd::estimateAdaptiveScaleNormals (points_.points, graph_, params_.num_threads, points_.normals,
                                             &normal_scale_stats_, true);
    stats_.given_normals_replaced = true;
    stats_.normals_seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - t1).count ();
    PCL_DEBUG ("[pcl::%s::segment] the given normals spread as much as the %d-neighbourhoods' (%zu of %zu "
               "probes unresolved): estimated again at an adaptive scale\n", name, k_used_,
               given_normal_check_stats_.unresolved, given_normal_check_stats_.probes);
  }
  if (!use_given_normals_ && normal_scale_ != pcl::rspd::NormalScale::Fixed)
  {
    pcl::rspd::estimateAdaptiveScaleNormals (points_.points, graph_, params_.num_threads, points_.normals,
                                             &normal_scale_stats_,
                                             normal_scale_ == pcl::rspd::NormalScale::Automatic);
    stats_.normals_seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - t1).count ();
    PCL_DEBUG ("[pcl::%s::segment] no normals given: PCA at an adaptive scale; %zu of %zu samples unresolved "
               "at k = %d, %zu from a wider scale, %zu unresolved at every scale\n", name,
               normal_scale_stats_.unresolved_at_k, n, k_used_, normal_scale_stats_.widened (),
               normal_scale_stats_.unresolved);
  }
  else if (!use_given_normals_)
  {
    PCL_DEBUG ("[pcl::%s::segment] no normals given: estimating them by PCA over the %d-neighbourhoods\n",
               name, k_used_);
    pcl::rspd::estimateNormals (points_.points, graph_, params_.num_threads, points_.normals);
    stats_.normals_seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - t1).count ();
  }
  stats_.edge_narrowed_normals = 0;
  params_.narrowed_cell_size = 0;
  if (!use_given_normals_ && edge_aware_normals_ && normal_fit_ == pcl::rspd::NormalFit::Pca &&
      normal_scale_stats_.widened () == 0)
  {
    // Departure (edge-aware normals): only where every normal is the k-neighbourhood's, which the
    // narrowing compares against (a normal from a wider scale is left as it is).
    const auto t2 = std::chrono::steady_clock::now ();
    stats_.edge_narrowed_normals = pcl::rspd::narrowNormalsAtEdges (
        points_.points, graph_, params_.num_threads, pcl::rspd::kMinAutomaticNeighbours, points_.normals,
        &points_.narrowed);
    // Where normals were narrowed they resolve faces down to kMinAutomaticNeighbours samples, and so
    // may the small-plane pass's cells there (DetectorParameters::narrowed_cell_size).
    params_.narrowed_cell_size = params_.small_cell_size > 0 ? pcl::rspd::kMinAutomaticNeighbours + 1 : 0;
    stats_.normals_seconds += std::chrono::duration<double> (std::chrono::steady_clock::now () - t2).count ();
    PCL_DEBUG ("[pcl::%s::segment] edge-aware normals: %zu of %zu narrowed to one face\n", name,
               stats_.edge_narrowed_normals, n);
  }
  // Narrowed normals for what growth left (DetectorParameters::left_normal_narrow): as the
  // edge-aware normals, on the k-neighbourhoods' own PCA normals only, and not where every normal
  // was narrowed already or the trimmed refit was asked for.
  params_.left_normal_narrow = left_normal_narrowing_ && !use_given_normals_ && !params_.left_normal_refit &&
                               !edge_aware_normals_ && normal_fit_ == pcl::rspd::NormalFit::Pca &&
                               normal_scale_stats_.widened () == 0;
  if (!use_given_normals_ && normal_fit_ == pcl::rspd::NormalFit::TrimmedPlane)
  {
    // Departure (robust normals): trimmed planes instead of PCA where the k-scale resolves a surface.
    const auto t2 = std::chrono::steady_clock::now ();
    pcl::rspd::refineNormalsTrimmed (points_.points, graph_, params_.num_threads, points_.normals,
                                     &trimmed_normal_stats_);
    stats_.normals_seconds += std::chrono::duration<double> (std::chrono::steady_clock::now () - t2).count ();
    PCL_DEBUG ("[pcl::%s::segment] trimmed-plane normals: %zu refined, %zu unresolved at k, %zu on a line\n",
               name, trimmed_normal_stats_.refined, trimmed_normal_stats_.unresolved,
               trimmed_normal_stats_.collinear);
  }
  return true;
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::buildPlanes (const std::vector<pcl::rspd::DetectedPatch>& patches)
{
  planes_.clear ();
  planes_.resize (patches.size ());
  labels_.assign (input_->size (), 0);
  const Eigen::Vector3d origin = input_->sensor_origin_.template head<3> ().template cast<double> ();
  // Planes are independent (disjoint members, own output slot): one per task, largest first.
  const std::ptrdiff_t num_patches = static_cast<std::ptrdiff_t> (patches.size ());
#pragma omp parallel for schedule(dynamic, 1) num_threads(pcl::rspd::resolveThreads (params_.num_threads))
  for (std::ptrdiff_t p = 0; p < num_patches; ++p)
  {
    const pcl::rspd::DetectedPatch& patch = patches[p];
    RobustPlane& plane = planes_[p];
    plane.indices.header = input_->header;
    plane.coefficients.header = input_->header;
    plane.indices.indices.reserve (patch.members.size ());
    for (const auto s : patch.members)
    {
      const pcl::index_t i = points_.input_indices[s];
      plane.indices.indices.push_back (i);
      labels_[i] = static_cast<std::uint32_t> (p + 1);
    }
    // Internal order is spatial; callers get their own indices ascending.
    std::sort (plane.indices.indices.begin (), plane.indices.indices.end ());
    plane.center = patch.center + points_.offset;
    plane.normal = patch.normal;
    if ((origin - plane.center).dot (plane.normal) < 0.0)
      plane.normal = -plane.normal;
    plane.coefficients.values = {static_cast<float> (plane.normal.x ()), static_cast<float> (plane.normal.y ()),
                                 static_cast<float> (plane.normal.z ()),
                                 static_cast<float> (-plane.normal.dot (plane.center))};
    plane.mdp = patch.mdp;
    plane.mnd = patch.mnd;

    // Centroid and covariance (centred frame, then shifted back), for pcl::PlanarRegion.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
    for (const auto s : patch.members)
      mean += points_.points[s].template cast<double> ();
    mean /= static_cast<double> (patch.members.size ());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero ();
    for (const auto s : patch.members)
    {
      const Eigen::Vector3d d = points_.points[s].template cast<double> () - mean;
      cov += d * d.transpose ();
    }
    plane.covariance = cov / static_cast<double> (patch.members.size ());
    plane.centroid = mean + points_.offset;

    // Convex hull of the members projected on the plane, in a basis (u, v, normal) that is
    // right-handed so the hull runs counter-clockwise about the normal; then the minimum-area
    // rectangle, which has a side on a hull edge (PCA axes are undefined for a square).
    const Eigen::Vector3d u0 = plane.normal.unitOrthogonal ();
    const Eigen::Vector3d v0 = plane.normal.cross (u0);
    std::vector<Eigen::Vector2d> flat;
    flat.reserve (patch.members.size ());
    for (const auto s : patch.members)
    {
      const Eigen::Vector3d d = points_.points[s].template cast<double> () - patch.center;
      flat.emplace_back (d.dot (u0), d.dot (v0));
    }
    const std::vector<Eigen::Vector2d> hull = pcl::rspd::detail::convexHull2D (std::move (flat));
    for (const auto& q : hull)
      plane.hull.push_back (plane.center + q.x () * u0 + q.y () * v0);
    double best_area = HUGE_VAL;
    Eigen::Vector2d best_axis (1.0, 0.0), best_lo (0.0, 0.0), best_hi (0.0, 0.0);
    for (std::size_t e = 0; e < hull.size (); ++e)
    {
      const Eigen::Vector2d edge = hull[(e + 1) % hull.size ()] - hull[e];
      if (!(edge.norm () > 0.0))
        continue;
      const Eigen::Vector2d a = edge.normalized (), b (-a.y (), a.x ());
      Eigen::Vector2d lo (HUGE_VAL, HUGE_VAL), hi (-HUGE_VAL, -HUGE_VAL);
      for (const auto& q : hull)
      {
        const Eigen::Vector2d t (q.dot (a), q.dot (b));
        lo = lo.cwiseMin (t);
        hi = hi.cwiseMax (t);
      }
      const double area = (hi - lo).prod ();
      if (area < best_area)
      {
        best_area = area;
        best_axis = a;
        best_lo = lo;
        best_hi = hi;
      }
    }
    Eigen::Vector2d a = best_axis, b (-a.y (), a.x ());
    Eigen::Vector2d size = best_hi - best_lo, mid = 0.5 * (best_lo + best_hi);
    if (size.y () > size.x ()) // longer side first
    {
      std::swap (size.x (), size.y ());
      const Eigen::Vector2d a_old = a;
      a = b;
      b = -a_old;
      mid = Eigen::Vector2d (mid.y (), -mid.x ());
    }
    const Eigen::Vector2d c2 = mid.x () * a + mid.y () * b;
    plane.rect_axes[0] = a.x () * u0 + a.y () * v0;
    plane.rect_axes[1] = plane.normal.cross (plane.rect_axes[0]);
    plane.rect_size = size;
    plane.rect_center = plane.center + c2.x () * u0 + c2.y () * v0;
  }
}

template <typename PointT, typename NormalT> bool
RobustPlaneSegmentation<PointT, NormalT>::compute ()
{
  if (computed_ && ok_)
    return true;
  computed_ = false;
  ok_ = false;
  planes_.clear ();
  labels_.clear ();
  stats_ = pcl::rspd::DetectorStatistics ();
  normal_scale_stats_ = pcl::rspd::NormalScaleStatistics ();
  trimmed_normal_stats_ = pcl::rspd::TrimmedNormalStatistics ();
  try
  {
    const auto t0 = std::chrono::steady_clock::now ();
    const bool prepared = prepareSamples ();
    stats_.prepare_seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - t0).count ();
    if (!prepared || !prepareNeighbourhoods ())
    {
      points_ = pcl::rspd::PointSet ();
      graph_ = pcl::rspd::NeighborGraph ();
      return false;
    }
    // Orientation independence (departure, setDetectionFrame): the phases run in the frame of
    // the dominant normal directions, and the samples and planes are turned back afterwards.
    const bool turn = detection_frame_ == pcl::rspd::DetectionFrame::DominantPlanes;
    const Eigen::Matrix3d frame = turn ? pcl::rspd::dominantFrame (points_) : Eigen::Matrix3d::Identity ();
    if (turn)
      pcl::rspd::rotateSamples (points_, frame, params_.num_threads);
    std::vector<pcl::rspd::DetectedPatch> patches;
    pcl::rspd::detectPlanes (points_, graph_, params_, patches, &stats_);
    if (turn)
    {
      pcl::rspd::rotateSamples (points_, frame.transpose (), params_.num_threads);
      for (auto& patch : patches)
      {
        patch.center = frame.transpose () * patch.center;
        patch.normal = (frame.transpose () * patch.normal).normalized ();
      }
    }
    const auto t1 = std::chrono::steady_clock::now ();
    buildPlanes (patches);
    stats_.output_seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - t1).count ();
  }
  catch (const std::exception& e)
  {
    PCL_ERROR ("[pcl::%s::segment] %s\n", getClassName ().c_str (), e.what ());
    points_ = pcl::rspd::PointSet (); // possibly still turned into the detection frame
    planes_.clear ();
    labels_.clear ();
    return false;
  }
  computed_ = true;
  ok_ = true;
  return true;
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::segment (std::vector<pcl::ModelCoefficients>& coefficients,
                                                   std::vector<pcl::PointIndices>& indices)
{
  coefficients.clear ();
  indices.clear ();
  if (!compute ())
    return;
  coefficients.reserve (planes_.size ());
  indices.reserve (planes_.size ());
  for (const auto& plane : planes_)
  {
    coefficients.push_back (plane.coefficients);
    indices.push_back (plane.indices);
  }
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::segment (pcl::PointIndices& inliers, pcl::ModelCoefficients& coefficients)
{
  inliers.indices.clear ();
  coefficients.values.clear ();
  if (!compute ())
    return;
  inliers.header = coefficients.header = input_->header;
  if (planes_.empty ())
  {
    PCL_DEBUG ("[pcl::%s::segment] no plane found\n", getClassName ().c_str ());
    return;
  }
  inliers = planes_.front ().indices;
  coefficients = planes_.front ().coefficients;
}

template <typename PointT, typename NormalT> void
RobustPlaneSegmentation<PointT, NormalT>::getLabels (pcl::PointCloud<pcl::Label>& labels)
{
  labels.clear ();
  if (!compute ())
    return;
  labels.resize (labels_.size ());
  for (std::size_t i = 0; i < labels_.size (); ++i)
    labels[i].label = labels_[i];
  labels.width = input_->width;
  labels.height = input_->height;
  labels.is_dense = true;
  labels.header = input_->header;
}

template <typename PointT, typename NormalT> pcl::PointCloud<pcl::PointXYZRGB>::Ptr
RobustPlaneSegmentation<PointT, NormalT>::getColoredCloud ()
{
  if (!compute ())
    return nullptr;
  auto colored = std::make_shared<pcl::PointCloud<pcl::PointXYZRGB>> ();
  colored->resize (input_->size ());
  for (std::size_t i = 0; i < input_->size (); ++i)
  {
    pcl::PointXYZRGB& q = (*colored)[i];
    q.x = (*input_)[i].x;
    q.y = (*input_)[i].y;
    q.z = (*input_)[i].z;
    const auto c = pcl::rspd::planeColor (labels_[i]);
    q.r = c[0];
    q.g = c[1];
    q.b = c[2];
  }
  colored->width = input_->width;
  colored->height = input_->height;
  colored->is_dense = input_->is_dense;
  colored->header = input_->header;
  colored->sensor_origin_ = input_->sensor_origin_;
  colored->sensor_orientation_ = input_->sensor_orientation_;
  return colored;
}

template <typename PointT, typename NormalT> const std::vector<RobustPlane>&
RobustPlaneSegmentation<PointT, NormalT>::getPlanes ()
{
  compute ();
  return planes_;
}

} // namespace pcl

