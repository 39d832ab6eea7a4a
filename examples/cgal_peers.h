/*
 * CGAL's two plane detectors as peers for rspd_compare (optional: built where CGAL is installed,
 * Debian's libcgal-dev). Kept in a translation unit of its own so that CGAL's headers, and their
 * compile time, stay out of the tool's other code.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <cstddef>
#include <vector>

namespace rspd_tools
{
/** \brief Whether this build has the CGAL peers (false: the functions below throw). */
bool
haveCgalPeers ();

/** \brief Settings of the CGAL peers, as the peer table states them. */
struct CgalPeerSettings
{
  std::size_t rg_neighbours = 12;      ///< region growing: k of its k-NN query
  double rg_max_distance = 0.0;        ///< region growing: point-to-plane distance (1 % of the extent)
  double rg_max_angle_deg = 25.0;      ///< region growing: normal to plane normal
  std::size_t min_region_size = 10;    ///< region growing: smallest region kept
};

/** \brief CGAL Shape_detection region growing on points with normals: least-squares plane fit
  * region, k-NN query and the least-squares seed sorting (CGAL's documented set-up).
  * \param[in] xyz x y z per point; \param[in] normals nx ny nz per point (same points).
  * \return the regions as lists of indices into the points, in the order CGAL found them. */
std::vector<std::vector<std::size_t>>
cgalRegionGrowing (const std::vector<float>& xyz, const std::vector<float>& normals, const CgalPeerSettings& s);

/** \brief CGAL Efficient RANSAC (Schnabel et al.) for planes with its default parameters
  * (probability 0.01, min points 1 % of the points, epsilon and cluster epsilon 1 % of the
  * bounding box diagonal, normal threshold 0.9), then the unassigned points left as they are.
  * CGAL's default generator is seeded with 12345 first (CGAL seeds it from the clock).
  * \return the planes' inliers as lists of indices into the points. */
std::vector<std::vector<std::size_t>>
cgalEfficientRansac (const std::vector<float>& xyz, const std::vector<float>& normals);
} // namespace rspd_tools
