/*
 * pcl_rspd: robust statistics used by the planarity test (Araújo & Oliveira 2020, Sec. 3.2).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace pcl
{
namespace rspd
{
/** \brief Scale that makes the MAD a consistent estimator of a normal distribution's standard
  * deviation (the paper's k in Eq. 2).
  */
constexpr double kMadScale = 1.4826;

/** \brief Standard error of a robust σ (kMadScale × median |d|) of n Gaussian distances, times √n:
  * the MAD's asymptotic variance is 1.36 σ² / n.
  */
constexpr double kRobustSigmaError = 1.166;

/** \brief \a sigma raised by \a errors standard errors of a robust σ measured on \a n samples
  * (kRobustSigmaError σ / √n): a set as noisy as \a sigma measures above it that rarely. */
inline double
robustSigmaBound (double sigma, std::size_t n, double errors)
{
  return sigma * (1.0 + errors * kRobustSigmaError / std::sqrt (static_cast<double> (n)));
}

/** \brief Median of \a values by linear-time selection (std::nth_element), never a full sort.
  * For an even count it is the mean of the two middle values. The order of \a values is changed.
  * \return NaN for an empty set.
  */
template <typename T>
inline double
medianInPlace (std::vector<T>& values)
{
  const std::size_t n = values.size ();
  if (n == 0)
    return std::nan ("");
  const std::size_t mid = n / 2;
  std::nth_element (values.begin (), values.begin () + mid, values.end ());
  const double upper = static_cast<double> (values[mid]);
  if (n % 2 == 1)
    return upper;
  // After selection every element before mid is <= values[mid]: the lower middle is their maximum.
  const double lower = static_cast<double> (*std::max_element (values.begin (), values.begin () + mid));
  return 0.5 * (lower + upper);
}

/** \brief Median of \a values (copied, the input is left untouched). */
template <typename T>
inline double
median (std::vector<T> values)
{
  return medianInPlace (values);
}

/** \brief Median and scaled median absolute deviation (Eq. 2) of a set of observations. */
struct RobustSpread
{
  double median = 0.0; ///< median of the observations
  double mad = 0.0;    ///< kMadScale * median(|x_i - median|)
};

/** \brief Median and MAD of \a values, by two selections. \a values is reordered and then holds
  * the absolute deviations.
  */
template <typename T>
inline RobustSpread
robustSpreadInPlace (std::vector<T>& values)
{
  RobustSpread s;
  s.median = medianInPlace (values);
  for (auto& v : values)
    v = static_cast<T> (std::abs (static_cast<double> (v) - s.median));
  s.mad = kMadScale * medianInPlace (values);
  return s;
}

/** \brief Median and MAD of \a values (copied). */
template <typename T>
inline RobustSpread
robustSpread (std::vector<T> values)
{
  return robustSpreadInPlace (values);
}

} // namespace rspd
} // namespace pcl
