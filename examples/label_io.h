/*
 * pcl_rspd tools: per-point plane label files (PCD with a "label" field, or raw little-endian uint32).
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Header-only (inline) so that a tool can use it without a change to the CMake target list.
 */
#pragma once

#include "cloud_io.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/PCLPointField.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

#include <sys/stat.h>

namespace rspd_tools
{
/** \brief True when \a path ends in \a ext, compared case-insensitively (ext includes the dot). */
inline bool
hasExtension (const std::string& path, const std::string& ext)
{
  if (path.size () < ext.size ())
    return false;
  return std::equal (ext.begin (), ext.end (), path.end () - ext.size (), [] (char a, char b) {
    return std::tolower (static_cast<unsigned char> (a)) ==
           std::tolower (static_cast<unsigned char> (b));
  });
}

/** \brief Size of the regular file \a path in bytes; false (with \a error set) when it is missing,
  * not a regular file or unreadable.
  */
inline bool
regularFileSize (const std::string& path, std::uint64_t& size, std::string& error)
{
  struct stat st;
  if (::stat (path.c_str (), &st) != 0)
  {
    error = path + ": " + std::generic_category ().message (errno);
    return false;
  }
  if (!S_ISREG (st.st_mode))
  {
    error = path + ": not a regular file";
    return false;
  }
  size = static_cast<std::uint64_t> (st.st_size);
  return true;
}

/** \brief Read one scalar of PCL type \a datatype at \a p as a label; false when it is negative,
  * not an integer, too large for uint32 or of an unsupported type.
  */
inline bool
labelFromBytes (const std::uint8_t* p, std::uint8_t datatype, std::uint32_t& label)
{
  // PCL stores PCD data in host order once loaded, so plain copies are right here.
  auto load = [p] (auto value) {
    std::memcpy (&value, p, sizeof (value));
    return value;
  };
  double v = 0.0;
  switch (datatype)
  {
    case pcl::PCLPointField::UINT8: label = load (std::uint8_t ()); return true;
    case pcl::PCLPointField::UINT16: label = load (std::uint16_t ()); return true;
    case pcl::PCLPointField::UINT32: label = load (std::uint32_t ()); return true;
    case pcl::PCLPointField::INT8: v = load (std::int8_t ()); break;
    case pcl::PCLPointField::INT16: v = load (std::int16_t ()); break;
    case pcl::PCLPointField::INT32: v = load (std::int32_t ()); break;
    // Some writers store labels as floats; accept them when they hold exact integers.
    case pcl::PCLPointField::FLOAT32: v = load (float ()); break;
    case pcl::PCLPointField::FLOAT64: v = load (double ()); break;
    default: return false;
  }
  if (!(v >= 0.0) || v > static_cast<double> (std::numeric_limits<std::uint32_t>::max ()) ||
      v != std::floor (v))
    return false;
  label = static_cast<std::uint32_t> (v);
  return true;
}

/** \brief Read per-point plane labels.
  * A path ending in ".pcd" (any case) is read as a PCD file and its field named "label" is used
  * (uint32 as written by pcl::PointXYZRGBL or pcl::Label; other integer types and integral floats
  * are accepted too). Anything else is read as raw little-endian uint32, one per point, and must be
  * exactly 4 * expected_count bytes long.
  * \param[in] path label file
  * \param[in] expected_count number of points of the cloud the labels belong to
  * \param[out] labels the labels, expected_count of them on success
  * \param[out] error one-line reason on failure
  * \return true on success
  */
inline bool
readLabels (const std::string& path, std::size_t expected_count, std::vector<std::uint32_t>& labels,
            std::string& error)
{
  labels.clear ();
  if (hasExtension (path, ".pcd"))
  {
    pcl::PCLPointCloud2 blob;
    if (!loadPcdBlob (path, blob, error)) // header and size checks before PCL reads it
      return false;
    const auto field = std::find_if (blob.fields.begin (), blob.fields.end (),
                                     [] (const pcl::PCLPointField& f) { return f.name == "label"; });
    if (field == blob.fields.end ())
    {
      error = path + ": no 'label' field";
      return false;
    }
    const std::size_t count = static_cast<std::size_t> (blob.width) * blob.height;
    if (count != expected_count)
    {
      error = path + ": " + std::to_string (count) + " labels for " +
              std::to_string (expected_count) + " points";
      return false;
    }
    const std::size_t size = pcl::getFieldSize (field->datatype);
    if (size == 0 || field->offset + size > blob.point_step ||
        blob.data.size () < static_cast<std::size_t> (blob.row_step) * blob.height ||
        static_cast<std::size_t> (blob.point_step) * blob.width > blob.row_step)
    {
      error = path + ": inconsistent PCD layout";
      return false;
    }
    labels.resize (count);
    for (std::size_t row = 0; row < blob.height; ++row)
      for (std::size_t col = 0; col < blob.width; ++col)
      {
        const std::uint8_t* p =
            blob.data.data () + row * blob.row_step + col * blob.point_step + field->offset;
        if (!labelFromBytes (p, field->datatype, labels[row * blob.width + col]))
        {
          error = path + ": label of point " + std::to_string (row * blob.width + col) +
                  " is not a valid uint32";
          labels.clear ();
          return false;
        }
      }
    return true;
  }

  std::uint64_t size = 0;
  if (!regularFileSize (path, size, error))
    return false;
  if (size != 4 * static_cast<std::uint64_t> (expected_count))
  {
    error = path + ": " + std::to_string (size) + " bytes, expected " +
            std::to_string (4 * static_cast<std::uint64_t> (expected_count)) + " (uint32 per point)";
    return false;
  }
  std::ifstream in (path, std::ios::binary);
  std::vector<unsigned char> bytes (static_cast<std::size_t> (size));
  if (!in || !in.read (reinterpret_cast<char*> (bytes.data ()),
                       static_cast<std::streamsize> (bytes.size ())))
  {
    error = path + ": read error";
    return false;
  }
  // Assemble bytes explicitly: the format is little-endian whatever the host is.
  labels.resize (expected_count);
  for (std::size_t i = 0; i < expected_count; ++i)
  {
    const unsigned char* b = bytes.data () + 4 * i;
    labels[i] = static_cast<std::uint32_t> (b[0]) | (static_cast<std::uint32_t> (b[1]) << 8) |
                (static_cast<std::uint32_t> (b[2]) << 16) | (static_cast<std::uint32_t> (b[3]) << 24);
  }
  return true;
}

/** \brief Write labels as raw little-endian uint32, one per point.
  * The data goes to path + ".tmp" first and is renamed over \a path only when complete, so a reader
  * never sees a truncated file.
  * \return true on success; on failure \a error holds a one-line reason and \a path is untouched
  */
inline bool
writeRawLabels (const std::string& path, const std::vector<std::uint32_t>& labels,
                std::string& error)
{
  std::vector<unsigned char> bytes (4 * labels.size ());
  for (std::size_t i = 0; i < labels.size (); ++i)
  {
    const std::uint32_t v = labels[i];
    bytes[4 * i] = static_cast<unsigned char> (v & 0xFFu);
    bytes[4 * i + 1] = static_cast<unsigned char> ((v >> 8) & 0xFFu);
    bytes[4 * i + 2] = static_cast<unsigned char> ((v >> 16) & 0xFFu);
    bytes[4 * i + 3] = static_cast<unsigned char> ((v >> 24) & 0xFFu);
  }
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out (tmp, std::ios::binary | std::ios::trunc);
    if (!out)
    {
      error = tmp + ": cannot open for writing";
      return false;
    }
    out.write (reinterpret_cast<const char*> (bytes.data ()),
               static_cast<std::streamsize> (bytes.size ()));
    out.close ();
    if (!out)
    {
      error = tmp + ": write error";
      std::remove (tmp.c_str ());
      return false;
    }
  }
  if (std::rename (tmp.c_str (), path.c_str ()) != 0)
  {
    error = path + ": cannot rename from " + tmp + ": " + std::generic_category ().message (errno);
    std::remove (tmp.c_str ());
    return false;
  }
  return true;
}

} // namespace rspd_tools
