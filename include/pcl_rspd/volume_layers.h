/*
 * pcl_rspd: volume layers — a noisy plane that is the boundary layer of a volume of scattered samples
 * rather than a surface (a departure from the paper).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/neighbor_graph.h>
#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/point_set.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief What lies beside and inside a plane's noise band over its footprint (countLayerSamples). */
struct LayerCounts
{
  std::size_t beside = 0;        ///< samplesBesideBand
  std::size_t other_in_band = 0; ///< the most samples one other plane holds inside the band
  std::uint32_t other = 0xffffffffu; ///< that plane's index (0xffffffff, kNoPatch: none)
  std::size_t flat_beside = 0;   ///< the larger beside count of the sides whose next layer, as thick, holds at least half as many
};

/** \brief Samples in the layer beside a plane's noise band, on its denser side, over its footprint.
  *
  * The footprint: the cells, of the members' median neighbourhood radius (the distance to their
  * farthest graph neighbour), that the members' projections onto the plane occupy. The layer: the
  * samples, held by any plane or none, between \a band and 2 \a band from the plane whose projection
  * falls in the footprint, counted on each side; the larger count is returned. 0 when the plane
  * cannot be judged (no members, a band or radius that is zero or not finite).
  * \param[in] points samples
  * \param[in] graph their k-NN graph
  * \param[in] plane the plane (members, center, unit normal)
  * \param[in] band the distance within which its noise lies */
std::size_t
samplesBesideBand (const PointSet& points, const NeighborGraph& graph, const PlanarPatch& plane, double band);

/** \brief samplesBesideBand, and the most samples that one plane other than \a self holds (by
  * \a labels, per sample the index of its plane or kNoPatch; null: not counted) within \a band of
  * the plane over its footprint, and LayerCounts::flat_beside (the next layer: between 2 and 3
  * \a band). All 0 when the plane cannot be judged. */
LayerCounts
countLayerSamples (const PointSet& points, const NeighborGraph& graph, const PlanarPatch& plane, double band,
                   const std::vector<std::uint32_t>* labels, std::uint32_t self);

/** \brief Clutter surrounding a plane (DetectorParameters::surrounding_clutter): of the samples
  * \a open (those no plane holds), those at a distance in [\a from, \a to) from the plane whose
  * projection falls in its footprint (as samplesBesideBand) and none of whose graph neighbours a
  * plane other than \a self holds, counted on each side; twice the smaller count is returned.
  *
  * The lesser side: a volume of clutter around a plane (a slab of outliers, a scanner's scattered
  * returns) lies on both sides, while what lies on one side only is other structure, a face no
  * plane found, the samples beside an edge, and is no clutter. Samples next to another plane are
  * that plane's edge. 0 when the plane cannot be judged.
  * \param[in] labels per sample, the index of its plane or kNoPatch */
std::size_t
clutterBesidePlane (const PointSet& points, const NeighborGraph& graph, const PlanarPatch& plane, double from,
                    double to, const std::vector<std::uint32_t>& labels, const std::vector<std::uint32_t>& open,
                    std::uint32_t self);

/** \brief Whether a plane of \a members samples and noise band \a band, with \a counts from
  * countLayerSamples, is a layer inside another plane's band (DetectorParameters::in_band_layer_check):
  * that plane (LayerCounts::other, band \a other_band) is more than four times as dense within the
  * band over the footprint as the plane itself.
  *
  * Densities, not counts: the other plane's samples there fill the thinner of the two bands, the
  * plane's own the whole of its band, so where \a other_band is the narrower and that plane holds
  * at least as many samples there as the plane (it spans the footprint; a small face under a share
  * of it says nothing of the density over the rest) the count ratio is scaled by \a band /
  * \a other_band (a band of 0 or one not finite: counts alone). A surface holds
  * at least about as many samples as any other surface where both lie within its noise: faces of
  * like density, one inside the other's band (two faces of a thin wall), give about 1. A plane
  * grown among the clutter beside a denser one, whose spread makes a band wide enough to take in
  * that plane, gives the density of that plane over the clutter's: a unit plane at σ 1 cm in a slab
  * of 20 % outliers kept, scaled ×1000 or turned, a plane of 7,400 outliers whose band held 80,000
  * of the true plane's samples (10.9); in 40 % outliers 1 km away one of 17,421 outliers, band 8.1 cm,
  * over the true plane's 65,447 samples, band 3.2 cm (3.8 by counts, 9.4 by densities). */
bool
isInBandLayer (const LayerCounts& counts, std::size_t members, double band = 0.0, double other_band = 0.0);

/** \brief isInBandLayer for plane \a self of \a patches, with \a band per plane (LayerCounts::other
  * indexes it; out of range: counts alone). */
bool
isInBandLayer (const LayerCounts& counts, const std::vector<PlanarPatch>& patches, const std::vector<double>& band,
               std::size_t self);

/** \brief Drop the noisy seeds' planes that are the boundary layers of a volume of samples
  * (departure, see DetectorParameters::volume_layer_check).
  *
  * A surface is a layer denser than the space beside it. A plane seeded by a noisy seed (retested or
  * joined: its seed's normals were spread beyond every other seed's) is dropped, its members left to
  * no plane, when the layer beside its band on one side, half as thick as the band, holds more than
  * twice as many samples as the plane (samplesBesideBand): the samples beside the band are four
  * times as dense as the plane's own, and the plane is a share of a volume of samples where it
  * ends, whose neighbourhoods, cut by the end, give PCA normals across it. A layer of one noisy
  * face has about as many samples beside it as it holds. Planes found from ordinary seeds are not
  * judged, unless \a every_plane: two faces of a thin wall lie in each other's layer, and while one
  * is still a seed the other outnumbers it; once the planes are final
  * (DetectorParameters::final_volume_layer_check) the faces, of like density, about match.
  * \param[in] points samples
  * \param[in] graph their k-NN graph
  * \param[in] band per plane, the distance within which its noise lies
  * \param[in] num_threads OpenMP threads (0: OpenMP's default); the result does not depend on it
  * \param[in,out] patches the planes; those dropped are removed, order otherwise kept
  * \param[in] every_plane judge every plane, not only the noisy seeds'
  * \param[in] first judge the planes from this index on (the others are kept)
  * \param[in] in_band_layers with \a every_plane: also drop the layers inside another plane's band
  * (isInBandLayer), counted against every plane in \a patches
  * \param[in,out] in_band_dropped if not null: incremented by the planes dropped as such layers
  * \param[in] flat_layers with \a every_plane: also drop the planes whose LayerCounts::flat_beside
  * exceeds their samples (DetectorParameters::flat_layers)
  * \return planes dropped */
std::size_t
dropVolumeLayers (const PointSet& points, const NeighborGraph& graph, const std::vector<double>& band,
                  int num_threads, std::vector<PlanarPatch>& patches, bool every_plane = false,
                  std::size_t first = 0, bool in_band_layers = false, std::size_t* in_band_dropped = nullptr,
                  bool flat_layers = false);

} // namespace rspd
} // namespace pcl
