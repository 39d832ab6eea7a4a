/*
 * pcl_rspd: the pipeline of Sec. 3 — split, then grow and merge until every patch is stable.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/band_layers.h>
#include <pcl_rspd/bent_planes.h>
#include <pcl_rspd/connected_parts.h>
#include <pcl_rspd/edge_sides.h>
#include <pcl_rspd/normal_estimation.h>
#include <pcl_rspd/octree_split.h>
#include <pcl_rspd/patch_growth.h>
#include <pcl_rspd/patch_merge.h>
#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/plane_completion.h>
#include <pcl_rspd/plane_curvature.h>
#include <pcl_rspd/plane_detector.h>
#include <pcl_rspd/plane_refit.h>
#include <pcl_rspd/position_planes.h>
#include <pcl_rspd/plane_support.h>
#include <pcl_rspd/robust_normals.h>
#include <pcl_rspd/robust_statistics.h>
#include <pcl_rspd/seed_groups.h>
#include <pcl_rspd/step_split.h>
#include <pcl_rspd/volume_layers.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <limits>

#include <Eigen/Eigenvalues>

namespace pcl
{
namespace rspd
{
namespace
{
/** Robust standard deviations that bound a plane's noise (a Gaussian's 3 σ: 99.7 %). */
constexpr double kBandSigmas = 3.0;

/** Most steps of the noise ladder (DetectorParameters::noisy_group_ladder). Each step's bound is
  * above the last by the MND of a plane seeded, so the ladder ends by itself; the cap bounds the cost
  * (the boxes at σ = 8 mm, 80,000 points, take three steps, bounds 0.16, 0.30 and 0.53 rad, the last
  * seeding up to 0.95 rad; a debug print). */
constexpr std::size_t kLadderSteps = 16;

/** Most passes of the step-side rule (settleStepSides) until no sample moves. */
constexpr int kStepSidePasses = 8;

/** How far, in neighbourhood radii of the sample (its k-th neighbour's distance) and along the
  * graph path that brought its plane to it, the last assignment may reach from the members growth
  * left. Growth stops where the normals bend, up to one radius short of an edge, and a path over the
  * graph's hops is longer than the straight line; the room's floor-wall corner, far from its
  * viewpoint and sparse, needs 3 (2 left 50 of its samples out). Without a bound, each round's
  * samples carry their plane to the next: in a window's band behind the facade's wall, with 30 %
  * outliers, from one outlier to the next over the whole wall (F1 0.889, 2 of 16 planes lost). */
constexpr double kAssignReachRadii = 3.0;

/** Robust standard deviations within which the last assignment takes a plane's noise tail (Tails):
  * a Gaussian leaves 6·10⁻⁵ of its samples beyond 4 σ, under one of a 10,000-sample plane, where 3 σ
  * leaves out 27 of them, each alone in a voxel of the plane's noise rim. */
constexpr double kTailSigmas = 4.0;

/** Each patch's median |d| of its members about its plane (NaN for a patch without members). */
std::vector<double>
medianDistances (const PointSet& points, const DetectorParameters& params, const std::vector<PlanarPatch>& patches)
{
  std::vector<double> median (patches.size ());
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolveThreads (params.num_threads))
  for (std::ptrdiff_t l = 0; l < static_cast<std::ptrdiff_t> (patches.size ()); ++l)
  {
    const PlanarPatch& patch = patches[l];
    std::vector<float> d (patch.members.size ());
    for (std::size_t t = 0; t < d.size (); ++t)
      d[t] = static_cast<float> (std::abs ((points.points[patch.members[t]].cast<double> () - patch.center).dot (patch.normal)));
    median[l] = d.empty () ? std::numeric_limits<double>::quiet_NaN () : medianInPlace (d);
  }
  return median;
}

/** Each patch's distance bound for its own samples: max(MDP, \a sigmas σ), σ = 1.4826 median |d| of
  * its members about its plane (\a median from medianDistances). MDP = median + α MAD of |d| (Eq. 6)
  * is about 2.45 σ on Gaussian noise. */
std::vector<double>
bandsOf (const std::vector<PlanarPatch>& patches, const std::vector<double>& median, double sigmas)
{
  std::vector<double> band (patches.size ());
  for (std::size_t l = 0; l < patches.size (); ++l)
    band[l] = std::isnan (median[l]) ? patches[l].mdp : std::max (patches[l].mdp, sigmas * kMadScale * median[l]);
  return band;
}

/** The noise bands at kBandSigmas (see bandsOf). */
std::vector<double>
noiseBands (const PointSet& points, const DetectorParameters& params, const std::vector<PlanarPatch>& patches)
{
  return bandsOf (patches, medianDistances (points, params, patches), kBandSigmas);
}

/** What growth left of \a samples (those no plane holds), made a plane: at least ε of them that pass
  * T1-T3 and \a accept (the plane; may mark it) and are no band layer (isBandLayer) of
  * a plane found. The outlier-seed retest and the thick-cell groups seed this way. The plane is
  * appended to \a patches, \a labels and \a band (its MDP: its members' spread is not known yet).
  * \return whether a plane was added */
template <typename Accept> bool
seedLeftSamples (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                 const std::vector<std::uint32_t>& samples, Accept&& accept, std::vector<PlanarPatch>& patches,
                 std::vector<double>& band, std::vector<std::uint32_t>& labels)
{
  std::vector<std::uint32_t> left;
  for (const auto i : samples)
    if (labels[i] == kNoPatch)
      left.push_back (i);
  if (left.size () < params.min_patch_size)
    return false;
  PlanarityResult test = robustPlanarityTest (points, left, params);
  if (test.verdict != PlanarityVerdict::Planar)
    return false;
  PlanarPatch plane;
  plane.members = std::move (test.inliers);
  plane.first_index = *std::min_element (plane.members.begin (), plane.members.end ());
  plane.setEstimate (test.estimate);
  if ((!patches.empty () && isBandLayer (points, graph, params, patches, band, labels, plane)) || !accept (plane))
    return false;
  for (const auto i : plane.members)
    labels[i] = static_cast<std::uint32_t> (patches.size ());
  patches.push_back (std::move (plane));
  band.push_back (patches.back ().mdp);
  return true;
}

/** Groups of thick cells (the first split's or the small-plane pass's), each made a plane of what
  * growth left of it (seedLeftSamples) against the current planes' noise bands: marked as noisy
  * (judged flat again once grown, no bound for the small-plane pass's seeds), and kept only if two
  * planes meeting at an edge do not explain it and its quadric shows no bend.
  * \return planes seeded */
std::size_t
seedThickGroups (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                 const std::vector<PlanarPatch>& groups, std::vector<PlanarPatch>& patches,
                 std::vector<std::uint32_t>& labels)
{
  std::vector<double> band = noiseBands (points, params, patches);
  const auto unbent = [&] (PlanarPatch& plane) {
    plane.joined = true;
    plane.retested = true;
    return !bentAtAnEdge (points, plane.members, params) && isFlatPatch (points, params, plane, false);
  };
  std::size_t seeded = 0;
  for (const auto& group : groups)
    seeded += seedLeftSamples (points, graph, params, group.members, unbent, patches, band, labels);
  return seeded;
}

/** One round of a pass that offers unlabelled samples to planes: sample open[j] joins plane
  * choice[j] (kNoPatch: stays open); the samples left open and their choices are compacted to the
  * front. \return samples that joined a plane */
std::size_t
applyChoices (std::vector<std::uint32_t>& open, std::vector<std::uint32_t>& choice, std::vector<PlanarPatch>& patches,
              std::vector<std::uint32_t>& labels)
{
  std::size_t kept = 0;
  for (std::size_t j = 0; j < open.size (); ++j)
  {
    if (choice[j] == kNoPatch)
    {
      open[kept++] = open[j];
      continue;
    }
    labels[open[j]] = choice[j];
    patches[choice[j]].members.push_back (open[j]);
  }
  const std::size_t added = open.size () - kept;
  open.resize (kept);
  choice.resize (kept);
  return added;
}

/** What a sample's graph neighbours hold: the first plane met, whether another plane is met too,
  * how many are held and how many there are. The Tails rule and the tail odds read it alike. */
struct NeighbourLabels
{
  std::uint32_t first = kNoPatch;
  bool several = false;
  int held = 0, neighbours = 0;

  /** Inside one plane: every held neighbour holds \a first, and they are most of the neighbours. */
  bool
  insideOne () const
  {
    return first != kNoPatch && !several && 2 * held > neighbours;
  }
};

NeighbourLabels
labelsAround (const NeighborGraph& graph, const std::vector<std::uint32_t>& labels, std::uint32_t i)
{
  NeighbourLabels a;
  graph.forEachNeighbor (i, [&] (std::uint32_t n) {
    const std::uint32_t l = labels[n];
    if (l != kNoPatch && a.first == kNoPatch)
      a.first = l;
    a.several = a.several || (l != kNoPatch && l != a.first);
    a.held += l != kNoPatch;
    ++a.neighbours;
  });
  return a;
}

/** Rim bands (DetectorParameters::rim_bands): whether sample \a i, within \a plane's MDP, has at
  * least a third of its neighbours within the plane's \a band among the plane's members (\a held of
  * them; its other neighbours hold no plane), and some neighbour off the band. Neighbours off the
  * band are another surface, or clutter, and do not count; without one, nothing beside the plane
  * tilted the sample's normal (the pipe a false plane runs through lies wholly in its band). */
bool
insideRimBand (const PointSet& points, const NeighborGraph& graph, const std::vector<std::uint32_t>& labels,
               const PlanarPatch& plane, double band, std::uint32_t i, int held)
{
  const auto offset = [&] (std::uint32_t j) {
    return std::abs ((points.points[j].cast<double> () - plane.center).dot (plane.normal));
  };
  if (!(offset (i) <= plane.mdp))
    return false;
  int free_in_band = 0, off_band = 0;
  graph.forEachNeighbor (i, [&] (std::uint32_t n) {
    const bool in_band = offset (n) <= band;
    free_in_band += labels[n] == kNoPatch && in_band;
    off_band += !in_band;
  });
  return off_band > 0 && 2 * held >= free_in_band;
}

/** The shell, in robust standard deviations of a plane, where its Gaussian noise leaves next to
  * nothing (a 6.8·10⁻⁶ share beyond 4.5 σ, under one sample of a 100,000-sample plane) and the samples
  * beside it that no plane holds are clutter; near enough that the Tails rule's conditions pass
  * about as often there as in the tail. */
constexpr double kClutterShellFrom = 4.5, kClutterShellTo = 6.0;

/** φ(0), the standard normal density at 0. */
constexpr double kInvSqrtTwoPi = 0.3989422804014327;

/** The members of \a plane farther from it than \a limit leave it (their labels kNoPatch); its
  * first index follows. */
void
releaseMembersBeyond (const PointSet& points, double limit, PlanarPatch& plane, std::vector<std::uint32_t>& labels)
{
  std::size_t kept = 0;
  for (const auto m : plane.members)
    if (std::abs ((points.points[m].cast<double> () - plane.center).dot (plane.normal)) <= limit)
      plane.members[kept++] = m;
    else
      labels[m] = kNoPatch;
  plane.members.resize (kept);
  if (kept > 0)
    plane.first_index = *std::min_element (plane.members.begin (), plane.members.end ());
}

/** Tail odds (departure, DetectorParameters::tail_odds): lowers each plane's tail limit to where its
  * Gaussian noise is no longer likelier than the clutter around it. Per plane, the clutter's density
  * per unit |d| is read from the samples no plane holds that lie beside it (most of their neighbours
  * are its members, their normals pass its MND, as the Tails rule asks) in the shell
  * kClutterShellFrom-kClutterShellTo σ; the noise's is N · 2φ(|d| / σ) for N members; they meet at
  * x σ, x = sqrt (2 ln (2 N φ(0) · width / count)). The limit stays within [kBandSigmas, kTailSigmas]
  * σ: a clean plane keeps the 4 σ tail, and a plane in dense clutter its 3 σ band. With
  * \a surrounding (DetectorParameters::surrounding_clutter) the count is at least the clutter
  * around the plane over its footprint (clutterBesidePlane), and the limit may fall below 3 σ, to
  * MDP. Footprint and density cancel, so nothing here has a unit. */
void
boundTailsByClutter (const PointSet& points, const NeighborGraph& graph, const std::vector<PlanarPatch>& patches,
                     const std::vector<double>& median, const std::vector<std::uint32_t>& labels,
                     bool surrounding, int num_threads, std::vector<double>& tail_limit)
{
  std::vector<std::size_t> shell (patches.size (), 0);
  for (std::uint32_t i = 0; i < labels.size (); ++i)
  {
    if (labels[i] != kNoPatch)
      continue;
    const NeighbourLabels around = labelsAround (graph, labels, i);
    const std::uint32_t first = around.first;
    if (!around.insideOne () || std::isnan (median[first]))
      continue;
    const PlanarPatch& patch = patches[first];
    const double sigma = kMadScale * median[first];
    const double d = std::abs ((points.points[i].cast<double> () - patch.center).dot (patch.normal));
    if (d >= kClutterShellFrom * sigma && d < kClutterShellTo * sigma &&
        std::abs (points.normals[i].cast<double> ().dot (patch.normal)) >= patch.cos_mnd)
      ++shell[first];
  }
  if (surrounding)
  {
    // Surrounding clutter (DetectorParameters::surrounding_clutter): where the clutter is dense, its
    // samples have clutter around them and the shell above misses them.
    std::vector<std::uint32_t> open;
    for (std::uint32_t i = 0; i < labels.size (); ++i)
      if (labels[i] == kNoPatch)
        open.push_back (i);
    const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (patches.size ());
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolveThreads (num_threads))
    for (std::ptrdiff_t l = 0; l < count; ++l)
      if (!std::isnan (median[l]))
      {
        const double sigma = kMadScale * median[l];
        shell[l] = std::max (shell[l], clutterBesidePlane (points, graph, patches[l], kClutterShellFrom * sigma,
                                                           kClutterShellTo * sigma, labels, open,
                                                           static_cast<std::uint32_t> (l)));
      }
  }
  // Without surrounding clutter a plane in dense clutter keeps its 3 σ band; with it, the tail ends
  // where the clutter's density meets the noise's, MDP its floor.
  const double lowest = surrounding ? 0.0 : kBandSigmas;
  for (std::size_t l = 0; l < patches.size (); ++l)
  {
    if (shell[l] == 0 || std::isnan (median[l]))
      continue;
    const double sigma = kMadScale * median[l];
    // Densities per unit |d| / σ: the noise's at 0 (2 φ(0) N), the clutter's (flat).
    const double noise = 2.0 * kInvSqrtTwoPi * static_cast<double> (patches[l].members.size ());
    const double clutter = static_cast<double> (shell[l]) / (kClutterShellTo - kClutterShellFrom);
    const double x = noise > clutter ? std::sqrt (2.0 * std::log (noise / clutter)) : 0.0;
    const double bound = std::max (patches[l].mdp, std::clamp (x, lowest, kTailSigmas) * sigma);
    tail_limit[l] = std::min (tail_limit[l], bound);
  }
}

/** Last assignment pass (departure, DetectorParameters::final_assignment): a sample no patch holds
  * joins the plane of a graph neighbour whose distance band it lies in (|d| <= MDP; the nearest
  * relative to MDP when several do, ties to the lower label), provided it is also among that
  * neighbour's k nearest (mutual neighbours: an isolated outlier is nobody's neighbour). The normal
  * condition is left out on purpose: PCA normals bend within a neighbourhood radius of an edge,
  * which is exactly where growth stops short. Edges: only samples next to two or more planes (an
  * edge band), so clutter and outliers beside a single plane stay out. Tails: also a sample most of
  * whose neighbours hold one plane, if |d| <= MDP, or if its normal passes that plane's MND and
  * |d| <= 4 σ, σ =
  * 1.4826 median |d| of the plane's members, and a sample next to two or more planes within a
  * plane's noise band max(MDP, 3 σ) instead of MDP: MDP (median + α MAD of |d|, Eq. 6) is about
  * 2.45 σ on Gaussian noise, so growth leaves the plane's own tail out, which a voxel-based count
  * sees as a rim of missed voxels on each side of a noisy plane (near an edge too, where the
  * normals bend and the noise is the same). Every mode but Tails' inside-a-plane case reaches no
  * farther than kAssignReachRadii from the plane's members along the graph. Each round reads the
  * labels of the round before, so the result does not depend on the thread count. With member
  * gaps (Tails; DetectorParameters::member_gaps) a sample joins a plane only where it lies among
  * its members (vouchingGaps, admittingGap). \a refused: the samples left at the end that member
  * gaps kept from a plane that would otherwise have taken them.
  * \return samples assigned */
std::size_t
assignRemainingSamples (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                        std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels, std::size_t& refused)
{
  refused = 0;
  const bool edges_only = params.final_assignment == FinalAssignment::Edges ||
                          params.final_assignment == FinalAssignment::Tails;
  const bool tails = params.final_assignment == FinalAssignment::Tails;
  // One median per plane serves both of Tails' bounds.
  const std::vector<double> median = tails ? medianDistances (points, params, patches) : std::vector<double> ();
  std::vector<double> tail_limit = tails ? bandsOf (patches, median, kTailSigmas) : std::vector<double> ();
  // Planes in clutter: where the clutter beside a plane outweighs its noise within its 4 σ tail.
  std::vector<char> in_clutter, clean;
  if (tails && (params.tail_odds || params.member_gaps))
  {
    std::vector<double> bounded = tail_limit;
    const bool surrounding = params.tail_odds && params.surrounding_clutter;
    boundTailsByClutter (points, graph, patches, median, labels, surrounding, params.num_threads, bounded);
    if (surrounding)
      // Surrounding clutter: growth and the far-member release admitted members out to MDP or 3 σ
      // whatever the clutter; beyond the tail's end they are likelier clutter than the plane's.
      for (std::size_t l = 0; l < patches.size (); ++l)
        if (bounded[l] < tail_limit[l])
          releaseMembersBeyond (points, bounded[l], patches[l], labels);
    if (params.member_gaps)
      for (std::size_t l = 0; l < patches.size (); ++l)
        in_clutter.push_back (bounded[l] < tail_limit[l]);
    if (params.rim_bands)
      for (std::size_t l = 0; l < patches.size (); ++l)
        clean.push_back (!(bounded[l] < tail_limit[l]));
    if (params.tail_odds)
      tail_limit = bounded;
  }
  const std::vector<double> edge_limit = tails ? bandsOf (patches, median, kBandSigmas) : std::vector<double> ();
  std::vector<std::uint32_t> left;
  for (std::uint32_t i = 0; i < labels.size (); ++i)
    if (labels[i] == kNoPatch)
      left.push_back (i);
  std::vector<std::uint32_t> choice (left.size ());
  // Reach: per sample, the length of the graph path that took its plane to it from a member growth
  // left (0 for those, and for tail samples, which lie inside their plane).
  std::vector<float> reach (labels.size (), 0.0f);
  for (const auto i : left)
    reach[i] = std::numeric_limits<float>::infinity ();
  std::vector<float> chosen_reach (left.size ());
  // Member gaps (departure, see DetectorParameters::member_gaps): the spacing each member vouches
  // with; a joiner vouches with the one that admitted it.
  std::vector<float> gaps;
  if (std::find (in_clutter.begin (), in_clutter.end (), 1) != in_clutter.end ()) // filled for member gaps only
    gaps = vouchingGaps (points, graph, patches, labels, left, in_clutter, params.num_threads);
  std::vector<float> chosen_gap (gaps.empty () ? 0 : left.size ());
  std::vector<char> beyond (gaps.empty () ? 0 : labels.size (), 0); // last refused by member gaps
  // Per sample, its k-neighbourhood's radius, measured once when first needed (rounds revisit it).
  std::vector<float> radius (labels.size (), -1.0f);
  std::size_t assigned = 0;
  // Per sample, the round it joined a plane in (0: before the pass). A sample none of whose
  // neighbours joined in the last round is judged on the same labels as then: it stays left.
  std::vector<std::uint32_t> joined_in (labels.size (), 0);
  for (std::uint32_t round = 1;; ++round)
  {
    const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (left.size ());
#pragma omp parallel for schedule(dynamic, 256) num_threads(resolveThreads (params.num_threads))
    for (std::ptrdiff_t j = 0; j < count; ++j)
    {
      const std::uint32_t i = left[j];
      choice[j] = kNoPatch;
      if (round > 1)
      {
        bool changed = false;
        graph.forEachNeighbor (i, [&] (std::uint32_t n) { changed = changed || joined_in[n] + 1 == round; });
        if (!changed)
          continue;
      }
      if (!beyond.empty ())
        beyond[i] = 0;
      bool beside_one = false; // Tails: the sample's labelled neighbours all hold one plane
      if (edges_only)
      {
        const NeighbourLabels around = labelsAround (graph, labels, i);
        // A tail sample lies inside its plane: most of its neighbours are members. (Beside the
        // plane's rim, the unlabelled samples may be a surface no seed reached.)
        bool inside = tails && around.insideOne ();
        if (!inside && !clean.empty () && !around.several && around.first != kNoPatch && clean[around.first])
          inside = insideRimBand (points, graph, labels, patches[around.first], edge_limit[around.first], i, around.held);
        if (!around.several && !inside)
          continue;
        beside_one = !around.several;
      }
      const Eigen::Vector3d p = points.points[i].cast<double> ();
      double best = HUGE_VAL;
      if (!beside_one && radius[i] < 0.0f)
      {
        double r = 0.0;
        graph.forEachNeighbor (i, [&] (std::uint32_t n) { r = std::max (r, (points.points[n].cast<double> () - p).norm ()); });
        radius[i] = static_cast<float> (r);
      }
      graph.forEachNeighbor (i, [&] (std::uint32_t n) {
        const std::uint32_t l = labels[n];
        if (l == kNoPatch || l == choice[j])
          return;
        const double path = reach[n] + (points.points[n].cast<double> () - p).norm ();
        if (!beside_one && path > kAssignReachRadii * static_cast<double> (radius[i]))
          return;
        const PlanarPatch& patch = patches[l];
        const double d = std::abs ((p - patch.center).dot (patch.normal));
        double r = d / (tails ? edge_limit[l] : patch.mdp);
        if (beside_one)
        {
          // Inside the plane's band (MDP) the sample is as close as its members and most of its
          // neighbours are members: its normal, which growth rejected, is noise (the cube at σ 1 %
          // of its edge left 1 % of its faces' middles out, most within 0.5 σ of the plane). Beyond
          // the band, in the tail, the normal must agree too, which keeps clutter out.
          if (d > patch.mdp && std::abs (points.normals[i].cast<double> ().dot (patch.normal)) < patch.cos_mnd)
            return;
          r = d / tail_limit[l];
        }
        if (!(r <= 1.0) || r > best || (r == best && l > choice[j]))
          return;
        bool mutual = false;
        graph.forEachNeighbor (n, [&] (std::uint32_t m) { mutual = mutual || m == i; });
        if (!mutual)
          return;
        float admitted = 0.0f;
        if (!gaps.empty () && in_clutter[l])
        {
          admitted = admittingGap (points, graph, patch, l, labels, gaps, i);
          if (std::isnan (admitted))
          {
            beyond[i] = 1;
            return;
          }
        }
        best = r;
        choice[j] = l;
        chosen_reach[j] = beside_one ? 0.0f : static_cast<float> (path);
        if (!gaps.empty ())
          chosen_gap[j] = admitted;
      });
    }
    for (std::size_t j = 0; j < left.size (); ++j)
      if (choice[j] != kNoPatch)
      {
        reach[left[j]] = chosen_reach[j];
        joined_in[left[j]] = round;
        if (!gaps.empty ())
          gaps[left[j]] = chosen_gap[j];
      }
    const std::size_t added = applyChoices (left, choice, patches, labels);
    assigned += added;
    if (added == 0)
    {
      if (!beyond.empty ())
        refused = static_cast<std::size_t> (std::count_if (left.begin (), left.end (), [&] (std::uint32_t i) { return beyond[i]; }));
      return assigned;
    }
  }
}

/** Drop the planes holding fewer than ε samples (Sec. 3.1 keeps none). \return planes dropped */
std::size_t
dropBelowEpsilon (const DetectorParameters& params, std::vector<PlanarPatch>& patches)
{
  const std::size_t before = patches.size ();
  patches.erase (std::remove_if (patches.begin (), patches.end (),
                                 [&] (const PlanarPatch& p) { return p.members.size () < params.min_patch_size; }),
                 patches.end ());
  return before - patches.size ();
}

/** Whether the normals of a grown plane its positions call bent (curvature \a c) do not turn with it
  * (DetectorParameters::judge_normal_turn): a flat face whose quadric bends by chance. */
bool
normalsDenyBend (const PointSet& points, const DetectorParameters& params, const PlanarPatch& patch,
                 const PlaneCurvature& c)
{
  if (!(params.judge_normal_turn > 0.0))
    return false;
  if (c.samples == 0 || isTube (c, patch.mdp))
    return false; // unmeasured, or a tube: judged by isFlatPatch alone
  return normalTurnAcross (points, patch.members, c) < params.judge_normal_turn * 2.0 * c.half_bend;
}

/** The planes noisy seeds seeded, judged once grown: split where two flat planes meeting at an
  * edge explain one that is not flat (DetectorParameters::noisy_bent_split), then every one still
  * not flat, or whose members' estimate fails T2 (DetectorParameters::noisy_grown_t2), dropped, with
  * every plane under \a min_size samples. Each plane's flatness is measured once. */
void
judgeNoisyPlanes (const PointSet& points, const DetectorParameters& params, std::size_t min_size,
                  std::vector<PlanarPatch>& patches, DetectorStatistics& st)
{
  std::vector<char> flat;
  if (params.noisy_bent_split)
    st.noisy_bent_planes += splitBentNoisyPlanes (points, params, patches, &flat);
  else
  {
    flat.resize (patches.size ());
    DetectorParameters judge = params; // see DetectorParameters::judge_bend_confidence
    if (params.bend_confidence > 0.0)
      judge.bend_confidence = params.judge_bend_confidence;
    for (std::size_t p = 0; p < patches.size (); ++p)
    {
      if (!patches[p].retested)
      {
        flat[p] = 1;
        continue;
      }
      const PlaneCurvature c = measureCurvature (points, patches[p].members);
      flat[p] = isFlatPatch (c, judge, patches[p], true) || normalsDenyBend (points, params, patches[p], c);
    }
  }
  if (params.noisy_grown_t2)
    for (std::size_t p = 0; p < patches.size (); ++p)
    {
      // Past T2 the normal test admits half of all directions: the plane has run into clutter or
      // onto the faces around it (bounded_reestimation kept its seed's estimate meanwhile).
      PlaneEstimate grown;
      if (flat[p] && patches[p].retested && estimatePlane (points, patches[p].members, params, grown) &&
          !(grown.mnd () < params.max_normal_deviation))
      {
        flat[p] = 0;
        ++st.noisy_past_t2;
      }
    }
  std::size_t kept = 0;
  for (std::size_t p = 0; p < patches.size (); ++p)
  {
    if (!flat[p] || patches[p].members.size () < min_size)
      continue;
    if (kept != p)
      patches[kept] = std::move (patches[p]);
    ++kept;
  }
  patches.resize (kept);
}

/** The noisy seeds' planes judged flat that are where a volume of samples ends, not surfaces (volume
  * layers, departure; see DetectorParameters::volume_layer_check): dropped, their members left to no
  * plane. */
void
dropNoisyVolumeLayers (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                       std::vector<PlanarPatch>& patches, DetectorStatistics& st)
{
  const bool any_noisy = std::any_of (patches.begin (), patches.end (),
                                      [] (const PlanarPatch& p) { return p.retested || p.joined; });
  if (params.volume_layer_check && any_noisy) // the bands read every member: only when one is judged
    st.volume_layers += dropVolumeLayers (points, graph, noiseBands (points, params, patches), params.num_threads, patches);
}

/** Whether a plane is a facet of a curved surface or a tube (departure, see
  * DetectorParameters::min_curvature_share, curved_tube_check). \a tube is set when it is a tube. */
bool
isCurvedFacet (const PointSet& points, const DetectorParameters& params, const PlanarPatch& patch, bool& tube)
{
  const std::vector<std::uint32_t>& members = patch.members;
  const PlaneCurvature c = measureCurvature (points, members);
  tube = params.curved_tube_check && isTube (c, patch.mdp);
  if (tube)
    return true;
  const bool bent = isCurvedPatch (c, patch.mnd, params) ||
                    (params.curved_normal_turn &&
                     isCurvedByNormals (c, normalTurnAcross (points, members, c), patch.mnd, params));
  if (!bent)
    return false;
  // The fold ratio keeps a plane for the bent-plane split, which cuts sides of ε samples each: one
  // of fewer than 2ε samples that bends beyond chance at the normals' path's confidence is no such
  // fold (DetectorParameters::curved_fold_two_sides).
  const bool too_small_to_fold = params.curved_fold_two_sides && members.size () < 2 * params.min_patch_size &&
                                 c.share >= chanceBendShare (c.samples, params.curved_turn_confidence);
  return too_small_to_fold || normalTurnRatio (points, members, c) < params.curved_fold_ratio;
}

/** Drop every plane that is a facet of a curved surface (isCurvedFacet); with \a judged, only the
  * planes it marks are judged, and it is kept in step with the planes kept. \a tubes counts the tubes
  * dropped. \return planes dropped */
std::size_t
dropCurvedPlanes (const PointSet& points, const DetectorParameters& params, std::vector<PlanarPatch>& patches,
                  std::size_t& tubes, std::vector<char>* judged = nullptr)
{
  std::vector<char> curved (patches.size (), 0);
  std::vector<char> tube (patches.size (), 0);
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (patches.size ());
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolveThreads (params.num_threads))
  for (std::ptrdiff_t p = 0; p < count; ++p)
  {
    if (judged && !(*judged)[p])
      continue;
    bool is_tube = false;
    curved[p] = isCurvedFacet (points, params, patches[p], is_tube);
    tube[p] = is_tube;
  }
  std::size_t dropped = 0;
  std::size_t kept = 0;
  for (std::size_t p = 0; p < patches.size (); ++p)
  {
    if (curved[p])
    {
      ++dropped;
      tubes += tube[p];
      continue;
    }
    if (kept != p)
    {
      patches[kept] = std::move (patches[p]);
      if (judged)
        (*judged)[kept] = (*judged)[p];
    }
    ++kept;
  }
  patches.resize (kept);
  if (judged)
    judged->resize (kept);
  return dropped;
}

/** Drop the seeds whose MND is an outlier among all seeds of the split (departure, see
  * DetectorParameters::drop_outlier_seeds): log MND above median + α·MAD of the seeds' log MND.
  * \return seeds dropped */
std::size_t
dropOutlierSeeds (const DetectorParameters& params, std::vector<PlanarPatch>& seeds, std::vector<PlanarPatch>* dropped)
{
  // Log scale: normal noise differs by factors across a scene (near and far, smooth and rough),
  // and a factor is what the robust spread should be measured in. MND below the normal-deviation
  // floor is rounding, not noise: it is floored before the log (on exact normals 1e-7 and 1e-5 rad
  // would otherwise be a factor of 100 apart), and the limit is widened by the floor (on a
  // noise-free box most seeds sit at the floor, MAD = 0, and a face whose normals round 1e-4 rad
  // differently would be all "outliers").
  const double floor = std::max (params.normal_deviation_floor, 1e-12);
  const auto log_mnd = [floor] (const PlanarPatch& p) { return std::log (std::max (p.mnd, floor)); };
  std::vector<double> logs;
  logs.reserve (seeds.size ());
  for (const auto& p : seeds)
    logs.push_back (log_mnd (p));
  const RobustSpread spread = robustSpreadInPlace (logs);
  const double limit = std::exp (spread.median + params.alpha * spread.mad) + params.normal_deviation_floor;
  const std::size_t before = seeds.size ();
  const auto outlier = [&] (const PlanarPatch& p) { return p.mnd > limit; };
  if (dropped)
    for (const auto& p : seeds)
      if (outlier (p))
        dropped->push_back (p);
  seeds.erase (std::remove_if (seeds.begin (), seeds.end (), outlier), seeds.end ());
  return before - seeds.size ();
}

/** Departure (far members), see DetectorParameters::release_far_members: members farther from their
  * plane's last estimate than its noise band leave it. \return (sample, a member its plane keeps)
  * per sample released, in patch order */
std::vector<std::pair<std::uint32_t, std::uint32_t>>
releaseFarMembers (const PointSet& points, const DetectorParameters& params, std::vector<PlanarPatch>& patches)
{
  const std::vector<double> band = noiseBands (points, params, patches);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> released;
  for (std::size_t l = 0; l < patches.size (); ++l)
  {
    PlanarPatch& patch = patches[l];
    std::vector<std::uint32_t> kept, far;
    kept.reserve (patch.members.size ());
    for (const auto m : patch.members)
      (std::abs ((points.points[m].cast<double> () - patch.center).dot (patch.normal)) <= band[l] ? kept : far).push_back (m);
    if (far.empty () || kept.empty ())
      continue;
    for (const auto m : far)
      released.emplace_back (m, kept.front ());
    patch.members.swap (kept);
  }
  return released;
}

/** Departure (released planes), see DetectorParameters::seed_released_planes: the released samples
  * that no plane took, joined by graph edges (either direction) into groups; a group of at least ε
  * samples that passes T1-T3 (or, failing only T3, whose inliers do, as the rim-cell retest) becomes a
  * plane, unless it lies on a neighbouring plane (DetectorParameters::released_layer_check). Groups in
  * order of their lowest sample. \return planes added */
std::size_t
seedReleasedPlanes (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                    const std::vector<std::pair<std::uint32_t, std::uint32_t>>& released,
                    std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels)
{
  std::vector<std::uint32_t> open;
  for (const auto& r : released)
    if (labels[r.first] == kNoPatch)
      open.push_back (r.first);
  std::sort (open.begin (), open.end ());
  // Groups over positions in open; UnionFind's root is a group's lowest position, so groups come in
  // order of their lowest sample.
  UnionFind sets (open.size ());
  for (std::uint32_t t = 0; t < open.size (); ++t)
    graph.forEachNeighbor (open[t], [&] (std::uint32_t j) {
      const auto it = std::lower_bound (open.begin (), open.end (), j);
      if (it != open.end () && *it == j)
        sets.unite (t, static_cast<std::uint32_t> (it - open.begin ()));
    });
  std::vector<std::vector<std::uint32_t>> groups (open.size ());
  for (std::uint32_t t = 0; t < open.size (); ++t)
    groups[sets.find (t)].push_back (open[t]);
  std::size_t added = 0;
  for (auto& group : groups)
  {
    if (group.size () < params.min_patch_size)
      continue;
    PlanarityResult test = robustPlanarityTest (points, group, params);
    if (test.verdict == PlanarityVerdict::TooManyOutliers)
      test = robustPlanarityTest (points, intervalInliers (points, group, test.estimate), params);
    if (test.verdict != PlanarityVerdict::Planar)
      continue;
    PlanarPatch plane;
    plane.members = std::move (test.inliers);
    std::sort (plane.members.begin (), plane.members.end ());
    plane.first_index = plane.members.front ();
    plane.setEstimate (test.estimate);
    if (params.released_layer_check && liesOnNeighbourPlane (points, graph, patches, labels, plane))
      continue; // a strip of a plane beside it, whose normals bend at the edge (see the parameter)
    for (const auto i : plane.members)
      labels[i] = static_cast<std::uint32_t> (patches.size ());
    patches.push_back (std::move (plane));
    ++added;
  }
  return added;
}

/** The rest of the far-member departure: growth restricted to the \a released samples (in rounds
  * that read the round before, each joins the neighbouring plane whose inlier test of Sec. 3.3 it
  * passes, nearest relative to MDP), then a released sample that no plane took and no other plane
  * borders goes back to the plane of its anchor (a member that plane kept). \return samples given back */
std::size_t
offerReleasedSamples (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                      const std::vector<std::pair<std::uint32_t, std::uint32_t>>& released,
                      std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels, std::size_t& seeded)
{
  std::vector<std::uint32_t> open;
  for (const auto& r : released)
    open.push_back (r.first);
  std::vector<std::uint32_t> choice (open.size ());
  for (;;)
  {
#pragma omp parallel for schedule(dynamic, 256) num_threads(resolveThreads (params.num_threads))
    for (std::ptrdiff_t j = 0; j < static_cast<std::ptrdiff_t> (open.size ()); ++j)
    {
      const std::uint32_t i = open[j];
      const Eigen::Vector3d p = points.points[i].cast<double> ();
      choice[j] = kNoPatch;
      double best = HUGE_VAL;
      graph.forEachNeighbor (i, [&] (std::uint32_t n) {
        const std::uint32_t l = labels[n];
        if (l == kNoPatch || !patches[l].isInlier (points.points[i], points.normals[i]))
          return;
        const double r = std::abs ((p - patches[l].center).dot (patches[l].normal)) / patches[l].mdp;
        if (r < best || (r == best && l < choice[j]))
        {
          best = r;
          choice[j] = l;
        }
      });
    }
    if (applyChoices (open, choice, patches, labels) == 0)
      break;
  }
  seeded = params.seed_released_planes ? seedReleasedPlanes (points, graph, params, released, patches, labels) : 0;
  std::size_t restored = 0;
  for (const auto& [sample, anchor] : released)
  {
    const std::uint32_t home = labels[anchor];
    if (labels[sample] != kNoPatch || home == kNoPatch)
      continue;
    bool bordered = false;
    graph.forEachNeighbor (sample, [&] (std::uint32_t j) {
      bordered = bordered || (labels[j] != kNoPatch && labels[j] != home);
    });
    if (bordered)
      continue; // left to the last assignment, which weighs both planes
    labels[sample] = home;
    patches[home].members.push_back (sample);
    ++restored;
  }
  return restored;
}

/** Sec. 3.5: grow, merge and re-estimate until no patch needs an update (or the cap). */
void
growMergeUntilStable (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                      std::vector<PlanarPatch>& patches, std::vector<std::uint32_t>& labels,
                      std::vector<std::uint8_t>& flags, DetectorStatistics& st, const PointSet* trimmed = nullptr)
{
  MergeRules rules;
  rules.coplanar = params.coplanar_merge;
  rules.max_outlier_ratio = params.max_outlier_ratio;
  rules.num_threads = params.num_threads;
  for (;;)
  {
    if (st.iterations >= params.max_iterations)
    {
      st.hit_iteration_cap = true;
      PCL_WARN ("[pcl::rspd::detectPlanes] stopped after %d grow-merge iterations with patches still "
                "unstable\n", st.iterations);
      return;
    }
    ++st.iterations;
    growPatches (points, graph, patches, labels, &flags, trimmed);
    st.merges += mergePatches (points, graph, patches, labels, &flags, rules);
    std::size_t kept = 0;
    const std::size_t updated = reestimateGrownPatches (points, params, patches, &kept, trimmed);
    st.kept_estimates += kept;
    st.reestimations += updated;
    if (updated == 0)
      return;
  }
}

/** Trimmed normals for what growth left (departure, DetectorParameters::left_normal_refit): a copy
  * of \a points in which the samples \a left have the normal of their k-neighbourhood's reweighted
  * trimmed plane. \return samples refitted */
std::size_t
refitLeftNormals (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
                  const std::vector<std::uint32_t>& left, PointSet& refitted)
{
  refitted = points;
  TrimmedNormalStatistics stats;
  refineNormalsTrimmed (refitted.points, graph, params.num_threads, refitted.normals, &stats, &left);
  return stats.refined;
}
} // namespace

void
detectPlanes (const PointSet& points, const NeighborGraph& graph, const DetectorParameters& params,
              std::vector<DetectedPatch>& result, DetectorStatistics* stats)
{
  result.clear ();
  DetectorStatistics local;
  DetectorStatistics& st = stats ? *stats : local;
  // The caller's stages (before detection) are kept; the rest is this run's.
  DetectorStatistics before = st;
  st = DetectorStatistics ();
  st.prepare_seconds = before.prepare_seconds;
  st.graph_seconds = before.graph_seconds;
  st.graph_bytes = before.graph_bytes;
  st.normals_seconds = before.normals_seconds;
  st.given_normals_replaced = before.given_normals_replaced;
  st.given_normals_blurred = before.given_normals_blurred;
  st.edge_narrowed_normals = before.edge_narrowed_normals;
  st.depth_levels = before.depth_levels;
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now ();

  // Split (Sec. 3.1).
  std::vector<PlanarPatch> joined; // groups of thick cells (join_thick_cells): seeds once growth is stable
  std::vector<PlanarPatch> patches = splitPhase (points, params, &st, nullptr, false, nullptr, &joined);
  std::vector<std::uint32_t> labels = labelSamples (points.size (), patches);
  std::vector<PlanarPatch> outlier_seeds;
  if (params.drop_outlier_seeds && patches.size () >= 3)
  {
    st.outlier_seeds = dropOutlierSeeds (params, patches, params.retest_outlier_seeds ? &outlier_seeds : nullptr);
    labels = labelSamples (points.size (), patches);
  }
  const auto t1 = Clock::now ();
  st.split_seconds = std::chrono::duration<double> (t1 - t0).count ();

  // Each pass's wall time from the end of the last (DetectorStatistics::pass_seconds).
  auto last = t1;
  const auto lap = [&] (const char* pass) {
    const auto now = Clock::now ();
    const double seconds = std::chrono::duration<double> (now - last).count ();
    last = now;
    for (auto& entry : st.pass_seconds)
      if (entry.first == pass)
      {
        entry.second += seconds;
        return;
      }
    st.pass_seconds.emplace_back (pass, seconds);
  };

  // Grow and merge until no patch needs an update (Sec. 3.3-3.5).
  std::vector<std::uint8_t> flags (points.size (), 0); // see SampleFlag
  growMergeUntilStable (points, graph, params, patches, labels, flags, st);
  lap ("grow-merge");

  if (!joined.empty ())
  {
    // Groups of thick cells (departure, see DetectorParameters::join_thick_cells), on what growth
    // left of them: a group is noisier than the cells seeded, and seeded with them it competed with
    // their growth (synpeb_pc01 0.9149 -> 0.9115, one more fragment, and rotations moved it by 0.008).
    st.joined_seeds = seedThickGroups (points, graph, params, joined, patches, labels);
    if (st.joined_seeds > 0)
      growMergeUntilStable (points, graph, params, patches, labels, flags, st);
  }

  lap ("thick-cell groups");
  if (!outlier_seeds.empty () && !patches.empty ())
  {
    // Outlier seeds, tested again (departure, see DetectorParameters::retest_outlier_seeds) on
    // what growth left of them; before the small-plane pass, whose seeds may be as noisy as they.
    std::vector<double> band = noiseBands (points, params, patches);
    const auto flat = [&] (PlanarPatch& plane) {
      plane.retested = true; // judged again once grown
      return isFlatPatch (points, params, plane, false);
    };
    for (const auto& seed : outlier_seeds)
      st.retested_seeds += seedLeftSamples (points, graph, params, seed.members, flat, patches, band, labels);
  }
  lap ("outlier seeds");
  std::vector<PlanarPatch> joined_left; // the small-plane pass's groups of thick cells
  PointSet refitted;                    // trimmed or narrowed normals of what growth left (left_normal_refit, left_normal_narrow)
  bool trimmed_seeds = false;           // a seed found on them grows on them (trimmed_seed_growth)
  bool shifted_seeds = false;           // the shifted grid seeded a plane: judged once grown
  if (params.small_cell_size > 0 && params.small_cell_size <= params.min_patch_size && !patches.empty ())
  {
    // Small-cell pass (departure, see DetectorParameters::small_cell_size): on the PCA normals, then
    // on the trimmed (left_normal_refit) or narrowed (left_normal_narrow) normals of the samples
    // still left; each split also on the shifted grid (shifted_small_grid).
    // The noisiest plane grown, the noisiest plane a noisy seed seeded (a retested outlier seed,
    // not grown yet, or a thick-cell group), and the tightest plane grown: a small seed's MND floor.
    // ... and the thickest (MDP) plane grown, which bounds the seeds on trimmed normals.
    double max_mnd = 0.0, max_retested_mnd = 0.0, min_mnd = HUGE_VAL, max_mdp = 0.0;
    std::vector<double> mnds; // of the planes grown: their median bounds the shifted grid's seeds
    for (const auto& p : patches)
    {
      max_mdp = std::max (max_mdp, p.mdp);
      // A noisy seed's plane (retested, or a thick-cell group) lets in only seeds as flat as it.
      const bool noisy = p.retested || p.joined;
      double& bound = noisy ? max_retested_mnd : max_mnd;
      bound = std::max (bound, p.mnd);
      if (!noisy)
      {
        min_mnd = std::min (min_mnd, p.mnd);
        mnds.push_back (p.mnd);
      }
    }
    const double median_mnd = mnds.empty () ? HUGE_VAL : medianInPlace (mnds);
    std::vector<double> band = noiseBands (points, params, patches);
    DetectorParameters small = params;
    small.min_patch_size = params.small_cell_size;
    if (params.narrowed_cell_size > 0 && params.narrowed_cell_size < params.small_cell_size &&
        points.narrowed.size () == points.size ())
    {
      // Edge-aware normals: smaller cells only where the normals resolve faces that small.
      small.min_patch_size = params.narrowed_cell_size;
      small.coarse_cell_size = params.small_cell_size;
    }
    const bool second_split = params.left_normal_refit || params.left_normal_narrow;
    for (int round = 0; round < (second_split ? 2 : 1); ++round)
    {
      std::vector<std::uint32_t> left;
      for (std::uint32_t i = 0; i < labels.size (); ++i)
        if (labels[i] == kNoPatch)
          left.push_back (i);
      if (round == 1)
      {
        if (left.empty ())
          break;
        if (params.left_normal_refit)
          st.left_refitted = refitLeftNormals (points, graph, params, left, refitted);
        else
        {
          refitted = points;
          st.left_refitted = narrowNormalsAtEdges (points.points, graph, params.num_threads, kMinAutomaticNeighbours,
                                                   refitted.normals, nullptr, &left);
        }
      }
      const PointSet& round_points = round == 0 ? points : refitted;
      // On the left samples' narrowed or trimmed normals a rim cell's inliers may be as few as the
      // faces narrowed normals resolve (DetectorParameters::left_rim_retest).
      small.rim_retest_min_size = round == 1 && params.left_rim_retest
                                      ? static_cast<std::size_t> (kMinAutomaticNeighbours) + 1
                                      : 0;
      std::size_t rim_seeds = 0;
      // Groups of thick cells on the PCA normals only: they seed once the pass's growth is stable.
      const double thick_bound = std::max (max_mnd, max_retested_mnd);
      std::vector<PlanarPatch> seeds = splitPhase (round_points, small, &st, &left, params.rim_cell_retest, &rim_seeds,
                                                   params.small_cell_thick_join && round == 0 ? &joined_left : nullptr,
                                                   thick_bound);
      st.rim_seeds += rim_seeds;
      const std::size_t first_grid_seeds = seeds.size ();
      if (params.shifted_small_grid)
      {
        // The shifted grid (DetectorParameters::shifted_small_grid) over what the first grid's seeds
        // left; only seeds as clean as the planes found.
        std::vector<char> taken (points.size (), 0);
        for (const auto& seed : seeds)
          for (const auto i : seed.members)
            taken[i] = 1;
        std::vector<std::uint32_t> untaken;
        untaken.reserve (left.size ());
        for (const auto i : left)
          if (!taken[i])
            untaken.push_back (i);
        std::size_t shifted_rim_seeds = 0;
        for (auto& seed : splitPhase (round_points, small, &st, &untaken, params.rim_cell_retest, &shifted_rim_seeds,
                                      nullptr, thick_bound, true))
          if (seed.mnd <= std::min (max_mnd, kShiftedSeedMndRatio * median_mnd) && seed.mdp <= max_mdp)
            seeds.push_back (std::move (seed));
        st.rim_seeds += shifted_rim_seeds;
      }
      std::vector<PlanarPatch> too_noisy; // turned down alone; joined below (noisy_seed_groups)
      for (std::size_t seed_index = 0; seed_index < seeds.size (); ++seed_index)
      {
        PlanarPatch& seed = seeds[seed_index];
        const bool shifted = seed_index >= first_grid_seeds;
        // Trimmed normals of scattered samples agree by chance: each is the plane of half a
        // neighbourhood. Such a seed is a slab, thicker than any plane grown (the facade at 10,000
        // points on PCL's k = 50 normals: 79 samples, three in four outliers, MND 24° within the
        // facade's 34°, MDP 0.80 m).
        if (round == 1 && seed.mdp > max_mdp)
          continue;
        if (seed.mnd > max_mnd && (seed.mnd > max_retested_mnd || !isFlatPatch (round_points, params, seed, false)))
        {
          // Noisier than every plane found: an edge band of bent normals, not a plane, or a piece of
          // a plane rougher than any found, which only a group of such seeds can tell.
          if (params.noisy_seed_groups && round == 0)
            too_noisy.push_back (std::move (seed));
          continue;
        }
        bool beside = false;
        if (isBandLayer (round_points, graph, params, patches, band, labels, seed, &beside))
          continue; // a layer of a found plane's noise band: its rim beside a step, or a duplicate
        for (const auto i : seed.members)
          labels[i] = static_cast<std::uint32_t> (patches.size ());
        if (params.small_seed_mnd_floor && std::isfinite (min_mnd) && seed.mnd < min_mnd)
        {
          seed.mnd = min_mnd; // see DetectorParameters::small_seed_mnd_floor
          seed.cos_mnd = std::cos (min_mnd);
        }
        // Let in by a retested seed, or found on the shifted grid: judged again once grown.
        seed.retested = seed.mnd > max_mnd || shifted;
        if (round == 1 && params.trimmed_seed_growth)
        {
          // Grown on the trimmed normals, it takes the strip of a neighbouring face along their edge
          // whose trimmed normals are its own, which a judge of its grown plane reads as a bend (the
          // boxes at 100,000 points on PCL's k = 50 normals: a 685-sample side grown to 645 with 35
          // samples of two neighbours, dropped whole); edge sides settle the strip, and the curved
          // check judges facets of curved surfaces.
          seed.trimmed = true;
          seed.retested = false;
          trimmed_seeds = true;
        }
        st.small_seeds_beside += beside;
        patches.push_back (std::move (seed));
        band.push_back (patches.back ().mdp); // its members' spread is not known yet: MDP
        ++st.small_seeds;
        st.small_seeds_trimmed += round;
        st.small_seeds_shifted += shifted;
        shifted_seeds = shifted_seeds || (shifted && patches.back ().retested);
      }
      double noisiest_seeded = 0.0; // MND of the noisiest plane a noisy seed seeded in this round
      // The groups' bounds: the noisiest and thickest plane found, then, step by step on the noise
      // ladder (DetectorParameters::noisy_group_ladder), the noisiest and thickest the last step seeded.
      double group_mnd = std::max (max_mnd, max_retested_mnd), group_mdp = max_mdp;
      for (std::size_t step = 0;; ++step)
      {
        double step_mnd = 0.0, step_mdp = 0.0;
        for (auto& seed : joinNoisySeeds (round_points, graph, params, too_noisy, group_mnd, group_mdp))
        {
          if (isBandLayer (round_points, graph, params, patches, band, labels, seed, nullptr))
            continue;
          for (const auto i : seed.members)
            labels[i] = static_cast<std::uint32_t> (patches.size ());
          seed.retested = true; // noisier than every plane found: judged again once grown
          noisiest_seeded = std::max (noisiest_seeded, seed.mnd);
          if (seed.members.size () >= params.min_patch_size)
          {
            // Only a plane by the paper's size rule (ε) raises the bound: climbing on smaller seeds,
            // the room with 10 % outliers (seed 2) reached the noise of its pillar's facets, which
            // became two false planes (samples 0.29-0.35 m from the pillar's axis, radius 0.3 m).
            step_mnd = std::max (step_mnd, seed.mnd);
            step_mdp = std::max (step_mdp, seed.mdp);
          }
          patches.push_back (std::move (seed));
          band.push_back (patches.back ().mdp);
          ++st.small_seeds;
          ++st.small_noisy_groups;
          st.small_ladder_seeds += step > 0;
        }
        // Each step climbs only above the last (MND grows strictly, so the ladder ends), on the
        // planes of ε samples or more it seeded; the seeds left are those whose samples no plane took.
        if (!params.noisy_group_ladder || !(step_mnd > group_mnd) || step + 1 >= kLadderSteps)
          break;
        group_mnd = step_mnd;
        group_mdp = std::max (group_mdp, step_mdp);
        too_noisy.erase (std::remove_if (too_noisy.begin (), too_noisy.end (),
                                         [&] (const PlanarPatch& p) {
                                           return std::any_of (p.members.begin (), p.members.end (),
                                                               [&] (std::uint32_t i) { return labels[i] != kNoPatch; });
                                         }),
                         too_noisy.end ());
        if (too_noisy.empty ())
          break;
      }
      if (round == 0 && params.small_cell_thick_join && params.thick_cells_follow_noisy_seeds && noisiest_seeded > thick_bound)
      {
        // See DetectorParameters::thick_cells_follow_noisy_seeds: the same cells, kept as thick up to
        // the MND of the noisiest plane seeded (the seeds' own statistics are not counted again).
        joined_left.clear ();
        splitPhase (round_points, small, nullptr, &left, params.rim_cell_retest, nullptr, &joined_left, noisiest_seeded);
        ++st.thick_rebound;
      }
    }
  }
  if (st.small_seeds > 0 || st.retested_seeds > 0)
  {
    growMergeUntilStable (points, graph, params, patches, labels, flags, st, trimmed_seeds ? &refitted : nullptr);
    refitted = PointSet (); // read by that grow-merge alone
    if (params.small_plane_completion)
      st.small_completed = completeSmallPlanes (points, graph, params, patches);
    dropBelowEpsilon (params, patches);
  }
  if (st.retested_seeds > 0 || st.joined_seeds > 0 || st.small_noisy_groups > 0 || shifted_seeds ||
      st.small_completed > 0)
  {
    // A plane an outlier seed, a group of thick cells, a group of noisy small seeds or the shifted
    // grid seeded, or that the small-plane completion completed by position: grown, it has the
    // samples its seed may have lacked to show a bend, and it must still be flat (at 10,000 points
    // a pipe is sampled a few times around, and its facets' seeds are too small to tell; at 20,000
    // the room's ball gave the shifted grid a facet of 26 samples; a depth camera's dithered view of
    // the room, an 18-sample seed completed with 112 samples, measured).
    judgeNoisyPlanes (points, params, 0, patches, st);
    dropNoisyVolumeLayers (points, graph, params, patches, st);
    labels = labelSamples (points.size (), patches);
  }
  if (!joined_left.empty () && !patches.empty ())
  {
    // Groups of the small-plane pass's thick cells (see DetectorParameters::small_cell_thick_join),
    // on what the pass's growth left of them, as the first split's groups (no MND bound: a group
    // joins cells along its plane's rims, where normals bend). Seeded with the pass's seeds, a strip
    // of an edge band between a riser's small seed and its treads joined the riser, whose plane
    // the bend of those members then dropped whole (the staircase at 50,000 points, seed 5).
    labels = labelSamples (points.size (), patches);
    st.small_joined_seeds = seedThickGroups (points, graph, params, joined_left, patches, labels);
    st.small_seeds += st.small_joined_seeds;
    if (st.small_joined_seeds > 0)
    {
      growMergeUntilStable (points, graph, params, patches, labels, flags, st);
      judgeNoisyPlanes (points, params, params.min_patch_size, patches, st);
      dropNoisyVolumeLayers (points, graph, params, patches, st);
      labels = labelSamples (points.size (), patches);
    }
  }

  lap ("small planes");
  if (params.release_far_members && !patches.empty ())
  {
    // Far members (departure, see DetectorParameters::release_far_members): released, offered to
    // the neighbouring planes, and given back where no other plane took or borders them.
    const auto released = releaseFarMembers (points, params, patches);
    st.released = released.size ();
    if (!released.empty ())
    {
      labels = labelSamples (points.size (), patches);
      st.restored = offerReleasedSamples (points, graph, params, released, patches, labels, st.released_planes);
    }
  }

  lap ("far members");
  if (params.connected_parts && !patches.empty ())
  {
    // Connected parts (departure, see DetectorParameters::connected_parts).
    labels = labelSamples (points.size (), patches);
    st.split_planes = splitDisconnectedPlanes (points, graph, params, patches, labels);
  }

  lap ("connected parts");
  if (params.curved_plane_check)
    st.curved_planes = dropCurvedPlanes (points, params, patches, st.curved_tubes);

  lap ("curved check");
  if (params.bent_plane_split && !patches.empty ())
  {
    // Bent planes (departure, see DetectorParameters::bent_plane_split); after the curved check,
    // which judges whole facets of a curved surface, not the parts a split would leave.
    std::vector<char> split;
    st.bent_planes = splitBentPlanes (points, params, patches, &split);
    if (params.curved_plane_check && params.curved_split_parts && st.bent_planes > 0)
      // The parts judged as planes are (DetectorParameters::curved_split_parts), before the join,
      // which would make a facet whole again.
      st.curved_parts = dropCurvedPlanes (points, params, patches, st.curved_tubes, &split);
    st.bent_joined = joinSplitFaces (points, graph, params, patches, split);
  }

  lap ("bent planes");
  if (params.step_split && !patches.empty ())
    // Step split (departure, see DetectorParameters::step_split): on planes already cut at their
    // edges, and before the passes that assign and move samples by each plane's noise band.
    // Until none splits: a call splits one region off each plane, and a wall whose band took
    // several recessed windows holds a step at each.
    for (std::size_t split = splitSteps (points, graph, params, patches); split > 0;
         split = splitSteps (points, graph, params, patches))
      st.steps_split += split;

  lap ("step split");
  if (params.layer_merge && patches.size () >= 2)
  {
    // Layers of one plane's noise band (departure, see DetectorParameters::layer_merge); passes until
    // none merges (each removes a plane), the bands measured again on the planes estimated again.
    for (;;)
    {
      labels = labelSamples (points.size (), patches);
      const std::size_t merged = mergeBandLayers (points, graph, params, noiseBands (points, params, patches), patches, labels);
      st.layers_merged += merged;
      if (merged == 0)
        break;
    }
  }

  if (params.across_step_check)
    // Planes across a step (departure, see DetectorParameters::across_step_check): once the far
    // members released have made the door a plane of its own, and the layers are merged.
    st.across_steps = dropPlanesAcrossSteps (points, graph, params, patches);
  lap ("layer merge");
  // Final refit (departure, see DetectorParameters::final_refit): the passes below judge samples by
  // their distance to each plane, which its least-squares plane gives better than its robust estimate.
  if (params.final_refit)
    refitPlanes (points, params.num_threads, patches);
  if (params.final_volume_layer_check && !patches.empty ())
    // Final volume layers (departure, see DetectorParameters::final_volume_layer_check): on the
    // refitted planes, before the last assignment gives their tails to the planes that stay.
    st.final_volume_layers = dropVolumeLayers (points, graph, noiseBands (points, params, patches), params.num_threads,
                                               patches, true, 0, params.in_band_layer_check, &st.in_band_layers,
                                               params.flat_layers);
  lap ("final refit");
  if (params.final_assignment != FinalAssignment::None && !patches.empty ())
  {
    labels = labelSamples (points.size (), patches); // the small-plane pass may have dropped patches
    st.assigned = assignRemainingSamples (points, graph, params, patches, labels, st.member_gap_refused);
  }
  lap ("last assignment");
  if (params.curved_plane_check && params.late_curved_check && !patches.empty ())
    // Late curved check (departure, see DetectorParameters::late_curved_check): with their tails,
    // facets show the bend their bands cut off.
    st.late_curved_planes = dropCurvedPlanes (points, params, patches, st.curved_tubes);
  lap ("late curved check");
  if (params.position_planes && !patches.empty ())
  {
    // Position planes (departure, see DetectorParameters::position_planes), as noisy as the noisiest
    // plane found at most; then their tails as the last assignment's.
    labels = labelSamples (points.size (), patches);
    const std::vector<double> median = medianDistances (points, params, patches);
    double noise = 0.0;
    for (const double m : median)
      if (std::isfinite (m))
        noise = std::max (noise, kMadScale * m);
    const std::size_t found_before = patches.size ();
    st.position_planes = seedPositionPlanes (points, graph, params, noise, bandsOf (patches, median, kBandSigmas),
                                             patches, labels);
    if (params.final_volume_layer_check && patches.size () > found_before)
    {
      // Judged as the planes before them were (final volume layers): the outliers a dropped plane
      // left are found again by position (a unit plane at σ 1 cm in a slab of 40 % outliers).
      st.final_volume_layers += dropVolumeLayers (points, graph, noiseBands (points, params, patches), params.num_threads,
                                                  patches, true, found_before, params.in_band_layer_check,
                                                  &st.in_band_layers, params.flat_layers);
      labels = labelSamples (points.size (), patches);
    }
    if (patches.size () > found_before && params.final_assignment != FinalAssignment::None)
      st.assigned += assignRemainingSamples (points, graph, params, patches, labels, st.member_gap_refused);
  }
  lap ("position planes");
  if (params.edge_sides && patches.size () >= 2)
  {
    labels = labelSamples (points.size (), patches);
    const EdgeSideCounts c = settleEdgeSides (points, graph, noiseBands (points, params, patches),
                                              params.num_threads, patches, labels, params.edge_corners,
                                              params.edge_wedges);
    st.edge_moved = c.moved;
    st.edge_cornered = c.cornered;
    st.edge_outside = c.outside;
    st.edge_released = c.released;
    patches.erase (std::remove_if (patches.begin (), patches.end (),
                                   [] (const PlanarPatch& p) { return p.members.empty (); }),
                   patches.end ());
  }

  lap ("edge sides");
  if ((params.step_sides || params.step_regions) && patches.size () >= 2)
  {
    labels = labelSamples (points.size (), patches);
    if (params.step_regions)
      // Regions first (departure, see DetectorParameters::step_regions): they move blocks the
      // per-sample rule leaves, and that rule, asked within the bands too, then settles their rims.
      // Until none moves; a region that moved may leave the next one beside the parallel plane.
      for (int pass = 0; pass < kStepSidePasses; ++pass)
      {
        const std::size_t moved = settleStepRegions (points, graph, noiseBands (points, params, patches), params.num_threads,
                                                     patches, labels);
        st.step_region_moved += moved;
        if (moved == 0)
          break;
      }
    // Each pass lets the samples whose neighbours the last one moved follow; a majority rule settles
    // in a few (the facade at σ = 5 cm: 4,104, 875, then 85 over two more); the cap guards a cycle.
    // Bands are measured again each pass: a plane that held the other's samples had a wider one, which
    // may have hidden the step (the facade at σ = 5 cm: F1 0.970 with the first pass's bands kept).
    for (int pass = 0; params.step_sides && pass < kStepSidePasses; ++pass)
    {
      const std::size_t moved = settleStepSides (points, graph, noiseBands (points, params, patches),
                                                 params.num_threads, patches, labels, params.step_regions);
      st.step_moved += moved;
      if (moved == 0)
        break;
    }
    patches.erase (std::remove_if (patches.begin (), patches.end (),
                                   [] (const PlanarPatch& p) { return p.members.empty (); }),
                   patches.end ());
  }

  lap ("step sides");
  // A plane holds ε samples (Sec. 3.1). Growth only adds, but the passes after it move samples
  // between planes: the staircase at 15,000 points (seed 15) on PCL's k = 50 normals kept a plane of
  // one sample, what the edge and step sides left of a tread's second plane, cut from a plane bent
  // over the riser below. What is left of such a plane is no plane. Asked before the plane support
  // releases the samples beyond a plane's rim: a sparse face beside a dense one loses rim samples
  // there that are its own (room layout 6: the cabinet's top, 205 samples for ε = 200, lost 9).
  st.below_epsilon = dropBelowEpsilon (params, patches);
  lap ("eps rule");
  if (params.support_check && !patches.empty ())
  {
    // Plane support (departure, see DetectorParameters::support_check): last, so that it judges
    // the samples every pass before it admitted.
    labels = labelSamples (points.size (), patches);
    st.unsupported = releaseUnsupportedMembers (points, graph, noiseBands (points, params, patches),
                                                params.num_threads, patches, labels, params.support_clutter,
                                                &st.clutter_released);
  }
  lap ("plane support");
  if (params.final_parts && !patches.empty ())
  {
    // Final parts (departure, see DetectorParameters::final_parts): on the members every pass left.
    labels = labelSamples (points.size (), patches);
    st.final_split = splitDisconnectedPlanes (points, graph, params, patches, labels, true, &st.final_strays);
  }
  lap ("final parts");
  if (params.final_refit)
    refitPlanes (points, params.num_threads, patches); // on the final members: the planes returned
  lap ("final refit");

  st.grow_merge_seconds = std::chrono::duration<double> (Clock::now () - t1).count ();

  // Largest first, ties by lowest member index.
  std::sort (patches.begin (), patches.end (), [] (const PlanarPatch& a, const PlanarPatch& b) {
    if (a.members.size () != b.members.size ())
      return a.members.size () > b.members.size ();
    return a.first_index < b.first_index;
  });
  result.reserve (patches.size ());
  for (auto& p : patches)
  {
    DetectedPatch d;
    d.members = std::move (p.members);
    std::sort (d.members.begin (), d.members.end ());
    d.center = p.center;
    d.normal = p.normal;
    d.mdp = p.mdp;
    d.mnd = p.mnd;
    result.push_back (std::move (d));
  }
}

} // namespace rspd
} // namespace pcl
