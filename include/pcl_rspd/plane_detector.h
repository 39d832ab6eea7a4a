/*
 * pcl_rspd: the pipeline of Sec. 3 on prepared data: split, then grow and merge until stable.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/neighbor_graph.h>
#include <pcl_rspd/point_set.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief The last assignment pass (see DetectorParameters::final_assignment). */
enum class FinalAssignment
{
  None,  ///< the paper: a sample growth did not take stays unassigned
  Edges, ///< samples whose neighbours belong to two or more planes (edge bands of bent normals)
  Tails, ///< Edges, and inside a plane (most neighbours hold it): samples within its band (MDP),
         ///< and its noise tail, within 4 robust standard deviations, whose normal passes its MND
  All    ///< every sample with a labelled neighbour (also takes clutter and outliers near a plane)
};

/** \brief The paper's k (Sec. 3.3): neighbours per sample of the graph and of the normals. */
constexpr int kPaperNeighbours = 50;

/** \brief The fewest neighbours the automatic k takes: measured on the generated scenes at 20,000 to
  * 50,000 points and on synpeb_test100, 15 beat 10 and 12 everywhere (noisier normals), and 20 lost
  * the 20,000-point staircase (README, "Automatic k"). */
constexpr int kMinAutomaticNeighbours = 15;

/** \brief k when the caller sets none and gives no normals (departure; with the caller's normals,
  * kPaperNeighbours): ε/2 between kMinAutomaticNeighbours and the paper's 50. A k-neighbourhood as large as the smallest plane the split seeds (ε samples) has no
  * clean normal anywhere on such a plane — every sample's neighbourhood reaches past its rim — and
  * its graph edges cross to the planes around it; half of it leaves the middle of such a plane
  * clean. From 100,000 samples on (ε ≥ 100, the default ratio) this is the paper's 50. A count, not a
  * length: no scale enters.
  * \param[in] epsilon ε, the resolved minimum patch size in samples */
inline int
automaticNumberOfNeighbours (std::size_t epsilon)
{
  return static_cast<int> (std::clamp<std::size_t> (epsilon / 2, kMinAutomaticNeighbours, kPaperNeighbours));
}

/** \brief The shifted grid's seeds (DetectorParameters::shifted_small_grid) are no noisier than this
  * many times the median MND of the planes found before the small-plane pass: that grid is there for
  * clean cells of small faces. Its noisier seeds, up to the noisiest plane's MND, were terraces of
  * a depth camera's dithered levels (two false planes in DepthLevels' room view) and took one face
  * more only on the room at σ = 1.2 cm and 20,000 points of the 84 sweep rows; at the median itself
  * synpeb_pc01 lost the plane the grid finds (53 → 52 of 60; measured). */
constexpr double kShiftedSeedMndRatio = 2.0;

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
    * again with cells down to this many samples (0 = off, the paper; RobustPlaneSegmentation uses
    * k + 1, at most ε/2 and at least 10; the pass runs if this is at most ε: at ε = 10, up to 10,000
    * samples, its cells are as large as Algorithm 1's, but they split only what growth left, a riser
    * without the treads that mixed into every cell of the first split), keep the new seeds
    * whose MND is no larger than the largest MND of the planes already found and fewer than half of
    * whose samples lie within the noise band of a plane a graph neighbour holds (a layer of that
    * plane), grow-merge again, and drop every plane still smaller than ε. Seeds a plane whose ε-sized cells always mix with a
    * neighbour. */
  std::size_t small_cell_size = 0;
  /** \brief Departure (with edge-aware normals, PointSet::narrowed; 0 = off): the small-cell pass's
    * cells go down to this many samples where a cell holds a sample whose normal was narrowed to its
    * face at an edge, and to small_cell_size elsewhere. Such a cell's normals resolve a face that
    * small; elsewhere they are k-neighbourhoods', and a cell narrower than those holds normals that
    * agree only because they share neighbours (a facet of a noisy pipe: 12 false planes on the
    * sweep's industrial rows with cells of 16 everywhere, 4 with this rule). */
  std::size_t narrowed_cell_size = 0;
  /** \brief Set by the small-cell pass for its split (not by callers): a cell smaller than this is
    * tested only if it holds a sample whose normal was narrowed (PointSet::narrowed). 0 = every cell
    * down to min_patch_size is tested. */
  std::size_t coarse_cell_size = 0;
  /** \brief Set by the small-cell pass for its second split (not by callers; 0 = off): a rim cell's
    * inliers (rim_cell_retest) are tested again while at least this many, instead of
    * min_patch_size. See left_rim_retest. */
  std::size_t rim_retest_min_size = 0;
  /** \brief Departure (small seeds' MND, part of the small-cell pass): a seed the pass keeps gets at
    * least the MND of the tightest plane grown (none seeded by a noisy seed). Its 15-50 samples lie
    * in a few neighbourhoods' widths, and their normals, averaged over largely the same neighbours,
    * agree far better than the plane's: a table top's seed at 30,000 points with k = 50 had an MND of
    * 0.1° against the room's 1-2°, grew from 17 to 25 samples, short of the 50 % that re-estimates
    * it, and stayed under ε. false = the seed's own MND. */
  bool small_seed_mnd_floor = true;
  /** \brief Departure (thick cells among the left samples, part of the small-plane pass and of the
    * thick-cell join: needs both): the pass's split keeps its thick cells too, if no noisier (MND)
    * than the noisiest plane found, and joins them as the first split does; what is left of a group
    * seeds a plane if it passes T1-T3, is no noise-band layer, is not bentAtAnEdge and its quadric
    * shows no bend, with no MND bound on the group (its cells run along its plane's rims, where
    * normals bend). Without the cells' bound, thick cells of outliers, as thick as they are wide,
    * with MNDs of 47-60°, joined into a 7 m slab that grew into a plane (the boxes with 15 %
    * outliers: F1 0.953 → 0.820). A noisy face whose every first-split cell holds a
    * neighbour, and whose small cells are too thick for their extent, is seeded no other way: a box's
    * face at σ = 3 cm, every cell of it under 0.4 m failing T1 at 45-72° (measured; the boxes with
    * seeds 2 and 3). A thick cell that two planes meeting at an edge explain does not replace the
    * thick cells below it here (the first split keeps its largest): at 10,000 points with PCL's
    * k = 50 normals a stair riser's thick cells gave way to parents across its edge with a tread,
    * whose groups are bent. false = the small cells alone. */
  bool small_cell_thick_join = true;
  /** \brief Departure (groups of noisy small seeds, part of the small-cell pass, on the PCA normals):
    * the pass's seeds turned down as noisier than every plane found are joined where they touch and
    * their planes agree, and a group seeds a plane if it holds ε samples, passes T1-T3, is flat, is
    * no edge band (bentAtAnEdge) or noise-band layer, and is at most noisy_group_ratio times as noisy
    * and as thick as the planes found (joinNoisySeeds). A rough face whose every octree cell holds
    * a piece of the next face is seeded no other way (the boxes with 15 % outliers: the roughest box,
    * σ = 3 cm, 0 of 5 faces). Each plane so seeded is judged flat again once grown. false = the
    * noisy seeds are turned down. */
  bool noisy_seed_groups = true;
  /** \brief See noisy_seed_groups: a group's MND and MDP may be at most this many times those of the
    * noisiest and thickest plane found (2). Measured (debug prints): the rough faces let in within 1.8
    * and 1.4 times, one more at 2.04 times kept out; a slab of outliers 5 times as thick, tank facets
    * 5 to 15 times as noisy. */
  double noisy_group_ratio = 2.0;
  /** \brief Departure (lone noisy seeds, part of noisy_seed_groups): a noisy seed that joins no other
    * seeds a plane by itself if it is within noisy_group_ratio of the planes found, flat and no edge
    * band or noise-band layer; it passed T1-T3 as a cell of the pass, and, as every noisy seed, is
    * judged flat again once grown and kept only if it then holds ε samples. A rough face whose seeds
    * are few and apart has no group: the boxes with 15 % outliers at 300,000 points (ε = 300) on PCL's
    * k = 50 normals, the σ = 3 cm box's two sides, 2,096 samples each, had one seed of 207 samples and
    * three of 67-177 that did not agree (the thin one's band held too few of the others' samples).
    * A group of fewer than ε samples is judged the same way: T1-T3 at the pass's cell size
    * (small_cell_size), ε asked of its grown plane (the room with 10 % outliers: the cabinet top's
    * two seeds, 117 and 68 samples, against ε = 200).
    * false = a seed too noisy alone seeds only in a group of ε samples. */
  bool noisy_lone_seeds = true;
  /** \brief Departure (noise ladder, part of noisy_seed_groups): once noisy seeds seeded planes
    * noisier than every plane found before, the seeds still turned down whose samples no plane took
    * are offered again against those planes (noisy_group_ratio times their MND and MDP), step by
    * step while a step seeds a plane of ε samples or more noisier than the last (smaller seeds are
    * seeded but raise no bound: climbing on them, the room with 10 % outliers, seed 2, reached its
    * pillar's facets, two false planes). Surfaces rougher than one another by
    * less than the ratio each (materials, ranges; the generated boxes at σ = 8 mm: six boxes at 1 to
    * 15 times the floor's noise) are seeded whichever of them the first split happened to seed:
    * without it, the boxes at 80,000 points found 13 of 32 planes with k = 40 and 22 with k = 50.
    * Every plane so seeded is judged flat again once grown, as every noisy seed's. false = one step
    * (the bound of the planes found before the pass). */
  bool noisy_group_ladder = true;
  /** \brief Departure (part of the noisy seeds' judgement, see judgeNoisyPlanes): a plane a noisy
    * seed seeded (PlanarPatch::retested), judged once grown, is dropped, its members left, where the
    * estimate of its members fails T2 (MND at or past max_normal_deviation). Such a seed was let in
    * on looser terms than the paper's; grown, its plane runs over whatever its band and its wide
    * MND admit (bounded_reestimation then keeps its seed's estimate), and past T2 its normal test
    * admits half of all directions: a cell of a rough box's top and a sliver of its side (MND
    * 59.8°, let in by the noise ladder at twice 34°) grew through 20 % outliers into a plane of
    * 4,953 samples, 1,841 of them outliers spread over 13 m of the scene (boxes, layout 204, 540,000
    * points, σ 2.9 mm, 20 % outliers: F1 0.888, two false planes; with this rule 0.967, and 0.989
    * with support_clutter too). Off by default: where faces are so rough that their
    * k-neighbourhoods' normals are noise, their own planes fail T2 on their members (the boxes at
    * σ 1 cm, whose roughest box is at 15 cm: 22 -> 17 of 32 planes, F1 0.816 -> 0.760), and the
    * boxes at layout 390 (20 % outliers) lost the roughest box's top (32 -> 31). true = such a plane
    * is dropped; false = kept on its seed's estimate. */
  bool noisy_grown_t2 = false;
  /** \brief Departure (part of small_cell_thick_join): where noisy seeds (groups or lone) seeded planes
    * noisier than the thick cells' bound of the pass (the noisiest plane found before it), the
    * pass's thick cells are collected again up to the MND of the noisiest plane so seeded: a face as
    * rough as those, none of whose cells passed T1, is then seeded by their group as the thick cells
    * of a face no noisier than the planes found are. The boxes with 15 % outliers on PCL's k = 50
    * normals: the σ = 3 cm box's top, cells of 0.21 and 0.43 m with MNDs of 13-21° against a bound of
    * 10.3°, while the noisy seeds of its sides and front seeded planes of up to 19.2° (debug prints);
    * 31 → 32 of 32. Raising the
    * bound by a fixed ratio (twice) instead found it too but lost a face of the boxes at 30,000
    * points, where the bound is already 45° and twice that keeps cells across edges. false = the
    * thick cells keep the bound of the planes found before the pass. */
  bool thick_cells_follow_noisy_seeds = true;
  /** \brief Departure (trimmed normals for what growth left, part of the small-cell pass): after
    * the pass's split on the PCA normals, the samples still left get the normal of their
    * k-neighbourhood's reweighted least-trimmed-squares plane (refineNormalsTrimmed) in a copy, and
    * are split a second time on those, with the same tests for a seed (its MND at most the largest
    * MND of the planes found, no layer of one) and one more: no thicker (MDP) than the thickest plane
    * found (trimmed normals of scattered outliers agree by chance over a slab). Growth and every later
    * pass read the PCA normals.
    * Near an edge a PCA normal averages both faces; on a small plane (a table's front panel, a
    * cabinet top at 100,000 points) most samples lie that near an edge, so T3 fails every cell of it
    * and the plane is never seeded. Only the left samples are refitted: refitting every sample costs
    * about twenty times the PCA normal stage. Letting growth read the trimmed normals too gained
    * more F1 but was not stable: synpeb_pc01 moved 1 km away lost 0.015 (a trimmed subset is not
    * continuous in the positions). Off by default here; RobustPlaneSegmentation sets it for the
    * caller's normals (setLeftNormalRefitOnGivenNormals, default on) and, on request, for normals it
    * estimates by PCA (setLeftNormalRefit, default off for its time). false = the paper. */
  bool left_normal_refit = false;
  /** \brief Departure (narrowed normals for what growth left, part of the small-cell pass; used when
    * left_normal_refit is false): the second split of the pass reads, for the samples still left,
    * their normals narrowed to one face at edges (narrowNormalsAtEdges), and its seeds grow on them
    * as trimmed_seed_growth says; every other normal stays the PCA one. Only meaningful on the
    * k-neighbourhoods' own PCA normals, which the narrowing compares against: RobustPlaneSegmentation
    * sets it for the normals it estimates by PCA at the k-scale (setLeftNormalNarrowing, default on).
    * Where the trimmed normals cost about twenty times the PCA stage, this costs a few prefix fits
    * per left sample. Alone it moves little (one plane more on 1 of 84 sweep rows; the 100,000-point
    * room finds every plane on 2 of 12 seeds, against 1); with shifted_small_grid it finds the
    * cabinet's top and front there on 11 of 12 seeds. false = no second split unless
    * left_normal_refit. */
  bool left_normal_narrow = false;
  /** \brief Departure (shifted grid, small-cell pass): each split of the pass runs again on the
    * shifted grid (kShiftedGridOffset, octree_split.h) over the samples its first grid's seeds left,
    * and a seed found so is kept only if it is no noisier (MND) and no thicker (MDP) than the
    * noisiest and thickest plane found before the pass and than kShiftedSeedMndRatio times their
    * median MND, and is judged flat again once grown (at 20,000 points a 26-sample facet of the
    * room's ball passed the seed's tests).
    * Cubic cells cut a small face wherever the first grid's boundaries fall: the 100,000-point
    * room's cabinet top (0.8 m, ~250 samples, k = 50) lies in cells of 0.38 m as 23-76 samples
    * beside its neighbours' leftovers, none a seed; the shifted grid holds a cell of 66 of it alone.
    * Only clean cells: the shifted grid's noisy seeds are those of slabs of outliers its cells cut
    * at the outliers' box (the facade at 400,000 points: 0.998 → 0.78 when they joined the noisy
    * seeds' groups), and the first grid's noisy seeds already have their groups. A ratio of the
    * bounding cube, so no length enters. false = the first grid only (the paper's one octree). */
  bool shifted_small_grid = true;
  /** \brief Departure (with left_normal_refit): a seed of the second split, found on the trimmed
    * normals, grows and is re-estimated on them in the grow-merge that follows the small-plane pass
    * (other planes read the PCA normals); it is not judged again once grown. On the PCA normals such a
    * seed of a small plane often cannot grow: near its rims they bend by more than its MND, and it
    * stays below ε (the room at 30,000 points on PCL's k = 50 normals: a table's front panel of 106
    * samples and a cabinet side of 124 seeded with 20 and 16, dropped). Judged once grown, a side of
    * the boxes at 100,000 points grown over a neighbour's edge strip was dropped whole (see the seed
    * loop in detectPlanes). false = such seeds grow on the PCA normals as every other. */
  bool trimmed_seed_growth = true;
  /** \brief Departure (small planes at a rim), used by the small-cell pass only: a cell that passes
    * T1 and T2 but fails T3 is tested again on its own inliers, and seeds a plane if they pass. The
    * pass's cells cannot shrink below k + 1 samples, and where a small plane meets others (a table's
    * front panel under its top) every such cell holds a band of the rim's bent normals, more than
    * T3's quarter; its inliers are the plane's clean part. false = such cells seed nothing. */
  bool rim_cell_retest = true;
  /** \brief Departure (part of rim_cell_retest): where the inliers of a rim cell still fail T3, their
    * own inliers are tested again, and so on until the test passes, fewer than ε are left or the
    * inliers no longer change. A cell's first estimate is taken with whatever else the cell holds
    * (a box side's cell with a quarter of floor samples: MND 12°), so its inliers keep the side's
    * rim, whose normals bend at the box's edges; the estimate on the side alone (MND 1.3°) makes
    * that rim 28 % outliers, and the side (521 samples, σ 2 mm, 5 % outliers in the scene) was
    * seeded by no cell. false = one retest. */
  bool rim_retest_until_stable = true;
  /** \brief Departure (part of rim_cell_retest, in the small-cell pass's second split, on the left
    * samples' narrowed (left_normal_narrow) or trimmed (left_normal_refit) normals): a rim cell's
    * inliers are tested again down to kMinAutomaticNeighbours + 1 of them (the faces narrowed normals
    * resolve, the least cell the edge-aware normals test) instead of the pass's k + 1; the plane they
    * seed must still grow to ε. A small face bordered by others on most sides keeps a quarter or more
    * of bent normals in every cell of k + 1 samples: the room at 60,000 points (seed 5, k = 30) had
    * its cabinet's top (154 samples, ε = 60) in a cell of 41 samples whose 26 inliers on narrowed
    * normals were the top's alone, and no other seed; on PCL's k = 50 normals (trimmed for the second
    * split) the top of the rooms at 60,000 (seed 3) and 80,000 points (seeds 2 and 5) likewise.
    * false = inliers as many as the pass's cells. */
  bool left_rim_retest = true;
  /** \brief Departure (outlier seeds): after the split, a seed whose MND is an outlier among all
    * seeds (log MND above median + α·MAD of the seeds' log MND) is dropped before growth. A coarse
    * cell can pass T1-T3 when its extent dwarfs a thick mix of surfaces (a rotated facade: a cell
    * several metres wide holding wall, recessed windows and outliers, MND 51° where seeds have 15°);
    * grown and merged, such a seed turns the scene into one plane. false = the paper. */
  bool drop_outlier_seeds = true;
  /** \brief Departure (outlier seeds tested again): with drop_outlier_seeds, once growth is stable,
    * each dropped seed's samples that no plane took are put to the planarity test again (T1-T3, ε)
    * and seed a plane if they pass, are no layer of a plane found and are flat (isFlatPatch: noise,
    * not a bend, spreads their normals). Dropping alone assumes one noise level: beside a smooth
    * floor, every seed on rough boxes is an outlier. The small-plane pass then also takes flat seeds
    * up to the noisiest retested seed's MND, and each plane so seeded must still be flat once grown.
    * false = outlier seeds are only dropped. */
  bool retest_outlier_seeds = true;
  /** \brief Departure (volume layers, dropVolumeLayers): a plane a noisy seed seeded (retested, or a
    * group of thick cells), once grown and judged flat, is dropped if the layer beside its noise band
    * on one side, half as thick as the band, holds more than twice as many samples over its
    * footprint as the plane holds: the samples beside it are four times as dense as its own, and it
    * is a share of a volume of scattered samples where the volume ends (whose cut neighbourhoods
    * give PCA normals across the end), not a surface. The facade with 25 % outliers at 100,000
    * points kept such a plane on 3 of 7 seeds, a slab up to 0.9 m thick where the outliers' box
    * ends below or above the wall (1,000-1,500 samples; F1 0.88-0.95 -> 0.995-0.997).
    * false = such planes are kept. */
  bool volume_layer_check = true;
  /** \brief Departure (final volume layers, dropVolumeLayers on every plane): once the planes are
    * final (after the layer merge and the final refit, before the last assignment; the position
    * planes once found), any plane, however seeded, is dropped by volume_layer_check's rule (the layer
    * beside its noise band on one side, half as thick as the band, holds more than twice as many
    * samples over its footprint as the plane). Where a thin slab of outliers wraps a plane, a clean
    * seed among them grows a plane of outliers whose band reaches the true plane's: a unit plane at
    * σ 1 cm in 20 % outliers kept two such planes, 5,500 samples each with 12.7 times as many beside
    * them (F1 0.790 -> 0.929). Over the sweeps' 342 rows and the real scans, no final plane had more
    * than 0.92 times its samples beside it. false = only noisy seeds' planes are judged. */
  bool final_volume_layer_check = true;
  /** \brief Departure (in-band layers, isInBandLayer): with final_volume_layer_check, a final plane
    * within whose noise band, over its footprint, another plane is more than four times as dense
    * as the plane itself (its samples there over the thinner of the two bands) is dropped too, and
    * the layer merge does not join such a plane to the plane whose band it lies in. A plane grown among the clutter beside a denser plane has a
    * spread, and so a band, wide enough to take in that plane: it is a share of the clutter or of
    * the noise around the plane, not a surface, and joined to it, it widens its band into the
    * clutter. A unit plane at σ 1 cm in a slab of 20 % outliers 0.141 thick kept such a plane when
    * scaled ×1000 or turned (F1 0.83 against 0.93 as given), and 1 km away the layer merge joined
    * one to the plane (0.89); in 40 % outliers 1 km away a plane of outliers with a band 2.5 times
    * the true plane's held 3.8 times fewer samples there but was 9.4 times less dense (F1 0.641 by
    * counts, 0.896 by densities). false = such planes are kept and joined. */
  bool in_band_layer_check = true;
  /** \brief Departure (flat layers, LayerCounts::flat_beside): with final_volume_layer_check, a
    * final plane is also dropped when the layer beside its band on one side (as samplesBesideBand)
    * holds more samples than the plane and the layer after it, as thick, holds at least half as
    * many again: the samples' density runs on flat past the plane, which is a layer of a volume of
    * clutter, not a surface. A surface's noise falls off beside it (a Gaussian's 3-6 σ against its
    * 6-9 σ), and a second face beside it (a thin wall, whose faces hold about as many samples each)
    * has nothing after it. The ratio-2 rule alone kept layers where the volume ends inside the
    * plane's band or where the plane holds a few outliers of many: a unit plane at σ 1 cm in a slab
    * of 30-40 % outliers kept a false plane of 284-1,400 members whose beside layer held 1.2-1.6
    * times as many. false = only the ratio-2 rule. */
  bool flat_layers = true;
  /** \brief Departure (small-plane completion, completeSmallPlanes; part of the small-plane pass):
    * before the pass drops its planes still short of ε, a plane a clean seed seeded that holds at
    * least half of ε takes the samples within the noise band of its members' least-squares plane that
    * connect to it and that no plane holds, or that a noisier plane turned from it holds farther
    * relative to its band; it is kept if that brings it to ε. A small face beside a noisier one
    * grows short of its rim (its median normal tilted by normals bent over the neighbour) and the
    * neighbour's wider band holds the strip along their edge: synpeb_pc01 found two faces more (53
    * -> 55 of 60). false = such planes are dropped. */
  bool small_plane_completion = true;
  /** \brief Departure (M4, coplanar groups): two groups merge only if at least (1 - T3 ratio) of the
    * samples of the group whose representative is smaller lie within the larger representative's
    * plane (the plane the merged group keeps) by the wider of the two representatives' MDP, or
    * failing that within the least-squares plane of all the larger group's samples (a representative
    * holding a small part of a large group tilts by its estimate's error across it). Pairs
    * meeting M1-M3 are joined largest representative first. false = the paper's transitive union of
    * every pair, which lets small steps (facets of a faceted or curved object, each within MND of
    * the next) chain a plane around a bend. */
  bool coplanar_merge = true;
  /** \brief Departure (last assignment): which samples no patch holds are offered to the planes of
    * their graph neighbours once grow-merge is stable, by distance alone (|d| <= MDP, nearest
    * relative to MDP; the sample must be among its neighbour's k nearest too); with Tails also a
    * sample most of whose neighbours hold one plane, if it lies within the plane's band (|d| <= MDP,
    * whatever its normal: inside a plane, a normal growth rejected is noise), or if its normal passes
    * that plane's MND and |d| <= 4 σ of the plane (σ = 1.4826 median |d| of its members). Without the
    * first case the cube at σ = 1 % of its edge left 1 % of its faces out, mostly within 0.5 σ of
    * their planes (F1 0.983; 0.986 with it). Except in that inside-a-plane
    * case, a plane reaches no farther than 3 neighbourhood radii from the members growth left, along
    * the graph path that brings it (each assigned sample carries it on to the next round). */
  FinalAssignment final_assignment = FinalAssignment::Tails;
  /** \brief Departure (position planes, seedPositionPlanes): after the last assignment, the samples no
    * plane holds are searched for planes by their positions alone: in each part the k-NN graph
    * connects, the plane of most samples connected within 3 σ of it (σ of the noisiest plane found),
    * kept if it has ε, is no noisier than that plane (within twice the standard error of its own
    * σ), bends no more than noise (curved_turn_confidence), is no tube, no band layer and lies on no neighbouring plane; its tails are then assigned as the
    * last assignment's. A small face sampled sparsely has PCA normals bent over most of it: the
    * room at 30,000 points (k = 15) left its cabinet's top (70-95 samples, ε = 30) in no plane on
    * four of six seeds, every cell of it failing T3 or noisier than every plane found. false = the
    * paper: what growth left stays unassigned but for the last assignment. */
  bool position_planes = true;
  /** \brief Departure (surface parts, part of position_planes): where the search of a part ended at
    * a plane turned down, what the part still holds on a surface (half of a sample's neighbourhood
    * within the pass's reach, and within a quarter of the neighbourhood's radius, of the
    * neighbourhood's plane) is cut into parts again and searched once
    * more, going on past the planes turned down there but for those inside no surface and those that
    * bend. Outliers join a scene's free samples into one part whose best plane is a slab of them,
    * and the faces beside it were never tried (boxes with 10 % outliers, layout 876: 30 of 32 planes
    * without, 32 with). false = the part is left at its first plane turned down. */
  bool position_surface_parts = true;
  /** \brief Departure (part of position_surface_parts): a member of a plane searched again must have
    * its neighbourhood's plane (least squares, then again on the half nearest to it) nearer parallel
    * to the plane than perpendicular. Where a face's noise is large against its size, the samples of
    * the faces beside it within the pass's reach are strips along its rims, all on one side of its
    * plane, and its quadric bends: the search ended there (boxes with 10 % outliers, layout 457: 24 of
    * 32 planes without, 32 with). false = by position alone. */
  bool position_surface_normals = true;
  /** \brief Departure (band samples in the position planes' bend): a plane found by position whose
    * members bend beyond chance is judged again with the unlabelled samples beside them, within its
    * trimmed band and facing it, that the pass had left out as lying in a neighbouring plane's band.
    * At a rim beside a plane found, which of a rough face's samples fall in that plane's band
    * depends on their offsets from the face: those left out lay toward the other plane, those kept
    * stand out of the face, and their curl read as a bend beyond chance, which ends the search of
    * the part (boxes layout 329 with 10 % outliers, isotropic noise: a face at σ 3.7 cm bent by a
    * share of 0.034 against chance's 0.029; 0.016 against 0.021 with its 139 band samples; the face
    * and the box's top were lost, 30 of 32). false = the members alone. */
  bool position_bend_band = true;
  /** \brief Departure (neighbours' slabs in the position planes' bend): a plane found by position
    * whose members bend beyond chance (and, with position_bend_band, still do with its band
    * samples) is judged again without the members that lie in the band of a plane found beside it
    * and crossing it (less than 45° from perpendicular). The pass left out a rough face's rim
    * samples that lie in such a band where a neighbour of theirs holds that plane: those below the
    * face, nearer that plane's members, more often than those above it, so the rim members
    * kept stand out of the face and curl its quadric; outside the slabs nothing was left out by its
    * offset (boxes layout 576, turned, σ 2.6 mm: a box's top at σ 3.9 cm, 841 members, bent by
    * 0.0207 against chance's 0.0193; flat without the 42 members in its four sides' bands: 31 ->
    * 32 of 32). false = not judged so. */
  bool position_bend_slabs = true;
  /** \brief Departure (join beside, part of position_planes): a plane found by position that lies on
    * a plane beside it (liesOnNeighbourPlane) gives that plane its members within the plane's noise
    * band, instead of leaving them to no plane. Neither growth nor the last assignment reached them:
    * no graph path leads from that plane's members to them (a room scanned on a grid: the rings
    * below the sensor, each other's nearest neighbours, a disc of 1,195 samples of the floor at
    * layout 315 and 212,000 points). false = they stay in no plane. */
  bool position_join_beside = true;
  /** \brief Departure (noise ladder of the surface parts, part of position_surface_parts): once the
    * surface parts are searched, what is still left is searched again for planes up to
    * noisy_group_ratio times as noisy as the noisiest plane kept (its reach as wide), step by step
    * while a step keeps a plane noisier than the last. Rough surfaces each a little rougher than the
    * last are found whichever the first passes happened to seed (boxes with 20 % outliers, layout
    * 725, boxes 3 to 15 times as rough as the floor: 12 of 32 planes without, 31 with). On a step,
    * a plane holds more than k samples (with fewer, no member's neighbourhood lies in it).
    * false = the noisiest plane found bounds every plane by position. */
  bool position_surface_ladder = true;
  /** \brief Departure (rungs of the noise ladder, part of position_surface_ladder): a step that keeps
    * no plane, but turned down a plane for its noise alone (flat, inside a surface, no layer, no
    * strip of a neighbouring plane) within noisy_group_ratio times the step's level, is followed by
    * a step at that level times noisy_group_ratio. The ladder climbs to rough faces that no plane
    * found anchors: boxes 3 times as rough as the floor, where outliers widened the octree's root
    * cell so that neither the first split nor the small-plane pass seeded any of them (boxes layout
    * 448, 1-20 % outliers: 7 of 32 planes without, 32 with). false = a step follows only a step that
    * kept a plane noisier than the last. */
  bool position_ladder_rungs = true;
  /** \brief Departure (tail odds): the Tails rule takes a plane's noise tail only as far as its
    * Gaussian noise stays likelier than the clutter beside it: the clutter's density per unit |d|
    * is read from the samples no plane holds beside the plane at 4.5-6 σ (where its noise leaves
    * 7·10⁻⁶ of its samples), and the tail ends where N · 2φ(|d| / σ) falls to it, within 3-4 σ. A
    * clean plane keeps its 4 σ tail. On the facade (15 % outliers) the 4 σ tail took more outliers
    * than samples of the wall between 3.2 and 4 σ, each outlier a voxel of its own beyond the wall's
    * band wherever a voxel boundary lies there: F1 over 16 voxel grids, median 0.981 -> 0.987, lowest
    * 0.975 -> 0.982. false = the Tails rule's 4 σ for every plane. */
  bool tail_odds = true;
  /** \brief Departure (surrounding clutter), with tail_odds: the clutter beside a plane is also
    * counted over its footprint (pcl::rspd::clutterBesidePlane: the samples no plane holds in the
    * same 4.5-6 σ shell, not beside another plane, twice the lesser side), the larger of the two
    * counts is taken, the tail ends at the crossing even below 3 σ (MDP stays the floor), and the
    * members beyond it are released before the last assignment. The shell above counts only
    * samples whose neighbours are mostly the plane's, and where clutter is dense its samples have
    * clutter around them: a unit plane at σ 1 cm in a slab of 20 % outliers had its clutter
    * undercounted about threefold (its tail ended at 2.93 σ where the outliers outnumber its own
    * samples from about 2.5 σ), and kept outliers out to 3-3.5 σ that growth had taken, as many as
    * its history gave it: F1 0.915-0.939 over the scene's seeds, scaled, moved and turned; 0.936-0.948
    * with it. false = the neighbourhood shell alone, floored at 3 σ, and the members kept. */
  bool surrounding_clutter = true;
  /** \brief Departure (member gaps): the Tails rule gives a sample to a plane only where it lies
    * among the plane's members: its in-plane gap to the nearest member beside it within
    * kSupportGapRatio times the gaps of those members that are supported themselves, a joiner
    * vouching for the next with the spacing that admitted it (pcl::rspd::vouchingGaps). In clutter
    * beside a rim, the rounds chained the plane from outlier to outlier: a facade at σ 4.3 cm with
    * 15 % outliers took 1,027 outliers more than 20 cm beyond its planes' rims, F1 0.928 -> 0.988.
    * false = the Tails rule by distance, normal and neighbours alone. */
  bool member_gaps = true;
  /** \brief Departure (rim bands), with tail_odds or member_gaps: the Tails rule also gives a clean
    * plane (no clutter beside it, as the tail odds measure it) a sample within its MDP beside it and
    * no other plane whose neighbours within the plane's 3 σ band are at least a third its members,
    * counting no neighbour off the band, where some neighbour lies off it (its neighbourhood reaches
    * the other surface: what tilted its normal). Why: where a plane ends at a surface that bends away (a
    * tank's flat top at its wall, a floor at a pillar's foot), a sample's k-neighbourhood near the
    * rim reaches down that surface and tilts its normal, so growth leaves a ring about a
    * neighbourhood wide, and the rule's "most of its neighbours members" never holds across it (the
    * surface's samples count against it, and on a rim the front has half its neighbours ahead): a
    * generated plant's tank tops kept 41-75 % of their samples. Clutter lies off the band too, so a
    * plane with clutter beside it is left to the rule as it was; and a false plane through a thin
    * pipe holds the whole pipe within its band, where no neighbour lies off it (without that
    * condition the rule grew one along the pipe into its elbow: 2.8 % of a plant's curved samples
    * claimed, 0.9 % with it). false = most neighbours members. */
  bool rim_bands = true;
  /** \brief Departure (far members): once grow-merge and the small-plane pass are stable, members
    * farther from their plane's last estimate than max(MDP, 3 σ) (σ = 1.4826 median |d| of its
    * members) are released; growth restricted to them follows (rounds reading the round before: a
    * released sample joins the neighbouring plane whose inlier test of Sec. 3.3 it passes, nearest
    * relative to MDP), and a released sample no plane took and no other plane borders goes back to
    * its plane. Growth tests a
    * sample against the estimate of the moment, which later re-estimates move: a wall seeded over a
    * door 2 cm proud of it keeps the door's samples otherwise. false = members are never revoked
    * (the paper). */
  bool release_far_members = true;
  /** \brief Departure (released planes, part of the far-member release): before the released samples
    * that no plane took go back, those joined by graph edges into a group of at least ε samples that
    * passes T1-T3 (failing only T3: whose inliers pass, as the rim-cell retest) become a plane. A door
    * 2 cm proud of its wall that no cell seeded is released whole by the wall and would otherwise go
    * back to it. false = they all go back. */
  bool seed_released_planes = true;
  /** \brief Departure (part of seed_released_planes): a group of released samples that lies on a
    * neighbouring plane at least as closely as on its own (liesOnNeighbourPlane) seeds nothing; its
    * samples go back or to the last assignment. Along an edge, the samples a plane released there
    * have normals bent towards it, so the plane beside them, which they lie on, turns them down, and
    * together they pass T1-T3 as a strip whose median normal is bent too: the staircase on PCL's
    * k = 50 normals got a false plane of 205 samples along its top tread's nose, tilted 22° from it.
    * false = every group that passes the tests becomes a plane. */
  bool released_layer_check = true;
  /** \brief Departure (edge sides, see settleEdgeSides): after the last assignment, a sample that
    * borders another plane leaves its plane when its projection onto it lies beyond the line where
    * the two planes meet, for the other plane if that one would own it by the same rule and holds it
    * within its noise band, else for none. Within a noise band of an edge, growth and the
    * distance-only passes take whichever plane reached a sample first: a step's riser keeps samples
    * of the tread's noise above the nose, which puts it in voxels the riser never enters.
    * false = the paper (and the passes before this one). */
  bool edge_sides = true;
  /** \brief Departure (edge corners, see settleEdgeSides): with edge_sides, a sample inside the
    * corner two planes make (its projection onto each on that plane's own side of the other) goes to
    * the nearer plane relative to its noise band. Noise along either normal can put a sample of
    * either plane there; the beyond rule settles only the samples the noise pushed out of the
    * corner, and growth gave the rest to whichever plane reached them first.
    * false = edge sides as before (issue #6's thirty-eighth session). */
  bool edge_corners = true;
  /** \brief Departure (edge wedges, see settleEdgeSides): with edge_sides, a sample outside the edge
    * of two planes (its projection onto each beyond the other) goes to the plane it lies farther
    * from relative to its noise band, within both bands, instead of to none. Noise along a normal
    * puts no sample there; noise across the edge does (a range sensor's along its rays, at an
    * oblique face), and for noise alike in every direction the farther plane is the likelier.
    * false = edge sides as before (issue #6's forty-second session). */
  bool edge_wedges = true;
  /** \brief Departure (thick-cell join, see splitPhase): the split also keeps the largest cells that
    * fail T1 alone (too thick for their extent, planar by T2 and T3) and joins those whose cubes touch
    * and whose planes agree; once growth is stable, what it left of each group of two or more seeds
    * a plane if it passes T1-T3, two planes meeting at an edge do not explain it (bentAtAnEdge: a
    * strip of cells along a noisy cube's edge), and it is no noise-band
    * layer of a plane found. Where the noise is thick against every cell that holds one plane alone,
    * the paper seeds nothing (a cube at σ = 3 % of its edge: 0 of 6 planes). false = the paper. */
  bool join_thick_cells = true;
  /** \brief Departure (step sides, see settleStepSides): after the edge sides, a sample that borders
    * a parallel plane offset from its own by more than the wider noise band goes to it when it lies
    * within that plane's band and that plane holds more of its neighbours; passes until none moves (at
    * most 8). Where a step is shallow against the noise, the plane grown first keeps
    * the samples of the other's noise that its band reaches: a facade at σ = 5 cm kept up to 30 % of
    * the samples of windows recessed 20 cm. false = the paper (and the passes before this one). */
  bool step_sides = true;
  /** \brief Departure (step regions, see settleStepRegions): before the step sides' samples, a
    * plane's regions that lie off it on one side (as the step split finds them) go to the parallel
    * plane beside them on that side, offset within the wider noise band, when their members lie
    * nearer to it (median distance, by two standard errors); passes until none moves (at most 8);
    * then the step sides' passes judge samples between such planes too (their rims: the wall's
    * samples in its noise tail beyond a window's edge lie nearer the window, but their neighbours are
    * the wall's). Where a step is under the planes' noise bands (a window 10 cm deep in a facade at
    * σ = 4 cm, 3σ band 12 cm) the step sides alone move no sample, and once the regions have moved,
    * a majority of neighbours no longer hands a plane the other's blocks. false = the step sides
    * between planes offset beyond their bands alone. */
  bool step_regions = true;
  /** \brief Departure (plane support, see releaseUnsupportedMembers): last of all, a member on or
    * beyond its plane's rim whose in-plane gap to the rest of the plane is more than
    * kSupportGapRatio times its neighbours' gaps (or with under kMinSupportShare of its neighbours in
    * the plane), and which lies in no other plane's noise band, leaves the plane. Growth and the last assignment judge a sample by its distance to the plane,
    * and an outlier within the band just beyond the rim has the plane's PCA normal. false = the
    * paper (and the passes before this one). */
  bool support_check = true;
  /** \brief Departure (clutter share, part of support_check, see releaseUnsupportedMembers): with
    * the plane support, a member wherever it lies in its plane leaves it where, within its
    * k-neighbourhood's ball, its plane's samples inside the noise band are no denser than the
    * unlabelled samples outside it; releases peel as the plane support's. A noisy plane in clutter
    * takes, by its band and its wide MND, the sheet of the clutter inside its band, and its
    * samples' neighbourhoods reach far into the clutter around it: the boxes, layout 204, 20 %
    * outliers, the σ 4.4 cm box's top held 184 outliers 0.1-2 m beyond its face, with 12-42 % of
    * their neighbours in the plane against 60-100 % for the face's own samples. No member of such a
    * sheet is on its rim, and its gaps are its own neighbours'. A plain majority (fewer neighbours in
    * the plane than in none) released the far, sparse walls of rooms in 20 % outliers too (room
    * layout 738: 1,283 samples of walls, F1 0.985 -> 0.962); comparing densities, their samples
    * stay. Asking also that the plane's samples be fewer than those unlabelled outside the band kept
    * the cubes at σ 1 % among outliers as they were (their edges lose up to 0.0016 of F1 without it)
    * but gave back most of the sheets of the boxes at layout 390 (F1 0.980 -> 0.924): not kept.
    * false = the plane support's rim rules alone. */
  bool support_clutter = true;
  /** \brief Departure (final parts, see splitDisconnectedPlanes' release_strays): after the plane
    * support, the connected parts once more, on the final members: a plane of two or more pieces of
    * surface is split into them, and a plane of one piece keeps only the members that a chain of
    * its members joins to it. The passes after growth (the last assignment, the edge and step sides)
    * claim samples by their distance to a plane wherever its band reaches, and clutter inside the
    * band joined them to the plane until the plane support's clutter share released it: the boxes,
    * layout 204, 20 % outliers, a rough box's top kept 592 samples of the sides of a box 3 m away,
    * tilting it by 4.7° and spreading its voxels so that it matched no face (F1 0.974, 31 of 32, one
    * false plane; 0.987, 32 of 32, with this). false = the planes as the plane support leaves them. */
  bool final_parts = true;
  /** \brief Departure (final refit, see refitPlanes): once the planes' samples are settled (after the
    * layer merge), each plane's C and N become the least-squares plane of its members within 2.5
    * robust sigmas, before the last assignment, the edge and step sides and the plane support judge
    * samples by their distance to it; and again on the final members, for the planes returned. The
    * robust estimate (Eqs. 3-9) is off by a large part of the noise at a plane's rims: on the
    * staircase at σ = 1 cm the samples within 1 cm of a riser's edges lay beyond the edge line of
    * both estimated planes and were released (F1 0.9737; 0.9828 with the refit). false = the paper's
    * estimate throughout. */
  bool final_refit = true;
  /** \brief Departure (connected parts, see splitDisconnectedPlanes): after the far-member release,
    * a plane whose members that pass its inlier test (Sec. 3.3) at its last estimate form two or more
    * parts of at least ε samples that no graph edge joins is split into them. M1 keeps a plane of the
    * paper in one piece, but samples of a surface crossing the gap between two pieces of one geometric
    * plane can join both and carry M1 across. false = the paper (and the planes as merged). */
  bool connected_parts = true;
  /** \brief Departure (bent planes, see splitBentPlanes): after the connected parts and the curved check, a plane whose
    * members two planes meeting at an edge explain (fitHinge: the robust σ falls to at most
    * bent_sigma_ratio, they meet at more than 90° minus T1's angle, each side has ε samples and passes
    * T1-T3) is split at the edge, and each part again (three levels); then parts of split planes
    * that are one face are joined again (joinSplitFaces). With noisy normals MND is wide, and growth
    * and re-estimation carry a plane over an edge onto the next face. false = the paper. */
  bool bent_plane_split = true;
  /** \brief Departure (layers of one plane's noise band, see mergeBandLayers): after the bent-plane
    * split, a plane at least half of whose members have a graph neighbour in a larger plane, whose
    * members lie (median) within that plane's noise band and which stays within it across its
    * extent, is merged into it, and the plane is estimated again. Two seeds of one noisy face grow
    * into two interleaved layers of its band, each estimated on its own side, its MDP too narrow for
    * M3 and M4 to join them (the room's cabinet front: 1,208 and 621 samples 4.6 mm apart, MDPs 5.3
    * and 3.8 mm). false = such layers stay apart. */
  bool layer_merge = true;
  /** \brief Departure (steps are no layers, see mergeBandLayers): with layer_merge, a plane whose
    * members' neighbourhoods (their samples held by it or the larger plane) average off the two
    * planes' joint plane by more than half its robust σ is a step beside the larger plane, not a
    * layer of its band, and stays apart. A facade at σ = 4 cm whose windows are recessed 10 cm:
    * the wall's band holds part of each window, every window member has a wall neighbour, and the
    * layer merge alone joined 8 of 9 windows to the wall (F1 0.776, 2 of 10 planes). false = the
    * layer merge alone. */
  bool layer_steps = true;
  /** \brief Departure (step split, see splitSteps): after the bent-plane split, a region of a plane
    * that lies parallel to the rest, offset by a step within the noise band (its neighbourhoods'
    * mean distance off the plane by half a robust σ, an inside, the offset across its border, planes
    * meeting beyond twice its half extent), is split off as a plane of its own, again until none
    * is. A door 2 cm proud of its wall scanned at σ = 8 mm to 2.5 cm is taken with the wall by
    * growth: no test of one sample's distance or normal tells it apart. false = such a region stays
    * in its plane. */
  bool step_split = true;
  /** \brief Departure (planes across a step, see dropPlanesAcrossSteps): after the layer merge, a
    * plane whose members lie on two planes beside it, parallel to each other and not to it, at least
    * as closely as on its own plane is dropped, its samples left to the last assignment. The
    * small-plane pass runs before the far-member release parts a door 2 cm proud of its wall from
    * the wall, and may seed a strip across the door's edge, half wall and half door, that passes
    * T1-T3 as one plane tilted by the step (the room at seed 7: 299 samples tilted 8.6°).
    * false = such a plane stays. */
  bool across_step_check = true;
  /** \brief Departure (bent noisy planes, see splitBentNoisyPlanes): where a plane a noisy seed
    * seeded is judged flat once grown, one that is not but that two flat planes meeting at an edge
    * explain is split into them instead of dropped. false = it is dropped (and the paper seeds no
    * such plane). Off by default since issue #6's eighteenth session: the industrial scene at
    * σ = 2 cm got two false planes, the halves of a pipe facet (hinge 16°, each half's quadric share
    * 0.03-0.06, within the flat test's allowance), and with bent_side_parent_mnd and the trimmed
    * refit of the caller's normals it gains synpeb_pc01 only 0.0013-0.0018 of F1. */
  bool noisy_bent_split = false;
  /** \brief Departure (part of bent_plane_split): a side of a bent plane passes T2 if its MND is
    * below the MND of the plane it was cut from, where that is wider than T2's 60°. Growth and
    * re-estimation (Sec. 3.5) test nothing again, so a plane on very noisy normals keeps an MND past
    * T2, and each side of it, as noisy, failed T2 and kept the plane whole: synpeb_pc01 on PCL's
    * k = 50 normals had a plane over two faces 39° apart (3,779 and 3,627 samples, MND 70°), the
    * side of 3,884 samples at MND 60.5°. false = T2 at 60° for every side. */
  bool bent_side_parent_mnd = true;
  /** \brief Bent planes: the largest ratio of the two planes' robust σ to the one plane's that counts as
    * a bend (0.8; fitHinge's search on flat noisy planes stays above 0.85). */
  double bent_sigma_ratio = 0.8;
  /** \brief Departure (part of bent_plane_split, see isEdgeTheNormalsConfirm): a hinge whose positions
    * alone are no bend (σ above bent_sigma_ratio of the one plane's) still is where the normals
    * confirm an edge: the two sides' mean normals turn by more than 90° minus T1's angle, as their
    * planes do, they turn in one step rather than steadily (normalTurnRatio at least 1, where a
    * curved surface gives less), and the positions explain at least half the share of the variance
    * the positions alone must (σ at most √((1 + r²) / 2) of the one plane's for r =
    * bent_sigma_ratio: 0.906). On faces whose noise is a large part of their width the positions
    * cannot reach 0.8 (synpeb_pc01: two faces 40° apart at σ 1.4-2 cm, 0.33-0.38 m wide, held by
    * one plane, σ ratio 0.855 with the true faces as sides), while their normals turn by 20-33° at
    * the edge. false = the positions alone decide. */
  bool bent_normal_edges = true;
  /** \brief Departure (part of bentAtAnEdge, which judges seeds and groups of cells): a set the
    * positions call bent at an edge (isBend) is so only if the mean normals of its two sides also
    * turn by more than 90° minus T1's angle (15°), the bend isBend asks of the positions. A cut
    * through few noisy samples can leave a side whose least-squares plane tilts by chance: a seed of
    * 76 samples on a box side at σ 3 cm (PCL's k = 50 normals), cut 60 / 16, gave sides 47° apart
    * whose normals turned 3.9°, and the side was never seeded; real edges in the seeds of the
    * scenes, of synpeb_pc01 and of room_scan1 turned their normals by 20-87°, flat faces cut by
    * chance by 2-14°. false = positions alone. */
  bool hinge_normal_turn = true;
  /** \brief Departure (residual pattern, the paper's Sec. 5 suggestion): once grow-merge is stable,
    * a quadric w = f(u, v) is fitted to each plane's samples over its least-squares plane
    * (measureCurvature), and the plane is dropped as a facet of a curved surface (pipe, tank, pillar,
    * ball) when the quadric explains at least this share of the residual variance (the deviation is
    * a bend, not noise) and turns the normal from the middle to the rim by at least half the plane's
    * MND (the bend, not noise, is what spreads its normals; a facet of a curved surface grows until
    * its rim normals reach MND, a scanned wall bends by a small part of it). Exact quadric fits (a few
    * scan lines) are not judged. 0.25, T3's share. */
  double min_curvature_share = 0.25;
  /** \brief Departure (a bend tested against noise, isFlatPatch): a patch is flat when its
    * quadric's share of the residual is below what a quadric explains of a flat plane's noise, with
    * as many samples, this often (chanceBendShare), or when it passes the fixed rule
    * (min_curvature_share, and the grown bend); grown, it must also be thinner than half its narrow
    * side. The curved-surface check counts a share only beyond the same bound. Under the fixed rule
    * a 16-sample seed of a flat face was bent two times in five, and a box face grown to 127 samples
    * at σ 2 cm, whose quadric bends 1.7° by chance against an MND of 3.3°, was dropped (boxes at
    * 30,000 points on k = 50 normals: 22 of 32 faces; 29 with the test). 0.95; 0 = the fixed rule
    * alone. */
  double bend_confidence = 0.95;
  /** \brief Departure (judging grown noisy planes): the confidence of the same noise test where a
    * plane that a noisy seed seeded is judged once grown (a retested outlier seed, a thick-cell group,
    * a small seed noisier than the planes found, a group of such seeds) and dropped whole if bent.
    * A scene judges dozens of such planes, and at 0.95 one flat face in twenty is called bent by
    * chance: the boxes at 50,000 points (seed 8) on PCL's k = 50 normals lost the σ = 3 cm box's side
    * of 411 samples, grown to 192, whose quadric share, 0.041, was the 0.95 quantile to three digits
    * (a debug print). 0.975 (0.99 also let a tank facet of the industrial scene at 30,000 points in,
    * and a false plane on the boxes at 20,000); used only where bend_confidence > 0. */
  double judge_bend_confidence = 0.975;
  /** \brief Departure (the judge of grown noisy planes): a plane whose positions bend beyond chance
    * is still kept as flat when its normals do not turn with them: their turn across it
    * (normalTurnAcross) below this share of the quadric's (twice its half-bend). On a curved facet the
    * normals turn with the surface; a flat face's quadric bends by chance, its normals by nothing
    * (the boxes at 40,000 points, seed 16, on PCL's k = 50 normals: a flat σ = 2 cm side of 231
    * samples, quadric share 0.067 against the 97.5 % quantile 0.041, half-bend 3.8° against half its
    * 5.1° MND, was dropped; its normals turn by 1.1° against the quadric's 7.6°, 0.14 of it). Measured
    * (debug prints): tank facets judged on the industrial scene 0.36-1.1 (small or very noisy ones
    * lowest), so 1/2 let two in; 1/4. Tubes (as thick as half their narrow side) are never kept
    * this way. 0 = every plane bent beyond chance is judged on its bend alone (before issue #6's
    * twenty-first session). */
  double judge_normal_turn = 0.25;
  /** \brief Whether the curved-surface check (min_curvature_share, curved_fold_ratio) runs. On by
    * default since issue #6's twenty-first session, with the fold ratio: at the scenes' own noise it
    * changes nothing (0 % of curved samples claimed either way), but at σ = 2-3 cm the room's 0.3 m
    * pillar became 2-4 false planes (67 % of its samples claimed) and the industrial scene's tank a
    * false plane; alone, the check also dropped synpeb_pc01's faces merged over a fold (52 -> 31 of
    * 60), which the bent-plane split would cut apart. false = the paper. */
  bool curved_plane_check = true;
  /** \brief Departure (late curved check; with curved_plane_check): the curved-surface check runs
    * again on every plane once the last assignment has given the planes their noise tails. A facet of
    * a curved surface grows within its band, which cuts off the part of the surface that bends away:
    * judged before the tails, what it holds bends by little more than chance; the tails bring the
    * bend in. The industrial scene in layout 967 (555,000 points, σ 7.2 mm, 10 % outliers) kept a
    * 0.4 m strip of a tank (quadric share 0.010 at 917 samples, 0.045 at 1,226 with its tails), and
    * the room at σ 3 cm (50,000 points, seed 41) facets holding 35 % of its pillar's samples (1.5 %
    * with the check). false = the check before the last assignment alone. */
  bool late_curved_check = true;
  /** \brief Departure (curved-surface check): a plane the quadric calls curved is dropped only if its
    * normals turn more smoothly than a fold would make them: normalTurnRatio (the residual of the
    * normals' angle about a line in the position over that about one step) below this. On a curved
    * surface whose normals turn across the plane by more than √48 ≈ 7 times their noise it is below
    * 1/2; two faces over one edge give at least 1, three equal faces over two edges about 1/2 to 1,
    * so 1/2 keeps folds of up to three faces for the bent-plane split, which runs after the check.
    * Measured (debug prints): the room's pillar and the tanks at σ = 1.5-4 cm, facets of 1,100-2,700
    * samples, 0.06-0.39 (smaller facets up to 0.70, some kept); synpeb_pc01's faces merged over a
    * fold 0.78-1.81. +inf = every plane the quadric calls curved is dropped. */
  double curved_fold_ratio = 0.5;
  /** \brief Departure (curved-surface check where noise swamps the normals): a plane is also a facet
    * of a curved surface when its quadric bends beyond chance (chanceBendShare at
    * curved_turn_confidence, without min_curvature_share's quarter) and its normals' own turn across
    * it (normalTurnAcross)
    * is at least half its MND, smoothly (curved_fold_ratio). Where noise is a large part of the
    * curvature, MND is the noise's, and neither the quadric's share nor its turn reaches the fixed
    * bounds: the industrial scene at σ = 3 cm (seed 3) kept a tank facet (share 0.05, half-bend 0.12
    * rad against MND 0.28, normals turning 0.34 rad) and two pipe facets (MND 0.64-0.66) as three
    * false planes, and the room at σ = 2.5 cm (seed 2) a pillar facet of 919 samples (share 0.23,
    * normals turning 0.90 rad against MND 0.73). A flat plane's normals turn by noise over its
    * extent, about √(12/n) of their spread, and its rims' bent normals are what MND measures.
    * false = the fixed bounds alone (before issue #6's twenty-fifth session). */
  bool curved_normal_turn = true;
  /** \brief Departure (curved-surface check): the fold ratio (curved_fold_ratio) keeps a plane the
    * quadric calls curved only if it has 2ε samples or bends within chance at curved_turn_confidence:
    * it keeps folds for the bent-plane split, which cuts a plane into sides of ε samples each, so a
    * smaller plane is no fold it could cut. A facet of the room's 0.3 m pillar whose normals turn by
    * less than √48 times their noise has a ratio of 0.6-0.8: at σ 1.5-2 cm facets of 150-266 samples
    * (ε 100-200, shares 0.21-0.31 against 99.9 % quantiles of 0.09-0.12) were false planes, 13-19 %
    * of the curved samples. Without the chance bound a small real face went too (the room at 20,000
    * points and σ 1.2 cm on PCL's k = 50 normals, 9 -> 8 of 12). false = the ratio at every size
    * (before issue #6's twenty-fifth session). */
  bool curved_fold_two_sides = true;
  /** \brief Departure (curved-surface check): a plane as thick as a tube (isTube: its noise band MDP
    * at least half its narrow side) is dropped as a tube sampled all round, whatever its quadric and
    * normals say. A thin pipe's samples from every side fold onto one plane through its axis: the
    * positions wrap round it (the quadric explains little of them) and the normals point all round
    * (their turn is no line in the position). The flat test asked it of noisy seeds' planes alone
    * (isFlatPatch); on PCL's k = 50 normals the industrial scene at 30,000 points (seed 5) kept a
    * ribbon along a pipe seeded by the first split's cells: 100 samples 0.22 m wide, MDP 0.16 m, MND
    * 45°, quadric share 0.05 against a 99.9 % chance bound of 0.16. false = tubes judged as other
    * planes (before issue #6's thirty-third session). */
  bool curved_tube_check = true;
  /** \brief Departure (curved-surface check): the parts the bent-plane split cut are judged by the
    * check again, as planes are. A plane the fold ratio kept for the split as a fold may be a facet
    * whose normals turn in steps only because they are blurred; cut, its parts bend as much as it did
    * (the room at 20,000 points, σ 1.2 cm, seed 43, on PCL's k = 50 normals: a pillar facet of 74
    * samples, share 0.88 and half-bend 0.67 rad against MND 0.16, fold ratio 0.92; its parts of 41
    * and 33 samples, shares 0.46 and 0.59, half-bends 0.43 and 0.49 rad, fold ratios 1.1; the part
    * under 2ε = 40 goes, the other is spared as a fold again and stays). Faces cut apart at a real
    * fold are flat and stay. false = the parts kept unjudged (before the thirty-third
    * session). */
  bool curved_split_parts = true;
  /** \brief The confidence of the noise test in the normals' path of the curved-surface check
    * (curved_normal_turn). Sparse faces' normals turn across them by their rims (the boxes at 10,000
    * points on PCL's k = 50 normals: 1.2-2.1 rad against MND 0.7-1.7), so the quadric's share decides
    * there, and at 95 % one flat face in twenty passes: two box faces and a facade wall were dropped
    * (shares 0.12-0.21 against 95 % quantiles 0.08-0.12). The facets it is for bend far beyond
    * chance (tank and pillar facets 0.05-0.23 against 99.9 % quantiles 0.012-0.024). 0.999. */
  double curved_turn_confidence = 0.999;
  /** \brief Departure (re-estimation within T2, Sec. 3.5): a plane keeps its last estimate when a
    * re-estimate's MND fails T2 (at least max_normal_deviation, 60°), as the paper's test would fail
    * the plane itself. A noisy seed's MND is wide; growth takes samples of the faces around it, each
    * re-estimate widens MND and MDP by their normals, and the plane runs away: the boxes at 10,000
    * points on PCL's k = 50 normals got one plane over a whole box, five faces, MND 173° and MDP
    * 0.81 m. Until issue #6's thirty-third session only noisy seeds' planes (PlanarPatch::retested)
    * were bounded; a split seed's plane runs away too where the given normals blur the faces: the
    * staircase at 10,000 points (seed 9) on PCL's k = 50 normals grew a riser's plane to MND 71° and
    * then over 6,600 samples of the flight (10 of 30 planes; 29 bounded). Over the 84 sweep rows, on
    * their own and on PCL's normals, no other label moved. false = the paper (every re-estimate
    * taken). */
  bool bounded_reestimation = true;
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
  std::size_t joined_seeds = 0;      ///< planes seeded by groups of thick cells once growth is stable (join_thick_cells)
  std::size_t outlier_seeds = 0;     ///< seeds dropped as MND outliers
  std::size_t retested_seeds = 0;    ///< of those, seeded again from what growth left (retest_outlier_seeds)
  std::size_t volume_layers = 0;     ///< noisy seeds' planes dropped as where a volume of samples ends (volume_layer_check)
  std::size_t final_volume_layers = 0; ///< final planes dropped as where a volume of samples ends (final_volume_layer_check)
  std::size_t in_band_layers = 0;      ///< of those, dropped as layers inside another plane's band (in_band_layer_check)
  int iterations = 0;                ///< grow-merge iterations
  std::size_t reestimations = 0;     ///< Sec. 3.5 updates
  std::size_t kept_estimates = 0;    ///< of those, re-estimates refused as failing T2 (bounded_reestimation)
  std::size_t merges = 0;            ///< patches absorbed by merging
  std::size_t small_seeds = 0;       ///< seeds of the small-cell pass kept (both rounds)
  std::size_t small_seeds_trimmed = 0; ///< of those, seeded on trimmed or narrowed normals (left_normal_refit, left_normal_narrow)
  std::size_t small_seeds_shifted = 0; ///< of those, seeded on the shifted grid (shifted_small_grid)
  std::size_t small_joined_seeds = 0; ///< of those, seeded by groups of the pass's thick cells (small_cell_thick_join)
  std::size_t small_noisy_groups = 0; ///< of those, seeded by groups of seeds too noisy alone (noisy_seed_groups)
  std::size_t small_ladder_seeds = 0; ///< of those, seeded past the first step of the noise ladder (noisy_group_ladder)
  std::size_t small_seeds_beside = 0; ///< of those, no band layer only as faces beside a plane (isBandLayer)
  std::size_t small_completed = 0;   ///< small-plane pass planes brought to ε by completion (small_plane_completion)
  std::size_t left_refitted = 0;     ///< left samples given a trimmed-plane or narrowed normal (left_normal_refit, left_normal_narrow)
  std::size_t released = 0;          ///< members released as far from their plane (release_far_members)
  std::size_t restored = 0;          ///< of those, given back to their plane
  std::size_t released_planes = 0;   ///< planes seeded by released samples (seed_released_planes)
  std::size_t rim_seeds = 0;         ///< small-cell pass: cells seeded by their inliers (rim_cell_retest), before the MND check
  std::size_t split_planes = 0;      ///< planes added by splitting planes into connected parts (connected_parts)
  std::size_t bent_planes = 0;       ///< planes added by splitting bent planes at their edge (bent_plane_split)
  std::size_t steps_split = 0;       ///< planes added by splitting off a step (step_split)
  std::size_t across_steps = 0;      ///< planes dropped as lying across a step (across_step_check)
  std::size_t layers_merged = 0;     ///< planes merged into a plane as layers of its noise band (layer_merge)
  std::size_t bent_joined = 0;       ///< of the planes then, those joined to another as one face (joinSplitFaces)
  std::size_t noisy_bent_planes = 0; ///< noisy seeds' planes split at an edge before they are judged flat (noisy_bent_split)
  std::size_t noisy_past_t2 = 0;     ///< noisy seeds' planes dropped once grown as failing T2 (noisy_grown_t2)
  std::size_t clutter_released = 0;  ///< of unsupported, members released amid clutter as dense as their plane (support_clutter)
  std::size_t final_split = 0;       ///< planes added by the final parts (final_parts)
  std::size_t final_strays = 0;      ///< members the final parts released as joined to their plane by no chain of members
  std::size_t edge_moved = 0;        ///< samples the edge-side rule gave to the other plane (edge_sides)
  std::size_t edge_cornered = 0;     ///< samples inside a corner given to the nearer plane (edge_corners)
  std::size_t edge_outside = 0;      ///< samples outside an edge kept by the farther plane (edge_wedges)
  std::size_t edge_released = 0;     ///< samples it took off their plane for none
  std::size_t step_moved = 0;        ///< samples the step-side rule gave to a parallel plane (step_sides)
  std::size_t step_region_moved = 0; ///< samples the step-region rule gave to a parallel plane (step_regions)
  std::size_t assigned = 0;          ///< samples the last assignment pass gave a plane
  std::size_t member_gap_refused = 0; ///< samples it left out as beyond the spacing of the members beside them (member_gaps)
  std::size_t position_planes = 0;   ///< planes found by position among what was left (position_planes)
  std::size_t unsupported = 0;       ///< samples released as beyond their plane's rim (support_check)
  std::size_t thick_rebound = 0;     ///< small-plane passes whose thick cells were collected again (thick_cells_follow_noisy_seeds)
  std::size_t below_epsilon = 0;     ///< planes the passes after growth left with fewer than ε samples, dropped
  std::size_t curved_planes = 0;     ///< planes dropped by the residual-pattern check
  std::size_t curved_tubes = 0;      ///< tubes among curved_planes, curved_parts and late_curved_planes (DetectorParameters::curved_tube_check)
  std::size_t late_curved_planes = 0; ///< planes dropped as curved once given their tails (late_curved_check)
  std::size_t curved_parts = 0;      ///< parts of bent planes the check dropped once cut (curved_split_parts)
  bool hit_iteration_cap = false;
  double prepare_seconds = 0.0;      ///< valid samples, centring, spatial order (wall time)
  double graph_seconds = 0.0;        ///< building the k-NN graph (wall time)
  std::size_t graph_bytes = 0;       ///< memory held by the compressed k-NN graph
  double normals_seconds = 0.0;      ///< estimating normals (0 when given and kept)
  bool given_normals_replaced = false; ///< the caller's normals were noise at the graph's scale, or blurred the faces, and were estimated again (RobustPlaneSegmentation::setGivenNormalCheck)
  bool given_normals_blurred = false; ///< of those, the caller's normals blurred the faces the automatic k resolves (givenNormalsBlurFaces): the detection ran at that k
  std::size_t edge_narrowed_normals = 0; ///< normals narrowed to one face at an edge (RobustPlaneSegmentation::setEdgeAwareNormals)
  std::size_t depth_levels = 0;      ///< distinct depths of a quantized camera cloud that were dithered (RobustPlaneSegmentation::setDepthLevelDither); 0 = none
  double split_seconds = 0.0;        ///< split phase
  double grow_merge_seconds = 0.0;   ///< grow-merge iterations and every pass after them
  /** Wall time of each pass within grow_merge_seconds, in the order first run ("grow-merge",
    * "small planes", "step split", ...; a pass run more than once is summed): where the time goes. */
  std::vector<std::pair<std::string, double>> pass_seconds;
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
