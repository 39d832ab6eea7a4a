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
#include <vector>

namespace pcl
{
namespace rspd
{
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
  * \return planes dropped */
std::size_t
dropVolumeLayers (const PointSet& points, const NeighborGraph& graph, const std::vector<double>& band,
                  int num_threads, std::vector<PlanarPatch>& patches, bool every_plane = false);

} // namespace rspd
} // namespace pcl
