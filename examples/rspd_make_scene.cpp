// SPDX-License-Identifier: BSD-3-Clause
/*
 * rspd_make_scene: write a synthetic scene (pcl_rspd/synthetic_scenes.h) as a binary PCD cloud
 * plus a ground-truth file of raw little-endian uint32 labels, one per point in cloud order
 * (0 = no plane, 1..K = plane). Given a .pcd or .ply file instead of a scene name, it moves that
 * cloud's points as it would move a scene (--rotate, --scale, --offset) and writes OUT_PREFIX.pcd
 * alone: the file's own truth still applies, point for point.
 *
 * Exit status: 0 success, 1 a file could not be written, 2 usage error.
 */

#include <pcl_rspd/synthetic_scenes.h>

#include "cloud_io.h"

#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace
{
const char* const kUsage =
  "usage: rspd_make_scene NAME OUT_PREFIX [-n N] [--noise S] [--isotropic] [--outliers R]"
  " [--rotate] [--scale F] [--offset X Y Z] [--seed S] [--layout L] [--no-shuffle] [--scan-grid] | rspd_make_scene --list\n"
  "       rspd_make_scene CLOUD.pcd|CLOUD.ply OUT_PREFIX [--rotate] [--scale F] [--offset X Y Z] [--seed S]";

/** \brief Whether a scene name is a cloud file to move rather than a scene to generate. */
bool
isCloudFile (const std::string& name)
{
  const auto ends = [&] (const char* ext) {
    const std::size_t n = std::strlen (ext);
    if (name.size () < n)
      return false;
    for (std::size_t i = 0; i < n; ++i)
      if (std::tolower (static_cast<unsigned char> (name[name.size () - n + i])) != ext[i])
        return false;
    return true;
  };
  return ends (".pcd") || ends (".ply");
}

/** \brief Thrown for a malformed command line; main prints it with the usage line. */
struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

double
parseDouble (const std::string& option, const char* text)
{
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod (text, &end);
  if (end == text || *end != '\0' || errno == ERANGE || !std::isfinite (value))
    throw UsageError (option + " expects a number, got '" + text + "'");
  return value;
}

unsigned long long
parseUnsigned (const std::string& option, const char* text, unsigned long long max)
{
  errno = 0;
  char* end = nullptr;
  // strtoull accepts a leading minus and wraps it; refuse it explicitly.
  const unsigned long long value = std::strtoull (text, &end, 10);
  if (end == text || *end != '\0' || errno == ERANGE || text[0] == '-' || text[0] == '+' ||
      value > max)
    throw UsageError (option + " expects a non-negative integer up to " + std::to_string (max) +
                      ", got '" + text + "'");
  return value;
}

/** \brief Write the labels as little-endian uint32 whatever the host byte order. */
bool
writeLabels (const std::string& path, const std::vector<std::uint32_t>& labels)
{
  std::FILE* f = std::fopen (path.c_str (), "wb");
  if (f == nullptr)
    return false;
  std::vector<unsigned char> bytes (labels.size () * 4);
  for (std::size_t i = 0; i < labels.size (); ++i)
    for (int b = 0; b < 4; ++b)
      bytes[4 * i + b] = static_cast<unsigned char> ((labels[i] >> (8 * b)) & 0xffu);
  const bool written =
    bytes.empty () || std::fwrite (bytes.data (), 1, bytes.size (), f) == bytes.size ();
  const bool closed = std::fclose (f) == 0;
  return written && closed;
}

/** \brief Temporary name next to the target, so that the final rename stays on one file system. */
std::string
tempName (const std::string& path)
{
  return path + ".tmp" + std::to_string (static_cast<long> (::getpid ()));
}
} // namespace

int
main (int argc, char** argv)
{
  pcl::rspd::SceneOptions options;
  std::vector<std::string> positional;
  try
  {
    for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      auto value = [&] (int count) {
        if (i + count >= argc)
          throw UsageError (arg + " expects " + std::to_string (count) +
                            (count == 1 ? " value" : " values"));
        i += count;
      };
      if (arg == "--list")
      {
        for (const auto& name : pcl::rspd::sceneNames ())
          std::printf ("%s\n", name.c_str ());
        return 0;
      }
      else if (arg == "-h" || arg == "--help")
      {
        std::printf ("%s\n", kUsage);
        return 0;
      }
      else if (arg == "-n")
      {
        value (1);
        options.num_points = static_cast<std::size_t> (
          parseUnsigned (arg, argv[i], std::numeric_limits<std::uint32_t>::max ()));
      }
      else if (arg == "--noise")
      {
        value (1);
        options.noise = parseDouble (arg, argv[i]);
        if (options.noise < 0.0)
          throw UsageError ("--noise must be >= 0");
      }
      else if (arg == "--isotropic")
        options.isotropic_noise = true;
      else if (arg == "--outliers")
      {
        value (1);
        options.outlier_ratio = parseDouble (arg, argv[i]);
        if (options.outlier_ratio < 0.0 || options.outlier_ratio > 1.0)
          throw UsageError ("--outliers must be in [0, 1]");
      }
      else if (arg == "--rotate")
        options.random_rotation = true;
      else if (arg == "--scale")
      {
        value (1);
        options.scale = parseDouble (arg, argv[i]);
        if (options.scale <= 0.0)
          throw UsageError ("--scale must be > 0");
      }
      else if (arg == "--offset")
      {
        value (3);
        for (int d = 0; d < 3; ++d)
          options.offset[d] = parseDouble (arg, argv[i - 2 + d]);
      }
      else if (arg == "--seed")
      {
        value (1);
        options.seed = static_cast<std::uint32_t> (
          parseUnsigned (arg, argv[i], std::numeric_limits<std::uint32_t>::max ()));
      }
      else if (arg == "--layout")
      {
        value (1);
        options.layout = static_cast<std::uint32_t> (
          parseUnsigned (arg, argv[i], std::numeric_limits<std::uint32_t>::max ()));
      }
      else if (arg == "--no-shuffle")
        options.shuffle = false;
      else if (arg == "--scan-grid")
        options.scan_grid = true;
      else if (arg.size () > 1 && arg[0] == '-')
        throw UsageError ("unknown option '" + arg + "'");
      else
        positional.push_back (arg);
    }
    if (positional.size () != 2)
      throw UsageError ("expected NAME and OUT_PREFIX");
  }
  catch (const UsageError& e)
  {
    std::fprintf (stderr, "rspd_make_scene: %s\n%s\n", e.what (), kUsage);
    return 2;
  }

  const std::string& name = positional[0];
  const std::string& prefix = positional[1];
  if (isCloudFile (name))
  {
    if (options.num_points != 0 || options.noise >= 0.0 || options.isotropic_noise || options.outlier_ratio >= 0.0 ||
        !options.shuffle || options.layout != 0 || options.scan_grid)
    {
      std::fprintf (stderr, "rspd_make_scene: -n, --noise, --isotropic, --outliers, --layout, --no-shuffle and --scan-grid apply to generated "
                    "scenes, not to '%s'\n%s\n", name.c_str (), kUsage);
      return 2;
    }
    pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
    rspd_tools::LoadedCloud loaded;
    std::string error;
    if (!rspd_tools::loadCloud (name, loaded, error))
    {
      std::fprintf (stderr, "rspd_make_scene: %s\n", error.c_str ());
      return 1;
    }
    pcl::PointCloud<pcl::PointXYZ> cloud = *loaded.xyz;
    pcl::rspd::transformCloud (cloud, options);
    // Temporary file next to the target, renamed into place once complete (cloud_io's helpers).
    const std::string pcd_path = prefix + ".pcd";
    std::string tmp;
    if (!rspd_tools::createTempFileFor (pcd_path, tmp, error))
    {
      std::fprintf (stderr, "rspd_make_scene: %s\n", error.c_str ());
      return 1;
    }
    int status = -1;
    try
    {
      status = pcl::io::savePCDFileBinary (tmp, cloud);
    }
    catch (const std::exception&)
    {
      status = -1;
    }
    if (status < 0)
    {
      rspd_tools::discardTempFile (tmp);
      std::fprintf (stderr, "rspd_make_scene: cannot write '%s'\n", pcd_path.c_str ());
      return 1;
    }
    if (!rspd_tools::commitTempFile (tmp, pcd_path, error))
    {
      std::fprintf (stderr, "rspd_make_scene: %s\n", error.c_str ());
      return 1;
    }
    std::printf ("%s: %zu points moved -> %s (the input's truth applies, same point order)\n", name.c_str (),
                 cloud.size (), pcd_path.c_str ());
    return 0;
  }
  pcl::rspd::Scene scene;
  try
  {
    scene = pcl::rspd::makeScene (name, options);
  }
  catch (const std::invalid_argument& e)
  {
    std::fprintf (stderr, "rspd_make_scene: %s (see --list)\n%s\n", e.what (), kUsage);
    return 2;
  }

  // One clear line of our own on failure instead of PCL's console messages.
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  const std::string pcd_path = prefix + ".pcd";
  const std::string gt_path = prefix + ".gt";
  const std::string pcd_tmp = tempName (pcd_path);
  const std::string gt_tmp = tempName (gt_path);

  // Both files go to temporary names first and are renamed only once both are complete, so a
  // failure never leaves a cloud without its labels or a truncated file under the final name.
  auto fail = [&] (const std::string& path, int err) {
    std::remove (pcd_tmp.c_str ());
    std::remove (gt_tmp.c_str ());
    std::fprintf (stderr, "rspd_make_scene: cannot write '%s'%s%s\n", path.c_str (),
                  err != 0 ? ": " : "", err != 0 ? std::strerror (err) : "");
    return 1;
  };
  errno = 0;
  int pcd_status = -1;
  try
  {
    pcd_status = pcl::io::savePCDFileBinary (pcd_tmp, scene.cloud);
  }
  catch (const std::exception&)
  {
    pcd_status = -1;
  }
  if (pcd_status < 0)
    return fail (pcd_path, errno);
  errno = 0;
  if (!writeLabels (gt_tmp, scene.labels))
    return fail (gt_path, errno);
  errno = 0;
  if (std::rename (pcd_tmp.c_str (), pcd_path.c_str ()) != 0)
    return fail (pcd_path, errno);
  errno = 0;
  if (std::rename (gt_tmp.c_str (), gt_path.c_str ()) != 0)
    return fail (gt_path, errno);

  std::size_t curved = 0, outliers = 0;
  for (const auto kind : scene.kinds)
  {
    curved += (kind == pcl::rspd::SurfaceKind::Curved);
    outliers += (kind == pcl::rspd::SurfaceKind::Outlier);
  }
  std::printf ("%s: %zu points, %d planes, %zu curved, %zu outliers -> %s, %s\n",
               scene.name.c_str (), scene.cloud.size (), scene.num_planes, curved, outliers,
               pcd_path.c_str (), gt_path.c_str ());
  return 0;
}
