/*
 * pcl_rspd tools: checked point cloud reading and labelled cloud writing, shared by the tools.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl_rspd/plane_colors.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/memory.h>
#include <pcl/pcl_macros.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rspd_tools
{
/** \brief A point cloud read from a file: the raw blob with every field, and typed views of it. */
struct LoadedCloud
{
  /** \brief Every field of the file, with width/height as stored (organized stays organized). */
  pcl::PCLPointCloud2 blob;
  /** \brief Sensor acquisition origin from the file (VIEWPOINT / PLY camera). */
  Eigen::Vector4f origin = Eigen::Vector4f::Zero ();
  /** \brief Sensor acquisition orientation from the file. */
  Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity ();
  /** \brief Positions of every point, same order, width and height as \a blob; NaN points kept.
    * Carries the sensor origin and orientation. Never null after a successful load. */
  pcl::PointCloud<pcl::PointXYZ>::Ptr xyz;
  /** \brief normal_x/normal_y/normal_z of every point if the file has them, null otherwise. */
  pcl::PointCloud<pcl::Normal>::Ptr normals;
  /** \brief What was read, e.g. "pcd binary_compressed" or "ply binary_little_endian". */
  std::string format;

  /** \brief Number of points (width * height). */
  std::size_t
  size () const { return static_cast<std::size_t> (blob.width) * blob.height; }

  PCL_MAKE_ALIGNED_OPERATOR_NEW
};

/** \brief Read a .pcd (ascii, binary, binary_compressed) or .ply file.
  *
  * The PCD header (and the PLY header) is checked here before PCL sees the file, because PCL 1.13's
  * PCD reader can crash on random bytes, allocates whatever POINTS claims, and loads clouds without
  * x/y/z as zeros. Refused: missing, unreadable or empty files, directories, headers whose
  * FIELDS/SIZE/TYPE/COUNT disagree, POINTS != WIDTH * HEIGHT, zero points, no x, y or z field,
  * binary data shorter than the header promises, a binary_compressed block whose sizes or LZF
  * stream are inconsistent, ascii data with fewer rows (or values) than promised.
  *
  * \param[in] path file to read; the format comes from the extension (.pcd, .ply, any case), and
  *            from the first bytes when the extension is neither
  * \param[out] out the cloud; left empty on failure (no partial result)
  * \param[out] error one human-readable sentence naming the file, set on failure
  * \return true on success
  */
bool
loadCloud (const std::string& path, LoadedCloud& out, std::string& error);

/** \brief Read any PCD file (x, y and z not required, e.g. a pcl::Label cloud) into a blob, with
  * the same header, size and block checks as loadCloud. \return false with \a error set otherwise */
bool
loadPcdBlob (const std::string& path, pcl::PCLPointCloud2& blob, std::string& error);

/** \brief Wrap an in-memory cloud (e.g. a generated scene) as if it had been read from a file. */
void
makeLoadedCloud (const pcl::PointCloud<pcl::PointXYZ>& cloud, LoadedCloud& out);

/** \brief Whether pcl::PCDReader would take the start of this binary DATA section for more header
  * lines (it reads on after "DATA" while lines are empty, comments or start with a keyword). */
bool
pcdDataMisreadAsHeader (const std::vector<std::uint8_t>& data);

/** \brief Write \a in with a per-point plane label and a colour, as a binary PCD.
  *
  * Every input point is written in the same order (organized stays organized), with the input's
  * fields (PCD padding fields "_" dropped) and sensor pose, plus a uint32 field "label" and a
  * float-packed field "rgb" as in pcl::PointXYZRGB (existing label / rgb / rgba fields get their
  * values replaced). Colours come from labelColour(). The file is written next to \a path under a
  * temporary name and renamed, so \a path never holds a half-written file. In the rare case that
  * the first point's bytes would be read by PCL as a header line (pcdDataMisreadAsHeader), the
  * label (or else the colour) field is written first instead, so the file always reads back.
  *
  * \param[in] labels one label per point (0: no plane)
  * \return true on success; false with \a error set otherwise (nothing left behind)
  */
bool
writeLabeledCloud (const std::string& path, const LoadedCloud& in,
                   const std::vector<std::uint32_t>& labels, std::string& error);

/** \brief Number of points with finite x, y and z. */
std::size_t
countFinite (const pcl::PointCloud<pcl::PointXYZ>& cloud);

/** \name Atomic file output: write to a temporary file next to the target, then rename. */
///@{
/** \brief Create an empty temporary file in the directory of \a path (so that rename() onto
  * \a path is atomic), with the permissions a new file would get. */
bool
createTempFileFor (const std::string& path, std::string& tmp_path, std::string& error);

/** \brief Rename \a tmp_path onto \a path; removes \a tmp_path if that fails. */
bool
commitTempFile (const std::string& tmp_path, const std::string& path, std::string& error);

/** \brief Remove a temporary file (ignores errors). */
void
discardTempFile (const std::string& tmp_path);

/** \brief Write \a content to \a path atomically. */
bool
writeFileAtomically (const std::string& path, const std::string& content, std::string& error);

/** \brief Check early that \a path can be written (not a directory, directory writable), by
  * creating and removing a temporary file next to it. Nothing is left behind. */
bool
checkWritable (const std::string& path, std::string& error);
///@}

/** \brief Colour of a plane label (grey for 0), shared by the labelled PCD, the PNG and the
  * library's coloured cloud: pcl::rspd::planeColor. */
inline std::array<std::uint8_t, 3>
labelColour (std::uint32_t label)
{
  return pcl::rspd::planeColor (label);
}

} // namespace rspd_tools
