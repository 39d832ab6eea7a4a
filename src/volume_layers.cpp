/*
 * pcl_rspd: volume layers (see volume_layers.h).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/normal_estimation.h>  // resolveThreads
#include <pcl_rspd/patch_growth.h>      // labelSamples, kNoPatch
#include <pcl_rspd/robust_statistics.h> // medianInPlace
#include <pcl_rspd/volume_layers.h>

#include <Eigen/Geometry> // cross, unitOrthogonal

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace pcl
{
namespace rspd
{
namespace
{
/** A noisy seed's plane is a volume layer when the layer beside its band holds more than this many
  * times its samples. Samples of one volume, of which the plane holds a share s of its band's (those
  * whose cut neighbourhoods turn their normals across the end), give 1 / (2 s): the facade's slabs of
  * outliers 2.5-6.0 (four planes, three seeds with 25 % outliers at 100,000 points). A layer of one
  * noisy face gives about 1 wherever it lies in the face's noise: the boxes at σ 1 cm, faces at 10
  * and 15 cm held by planes with bands of 9-21 cm, 0.73-1.25 (at 1, one of them was dropped). */
constexpr double kVolumeLayerRatio = 2.0;

/** With the flat layers (DetectorParameters::flat_layers) a final plane is a layer of clutter when
  * the layer beside its band on a side where the next layer holds at least half as many samples
  * holds more than this many times its samples: the density beside the band, half as thick, twice
  * the plane's own. Two faces of a thin wall give about 1 but nothing after the other face; a
  * false plane in a slab of 30-40 % outliers gave 1.2-1.6 (the slab's density runs on flat). */
constexpr double kFlatLayerRatio = 1.0;

/** A plane is a layer inside another's band when that plane is more than this many times as dense
  * within its band over its footprint (isInBandLayer). Faces of like density, one inside the other's
  * band, give about 1 (two faces of a thin wall), and a face's noise shared by two planes that the
  * layer merge has not joined at most about 2; the clutter beside a plane gives the plane's density
  * over the clutter's (a unit plane at σ 1 cm in a slab of 20 % outliers 0.141 thick: 9.4 and 10.9;
  * in 40 % outliers 1 km away, a plane of 17,421 outliers with a band of 8.1 cm over the true plane's
  * 3.2 cm: 3.76 by counts, 9.4 by densities).
  * Over the sweeps' rows and the real scans no final plane exceeded 1.91 by densities (room_scan1:
  * 1.46 by counts, band ratio 1.31; synpeb_pc01 1.64). */
constexpr double kInBandLayerRatio = 4.0;

/** The footprint's cell is the median neighbourhood radius of at most about this many members, evenly
  * strided: a median of thousands is as good as one of all, and reading every member's row cost 0.1 s
  * on the 1M cube once every final plane is judged (DetectorParameters::final_volume_layer_check). */
constexpr std::size_t kRadiusSamples = 4096;
} // namespace

namespace
{
/** The cells, of the members' median neighbourhood radius, that a plane's members occupy on it. */
class Footprint
{
public:
  /** \return false when the plane cannot be judged (no members, a radius zero or not finite) */
  bool
  build (const PointSet& points, const NeighborGraph& graph, const PlanarPatch& plane)
  {
    if (plane.members.empty ())
      return false;
    // The cell: the members' median neighbourhood radius, so that a cell holds a few of them
    // wherever the plane is sampled, however sparsely (a scale of the cloud's own).
    const std::size_t stride = (plane.members.size () + kRadiusSamples - 1) / kRadiusSamples;
    std::vector<double> radii;
    radii.reserve (plane.members.size () / stride + 1);
    for (std::size_t m = 0; m < plane.members.size (); m += stride)
    {
      const std::uint32_t i = plane.members[m];
      const Eigen::Vector3d pi = points.points[i].cast<double> ();
      double r = 0.0;
      graph.forEachNeighbor (i, [&] (std::uint32_t j) { r = std::max (r, (points.points[j].cast<double> () - pi).norm ()); });
      radii.push_back (r);
    }
    cell_ = medianInPlace (radii);
    if (!(cell_ > 0.0) || !std::isfinite (cell_))
      return false;
    center_ = plane.center;
    normal_ = plane.normal;
    u_ = plane.normal.unitOrthogonal ();
    v_ = plane.normal.cross (u_);
    cells_.clear ();
    cells_.reserve (plane.members.size ());
    for (const auto i : plane.members)
    {
      const Eigen::Vector3d q = points.points[i].cast<double> () - center_;
      const double a = q.dot (u_) / cell_, b = q.dot (v_) / cell_;
      lo_u_ = std::min (lo_u_, a);
      hi_u_ = std::max (hi_u_, a);
      lo_v_ = std::min (lo_v_, b);
      hi_v_ = std::max (hi_v_, b);
      cells_.emplace_back (static_cast<std::int64_t> (std::floor (a)), static_cast<std::int64_t> (std::floor (b)));
    }
    std::sort (cells_.begin (), cells_.end ());
    cells_.erase (std::unique (cells_.begin (), cells_.end ()), cells_.end ());
    return true;
  }

  /** \brief The signed distance of \a p to the plane. */
  double
  distance (const Eigen::Vector3d& p) const { return (p - center_).dot (normal_); }

  /** \brief Whether the projection of \a p onto the plane falls in the footprint. */
  bool
  covers (const Eigen::Vector3d& p) const
  {
    const Eigen::Vector3d q = p - center_;
    const double a = q.dot (u_) / cell_, b = q.dot (v_) / cell_;
    if (!(a >= lo_u_ && a <= hi_u_ && b >= lo_v_ && b <= hi_v_)) // outside the members' extent (and no overflow below)
      return false;
    const Cell c (static_cast<std::int64_t> (std::floor (a)), static_cast<std::int64_t> (std::floor (b)));
    return std::binary_search (cells_.begin (), cells_.end (), c);
  }

private:
  using Cell = std::pair<std::int64_t, std::int64_t>;
  double cell_ = 0.0;
  Eigen::Vector3d center_, normal_, u_, v_;
  double lo_u_ = HUGE_VAL, hi_u_ = -HUGE_VAL, lo_v_ = HUGE_VAL, hi_v_ = -HUGE_VAL;
  std::vector<Cell> cells_;
};
} // namespace

LayerCounts
countLayerSamples (const PointSet& points, const NeighborGraph& graph, const PlanarPatch& plane, double band,
                   const std::vector<std::uint32_t>* labels, std::uint32_t self)
{
  LayerCounts counts;
  Footprint footprint;
  if (!(band > 0.0) || !std::isfinite (band) || !footprint.build (points, graph, plane))
    return counts;
  const bool others = labels && labels->size () == points.size ();
  std::vector<std::size_t> in_band; // per other plane, by label
  std::size_t above = 0, below = 0, further_above = 0, further_below = 0;
  for (std::size_t i = 0; i < points.size (); ++i)
  {
    const Eigen::Vector3d p = points.points[i].cast<double> ();
    const double d = footprint.distance (p);
    const double ad = std::abs (d);
    const bool beside = ad > band && ad <= 2.0 * band;
    const bool further = ad > 2.0 * band && ad <= 3.0 * band; // the next layer, for flat_beside
    const std::uint32_t l = others ? (*labels)[i] : kNoPatch;
    const bool other_in_band = ad <= band && l != kNoPatch && l != self;
    if (!(beside || further || other_in_band) || !footprint.covers (p))
      continue;
    if (further)
      ++(d > 0.0 ? further_above : further_below);
    else if (beside)
      ++(d > 0.0 ? above : below);
    else
    {
      if (l >= in_band.size ())
        in_band.resize (static_cast<std::size_t> (l) + 1, 0);
      ++in_band[l];
    }
  }
  counts.beside = std::max (above, below);
  if (2 * further_above >= above)
    counts.flat_beside = above;
  if (2 * further_below >= below)
    counts.flat_beside = std::max (counts.flat_beside, below);
  for (std::size_t l = 0; l < in_band.size (); ++l)
    if (in_band[l] > counts.other_in_band)
    {
      counts.other_in_band = in_band[l];
      counts.other = static_cast<std::uint32_t> (l);
    }
  return counts;
}

std::size_t
clutterBesidePlane (const PointSet& points, const NeighborGraph& graph, const PlanarPatch& plane, double from,
                    double to, const std::vector<std::uint32_t>& labels, const std::vector<std::uint32_t>& open,
                    std::uint32_t self)
{
  Footprint footprint;
  if (!(from >= 0.0 && from < to) || !std::isfinite (to) || labels.size () != points.size () ||
      !footprint.build (points, graph, plane))
    return 0;
  std::size_t above = 0, below = 0;
  for (const auto i : open)
  {
    const Eigen::Vector3d p = points.points[i].cast<double> ();
    const double d = footprint.distance (p);
    const double ad = std::abs (d);
    if (!(ad >= from && ad < to) || !footprint.covers (p))
      continue;
    bool beside_other = false;
    graph.forEachNeighbor (i, [&] (std::uint32_t n) {
      beside_other = beside_other || (labels[n] != kNoPatch && labels[n] != self);
    });
    if (!beside_other)
      ++(d > 0.0 ? above : below);
  }
  return 2 * std::min (above, below);
}

std::size_t
samplesBesideBand (const PointSet& points, const NeighborGraph& graph, const PlanarPatch& plane, double band)
{
  return countLayerSamples (points, graph, plane, band, nullptr, kNoPatch).beside;
}

bool
isInBandLayer (const LayerCounts& counts, std::size_t members, double band, double other_band)
{
  // Densities, not counts: the other plane's samples inside the band fill the thinner of the two
  // bands, the plane's own the whole of its band. Only where that plane holds at least as many there
  // as the plane: one holding fewer lies under a share of the footprint (a small face with a band of
  // micrometres on a wall of office1: 0.05 times the wall's samples, 20 times as dense), and its own
  // band says nothing of the density over the rest.
  const bool spans = counts.other_in_band >= members;
  const double thinner = spans && other_band > 0.0 && other_band < band && std::isfinite (band) ? band / other_band : 1.0;
  return thinner * static_cast<double> (counts.other_in_band) > kInBandLayerRatio * static_cast<double> (members);
}

bool
isInBandLayer (const LayerCounts& counts, const std::vector<PlanarPatch>& patches, const std::vector<double>& band,
               std::size_t self)
{
  return isInBandLayer (counts, patches[self].members.size (), band[self],
                        counts.other < band.size () ? band[counts.other] : 0.0);
}

std::size_t
dropVolumeLayers (const PointSet& points, const NeighborGraph& graph, const std::vector<double>& band,
                  int num_threads, std::vector<PlanarPatch>& patches, bool every_plane, std::size_t first,
                  bool in_band_layers, std::size_t* in_band_dropped, bool flat_layers)
{
  const std::size_t count = patches.size ();
  // 0: kept, 1: a volume layer, 2: a layer inside another plane's band.
  std::vector<char> drop (count, 0);
  const bool in_band = every_plane && in_band_layers;
  const std::vector<std::uint32_t> labels = in_band ? labelSamples (points.size (), patches) : std::vector<std::uint32_t> ();
#pragma omp parallel for schedule(dynamic, 1) num_threads(resolveThreads (num_threads))
  for (std::ptrdiff_t p = static_cast<std::ptrdiff_t> (first); p < static_cast<std::ptrdiff_t> (count); ++p)
  {
    const PlanarPatch& plane = patches[p];
    if (!(every_plane || plane.retested || plane.joined))
      continue;
    const LayerCounts c = countLayerSamples (points, graph, plane, band[p], in_band ? &labels : nullptr,
                                             static_cast<std::uint32_t> (p));
    if (static_cast<double> (c.beside) > kVolumeLayerRatio * static_cast<double> (plane.members.size ()))
      drop[p] = 1;
    else if (every_plane && flat_layers && static_cast<double> (c.flat_beside) > kFlatLayerRatio * static_cast<double> (plane.members.size ()))
      drop[p] = 1;
    else if (in_band && isInBandLayer (c, patches, band, static_cast<std::size_t> (p)))
      drop[p] = 2;
  }
  std::size_t kept = 0, in_band_count = 0;
  for (std::size_t p = 0; p < count; ++p)
  {
    in_band_count += drop[p] == 2 ? 1 : 0;
    if (drop[p])
      continue;
    if (kept != p)
      patches[kept] = std::move (patches[p]);
    ++kept;
  }
  patches.resize (kept);
  if (in_band_dropped)
    *in_band_dropped += in_band_count;
  return count - kept;
}

} // namespace rspd
} // namespace pcl
