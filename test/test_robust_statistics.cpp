/*
 * Tests of median and MAD by selection (Eq. 2).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/robust_statistics.h>

#include <gtest/gtest.h>

using namespace pcl::rspd;

TEST (RobustStatistics, MedianOddSize)
{
  EXPECT_DOUBLE_EQ (median (std::vector<double>{5, 1, 4, 2, 3}), 3.0);
  EXPECT_DOUBLE_EQ (median (std::vector<double>{7}), 7.0);
}

TEST (RobustStatistics, MedianEvenSizeIsMeanOfMiddleValues)
{
  EXPECT_DOUBLE_EQ (median (std::vector<double>{4, 1, 3, 2}), 2.5);
  EXPECT_DOUBLE_EQ (median (std::vector<float>{10, -2}), 4.0);
  EXPECT_DOUBLE_EQ (median (std::vector<double>{1, 1, 9, 9}), 5.0);
}

TEST (RobustStatistics, MedianOfEmptySetIsNaN)
{
  EXPECT_TRUE (std::isnan (median (std::vector<double>{})));
}

TEST (RobustStatistics, CopyingMedianLeavesInputUntouched)
{
  const std::vector<double> v{3, 1, 2};
  median (v);
  EXPECT_EQ (v, (std::vector<double>{3, 1, 2}));
}

TEST (RobustStatistics, MadHandComputedOdd)
{
  // Values 1 2 3 4 100: median 3; |x - 3| = 2 1 0 1 97 -> median 1; MAD = 1.4826.
  const RobustSpread s = robustSpread (std::vector<double>{1, 2, 3, 4, 100});
  EXPECT_DOUBLE_EQ (s.median, 3.0);
  EXPECT_DOUBLE_EQ (s.mad, 1.4826);
}

TEST (RobustStatistics, MadHandComputedEven)
{
  // Values 1 2 4 7: median 3; deviations 2 1 1 4 -> median 1.5; MAD = 1.5 * 1.4826.
  const RobustSpread s = robustSpread (std::vector<double>{7, 1, 4, 2});
  EXPECT_DOUBLE_EQ (s.median, 3.0);
  EXPECT_DOUBLE_EQ (s.mad, 1.5 * 1.4826);
}

TEST (RobustStatistics, MadIsZeroForConstantData)
{
  const RobustSpread s = robustSpread (std::vector<double> (11, 2.5));
  EXPECT_DOUBLE_EQ (s.median, 2.5);
  EXPECT_DOUBLE_EQ (s.mad, 0.0);
}

TEST (RobustStatistics, MadResistsHalfMinusOneOutliers)
{
  // 6 clean values around 0 and 5 wild ones: median and MAD stay with the clean ones.
  std::vector<double> v{-0.2, -0.1, 0.0, 0.05, 0.1, 0.2, 1e6, 2e6, 3e6, -4e6, 5e6};
  const RobustSpread s = robustSpread (v);
  EXPECT_LT (std::abs (s.median), 1.0);
  EXPECT_LT (s.mad, 1e6);
}

TEST (RobustStatistics, SelectionMatchesSortOnRandomData)
{
  std::vector<double> v;
  unsigned x = 12345;
  for (int n = 1; n < 60; ++n)
  {
    x = x * 1103515245u + 12345u;
    v.push_back ((x >> 8) % 1000 / 7.0);
    std::vector<double> sorted = v;
    std::sort (sorted.begin (), sorted.end ());
    const double expect = sorted.size () % 2 ? sorted[sorted.size () / 2]
                                             : 0.5 * (sorted[sorted.size () / 2 - 1] + sorted[sorted.size () / 2]);
    EXPECT_DOUBLE_EQ (median (v), expect);
  }
}

TEST (RobustStatistics, SigmaBoundAddsStandardErrorsThatShrinkWithTheCount)
{
  // Two standard errors of a robust σ of 100 samples: 2 × 1.166 / 10 of it; four times the samples,
  // half the margin; none asked, none added.
  EXPECT_DOUBLE_EQ (robustSigmaBound (2.0, 100, 2.0), 2.0 * (1.0 + 0.2332));
  EXPECT_DOUBLE_EQ (robustSigmaBound (2.0, 400, 2.0) - 2.0, 0.5 * (robustSigmaBound (2.0, 100, 2.0) - 2.0));
  EXPECT_DOUBLE_EQ (robustSigmaBound (2.0, 100, 0.0), 2.0);
}
