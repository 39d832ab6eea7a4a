/*
 * A point type outside the precompiled list works with PCL_NO_PRECOMPILE.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#define PCL_NO_PRECOMPILE
#include <pcl_rspd/robust_plane_segmentation.h>

#include <gtest/gtest.h>

TEST (NoPrecompile, PointXYZLWithPointXYZINormal)
{
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZL>> ();
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j)
    {
      pcl::PointXYZL p;
      p.x = i * 0.01f;
      p.y = j * 0.01f;
      p.z = 0.0f;
      p.label = 7;
      cloud->push_back (p);
    }
  pcl::RobustPlaneSegmentation<pcl::PointXYZL, pcl::PointXYZINormal> seg;
  seg.setInputCloud (cloud);
  pcl::PointIndices inliers;
  pcl::ModelCoefficients coefficients;
  seg.segment (inliers, coefficients);
  EXPECT_EQ (inliers.indices.size (), cloud->size ());
  ASSERT_EQ (coefficients.values.size (), 4u);
  EXPECT_NEAR (std::abs (coefficients.values[2]), 1.0f, 1e-5f);
}
