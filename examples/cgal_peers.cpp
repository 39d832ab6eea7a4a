/*
 * CGAL's plane detectors as rspd_compare peers, see cgal_peers.h.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "cgal_peers.h"

#include <stdexcept>

#ifdef RSPD_HAVE_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Shape_detection/Efficient_RANSAC.h>
#include <CGAL/Shape_detection/Region_growing/Region_growing.h>
#include <CGAL/Shape_detection/Region_growing/Region_growing_on_point_set.h>
#include <CGAL/Random.h>
#include <CGAL/property_map.h>

#include <iterator>
#include <tuple>

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// The point's own index rides along: Efficient RANSAC reorders its input range.
using PointWithNormal = std::tuple<Kernel::Point_3, Kernel::Vector_3, std::size_t>;
using Points = std::vector<PointWithNormal>;
using PointMap = CGAL::Nth_of_tuple_property_map<0, PointWithNormal>;
using NormalMap = CGAL::Nth_of_tuple_property_map<1, PointWithNormal>;

Points
toCgal (const std::vector<float>& xyz, const std::vector<float>& normals)
{
  if (xyz.size () != normals.size () || xyz.size () % 3 != 0)
    throw std::invalid_argument ("CGAL peers: points and normals differ in size");
  Points points;
  points.reserve (xyz.size () / 3);
  for (std::size_t i = 0; i < xyz.size (); i += 3)
    points.emplace_back (Kernel::Point_3 (xyz[i], xyz[i + 1], xyz[i + 2]),
                         Kernel::Vector_3 (normals[i], normals[i + 1], normals[i + 2]), i / 3);
  return points;
}
} // namespace

namespace rspd_tools
{
bool
haveCgalPeers ()
{
  return true;
}

std::vector<std::vector<std::size_t>>
cgalRegionGrowing (const std::vector<float>& xyz, const std::vector<float>& normals, const CgalPeerSettings& s)
{
  namespace SD = CGAL::Shape_detection;
  using Query = SD::Point_set::K_neighbor_query<Kernel, Points, PointMap>;
  using Region = SD::Point_set::Least_squares_plane_fit_region<Kernel, Points, PointMap, NormalMap>;
  using Sorting = SD::Point_set::Least_squares_plane_fit_sorting<Kernel, Points, Query, PointMap>;
  using Growing = SD::Region_growing<Points, Query, Region, typename Sorting::Seed_map>;
  std::vector<std::vector<std::size_t>> regions;
  const Points points = toCgal (xyz, normals);
  if (points.empty ())
    return regions;
  Query query (points, s.rg_neighbours);
  Region region (points, s.rg_max_distance, s.rg_max_angle_deg, s.min_region_size);
  Sorting sorting (points, query);
  sorting.sort ();
  Growing growing (points, query, region, sorting.seed_map ());
  growing.detect (std::back_inserter (regions));
  return regions;
}

std::vector<std::vector<std::size_t>>
cgalEfficientRansac (const std::vector<float>& xyz, const std::vector<float>& normals)
{
  namespace SD = CGAL::Shape_detection;
  using Traits = SD::Efficient_RANSAC_traits<Kernel, Points, PointMap, NormalMap>;
  using Ransac = SD::Efficient_RANSAC<Traits>;
  std::vector<std::vector<std::size_t>> planes;
  Points points = toCgal (xyz, normals);
  if (points.empty ())
    return planes;
  // CGAL seeds its default generator from the clock; a fixed seed (as the SAC loop's 12345) makes
  // the peer's rows reproducible.
  CGAL::get_default_random () = CGAL::Random (12345);
  Ransac ransac;
  ransac.set_input (points);
  ransac.add_shape_factory<SD::Plane<Traits>> ();
  ransac.detect (); // default Parameters: the values cgal_peers.h lists
  for (const auto& shape : ransac.shapes ())
  {
    std::vector<std::size_t> members;
    for (const std::size_t j : shape->indices_of_assigned_points ())
      members.push_back (std::get<2> (points[j]));
    planes.push_back (std::move (members));
  }
  return planes;
}
} // namespace rspd_tools

#else

namespace rspd_tools
{
bool
haveCgalPeers ()
{
  return false;
}

std::vector<std::vector<std::size_t>>
cgalRegionGrowing (const std::vector<float>&, const std::vector<float>&, const CgalPeerSettings&)
{
  throw std::runtime_error ("this rspd_compare was built without CGAL (install libcgal-dev and rebuild)");
}

std::vector<std::vector<std::size_t>>
cgalEfficientRansac (const std::vector<float>&, const std::vector<float>&)
{
  throw std::runtime_error ("this rspd_compare was built without CGAL (install libcgal-dev and rebuild)");
}
} // namespace rspd_tools

#endif
