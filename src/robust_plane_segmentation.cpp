/*
 * pcl_rspd: explicit instantiations of RobustPlaneSegmentation for the common point types.
 * Other types: define PCL_NO_PRECOMPILE before including robust_plane_segmentation.h.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/impl/robust_plane_segmentation.hpp>

#ifndef PCL_NO_PRECOMPILE
// A short list on purpose: every pair costs compile time; PCL_NO_PRECOMPILE serves the rest.
template class pcl::RobustPlaneSegmentation<pcl::PointXYZ, pcl::Normal>;
template class pcl::RobustPlaneSegmentation<pcl::PointXYZI, pcl::Normal>;
template class pcl::RobustPlaneSegmentation<pcl::PointXYZRGB, pcl::Normal>;
template class pcl::RobustPlaneSegmentation<pcl::PointXYZRGBA, pcl::Normal>;
template class pcl::RobustPlaneSegmentation<pcl::PointNormal, pcl::Normal>;
template class pcl::RobustPlaneSegmentation<pcl::PointXYZRGBNormal, pcl::Normal>;
template class pcl::RobustPlaneSegmentation<pcl::PointXYZ, pcl::PointNormal>;
template class pcl::RobustPlaneSegmentation<pcl::PointXYZI, pcl::PointNormal>;
template class pcl::RobustPlaneSegmentation<pcl::PointXYZRGB, pcl::PointNormal>;
template class pcl::RobustPlaneSegmentation<pcl::PointXYZRGBA, pcl::PointNormal>;
template class pcl::RobustPlaneSegmentation<pcl::PointNormal, pcl::PointNormal>;
template class pcl::RobustPlaneSegmentation<pcl::PointXYZRGBNormal, pcl::PointNormal>;
#endif
