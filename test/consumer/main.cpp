// Downstream use of the installed package: segment a small generated box corner.
#include <pcl_rspd/robust_plane_segmentation.h>

#include <cstdio>
#include <random>

int
main ()
{
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  std::mt19937 rng (1);
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  for (int f = 0; f < 3; ++f)
    for (int i = 0; i < 2000; ++i)
    {
      float c[3] = {u (rng), u (rng), u (rng)};
      c[f] = 0.0f;
      cloud->push_back (pcl::PointXYZ (c[0], c[1], c[2]));
    }
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> planes;
  seg.segment (coefficients, planes);
  std::printf ("%zu planes\n", planes.size ());
  return planes.size () == 3 ? 0 : 1;
}
