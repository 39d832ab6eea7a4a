/*
 * pcl_rspd: robust statistics plane detection for unorganized point clouds, PCL-native.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/depth_levels.h>
#include <pcl_rspd/dominant_frame.h>
#include <pcl_rspd/normal_estimation.h>
#include <pcl_rspd/plane_detector.h>
#include <pcl_rspd/robust_normals.h>

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/pcl_base.h>
#include <pcl/pcl_macros.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/search/search.h>

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

namespace pcl
{
/** \brief Everything known about one detected plane, in the input cloud's frame. */
struct RobustPlane
{
  pcl::PointIndices indices;           ///< members, indices into the input cloud, ascending
  pcl::ModelCoefficients coefficients; ///< [a b c d], unit normal towards the cloud's sensor origin
  Eigen::Vector3d center = Eigen::Vector3d::Zero ();   ///< C: component-wise median of members' positions (Eq. 3)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ ();  ///< N, oriented as in coefficients
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero (); ///< mean of the members' positions
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero (); ///< covariance of the members' positions
  double mdp = 0.0; ///< maximum distance to plane (input units)
  double mnd = 0.0; ///< maximum normal deviation (radians)
  /** \brief In-plane extent as an oriented rectangle: centre, two unit in-plane axes and the
    * side lengths along them (rect_size[0] >= rect_size[1]). */
  Eigen::Vector3d rect_center = Eigen::Vector3d::Zero ();
  Eigen::Vector3d rect_axes[2] = {Eigen::Vector3d::UnitX (), Eigen::Vector3d::UnitY ()};
  Eigen::Vector2d rect_size = Eigen::Vector2d::Zero ();
  /** \brief Boundary polygon: the convex hull of the members projected on the plane,
    * counter-clockwise about the normal. */
  std::vector<Eigen::Vector3d> hull;
};

/** \brief Finds every plane in an unorganized point cloud with robust statistics, without
  * parameter tuning.
  *
  * Implements "A robust statistics approach for plane detection in unorganized point clouds" by
  * A. M. C. Araújo and M. M. Oliveira, Pattern Recognition 100 (2020) 107115 (RSPD):
  *  - split (Sec. 3.1): an octree over the valid samples is subdivided until a cell holds fewer than
  *    ε samples; cells are tested bottom-up, a parent only when none of its children became a patch;
  *  - robust planarity test (Sec. 3.2): plane (C, N) from component-wise medians; T1 compares
  *    MDP = median(D) + α·MAD(D) with the cell's in-plane extent through the angle of
  *    F = 0.5·max(w, l)·U + MDP·N with N (> 75°); T2 needs MND = median(Φ) + α·MAD(Φ) < 60°;
  *    T3 rejects a cell with 25 % or more outliers, and an accepted patch drops its outliers;
  *  - grow (Sec. 3.3): breadth-first on the k-NN graph (k = 50; see automatic k below), patches by
  *    increasing MND;
  *  - merge (Sec. 3.4): union-find over pairs that are adjacent (M1), have normals closer than the
  *    larger MND (M2) and where a boundary sample of one is an inlier of the other (M3);
  *  - iterate (Sec. 3.5): a patch that grew by more than 50 % is re-estimated and grow/merge repeat.
  *
  * Where the paper is silent or its letter fails on real data, these departures are made; each can
  * be switched back to the paper's behaviour:
  *  - automatic k (setNumberOfNeighbours(50) for the paper): with normals estimated here, k = ε/2
  *    between 15 and 50, the paper's 50 from 100,000 valid points on; below that a 50-neighbourhood is
  *    as large as the smallest plane the split seeds, and no sample of such a plane has a clean normal
  *    (pcl::rspd::automaticNumberOfNeighbours); with given normals, 50 (the automatic k when
  *    setGivenNormalCheck finds that they blur the faces it resolves);
  *  - zero spread: the interval half-widths have floors that scale with the data (1e-6 of the
  *    patch's in-plane extent for distances, 1e-3 rad for normals), so a noise-free plane (MAD = 0,
  *    the paper's Table 5) passes and grows (setDistanceFloorRatio(0), setNormalDeviationFloor(0));
  *  - normal signs: unoriented normals are flipped into the hemisphere of the cell's dominant
  *    direction (principal eigenvector of Σ nᵢnᵢᵀ) before the median of Eq. 4
  *    (setAlignNormalsBeforeMedian(false));
  *  - w and l of T1 are the extents along the two in-plane principal axes of the cell's samples,
  *    never an axis-aligned box, so the test does not depend on the cloud's orientation;
  *  - positions are centred in double precision before any statistic, so a scene far from the
  *    origin gives the planes it gives at the origin;
  *  - small planes (setSmallPlaneSeeding(false) for the paper): a plane whose ε-sample octree cells
  *    always mix with a neighbour (a stair riser between two treads) is never seeded by Algorithm 1.
  *    Once grow-merge is stable, the samples no plane holds are split again with cells down to k + 1
  *    samples (at most ε/2, at least 10; at ε = 10 as large as the first split's, but on what
  *    growth left alone); a new seed is kept only if its MND is at most the largest
  *    MND of the planes found (edge bands of bent normals are noisier and would bridge faces through
  *    M2) and it is not a layer of a found plane's noise band, grow-merge runs again, and planes
  *    still smaller than ε are dropped;
  *  - shifted grid (setShiftedGrid(false) for the paper): each split of the small-plane pass runs
  *    again, over what its seeds left, on an octree moved by a third of a cell at every level, so a
  *    face every cell of the first grid cuts into untestable pieces lies whole in one; its seeds must
  *    be as clean as the planes found, and are judged flat again once grown;
  *  - narrowed normals for what growth left (setLeftNormalNarrowing(false) for none): with normals
  *    estimated here by PCA, that pass's second split reads the left samples' normals narrowed to
  *    one face at edges (the trimmed ones below when setLeftNormalRefit asks for them); there, as
  *    on trimmed normals, a rim cell's inliers are tested again down to 16 of them
  *    (setLeftRimRetest(false): k + 1);
  *  - trimmed normals for what growth left (setLeftNormalRefitOnGivenNormals(false) and
  *    setLeftNormalRefit(false) for the paper): that pass
  *    splits a second time the samples still left, on the normals of their neighbourhoods'
  *    reweighted least-trimmed-squares planes, with the same tests for a seed and one more (no
  *    thicker than the thickest plane found); a seed found so grows on those normals
  *    (setTrimmedSeedGrowth), every other plane and every later pass on the normals they had.
  *    A small plane's normals bend towards its neighbours over most of it (a table's front panel at
  *    100,000 points), and T3 then fails every cell of it. On by default for the caller's normals,
  *    whose scale was chosen without this cloud's small planes in view and which leave the time of
  *    a normal stage to spend; off by default for normals estimated here, for its time;
  *  - outlier seeds (setDropOutlierSeeds(false) for the paper): a seed whose MND is an outlier among
  *    all seeds of the split (log scale, median + α·MAD) is dropped before growth, and tested again
  *    on what growth left of it (setOutlierSeedRetest(false): not), seeding a plane if flat;
  *  - small-plane completion (setSmallPlaneCompletion(false): dropped): a plane the small-plane
  *    pass seeded that growth left short of ε, but at half of it or more, takes the samples of its
  *    surface within its noise band that no plane or a noisier plane turned from it holds, and is
  *    kept if that brings it to ε;
  *  - volume layers (setVolumeLayerCheck(false): kept): a plane such a noisy seed seeded is
  *    dropped once grown if the samples beside its noise band are four times as dense as within it
  *    (the end of a volume of clutter, not a surface); once the planes are final every plane is
  *    judged so (setFinalVolumeLayerCheck), and also dropped if the layers beside its band run on
  *    flat and denser than it (setFlatLayers(false) for the ratio alone);
  *  - re-estimation within T2 (setBoundedReestimation(false) for the paper): a plane such a noisy
  *    seed seeded keeps its last estimate when a re-estimate's MND fails T2 (60°), where growth
  *    onto the faces around it would otherwise widen MND and MDP until it holds a whole box;
  *  - bent noisy planes (setNoisyPlaneBentSplit(false): dropped): such a plane that is not flat
  *    once grown but that two flat planes meeting at an edge explain is split into them;
  *  - coplanar groups, M4 (setCoplanarMerge(false) for the paper): groups join largest first and
  *    only when most of the smaller one lies in the distance band of the plane the union keeps (or
  *    of the least-squares plane of the larger group's samples), so facets of a faceted or curved
  *    object do not chain into one plane;
  *  - far members (setFarMemberRelease(false) for the paper): members farther from their plane's
  *    final estimate than its noise band are offered to the neighbouring planes, and a group of them
  *    that is a plane by T1-T3 becomes one (setReleasedPlaneSeeding(false): they go back);
  *  - connected parts (setConnectedParts(false) for the paper): after the far-member release, a plane
  *    whose members that pass its inlier test at its last estimate form separate parts of at least ε
  *    samples each (no graph edge between them) is split into them;
  *  - bent planes (setBentPlaneSplit(false) for the paper): then a plane whose samples lie on two
  *    planes meeting at an edge (more than 90° minus T1's angle apart, the robust spread down to 0.8
  *    of one plane's or less, each side passing T1-T3) is split there, and each part again; noisy
  *    normals give a wide MND, and growth carries a plane over an edge onto the next face;
  *  - step split (setStepSplit(false) for the paper): then a region of a plane whose neighbourhoods
  *    lie off it on one side, with an inside, offset across its border and parallel to the rest
  *    across its extent, is split off: a door 2 cm proud of a wall at σ = 1.5 cm lies in its band;
  *  - band layers (setLayerMerge(false) for the paper): then a plane lying among a larger plane's
  *    samples (half of its members beside one of them) and within that plane's noise band across its
  *    extent is merged into it: two seeds of one noisy face grow into two layers of its band; not
  *    a plane whose neighbourhoods average off the two planes' joint plane (setLayerSteps(false) to
  *    merge it too): a window recessed within its wall's band is a step, not a layer;
  *  - planes across a step (setAcrossStepCheck(false) to keep them): then a plane whose members lie
  *    on two planes beside it, parallel to each other and not to it, at least as closely as on its
  *    own is dropped: a strip seeded across a door's edge before the door was parted from its wall;
  *  - edge sides (setEdgeSides(false) for the paper): after the last assignment, a sample next to
  *    another plane leaves its plane when its projection onto it lies beyond the line where the two
  *    planes meet (the side the plane's members hold), for the other plane if that one would own it
  *    by the same rule and holds it within its noise band, else for none;
  *  - thick-cell join (setThickCellJoin(false) for the paper): the split also joins touching cells
  *    that fail T1 alone and agree on their plane; once growth is stable, what it left of each group
  *    seeds a plane if it passes T1-T3 (a cube at σ = 3 % of its edge: no cell holding one face is
  *    wide enough for T1); the small-plane pass joins its own thick cells, if no noisier than the
  *    noisiest plane found, the same way (setSmallPassThickCellJoin(false) for its cells alone);
  *  - step sides (setStepSides(false) for the paper): then a sample next to a parallel plane offset
  *    by more than both noise bands goes to it when it lies within its band and it holds more of the
  *    sample's neighbours, until none moves (a window recessed 20 cm behind a wall scanned at
  *    σ = 5 cm: distance cannot tell where the bands overlap, the neighbours can); before that
  *    (setStepRegions(false) for samples one at a time), a plane's region that lies off it toward
  *    a parallel plane beside it goes to that plane when its samples lie nearer to it (a window
  *    10 cm deep in a wall at σ = 4 cm, inside the wall's band);
  *  - final refit (setFinalRefit(false) for the paper's estimate): once the planes' samples are
  *    settled, each plane's centre and normal become the least-squares plane of its members within
  *    2.5 robust sigmas, before the passes below judge distances to it, and again on the final
  *    members for the planes returned (the robust estimate is off by much of the noise at a plane's
  *    rims: a noisy staircase's edge samples lay beyond both planes' edge lines);
  *  - plane support (setSupportCheck(false) for the paper): last, a member on or beyond its plane's
  *    rim whose in-plane gap to the rest of the plane is more than 6 times its neighbours' gaps, or
  *    which lies ahead of all its plane's neighbours by more than 2 of their gaps (or with under a
  *    tenth of its neighbours in the plane), and which lies in no other plane's noise band, leaves
  *    the plane, in rounds while releases expose more (outliers within the band just beyond a rim
  *    have the plane's PCA normal and pass growth);
  *  - last assignment (setFinalAssignment(None) for the paper): samples growth left out next to two
  *    or more planes join the one whose MDP band holds them (edge bands of bent normals), and samples
  *    inside one plane join it if their normal passes its MND and they lie within 4 robust standard
  *    deviations of it (the noise tail MDP cuts off); the first kind reaches no farther than 3
  *    neighbourhood radii from the plane's grown members;
  *  - surrounding clutter (setSurroundingClutter(false) for the tail odds' neighbourhood count
  *    alone): the clutter around a plane is counted over its footprint too, both sides, and the
  *    members beyond the tail's end (below 3 σ in dense clutter, MDP the floor) leave it;
  *  - member gaps (setMemberGaps(false) for the last assignment above alone): beside a plane in
  *    clutter, a sample joins it only where it lies among its members, its in-plane gap to the
  *    nearest within 6 times the gaps of the supported members beside it (a joiner vouches with
  *    the spacing that admitted it), so the rounds do not chain the plane from outlier to outlier
  *    through the clutter beyond its rim;
  *  - rim bands (setRimBands(false) for "most of its neighbours members" alone): beside a clean
  *    plane, a sample within its MDP joins it where its members are at least a third of its
  *    neighbours within the plane's band and some neighbour lies off it, so the ring whose normals
  *    a surface bending away beside the rim tilts (a tank's flat top at its wall) is its plane's;
  *  - position planes (setPositionPlanes(false) for the paper): then, among the samples no plane
  *    holds, planes fitted by position alone in each part the k-NN graph connects, kept if ε or more
  *    lie within the noise of the noisiest plane found and bend no more than noise (a small face
  *    sampled sparsely, whose PCA normals bend over most of it);
  *  - robust normals are available, off by default for their cost (setNormalFit(TrimmedPlane)): the
  *    reweighted least-trimmed-squares plane of the same k-neighbourhood (pcl::rspd::refineNormalsTrimmed),
  *    so normals near an edge belong to one face instead of bending between two;
  *  - orientation (setDetectionFrame(InputAxes) for the paper): the octree cells and the
  *    component-wise medians of Eqs. 3-4 follow the cloud's axes; the phases run instead in the frame
  *    of the dominant normal directions (pcl::rspd::dominantFrame), so a rotated cloud gives the
  *    same planes, and the cells of a scene not aligned with its axes hold one wall, not a slice of two;
  *  - a curved-surface check (setCurvedPlaneCheck, on by default) drops planes whose samples bend
  *    and whose normals turn smoothly: facets of pipes, tanks, pillars and balls; where noise hides
  *    the bend from the quadric's fixed bounds, a bend beyond chance and normals turning across the
  *    plane by half its MND suffice (setCurvedNormalTurn);
  *  - depth levels (setDepthLevelDither, off by default): where a structured-light or stereo
  *    camera quantized the depths along its axis, each sample's depth is drawn again within its
  *    level's bin for the detection, so the levels' flat terraces make no planes of their own.
  *
  * Without setInputNormals, normals are estimated by PCA over the same k-neighbourhoods that form
  * the growth graph. Where noise along the normal is as large as such a neighbourhood (a million
  * samples on a unit cube with 1 % noise), those normals are noise and nothing is found;
  * setNormalScale (Adaptive or Automatic) then takes each such sample's normal from the finest wider
  * scale that resolves a surface, and leaves every other normal as it is (Automatic, the default, does
  * that only when most samples are unresolved, so resolved scenes keep exactly the PCA normals). Without
  * setSearchMethod, the graph comes from the library's own exact k-NN (pcl::rspd::buildKnnGraph);
  * any pcl::search::Search can be plugged in instead.
  *
  * The setters of pcl::SACSegmentation (setModelType, setMethodType, setDistanceThreshold,
  * setMaxIterations, setProbability, setOptimizeCoefficients) are accepted so that a pipeline can
  * swap classes by changing one declaration: only plane models are supported; the thresholds are
  * ignored (the method estimates its own) and say so at PCL_DEBUG level.
  *
  * \ingroup segmentation
  */
template <typename PointT, typename NormalT = pcl::Normal>
class RobustPlaneSegmentation : public pcl::PCLBase<PointT>
{
public:
  using PointCloud = pcl::PointCloud<PointT>;
  using PointCloudConstPtr = typename PointCloud::ConstPtr;
  using Normals = pcl::PointCloud<NormalT>;
  using NormalsConstPtr = typename Normals::ConstPtr;
  using Search = pcl::search::Search<PointT>;
  using SearchPtr = typename Search::Ptr;

  using PCLBase<PointT>::input_;
  using PCLBase<PointT>::indices_;
  using PCLBase<PointT>::initCompute;
  using PCLBase<PointT>::deinitCompute;

  /** \brief Constructor with the paper's defaults. */
  RobustPlaneSegmentation ();

  ~RobustPlaneSegmentation () override = default;

  /** \brief Set the input cloud (invalidates cached results). */
  void
  setInputCloud (const PointCloudConstPtr& cloud) override;

  /** \brief Restrict the detection to these indices (invalidates cached results). */
  void
  setIndices (const IndicesPtr& indices) override;
  /** \brief Restrict the detection to these indices (invalidates cached results). */
  void
  setIndices (const IndicesConstPtr& indices) override;
  /** \brief Restrict the detection to these indices (invalidates cached results). */
  void
  setIndices (const PointIndicesConstPtr& indices) override;
  /** \brief Restrict the detection to a block of an organized cloud (invalidates cached results). */
  void
  setIndices (std::size_t row_start, std::size_t col_start, std::size_t nb_rows, std::size_t nb_cols) override;

  /** \brief Per-point normals, same size and order as the input cloud. Optional: without them,
    * normals are estimated by PCA over the k-neighbourhoods of the growth graph. */
  void
  setInputNormals (const NormalsConstPtr& normals);
  /** \brief The normals given with setInputNormals (null if none). */
  NormalsConstPtr
  getInputNormals () const { return normals_; }

  /** \brief Search method for the k-NN graph (optional: the library's own exact k-NN otherwise). */
  void
  setSearchMethod (const SearchPtr& search);
  /** \brief The search method given with setSearchMethod (null if none). */
  SearchPtr
  getSearchMethod () const { return search_; }

  /** \brief k, the neighbours per sample of the graph and of normal estimation, not counting the
    * sample itself (>= 3; the paper's is 50, Sec. 3.3), or 0, the default: automatic, ε/2 between
    * 15 and 50 (pcl::rspd::automaticNumberOfNeighbours), i.e. 50 from 100,000 valid points on, when
    * the normals are estimated here; 50 with normals from setInputNormals, whose scale is the
    * caller's. */
  void
  setNumberOfNeighbours (int k);
  /** \brief k as set: 0 for automatic. */
  int
  getNumberOfNeighbours () const { return k_; }
  /** \brief k the last segmentation used (0 before any): the one set, or the automatic choice. */
  int
  getNumberOfNeighboursUsed () const { return k_used_; }

  /** \brief ε as a fraction of the number n of valid samples: ε = max(10, ceil(ratio·n))
    * (default 0.001, Sec. 3.1). */
  void
  setMinPatchSizeRatio (double ratio);
  /** \brief ε as a fraction of the number of valid samples. */
  double
  getMinPatchSizeRatio () const { return min_patch_ratio_; }

  /** \brief ε directly, in samples (>= 3); wins over the ratio. 0 returns to the ratio. */
  void
  setMinPatchSize (std::size_t min_size);
  /** \brief ε set directly (0: derived from the ratio). */
  std::size_t
  getMinPatchSize () const { return min_patch_size_; }

  /** \brief OpenMP threads (0, the default: what OpenMP gives, so OMP_NUM_THREADS is honoured).
    * The output does not depend on it. */
  void
  setNumberOfThreads (unsigned int threads);
  /** \brief OpenMP threads (0: OpenMP's default). */
  unsigned int
  getNumberOfThreads () const { return static_cast<unsigned int> (params_.num_threads); }

  /** \brief T1: minimum angle between F and N, radians (default 75°). */
  void
  setMinDistanceTestAngle (double radians);
  /** \brief T1 threshold, radians. */
  double
  getMinDistanceTestAngle () const { return params_.min_distance_angle; }

  /** \brief T2: MND must stay below this, radians (default 60°). */
  void
  setMaxNormalDeviation (double radians);
  /** \brief T2 threshold, radians. */
  double
  getMaxNormalDeviation () const { return params_.max_normal_deviation; }

  /** \brief T3: share of outliers at which a cell is rejected, in (0, 1] (default 0.25). */
  void
  setMaxOutlierRatio (double ratio);
  /** \brief T3 threshold. */
  double
  getMaxOutlierRatio () const { return params_.max_outlier_ratio; }

  /** \brief α: half-width of the inlier intervals in MADs (default 3, Eqs. 6 and 9). */
  void
  setAlpha (double alpha);
  /** \brief α, in MADs. */
  double
  getAlpha () const { return params_.alpha; }

  /** \brief Floor of the distance interval's half-width as a fraction of the patch's in-plane
    * extent (default 1e-6; 0 = the paper's letter). */
  void
  setDistanceFloorRatio (double ratio);
  /** \brief Floor of the distance interval, fraction of the patch extent. */
  double
  getDistanceFloorRatio () const { return params_.distance_floor_ratio; }

  /** \brief Floor of the normal-deviation interval's half-width, radians (default 1e-3; 0 = paper). */
  void
  setNormalDeviationFloor (double radians);
  /** \brief Floor of the normal-deviation interval, radians. */
  double
  getNormalDeviationFloor () const { return params_.normal_deviation_floor; }

  /** \brief Flip normals into the cell's dominant hemisphere before the median of Eq. 4
    * (default true; false = the paper's plain component-wise median). */
  void
  setAlignNormalsBeforeMedian (bool align);
  /** \brief Whether normals are aligned before the median of Eq. 4. */
  bool
  getAlignNormalsBeforeMedian () const { return params_.align_normals; }

  /** \brief Small-plane pass (default on): after the paper's split-grow-merge, split the unassigned
    * samples again with cells down to k + 1 samples (the normal-estimation neighbourhood), keep seeds
    * whose MND is at most the largest MND of the planes found and that are not a layer of a found
    * plane's noise band, grow-merge, and drop planes smaller than ε. false = the paper's single
    * split. */
  void
  setSmallPlaneSeeding (bool enable);
  /** \brief Whether the small-plane pass runs. */
  bool
  getSmallPlaneSeeding () const { return small_plane_seeding_; }

  /** \brief Trimmed normals for what growth left (default off, for its time; false = the paper): the small-plane
    * pass splits the samples it left a second time, on the normals of their k-neighbourhoods'
    * reweighted least-trimmed-squares planes (pcl::rspd::refineNormalsTrimmed); growth and the later
    * passes keep the PCA normals. Applies only to normals estimated here by PCA (not with
    * setNormalFit(TrimmedPlane), where every normal is trimmed already; normals given with
    * setInputNormals have setLeftNormalRefitOnGivenNormals). See
    * pcl::rspd::DetectorParameters::left_normal_refit and setTrimmedSeedGrowth. */
  void
  setLeftNormalRefit (bool enable);
  /** \brief Whether the left samples' normals are refitted (normals estimated here). */
  bool
  getLeftNormalRefit () const { return left_normal_refit_; }

  /** \brief Narrowed normals for what growth left (default on; false = the paper, with
    * setShiftedGrid(false) this release's earlier default): unless setLeftNormalRefit asks for
    * trimmed normals, the small-plane pass splits the samples it left a second time, on their PCA
    * normals narrowed to one face at edges (pcl::rspd::narrowNormalsAtEdges, as setEdgeAwareNormals
    * does for every sample), and a seed found so grows on them. Applies only to the normals
    * estimated here by PCA at the k-scale (not with setInputNormals, setNormalFit(TrimmedPlane),
    * setEdgeAwareNormals(true), or where the adaptive scale widened a normal). With the shifted
    * grid, the room at 100,000 points finds its cabinet's top and front: 12 of 12 planes on 11 of
    * 12 seeds, against 1 of 12 before (README). See pcl::rspd::DetectorParameters::left_normal_narrow. */
  void
  setLeftNormalNarrowing (bool enable);
  /** \brief Whether the left samples' normals are narrowed at edges (normals estimated here). */
  bool
  getLeftNormalNarrowing () const { return left_normal_narrowing_; }

  /** \brief Shifted grid (default on; false = the paper's one octree): each split of the small-plane
    * pass runs again, over what its seeds left, on an octree whose cells are moved by a third or two
    * thirds of a cell at every level (pcl::rspd::kShiftedGridOffset), and keeps only seeds no noisier
    * and no thicker than the planes found, judged flat again once grown. A small face that every
    * cell of the first grid cuts into untestable pieces lies whole in a cell of the shifted one. See
    * pcl::rspd::DetectorParameters::shifted_small_grid. */
  void
  setShiftedGrid (bool enable);
  /** \brief Whether the small-plane pass also splits on the shifted grid. */
  bool
  getShiftedGrid () const { return shifted_grid_; }

  /** \brief Trimmed normals for what growth left, with the caller's normals (setInputNormals;
    * default on; false = the paper, and the normals used as given throughout): as
    * setLeftNormalRefit, for the small-plane pass's second split only. The caller's normals come at
    * a scale chosen without this cloud's small planes in view (PCL's k = 50 on 10,000 points
    * reaches 0.4 m in a room), and with them detection skips its normal stage, which leaves time for
    * the refit: on PCL's k = 50 normals (rspd_compare) the boxes at 10,000 points 13 → 18 of 32
    * planes, at 20,000 25 → 28, the room at 50,000 points 9 → 11 of 12, the industrial yard at
    * 10,000 points 5 → 6 of 6; the 300,000-point room's detection 0.43 → 0.54 s (README). */
  void
  setLeftNormalRefitOnGivenNormals (bool enable);
  /** \brief Whether the left samples' normals are refitted when the caller gives normals. */
  bool
  getLeftNormalRefitOnGivenNormals () const { return given_normals_left_refit_; }

  /** \brief With the left samples' normals refitted: a seed found on the trimmed normals grows and is
    * re-estimated on them (default true; false = on the normals every other plane reads, where a
    * small plane's seed often cannot grow past its bent rims and stays below ε). See
    * pcl::rspd::DetectorParameters::trimmed_seed_growth. */
  void
  setTrimmedSeedGrowth (bool enable);
  /** \brief Whether seeds found on the trimmed normals grow on them. */
  bool
  getTrimmedSeedGrowth () const { return params_.trimmed_seed_growth; }

  /** \brief Noisy given normals (default true, with setNormalScale(Automatic); false = the caller's
    * normals are always used as given): when most of the cloud's k-neighbourhoods resolve no surface
    * and the caller's normals agree with their neighbours' no better than those neighbourhoods' PCA
    * normals do (pcl::rspd::givenNormalsAreNoise), they are noise at this scale, and normals are
    * estimated here instead, at the finest scale that resolves a surface (as without normals). PCL's
    * k = 50 normals on the 1M-point cube with noise 1 % of its edge gave no plane at all (0 of 6);
    * estimated again, 6 of 6 (README). Below 100,000 samples also when they blur the faces the
    * automatic k resolves, at most of its neighbourhoods or where most 50-neighbourhoods' PCA
    * normals do (pcl::rspd::givenNormalsBlurFaces: normals of that coarser scale): the detection
    * then runs as without them, at that k (a 5,000-sample staircase on PCL's k = 50 normals: 1 of
    * 30 planes as given, 30 so; an 8,000-sample facade: 15 of 16, 16).
    * getStatistics().given_normals_replaced (and given_normals_blurred) says whether it happened. */
  void
  setGivenNormalCheck (bool enable);
  /** \brief Whether noisy given normals are estimated again. */
  bool
  getGivenNormalCheck () const { return given_normal_check_; }

  /** \brief Depth levels dithered (default false: the samples as given): a structured-light or
    * stereo camera quantizes depth, and each surface not square to its axis becomes exactly flat
    * terraces at those depths, each a plane of its own square to the axis (office1: 23 of 44 planes).
    * When the samples' depths along the camera's axis (sensor_orientation_ applied to +z, from
    * sensor_origin_) are such levels (pcl::rspd::findDepthLevels), each sample is moved, for the
    * detection only, along its ray to a depth drawn within its level's bin
    * (pcl::rspd::ditherDepthLevels): the rounding becomes noise again. The caller's cloud is not
    * changed; the planes are fitted to the dithered samples. getStatistics().depth_levels says how
    * many levels were found (0: not quantized, nothing moved). See the README (depth levels). */
  void
  setDepthLevelDither (bool enable);
  /** \brief Whether quantized depth levels are dithered. */
  bool
  getDepthLevelDither () const { return depth_level_dither_; }

  /** \brief Rim cells in the small-plane pass (default true; false = they seed nothing): a cell that
    * passes T1 and T2 but fails T3 is tested again on its own inliers, which seed a plane if they
    * pass — where a small plane meets others, every cell of k + 1 samples holds a band of bent
    * normals along its rim. See pcl::rspd::DetectorParameters::rim_cell_retest. */
  void
  setRimCellRetest (bool enable);
  /** \brief Whether rim cells are tested again on their inliers. */
  bool
  getRimCellRetest () const { return params_.rim_cell_retest; }

  /** \brief Rim cells retested until stable (default true; false = one retest): where a rim cell's
    * inliers still fail T3, their own inliers are tested again, until the test passes, fewer than ε
    * are left or they no longer change. See pcl::rspd::DetectorParameters::rim_retest_until_stable. */
  void
  setRimRetestUntilStable (bool enable);
  /** \brief Whether rim cells are retested until stable. */
  bool
  getRimRetestUntilStable () const { return params_.rim_retest_until_stable; }

  /** \brief Rim cells on the left samples' normals (default true; false = inliers as many as the
    * cells): in the small-plane pass's second split, on the narrowed or trimmed normals of what growth
    * left, a rim cell's inliers are tested again down to 16 of them, the faces narrowed normals
    * resolve, instead of k + 1. See pcl::rspd::DetectorParameters::left_rim_retest. */
  void
  setLeftRimRetest (bool enable);
  /** \brief Whether rim cells' inliers on the left samples' normals are tested down to 16 of them. */
  bool
  getLeftRimRetest () const { return params_.left_rim_retest; }

  /** \brief Position planes (default true; false = the paper): after the last assignment, the
    * samples no plane holds are searched for planes by their positions alone, in the parts the k-NN
    * graph connects: kept if ε or more lie within the noise of the noisiest plane found, bend no more
    * than noise and are no layer of a plane found (a small face whose normals bend over most of it).
    * See pcl::rspd::seedPositionPlanes and pcl::rspd::DetectorParameters::position_planes. */
  void
  setPositionPlanes (bool enable);
  /** \brief Whether what is left is searched for planes by position. */
  bool
  getPositionPlanes () const { return params_.position_planes; }
  /** \brief Surface parts (default true; false = a part is left at its first plane turned down):
    * with position planes on, where a part's search ended at a plane turned down (a slab of
    * outliers, say), the samples it still holds that lie on a surface are searched again. See
    * pcl::rspd::DetectorParameters::position_surface_parts. */
  void
  setPositionSurfaceParts (bool enable);
  /** \brief Whether what a part still holds on a surface is searched again. */
  bool
  getPositionSurfaceParts () const { return params_.position_surface_parts; }
  /** \brief Same-face members (default true; false = by position alone): with surface parts on, a
    * member of a plane searched again must have its neighbourhood's plane nearer parallel to the
    * plane than perpendicular, so that the strips of the faces beside it do not bend it. See
    * pcl::rspd::DetectorParameters::position_surface_normals. */
  void
  setPositionSurfaceNormals (bool enable);
  /** \brief Whether members of planes searched again must face their plane. */
  bool
  getPositionSurfaceNormals () const { return params_.position_surface_normals; }
  /** \brief Band samples in the bend (default true; false = the members alone): a plane found by
    * position that bends beyond chance is judged again with the unlabelled samples beside it that
    * the pass left out as lying in a neighbouring plane's band. See
    * pcl::rspd::DetectorParameters::position_bend_band. */
  void
  setPositionBendBand (bool enable);
  /** \brief Whether the position planes' bend is judged with those band samples too. */
  bool
  getPositionBendBand () const { return params_.position_bend_band; }
  /** \brief Neighbours' slabs in the bend (default true; false = not): a plane found by position
    * that still bends beyond chance is judged again without its members in the bands of the planes
    * found beside it that cross it. See pcl::rspd::DetectorParameters::position_bend_slabs. */
  void
  setPositionBendSlabs (bool enable);
  /** \brief Whether the position planes' bend is judged without the neighbours' slabs too. */
  bool
  getPositionBendSlabs () const { return params_.position_bend_slabs; }
  /** \brief Join beside (default true; false = left in no plane): a plane found by position that lies
    * on a plane beside it gives that plane its members within its noise band. See
    * pcl::rspd::DetectorParameters::position_join_beside. */
  void
  setPositionJoinBeside (bool enable);
  /** \brief Whether a position plane lying on a plane beside it joins that plane. */
  bool
  getPositionJoinBeside () const { return params_.position_join_beside; }
  /** \brief Noise ladder of the surface parts (default true; false = the noisiest plane found bounds
    * every plane by position): what is still left is searched again for planes up to twice as
    * noisy as the noisiest plane kept, step by step while a step keeps a noisier one. See
    * pcl::rspd::DetectorParameters::position_surface_ladder. */
  void
  setPositionSurfaceLadder (bool enable);
  /** \brief Whether the surface parts climb a noise ladder. */
  bool
  getPositionSurfaceLadder () const { return params_.position_surface_ladder; }
  /** \brief Rungs of the noise ladder (default true; false = a step follows only a step that kept a
    * noisier plane): a step that keeps no plane but turned one down for its noise alone, within the
    * next step's noise, is followed by that step. See
    * pcl::rspd::DetectorParameters::position_ladder_rungs. */
  void
  setPositionLadderRungs (bool enable);
  /** \brief Whether the noise ladder steps on turned-down planes too. */
  bool
  getPositionLadderRungs () const { return params_.position_ladder_rungs; }

  /** \brief Tail odds (default true; false = every plane's 4 σ tail): the last assignment takes a
    * plane's noise tail only as far as its noise stays likelier than the clutter measured beside it
    * (between 3 and 4 σ), so that outliers in a plane's band stay out where they outnumber its
    * samples. See pcl::rspd::DetectorParameters::tail_odds. */
  void
  setTailOdds (bool enable);
  /** \brief Whether each plane's tail ends where the clutter beside it outweighs its noise. */
  bool
  getTailOdds () const { return params_.tail_odds; }

  /** \brief Surrounding clutter (default true; false = the tail odds' neighbourhood shell alone):
    * with the tail odds, the clutter beside a plane is also counted over its footprint, on both
    * sides (twice the lesser), the tail ends where the clutter outweighs the plane's noise even
    * below 3 σ (MDP the floor), and the members beyond it leave the plane before the last
    * assignment. See pcl::rspd::DetectorParameters::surrounding_clutter. */
  void
  setSurroundingClutter (bool enable);
  /** \brief Whether the tail odds count the clutter around each plane over its footprint. */
  bool
  getSurroundingClutter () const { return params_.surrounding_clutter; }

  /** \brief Member gaps (default true; false = the last assignment by distance, normal and
    * neighbours alone): the last assignment gives a sample to a plane only where it lies among the
    * plane's members, its in-plane gap to the nearest within 6 times theirs, so that it does not
    * chain from outlier to outlier through the clutter beside a rim. See
    * pcl::rspd::DetectorParameters::member_gaps. */
  void
  setMemberGaps (bool enable);
  /** \brief Whether the last assignment keeps to the spacing of each plane's members. */
  bool
  getMemberGaps () const { return params_.member_gaps; }

  /** \brief Rim bands (default true; false = a sample joins a plane beside it only when most of its
    * neighbours are members): beside a plane with no clutter around it, the last assignment also
    * gives it a sample within its MDP whose neighbours within its band are at least a third its
    * members, counting no neighbour off the band (and one at least lies off it), so that a rim whose normals tilt toward a surface
    * bending away beside it (a tank's flat top at its wall) joins its plane. See
    * pcl::rspd::DetectorParameters::rim_bands. */
  void
  setRimBands (bool enable);
  /** \brief Whether the last assignment takes a clean plane's rim band. */
  bool
  getRimBands () const { return params_.rim_bands; }

  /** \brief Normals turn at a hinge (default true; false = positions alone): a seed or a group of
    * cells is bent at an edge, and seeds nothing, only if its two sides' mean normals turn by more
    * than 90° minus T1's angle as their planes do. See
    * pcl::rspd::DetectorParameters::hinge_normal_turn. */
  void
  setHingeNormalTurn (bool enable);
  /** \brief Whether a hinge needs the normals to turn too. */
  bool
  getHingeNormalTurn () const { return params_.hinge_normal_turn; }

  /** \brief Far members (default true; false = the paper, members are never revoked): once
    * grow-merge is stable, members farther from their plane's last estimate than its noise band
    * (max(MDP, 3 robust σ)) are released, a neighbouring plane whose inlier test they pass takes
    * them, and the rest go back unless another plane borders them. See pcl::rspd::DetectorParameters::release_far_members. */
  void
  setFarMemberRelease (bool enable);
  /** \brief Whether far members are released. */
  bool
  getFarMemberRelease () const { return params_.release_far_members; }

  /** \brief Released planes (default true; false = every released sample no plane took goes back):
    * with the far-member release on, released samples that no plane took and that form a group of at
    * least ε samples (graph edges) passing T1-T3 become a plane. See
    * pcl::rspd::DetectorParameters::seed_released_planes. */
  void
  setReleasedPlaneSeeding (bool enable);
  /** \brief Whether groups of released samples may seed planes. */
  bool
  getReleasedPlaneSeeding () const { return params_.seed_released_planes; }

  /** \brief Released strips (default true; false = every group that passes T1-T3 becomes a plane):
    * a group of released samples that lies on a neighbouring plane at least as closely as on its own
    * seeds nothing (a strip along an edge, whose normals bend towards the plane that released it).
    * See pcl::rspd::DetectorParameters::released_layer_check. */
  void
  setReleasedLayerCheck (bool enable);
  /** \brief Whether released groups lying on a neighbouring plane are kept from seeding. */
  bool
  getReleasedLayerCheck () const { return params_.released_layer_check; }

  /** \brief Bent planes' noisy sides (default true; false = T2 at 60° for every side): a side of a
    * bent plane passes T2 if its MND is below that of the plane it was cut from, where that is wider
    * than 60°. See pcl::rspd::DetectorParameters::bent_side_parent_mnd. */
  void
  setBentSideParentMnd (bool enable);
  /** \brief Whether bent planes' sides are held to their plane's MND where it is past T2. */
  bool
  getBentSideParentMnd () const { return params_.bent_side_parent_mnd; }

  /** \brief Edges the normals confirm (default true; false = the positions alone tell a bent plane):
    * a plane whose two sides meet at more than 15° is split there where its noise keeps two planes
    * from lowering the positions' σ to 0.8 of one plane's, if they lower it to 0.906, the sides'
    * mean normals turn by more than 15° too, and in one step rather than steadily (no curved
    * surface). See pcl::rspd::DetectorParameters::bent_normal_edges. */
  void
  setBentNormalEdges (bool enable);
  /** \brief Whether edges the normals confirm split bent planes. */
  bool
  getBentNormalEdges () const { return params_.bent_normal_edges; }

  /** \brief Connected parts (default true; false = the paper): a plane whose members that pass its
    * inlier test at its last estimate form two or more parts of at least ε samples with no graph edge
    * between them is split into them. See pcl::rspd::splitDisconnectedPlanes and
    * pcl::rspd::DetectorParameters::connected_parts. */
  void
  setConnectedParts (bool enable);
  /** \brief Whether planes made of separate parts are split. */
  bool
  getConnectedParts () const { return params_.connected_parts; }

  /** \brief Bent planes (default true; false = the paper): a plane whose samples lie on two planes
    * meeting at an edge (more than 90° minus T1's angle apart, lowering the robust spread to at most
    * 0.8 of one plane's, each side a plane by T1-T3) is split there, and each part again; parts of
    * split planes that are one face (touching, within 15°, no bend or step between them) are then
    * joined. See pcl::rspd::splitBentPlanes, pcl::rspd::joinSplitFaces and
    * pcl::rspd::DetectorParameters::bent_plane_split. */
  void
  setBentPlaneSplit (bool enable);
  /** \brief Whether planes bent at an edge are split. */
  bool
  getBentPlaneSplit () const { return params_.bent_plane_split; }

  /** \brief Band layers (default true; false = the paper): after the bent-plane split, a plane at
    * least half of whose members border a larger plane, whose members lie (median) within that
    * plane's noise band and which does not tilt out of it across its extent, is merged into it and
    * the plane estimated again, until none is. See pcl::rspd::mergeBandLayers and
    * pcl::rspd::DetectorParameters::layer_merge. */
  void
  setLayerMerge (bool enable);
  /** \brief Whether layers of a plane's noise band are merged into it. */
  bool
  getLayerMerge () const { return params_.layer_merge; }

  /** \brief Steps are no layers (default true; false = the layer merge alone): with the layer merge,
    * a plane whose members' neighbourhoods average off its joint plane with the larger plane by more
    * than half that plane's robust σ (a window recessed within its wall's noise band) stays apart.
    * See pcl::rspd::DetectorParameters::layer_steps. */
  void
  setLayerSteps (bool enable);
  /** \brief Whether a step beside a larger plane is kept out of the layer merge. */
  bool
  getLayerSteps () const { return params_.layer_steps; }

  /** \brief Step split (default true; false = the region stays in its plane): after the bent-plane
    * split, a region of a plane that lies parallel to the rest, offset by a step within the noise
    * band (a door 2 cm proud of its wall at σ = 1.5 cm), is split off as a plane of its own. See
    * pcl::rspd::splitSteps and pcl::rspd::DetectorParameters::step_split. */
  void
  setStepSplit (bool enable);
  /** \brief Whether regions offset by a step within a plane's noise band are split off. */
  bool
  getStepSplit () const { return params_.step_split; }

  /** \brief Planes across a step (default true; false = they stay): after the layer merge, a plane
    * whose members lie on two planes beside it, parallel to each other and not to it, at least as
    * closely (robust σ of the distance to the nearer) as on its own plane is dropped, its samples
    * left to the last assignment: a strip of a door's and its wall's samples seeded before the door
    * was parted from the wall. See pcl::rspd::dropPlanesAcrossSteps and
    * pcl::rspd::DetectorParameters::across_step_check. */
  void
  setAcrossStepCheck (bool enable);
  /** \brief Whether planes that only bridge a step between two parallel planes are dropped. */
  bool
  getAcrossStepCheck () const { return params_.across_step_check; }

  /** \brief Edge sides (default true; false = the paper): where two planes meet, a sample of one
    * whose projection onto it lies beyond the line where they meet leaves it, for the other plane
    * (within its noise band, projection on its own side) or for none. See pcl::rspd::settleEdgeSides
    * and pcl::rspd::DetectorParameters::edge_sides. */
  void
  setEdgeSides (bool enable);
  /** \brief Whether samples beyond the line where their plane meets another leave it. */
  bool
  getEdgeSides () const { return params_.edge_sides; }

  /** \brief Edge corners (default true; false = edge sides as before): with edge sides on, a sample
    * inside the corner two planes make goes to the nearer plane relative to its noise band. See
    * pcl::rspd::settleEdgeSides and pcl::rspd::DetectorParameters::edge_corners. */
  void
  setEdgeCorners (bool enable);
  /** \brief Whether samples inside a corner go to the nearer plane. */
  bool
  getEdgeCorners () const { return params_.edge_corners; }

  /** \brief Edge wedges (default true; false = edge sides as before): with edge sides on, a sample
    * outside the edge of two planes (beyond each) goes to the plane it lies farther from, within
    * both noise bands, instead of to none. See pcl::rspd::settleEdgeSides and
    * pcl::rspd::DetectorParameters::edge_wedges. */
  void
  setEdgeWedges (bool enable);
  /** \brief Whether samples outside an edge go to the farther plane. */
  bool
  getEdgeWedges () const { return params_.edge_wedges; }

  /** \brief Thick-cell join (default true; false = the paper): the split also keeps the largest
    * cells that fail T1 alone (too thick for their extent, planar by T2 and T3), joins touching ones
    * whose planes agree, and seeds a patch from each group that passes T1-T3 as a whole. See
    * pcl::rspd::DetectorParameters::join_thick_cells. */
  void
  setThickCellJoin (bool enable);
  /** \brief Whether groups of thick cells may seed patches. */
  bool
  getThickCellJoin () const { return params_.join_thick_cells; }

  /** \brief Step sides (default true; false = the paper): where two parallel planes make a step
    * deeper than the wider of their noise bands, a sample of one that lies within the other's band
    * goes to it when the other holds more of its neighbours (passes until none moves). See pcl::rspd::settleStepSides and
    * pcl::rspd::DetectorParameters::step_sides. */
  void
  setStepSides (bool enable);
  /** \brief Whether samples nearer a parallel plane across a step go to it. */
  bool
  getStepSides () const { return params_.step_sides; }

  /** \brief Step regions (default true; false = samples one at a time): before the step sides, a
    * plane's region that lies off it on one side, toward a parallel plane beside it, goes to that
    * plane when the median of its samples' distances to it is below that to their own plane (a
    * block of a window's samples that the wall's band took). See pcl::rspd::settleStepRegions and
    * pcl::rspd::DetectorParameters::step_regions. */
  void
  setStepRegions (bool enable);
  /** \brief Whether regions off a plane toward a parallel plane beside them go to it. */
  bool
  getStepRegions () const { return params_.step_regions; }

  /** \brief Plane support (default true; false = the paper): last of all, a member on or beyond its
    * plane's rim whose in-plane gap to the plane's nearest other sample is more than 6 times its
    * neighbours' gaps, or which lies ahead of all of them by more than 2 such gaps (or with under a
    * tenth of its neighbours in the plane), and which lies in no other plane's noise band, leaves the
    * plane for none; releases peel, up to 8 rounds. See
    * pcl::rspd::releaseUnsupportedMembers and pcl::rspd::DetectorParameters::support_check. */
  void
  setSupportCheck (bool enable);
  /** \brief Whether members beyond their plane's rim are released. */
  bool
  getSupportCheck () const { return params_.support_check; }

  /** \brief Clutter share (default true; false = the plane support's rim rules alone): with the
    * plane support, a member whose plane, within its neighbourhood, is no denser inside its noise
    * band than the unlabelled samples outside it leaves it wherever it lies, as a sheet of clutter
    * a noisy plane's band took. See pcl::rspd::releaseUnsupportedMembers and
    * pcl::rspd::DetectorParameters::support_clutter. */
  void
  setSupportClutter (bool enable);
  /** \brief Whether members amid clutter as dense as their plane are released. */
  bool
  getSupportClutter () const { return params_.support_clutter; }

  /** \brief Final parts (default true; false = the planes as the plane support leaves them): after
    * the plane support, a plane of two or more pieces of surface is split into them, and a plane of
    * one keeps only the members that a chain of its members joins to it. See
    * pcl::rspd::splitDisconnectedPlanes and pcl::rspd::DetectorParameters::final_parts. */
  void
  setFinalParts (bool enable);
  /** \brief Whether the final members are cut into connected parts once more. */
  bool
  getFinalParts () const { return params_.final_parts; }

  /** \brief Final refit (default true; false = the paper's robust estimate throughout): once the
    * planes' samples are settled, each plane's centre and normal become the least-squares plane of
    * its members within 2.5 robust sigmas, before the last assignment, the edge and step sides and
    * the plane support; and again on the final members, for the coefficients returned. See
    * pcl::rspd::refitPlanes and pcl::rspd::DetectorParameters::final_refit. */
  void
  setFinalRefit (bool enable);
  /** \brief Whether the planes are refitted by least squares before the last passes. */
  bool
  getFinalRefit () const { return params_.final_refit; }

  /** \brief M4, coplanar groups (default true; false = the paper's transitive M1-M3): a group joins
    * another only if most of its samples lie in the distance band of the plane the merged group
    * keeps. See pcl::rspd::DetectorParameters::coplanar_merge. */
  void
  setCoplanarMerge (bool enable);
  /** \brief Whether merging checks M4. */
  bool
  getCoplanarMerge () const { return params_.coplanar_merge; }

  /** \brief How estimated normals are fitted (used only without setInputNormals; default
    * pcl::rspd::NormalFit::Pca, the paper's; TrimmedPlane: least trimmed squares on the same
    * k-neighbourhood, then reweighted, where that neighbourhood resolves a surface — more accurate
    * at edges, about 20 times the cost of the normal stage). See pcl::rspd::refineNormalsTrimmed. */
  void
  setNormalFit (pcl::rspd::NormalFit fit);
  /** \brief How estimated normals are fitted. */
  pcl::rspd::NormalFit
  getNormalFit () const { return normal_fit_; }

  /** \brief The axes the octree is cut along and the medians of Eqs. 3-4 are taken on (default
    * pcl::rspd::DetectionFrame::DominantPlanes: those of the most common normal directions, so the
    * planes found do not depend on how the cloud is rotated; InputAxes = the paper). */
  void
  setDetectionFrame (pcl::rspd::DetectionFrame frame);
  /** \brief The axes the method works along. */
  pcl::rspd::DetectionFrame
  getDetectionFrame () const { return detection_frame_; }

  /** \brief Drop seeds whose MND is an outlier among the split's seeds (default on; off = the
    * paper). See pcl::rspd::DetectorParameters::drop_outlier_seeds. */
  void
  setDropOutlierSeeds (bool enable);
  /** \brief Whether outlier seeds are dropped. */
  bool
  getDropOutlierSeeds () const { return params_.drop_outlier_seeds; }

  /** \brief With outlier seeds dropped, test each again once growth is stable, on its samples no
    * plane took, and seed a plane if they pass T1-T3 and a quadric does not explain their spread
    * (default on; a thin board's noisy faces in a scene of smooth walls). See
    * pcl::rspd::DetectorParameters::retest_outlier_seeds. */
  void
  setOutlierSeedRetest (bool enable);
  /** \brief Whether dropped outlier seeds are tested again. */
  bool
  getOutlierSeedRetest () const { return params_.retest_outlier_seeds; }

  /** \brief Small-plane completion (default on; false = such planes are dropped, as the ε rule
    * drops every plane short of ε): before the small-plane pass drops its planes still short of ε, a
    * plane a clean seed seeded that holds at least half of ε takes, through the k-NN graph, the
    * samples within the noise band of its members' least-squares plane that no plane holds, or that
    * a noisier plane turned from it holds farther relative to that plane's band, and is kept if that
    * brings it to ε: a small face beside a noisier one, whose growth stopped short of its rim and
    * whose edge strip the neighbour's wider band held. See pcl::rspd::completeSmallPlanes and
    * pcl::rspd::DetectorParameters::small_plane_completion. */
  void
  setSmallPlaneCompletion (bool enable);
  /** \brief Whether small-plane pass planes short of ε are completed before the ε rule. */
  bool
  getSmallPlaneCompletion () const { return params_.small_plane_completion; }

  /** \brief Volume layers (default on; false = such planes are kept): a plane a noisy seed seeded
    * (a retested outlier seed, a group of thick cells) is dropped when the layer beside its noise
    * band on one side, half as thick as the band, holds more than twice as many samples as the
    * plane: it is where a volume of scattered samples (clutter, outliers) ends, not a surface. See
    * pcl::rspd::dropVolumeLayers and pcl::rspd::DetectorParameters::volume_layer_check. */
  void
  setVolumeLayerCheck (bool enable);
  /** \brief Whether noisy seeds' planes that end a volume of samples are dropped. */
  bool
  getVolumeLayerCheck () const { return params_.volume_layer_check; }

  /** \brief Final volume layers (default on; false = only noisy seeds' planes are judged): once the
    * planes are final, before the last assignment, every plane is judged by the volume-layer rule
    * (setVolumeLayerCheck), however it was seeded: a thin slab of outliers wrapping a plane grows
    * planes of outliers from clean seeds, whose bands reach the true plane's. See
    * pcl::rspd::DetectorParameters::final_volume_layer_check. */
  void
  setFinalVolumeLayerCheck (bool enable);
  /** \brief Whether every final plane that ends a volume of samples is dropped. */
  bool
  getFinalVolumeLayerCheck () const { return params_.final_volume_layer_check; }

  /** \brief In-band layers (default on; false = such planes are kept): with the final volume
    * layers, a final plane within whose noise band another plane is more than four times as dense
    * over its footprint is dropped, and the layer merge does not join it to that plane: a
    * plane grown among the clutter beside a denser one, whose band takes that plane in. See
    * pcl::rspd::DetectorParameters::in_band_layer_check. */
  void
  setInBandLayerCheck (bool enable);
  /** \brief Whether the final planes that are layers inside another plane's band are dropped. */
  bool
  getInBandLayerCheck () const { return params_.in_band_layer_check; }

  /** \brief Flat layers (default on; false = the final volume layers' ratio alone): with the final
    * volume layers, a final plane is also dropped when the layer beside its band on one side holds
    * more samples than the plane and the next layer as many again: a layer of a volume of clutter,
    * whose density runs on flat past it. See pcl::rspd::DetectorParameters::flat_layers. */
  void
  setFlatLayers (bool enable);
  /** \brief Whether the final planes that are layers of a flat volume of clutter are dropped. */
  bool
  getFlatLayers () const { return params_.flat_layers; }

  /** \brief Curved-surface check (default on; false = the paper): a plane is dropped when a quadric
    * fitted to its samples explains at least a quarter of its residual variance and turns the
    * surface normal by more than half the plane's MND between its middle and its rim (a facet of a
    * pipe, tank, pillar or ball), unless its normals turn in steps, as over the edges of a fold (see
    * setCurvedFoldRatio). See pcl::rspd::DetectorParameters::min_curvature_share. */
  void
  setCurvedPlaneCheck (bool enable);
  /** \brief Whether curved-surface facets are dropped. */
  bool
  getCurvedPlaneCheck () const { return params_.curved_plane_check; }

  /** \brief Late curved check (default on; false = the curved-surface check before the last
    * assignment alone): the check runs again once the planes hold their noise tails, which bring in
    * the bend a facet's band cut off. No effect with setCurvedPlaneCheck (false). See
    * pcl::rspd::DetectorParameters::late_curved_check. */
  void
  setLateCurvedCheck (bool enable);
  /** \brief Whether the curved-surface check runs again after the last assignment. */
  bool
  getLateCurvedCheck () const { return params_.late_curved_check; }

  /** \brief The curved-surface check drops a plane only if the residual of its normals' turn about a
    * line in the position is below this share of that about one step (default 0.5: a fold over up to
    * three faces is kept for the bent-plane split; +inf: every plane the quadric calls curved is
    * dropped). Must be positive. See pcl::rspd::DetectorParameters::curved_fold_ratio. */
  void
  setCurvedFoldRatio (double ratio);
  /** \brief The curved-surface check's fold ratio. */
  double
  getCurvedFoldRatio () const { return params_.curved_fold_ratio; }

  /** \brief The curved-surface check also reads the normals' own turn (default true; false = the
    * quadric's fixed bounds alone): a plane whose quadric bends beyond chance and whose normals turn
    * across it by at least half its MND, smoothly, is a curved facet even where noise keeps the
    * quadric's share below a quarter or its turn below half MND. See
    * pcl::rspd::DetectorParameters::curved_normal_turn. */
  void
  setCurvedNormalTurn (bool enable);
  /** \brief Whether the curved-surface check reads the normals' own turn. */
  bool
  getCurvedNormalTurn () const { return params_.curved_normal_turn; }

  /** \brief The curved-surface check's fold ratio spares a plane that bends beyond chance (99.9 %)
    * only if it has 2ε samples (default true; false = at every size): it keeps folds for the
    * bent-plane split, whose sides hold ε samples each. See
    * pcl::rspd::DetectorParameters::curved_fold_two_sides. */
  void
  setCurvedFoldTwoSides (bool enable);
  /** \brief Whether the fold ratio spares only planes of 2ε samples. */
  bool
  getCurvedFoldTwoSides () const { return params_.curved_fold_two_sides; }

  /** \brief The curved-surface check drops a plane as thick as a tube (its noise band at least half
    * its narrow side: a thin pipe's samples from every side) whatever its quadric and normals say
    * (default true; false = tubes judged as other planes). See
    * pcl::rspd::DetectorParameters::curved_tube_check. */
  void
  setCurvedTubeCheck (bool enable);
  /** \brief Whether the curved-surface check drops tubes. */
  bool
  getCurvedTubeCheck () const { return params_.curved_tube_check; }

  /** \brief The curved-surface check judges the parts the bent-plane split cut, as it judges planes
    * (default true; false = the parts kept unjudged). See
    * pcl::rspd::DetectorParameters::curved_split_parts. */
  void
  setCurvedSplitParts (bool enable);
  /** \brief Whether the curved-surface check judges the bent-plane split's parts. */
  bool
  getCurvedSplitParts () const { return params_.curved_split_parts; }

  /** \brief Small seeds' MND floor (default true; false = a seed's own MND): a seed of the
    * small-plane pass gets at least the MND of the tightest plane grown, since the normals of its few
    * samples share most of their neighbours and agree better than its plane's do. See
    * pcl::rspd::DetectorParameters::small_seed_mnd_floor. */
  void
  setSmallSeedMndFloor (bool enable);
  /** \brief Whether small seeds' MND is floored. */
  bool
  getSmallSeedMndFloor () const { return params_.small_seed_mnd_floor; }

  /** \brief Re-estimation within T2 (default true; false = the paper): a plane keeps its last
    * estimate when a re-estimate (Sec. 3.5) fails T2 (only noisy seeds' planes until issue #6's
    * thirty-third session). See pcl::rspd::DetectorParameters::bounded_reestimation. */
  void
  setBoundedReestimation (bool enable);
  /** \brief Whether planes keep an estimate within T2. */
  bool
  getBoundedReestimation () const { return params_.bounded_reestimation; }

  /** \brief Bent noisy planes (default false since issue #6's eighteenth session: such a plane is
    * dropped): a plane a noisy seed seeded that is not flat once grown, but that two flat planes
    * meeting at an edge explain, is split into them rather than dropped. Off because it also split a
    * pipe facet into two halves each judged flat at σ = 2 cm (two false planes). See
    * pcl::rspd::DetectorParameters::noisy_bent_split. */
  void
  setNoisyPlaneBentSplit (bool enable);
  /** \brief Whether bent noisy planes are split rather than dropped. */
  bool
  getNoisyPlaneBentSplit () const { return params_.noisy_bent_split; }

  /** \brief Thick cells among the left samples (default true; false = the small cells alone): the
    * small-plane pass's split also joins touching cells that fail T1 alone, as the thick-cell join
    * does in the first split (it needs setThickCellJoin(true) too). See
    * pcl::rspd::DetectorParameters::small_cell_thick_join. */
  void
  setSmallPassThickCellJoin (bool enable);
  /** \brief Whether the small-plane pass joins its thick cells. */
  bool
  getSmallPassThickCellJoin () const { return params_.small_cell_thick_join; }

  /** \brief Groups of noisy small seeds (default true; false = such seeds are turned down): the
    * small-plane pass's seeds noisier than every plane found, turned down alone, are joined where
    * they touch and agree, and a group of ε samples seeds a plane if it passes T1-T3, is flat, is no
    * edge band or noise-band layer, and is at most twice as noisy and thick as the planes found. See
    * pcl::rspd::DetectorParameters::noisy_seed_groups and pcl::rspd::joinNoisySeeds. */
  void
  setNoisySeedGroups (bool enable);
  /** \brief Whether groups of noisy small seeds may seed planes. */
  bool
  getNoisySeedGroups () const { return params_.noisy_seed_groups; }
  /** \brief Lone noisy seeds (default true; false = a noisy seed seeds only in a group of ε samples):
    * with the groups of noisy small seeds on, a noisy seed that joins no other seeds a plane alone if
    * it is within the groups' ratio of the planes found, flat, and no edge band or noise-band layer;
    * its grown plane must hold ε samples. A group of fewer than ε samples is judged the same way.
    * See pcl::rspd::DetectorParameters::noisy_lone_seeds. */
  void
  setNoisyLoneSeeds (bool enable);
  /** \brief Whether a lone noisy small seed may seed a plane. */
  bool
  getNoisyLoneSeeds () const { return params_.noisy_lone_seeds; }
  /** \brief Noise ladder (default true; false = one step): with the groups of noisy small seeds
    * on, once noisy seeds seeded planes of ε samples or more noisier than every plane found, the
    * noisy seeds still left are offered again against those, step by step while a step seeds such a
    * noisier plane, so surfaces each a little rougher than the last are all seeded. See
    * pcl::rspd::DetectorParameters::noisy_group_ladder. */
  void
  setNoisyGroupLadder (bool enable);
  /** \brief Whether the noisy seeds climb the noise ladder. */
  bool
  getNoisyGroupLadder () const { return params_.noisy_group_ladder; }
  /** \brief Noisy planes past T2 (default false: kept on their seed's estimate): a plane a noisy
    * seed seeded, judged once grown, is dropped where its members' estimate fails T2, as a plane run
    * into clutter or onto the faces around it; off by default, as faces rough enough that their
    * normals are noise fail it too. See pcl::rspd::DetectorParameters::noisy_grown_t2. */
  void
  setNoisyGrownT2 (bool enable);
  /** \brief Whether noisy seeds' grown planes must pass T2 on their members. */
  bool
  getNoisyGrownT2 () const { return params_.noisy_grown_t2; }
  /** \brief Thick cells that follow the noisy seeds (default true; false = the bound of the planes
    * found before the pass): where noisy small seeds seeded planes noisier than the small-plane
    * pass's thick cells may be, its thick cells are collected again up to the noisiest such plane's
    * MND. See pcl::rspd::DetectorParameters::thick_cells_follow_noisy_seeds. */
  void
  setThickCellsFollowNoisySeeds (bool enable);
  /** \brief Whether the small-plane pass's thick cells follow the noisy seeds' planes. */
  bool
  getThickCellsFollowNoisySeeds () const { return params_.thick_cells_follow_noisy_seeds; }
  /** \brief How many times as noisy (MND) and thick (MDP) as the noisiest and thickest plane found
    * a group of noisy small seeds may be, at least 1 (default 2). See
    * pcl::rspd::DetectorParameters::noisy_group_ratio. */
  void
  setNoisySeedGroupRatio (double ratio);
  /** \brief The noisy groups' bound, as a multiple of the planes found. */
  double
  getNoisySeedGroupRatio () const { return params_.noisy_group_ratio; }

  /** \brief Bend tested against noise (default true; false = a fixed share, as before): where a
    * noisy seed or plane is judged flat (the outlier-seed retest, the thick-cell groups, the
    * small-plane pass), a quadric's share of its residual counts as a bend only beyond what the
    * quadric explains of a flat plane's noise with as many samples (95 % of the time), and a grown
    * plane must be thinner than half its narrow side. See pcl::rspd::isFlatPatch and
    * pcl::rspd::DetectorParameters::bend_confidence. */
  void
  setBendNoiseTest (bool enable);
  /** \brief Whether bends are tested against noise. */
  bool
  getBendNoiseTest () const { return params_.bend_confidence > 0.0; }
  /** \brief The noise test's confidence where a noisy seed's plane, once grown, is judged and dropped
    * whole if bent, in (0, 1) (default 0.975; 0.95, the seeds' own, was the value before issue #6's
    * nineteenth session). Used only with the bend noise test on. See
    * pcl::rspd::DetectorParameters::judge_bend_confidence. */
  void
  setGrownPlaneBendConfidence (double confidence);
  /** \brief The grown noisy planes' bend confidence. */
  double
  getGrownPlaneBendConfidence () const { return params_.judge_bend_confidence; }
  /** \brief Where a noisy seed's plane, once grown, bends beyond chance, it is still kept if its
    * normals turn across it by less than this share of the bend (default 0.25; 0 = judged on the
    * positions' bend alone). Must be at least 0. See
    * pcl::rspd::DetectorParameters::judge_normal_turn. */
  void
  setGrownPlaneNormalTurn (double share);
  /** \brief The grown noisy planes' normal-turn share. */
  double
  getGrownPlaneNormalTurn () const { return params_.judge_normal_turn; }

  /** \brief Last assignment pass once grow-merge is stable (default Tails; None = the paper): samples
    * growth left out join a neighbouring plane: at edges by distance alone (Edges), and inside a
    * plane also those within its band, whatever their normal, and its noise tail (Tails). See
    * pcl::rspd::DetectorParameters::final_assignment. */
  void
  setFinalAssignment (pcl::rspd::FinalAssignment mode);
  /** \brief Which samples the last assignment pass offers to planes. */
  pcl::rspd::FinalAssignment
  getFinalAssignment () const { return params_.final_assignment; }

  /** \brief Where estimated normals come from (used only without setInputNormals; default
    * pcl::rspd::NormalScale::Automatic; Fixed is the paper's, the sample's k-neighbourhood). Where noise along the normal is
    * about as large as a k-neighbourhood's radius (a million samples on a unit cube with 1 % noise),
    * that neighbourhood fills a ball rather than a slab, its normal is noise and no plane is found.
    * Adaptive: each sample whose k-neighbourhood resolves no surface takes its normal from the finest
    * wider scale that does, the k-neighbourhood among every 2nd, 4th, 8th, ... sample of the spatial
    * order (2, 4, 8, ... times the area, k unchanged); "resolves" tests the ratio of the two smallest
    * covariance eigenvalues against what k + 1 samples filling a ball give (5 % level;
    * pcl::rspd::estimateAdaptiveScaleNormals). Samples the k-scale resolves keep their normal, only the
    * others pay for a wider search, and the growth graph stays the exact k-NN graph. Automatic: the
    * same, but only when the k-scale fails for most samples; a scene the k-scale resolves keeps the
    * Fixed normals exactly (outliers and clutter are not given a wide-scale normal). */
  void
  setNormalScale (pcl::rspd::NormalScale scale);
  /** \brief Where estimated normals come from. */
  pcl::rspd::NormalScale
  getNormalScale () const { return normal_scale_; }

  /** \brief Edge-aware normals (default false: the k-neighbourhood's PCA normal; used only for
    * normals estimated here by PCA, where every one comes from the k-neighbourhood): each sample's
    * normal is refitted over the widest prefix of its neighbours, nearest first (down to 15), that
    * stays on one face, where that turns from the k-normal by more than its noise
    * (pcl::rspd::narrowNormalsAtEdges), and the small-plane pass's cells go down to 16 samples instead
    * of k + 1 where they hold such a normal. A small face at the scale of a k-neighbourhood is then seeded: the room at 100,000
    * points (k = 50) finds its cabinet's top and front on 12 of 12 seeds, against 10-11 of 12
    * planes without. Off by default because it loses elsewhere: in noisy scenes with curved
    * surfaces, facets of pipes become planes, and on noisy clouds with outliers the result changes
    * with the cloud's units and place (docs/departures.md, "Edge-aware normals"). */
  void
  setEdgeAwareNormals (bool enable);
  /** \brief Whether estimated normals are narrowed to one face at edges. */
  bool
  getEdgeAwareNormals () const { return edge_aware_normals_; }

  /** \brief Safety cap on grow-merge iterations (default 100); reaching it is logged. */
  void
  setMaxGrowMergeIterations (int iterations);
  /** \brief Cap on grow-merge iterations. */
  int
  getMaxGrowMergeIterations () const { return params_.max_iterations; }

  /** \name SACSegmentation compatibility: plane models only, thresholds ignored. */
  ///@{
  /** \brief Only pcl::SACMODEL_PLANE (and its perpendicular/parallel/normal variants, treated as
    * a plain plane) is accepted; other models make segment() fail with PCL_ERROR. */
  void
  setModelType (int model);
  /** \brief Model type last set. */
  int
  getModelType () const { return model_type_; }
  /** \brief Ignored: the method is deterministic (logged at PCL_DEBUG). */
  void
  setMethodType (int method);
  /** \brief Method type last set (ignored). */
  int
  getMethodType () const { return method_type_; }
  /** \brief Ignored: MDP is estimated per plane from the data (logged at PCL_DEBUG). */
  void
  setDistanceThreshold (double threshold);
  /** \brief Distance threshold last set (ignored). */
  double
  getDistanceThreshold () const { return distance_threshold_; }
  /** \brief Ignored: no random iterations (logged at PCL_DEBUG). See setMaxGrowMergeIterations. */
  void
  setMaxIterations (int iterations);
  /** \brief Ignored: no random sampling (logged at PCL_DEBUG). */
  void
  setProbability (double probability);
  /** \brief Ignored (logged at PCL_DEBUG): with the final refit (setFinalRefit, the default) the
    * coefficients are already each plane's least-squares plane of its members; without it they are
    * the paper's robust estimate. */
  void
  setOptimizeCoefficients (bool optimize);
  ///@}

  /** \brief Detect every plane.
    * \param[out] coefficients per plane [a b c d], unit normal towards the cloud's sensor origin
    * \param[out] indices per plane, indices into the input cloud (ascending)
    * Planes come largest first (ties: lowest index). Each output carries the cloud's header.
    * On failure both are cleared and PCL_ERROR says why.
    */
  void
  segment (std::vector<pcl::ModelCoefficients>& coefficients, std::vector<pcl::PointIndices>& indices);

  /** \brief The largest plane only, as pcl::SACSegmentation::segment gives it. */
  void
  segment (pcl::PointIndices& inliers, pcl::ModelCoefficients& coefficients);

  /** \brief Per-point labels, same size and order as the input (0 = no plane, i = i-th plane of
    * segment()). Runs the detection if needed; empty on failure. */
  void
  getLabels (pcl::PointCloud<pcl::Label>& labels);

  /** \brief The input's positions coloured by plane (grey for none), for viewing. Null on failure. */
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr
  getColoredCloud ();

  /** \brief Every plane with its statistics, rectangle and hull. Runs the detection if needed. */
  const std::vector<RobustPlane>&
  getPlanes ();

  /** \brief Normals used for the last detection, one per valid sample, as unit vectors in the
    * order of getValidIndices(). */
  const std::vector<Eigen::Vector3f>&
  getUsedNormals () const { return points_.normals; }

  /** \brief Indices of the valid samples (finite, within the indices) of the last detection, in
    * the library's internal order (spatial, not ascending; getUsedNormals() follows it). */
  const std::vector<pcl::index_t>&
  getValidIndices () const { return points_.input_indices; }

  /** \brief ε of the last detection (resolved from the ratio or set directly). */
  std::size_t
  getResolvedMinPatchSize () const { return params_.min_patch_size; }

  /** \brief Counters of the last detection. */
  const pcl::rspd::DetectorStatistics&
  getStatistics () const { return stats_; }

  /** \brief Samples per normal scale in the last detection (empty unless the normals were estimated
    * with NormalScale Adaptive or Automatic). */
  const pcl::rspd::NormalScaleStatistics&
  getNormalScaleStatistics () const { return normal_scale_stats_; }

  /** \brief What the check of the caller's normals measured in the last segmentation (setGivenNormalCheck). */
  const pcl::rspd::GivenNormalCheck&
  getGivenNormalCheckStatistics () const { return given_normal_check_stats_; }
  /** \brief What the trimmed-plane normal fit did in the last detection (zeros with NormalFit::Pca
    * or given normals). */
  const pcl::rspd::TrimmedNormalStatistics&
  getTrimmedNormalStatistics () const { return trimmed_normal_stats_; }

  /** \brief Whether the last detection succeeded. */
  bool
  hasResult () const { return computed_ && ok_; }

protected:
  /** \brief Class name for messages. */
  std::string
  getClassName () const { return "RobustPlaneSegmentation"; }

  /** \brief Run the detection unless a cached result is valid. \return success */
  bool
  compute ();

  /** \brief Validate inputs and fill points_ with valid, centred samples. */
  bool
  prepareSamples ();

  /** \brief Build graph_ (with search_ if set) and, if no normals were given, estimate them. */
  bool
  prepareNeighbourhoods ();

  /** \brief The parameters that follow k_used_ and use_given_normals_ (the small-plane pass's cell
    * size, the second fit of what growth left). */
  void
  setNeighbourDependentParameters ();

  /** \brief Convert the detector's patches into planes_ and labels_. */
  void
  buildPlanes (const std::vector<pcl::rspd::DetectedPatch>& patches);

  /** \brief Forget cached results. */
  void
  invalidate () { computed_ = false; }

  NormalsConstPtr normals_;
  SearchPtr search_;
  int k_ = 0;      ///< 0: automatic
  int k_used_ = 0; ///< k of the last segmentation
  double min_patch_ratio_ = 0.001;
  std::size_t min_patch_size_ = 0;
  bool small_plane_seeding_ = true;
  bool left_normal_refit_ = false;
  bool given_normals_left_refit_ = true;
  bool left_normal_narrowing_ = true;
  bool shifted_grid_ = true;
  bool given_normal_check_ = true;
  bool use_given_normals_ = false; ///< the last segmentation read the caller's normals (not estimated again)
  bool depth_level_dither_ = false;
  bool edge_aware_normals_ = false;
  pcl::rspd::GivenNormalCheck given_normal_check_stats_;
  pcl::rspd::NormalScale normal_scale_ = pcl::rspd::NormalScale::Automatic;
  pcl::rspd::DetectionFrame detection_frame_ = pcl::rspd::DetectionFrame::DominantPlanes;
  pcl::rspd::NormalFit normal_fit_ = pcl::rspd::NormalFit::Pca;
  pcl::rspd::DetectorParameters params_;

  int model_type_;
  int method_type_;
  double distance_threshold_ = 0.0;

  // Cached state of the last detection.
  bool computed_ = false;
  bool ok_ = false;
  pcl::rspd::PointSet points_;
  pcl::rspd::NeighborGraph graph_;
  pcl::rspd::DetectorStatistics stats_;
  pcl::rspd::NormalScaleStatistics normal_scale_stats_;
  pcl::rspd::TrimmedNormalStatistics trimmed_normal_stats_;
  std::vector<RobustPlane> planes_;
  std::vector<std::uint32_t> labels_;

public:
  PCL_MAKE_ALIGNED_OPERATOR_NEW
};
} // namespace pcl

#ifdef PCL_NO_PRECOMPILE
#include <pcl_rspd/impl/robust_plane_segmentation.hpp>
#endif
