/*
 * pcl_rspd: one colour per plane label, shared by the coloured cloud, the PCD writer and the PNG.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace pcl
{
namespace rspd
{
/** \brief RGB colour of plane \a label.
  *
  * Label 0 (no plane) is grey (128, 128, 128). Plane labels walk the hue circle by the golden
  * angle, so consecutive labels (the largest planes) are far apart in hue, while saturation and
  * value cycle with co-prime periods to tell apart hues that come close again after many labels.
  * Deterministic, no random numbers.
  */
inline std::array<std::uint8_t, 3>
planeColor (std::uint32_t label)
{
  if (label == 0)
    return {128, 128, 128};
  const std::uint32_t i = label - 1;
  double h = 0.02 + 0.6180339887498949 * static_cast<double> (i); // start at a warm red
  h -= std::floor (h);
  static const double saturations[2] = {0.85, 0.6};
  static const double values[3] = {0.95, 0.78, 0.62};
  const double s = saturations[i % 2];
  const double v = values[(i / 2) % 3];
  const double h6 = h * 6.0;
  const int sector = static_cast<int> (h6) % 6;
  const double f = h6 - std::floor (h6);
  const double p = v * (1.0 - s), q = v * (1.0 - s * f), t = v * (1.0 - s * (1.0 - f));
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
  const auto to_byte = [] (double c) {
    return static_cast<std::uint8_t> (std::min (255.0, std::max (0.0, std::round (c * 255.0))));
  };
  return {to_byte (r), to_byte (g), to_byte (b)};
}

} // namespace rspd
} // namespace pcl
