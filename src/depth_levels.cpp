/*
 * pcl_rspd: depth levels of quantized camera clouds, and their dither (see depth_levels.h).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/depth_levels.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace pcl
{
namespace rspd
{
namespace
{
constexpr std::size_t kMinLevels = 16;
constexpr double kOnLevelsShare = 0.95;

/** A draw in [0, 1) from the bits of a sample's coordinates (splitmix64 over the three doubles): the
  * same sample, the same draw, in any order and on any thread. */
double
drawOf (const Eigen::Vector3d& p)
{
  std::uint64_t h = 0x9E3779B97F4A7C15ull;
  for (int i = 0; i < 3; ++i)
  {
    std::uint64_t bits;
    const double v = p[i] == 0.0 ? 0.0 : p[i]; // -0 and +0 draw alike
    std::memcpy (&bits, &v, sizeof bits);
    h ^= bits;
    h += 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
    h ^= h >> 31;
  }
  return static_cast<double> (h >> 11) * (1.0 / 9007199254740992.0); // 53 bits
}

/** A sample's depth as the camera stored it: a float. Depths recomputed from float coordinates along
  * an axis given as a float quaternion differ by a few float steps within one level. */
float
storedDepth (const Eigen::Vector3d& p, const Eigen::Vector3d& origin, const Eigen::Vector3d& axis)
{
  return static_cast<float> ((p - origin).dot (axis));
}
} // namespace

DepthLevels
findDepthLevels (const std::vector<Eigen::Vector3d>& positions, const Eigen::Vector3d& origin, const Eigen::Vector3d& axis)
{
  DepthLevels out;
  out.samples = positions.size ();
  std::vector<float> depth;
  depth.reserve (positions.size ());
  bool in_front = true;
  for (const auto& p : positions)
  {
    const float d = storedDepth (p, origin, axis);
    in_front = in_front && d > 0.0f;
    depth.push_back (d);
  }
  std::sort (depth.begin (), depth.end ());
  // A level: a run of depths each within two float steps of the one before (see storedDepth).
  std::vector<double> centre;
  std::vector<float> first;
  for (std::size_t i = 0; i < depth.size ();)
  {
    std::size_t j = i + 1;
    while (j < depth.size () &&
           depth[j] <= std::nextafter (std::nextafter (depth[j - 1], HUGE_VALF), HUGE_VALF))
      ++j;
    if (j - i >= 2)
      out.on_levels += j - i;
    first.push_back (depth[i]);
    centre.push_back (0.5 * (static_cast<double> (depth[i]) + static_cast<double> (depth[j - 1])));
    i = j;
  }
  out.distinct = centre.size ();
  out.quantized = in_front && centre.size () >= kMinLevels &&
                  static_cast<double> (out.on_levels) >= kOnLevelsShare * static_cast<double> (out.samples);
  if (out.quantized)
  {
    out.levels = std::move (centre);
    out.first = std::move (first);
  }
  return out;
}

void
ditherDepthLevels (std::vector<Eigen::Vector3d>& positions, const Eigen::Vector3d& origin, const Eigen::Vector3d& axis,
                   const DepthLevels& levels)
{
  const std::vector<double>& l = levels.levels;
  if (l.size () < 2 || levels.first.size () != l.size ())
    return;
  for (auto& p : positions)
  {
    const double d = (p - origin).dot (axis);
    const float stored = storedDepth (p, origin, axis);
    if (!(d > 0.0) || stored < levels.first.front ())
      continue;
    // The level whose run holds the stored depth: the last one starting at or below it.
    const std::size_t m =
        static_cast<std::size_t> (std::upper_bound (levels.first.begin (), levels.first.end (), stored) - levels.first.begin ()) - 1;
    const double below = 0.5 * (m > 0 ? l[m] - l[m - 1] : l[1] - l[0]);
    const double above = 0.5 * (m + 1 < l.size () ? l[m + 1] - l[m] : l[m] - l[m - 1]);
    const double u = drawOf (p);
    const double target = u < 0.5 ? l[m] - below * (1.0 - 2.0 * u) : l[m] + above * (2.0 * u - 1.0);
    p = origin + (p - origin) * (target / d);
  }
}
} // namespace rspd
} // namespace pcl
