/*
 * pcl_rspd: one colour per plane label, shared by the coloured cloud, the PCD writer and the PNG.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace pcl
{
namespace rspd
{
/** \brief RGB colour of plane \a label: grey (128, 128, 128) for 0 (no plane), otherwise hues
  * spread by the golden angle so that neighbouring labels differ, at two saturation/value levels. */
inline std::array<std::uint8_t, 3>
planeColor (std::uint32_t label)
{
  if (label == 0)
    return {128, 128, 128};
  const double hue = std::fmod (static_cast<double> (label - 1) * 137.50776405, 360.0) / 60.0;
  const double s = (label % 2) ? 0.85 : 0.65;
  const double v = (label % 3 == 0) ? 0.75 : 0.95;
  const int sector = static_cast<int> (hue) % 6;
  const double f = hue - std::floor (hue);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  double r = v, g = t, b = p;
  switch (sector)
  {
    case 1: r = q; g = v; b = p; break;
    case 2: r = p; g = v; b = t; break;
    case 3: r = p; g = q; b = v; break;
    case 4: r = t; g = p; b = v; break;
    case 5: r = v; g = p; b = q; break;
    default: break;
  }
  return {static_cast<std::uint8_t> (std::lround (255 * r)), static_cast<std::uint8_t> (std::lround (255 * g)),
          static_cast<std::uint8_t> (std::lround (255 * b))};
}

} // namespace rspd
} // namespace pcl
