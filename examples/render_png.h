/*
 * pcl_rspd tools: a small software point renderer that writes a PNG of a labelled cloud.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Debian's VTK has no offscreen context, so the picture is drawn here: two oblique perspective
 * views (from above and from below), each point a small square or disc in a z-buffer, coloured by
 * plane label with the palette of the labelled PCD (cloud_io.h), shaded by depth and by the
 * orientation of its plane.
 */
#pragma once

#include "cloud_io.h"

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace rspd_tools
{
namespace detail
{
/** \brief Where libpng's error callback leaves its message before jumping back. */
struct PngErrorState
{
  char message[256];
};

inline void
pngError (png_structp png, png_const_charp message)
{
  auto* state = static_cast<PngErrorState*> (png_get_error_ptr (png));
  if (state)
  {
    std::strncpy (state->message, message ? message : "unknown libpng error", sizeof (state->message) - 1);
    state->message[sizeof (state->message) - 1] = '\0';
  }
  png_longjmp (png, 1);
}

inline void
pngWarning (png_structp, png_const_charp)
{
  // libpng warnings are not worth a line on stderr of a tool.
}

/** \brief Write an 8-bit RGB image. Kept free of C++ objects with destructors, because libpng
  * reports errors with longjmp, which would skip them. */
inline bool
writePngRgb (const char* path, int width, int height, png_bytep* rows, PngErrorState* state)
{
  std::FILE* fp = std::fopen (path, "wb");
  if (!fp)
  {
    std::snprintf (state->message, sizeof (state->message), "cannot open for writing: %s", std::strerror (errno));
    return false;
  }
  png_structp png = png_create_write_struct (PNG_LIBPNG_VER_STRING, state, pngError, pngWarning);
  png_infop info = png ? png_create_info_struct (png) : nullptr;
  if (!png || !info)
  {
    std::snprintf (state->message, sizeof (state->message), "libpng initialisation failed");
    png_destroy_write_struct (png ? &png : nullptr, nullptr);
    std::fclose (fp);
    return false;
  }
  if (setjmp (png_jmpbuf (png)))
  {
    png_destroy_write_struct (&png, &info);
    std::fclose (fp);
    return false;
  }
  png_init_io (png, fp);
  png_set_IHDR (png, info, static_cast<png_uint_32> (width), static_cast<png_uint_32> (height), 8,
                PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info (png, info);
  png_write_image (png, rows);
  png_write_end (png, nullptr);
  png_destroy_write_struct (&png, &info);
  if (std::fclose (fp) != 0)
  {
    std::snprintf (state->message, sizeof (state->message), "cannot finish writing: %s", std::strerror (errno));
    return false;
  }
  return true;
}

/** \brief The q-quantile of \a v (0 <= q <= 1); reorders \a v. */
inline double
quantile (std::vector<double>& v, double q)
{
  if (v.empty ())
    return 0.0;
  const std::size_t k = std::min (v.size () - 1, static_cast<std::size_t> (q * static_cast<double> (v.size () - 1) + 0.5));
  std::nth_element (v.begin (), v.begin () + static_cast<std::ptrdiff_t> (k), v.end ());
  return v[k];
}

/** \brief Flip \a v so that its largest component is positive: a deterministic sign for
  * eigenvectors, whose sign the solver leaves arbitrary. */
inline Eigen::Vector3d
canonicalSign (const Eigen::Vector3d& v)
{
  Eigen::Index i = 0;
  v.cwiseAbs ().maxCoeff (&i);
  return v[i] < 0.0 ? Eigen::Vector3d (-v) : v;
}

/** \brief Per-label shape: plane normal pointing away from the scene centre, and how far and how
  * large the plane is, for shading and for the cut-away. */
struct LabelShape
{
  std::size_t count = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero ();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ (); ///< outward: away from the scene's mean
  double offset = 0.0;     ///< distance of the label's mean from the scene's mean along normal
  double area = 0.0;       ///< sqrt of the product of the two in-plane variances
  /** \brief A large plane at the scene's boundary facing another one across the scene (a room's
    * wall, floor or ceiling): the kind of plane that hides the inside and may be cut away. */
  bool enclosing = false;
};

/** \brief What both views share: the valid points, a robust centre and size, principal axes. */
struct SceneFrame
{
  std::vector<std::size_t> valid;                     ///< indices of finite points
  Eigen::Vector3d centre = Eigen::Vector3d::Zero ();  ///< component-wise median
  Eigen::Vector3d mean = Eigen::Vector3d::Zero ();    ///< mean of the kept points, relative to centre
  Eigen::Vector3d small_axis = Eigen::Vector3d::UnitZ ();
  Eigen::Vector3d mid_axis = Eigen::Vector3d::UnitY ();
  Eigen::Vector3d large_axis = Eigen::Vector3d::UnitX ();
  double radius = 1.0;     ///< 98th percentile of distances to the centre
  double area = 0.0;       ///< sqrt of the product of the two largest variances
  std::size_t kept = 0;    ///< points within twice the radius, used for the statistics
  std::map<std::uint32_t, LabelShape> shapes;
};

/** \brief Fill \a f. Centre and size are robust (median, 98th percentile), so that a few far
  * outliers neither move nor shrink the view; positions are taken relative to the centre in
  * double precision, so clouds far from the origin keep their detail. */
inline void
analyseScene (const pcl::PointCloud<pcl::PointXYZ>& cloud, const std::vector<std::uint32_t>& labels, SceneFrame& f)
{
  f.valid.clear ();
  f.valid.reserve (cloud.size ());
  for (std::size_t i = 0; i < cloud.size (); ++i)
  {
    const auto& p = cloud[i];
    if (std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z))
      f.valid.push_back (i);
  }
  if (f.valid.empty ())
    return;
  {
    std::vector<double> coord (f.valid.size ());
    for (int a = 0; a < 3; ++a)
    {
      for (std::size_t j = 0; j < f.valid.size (); ++j)
        coord[j] = cloud[f.valid[j]].data[a];
      f.centre[a] = quantile (coord, 0.5);
    }
  }
  std::vector<double> dist (f.valid.size ());
  double max_dist = 0.0;
  for (std::size_t j = 0; j < f.valid.size (); ++j)
  {
    dist[j] = (cloud[f.valid[j]].getVector3fMap ().cast<double> () - f.centre).norm ();
    max_dist = std::max (max_dist, dist[j]);
  }
  {
    std::vector<double> sorted = dist;
    f.radius = quantile (sorted, 0.98);
  }
  if (!(f.radius > 0.0))
    f.radius = max_dist > 0.0 ? max_dist : 1.0;

  Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero ();
  f.kept = 0;
  for (std::size_t j = 0; j < f.valid.size (); ++j)
  {
    if (dist[j] > 2.0 * f.radius)
      continue;
    const std::size_t i = f.valid[j];
    const Eigen::Vector3d q = cloud[i].getVector3fMap ().cast<double> () - f.centre;
    ++f.kept;
    sum += q;
    outer += q * q.transpose ();
    if (labels[i] != 0)
    {
      LabelShape& s = f.shapes[labels[i]];
      ++s.count;
      s.sum += q;
      s.outer += q * q.transpose ();
    }
  }
  const double n = static_cast<double> (std::max<std::size_t> (f.kept, 1));
  f.mean = sum / n;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (outer / n - f.mean * f.mean.transpose ());
  const Eigen::Vector3d eval = solver.eigenvalues ().cwiseMax (0.0);  // ascending
  f.area = std::sqrt (eval[1] * eval[2]);
  f.mid_axis = canonicalSign (solver.eigenvectors ().col (1));
  f.large_axis = canonicalSign (solver.eigenvectors ().col (2));
  f.small_axis = solver.eigenvectors ().col (0);
  // Most scenes are z-up: make the thin axis point up when it is roughly vertical.
  if (std::abs (f.small_axis.z ()) >= 0.3)
    f.small_axis = f.small_axis.z () < 0.0 ? Eigen::Vector3d (-f.small_axis) : f.small_axis;
  else
    f.small_axis = canonicalSign (f.small_axis);

  for (auto& entry : f.shapes)
  {
    LabelShape& s = entry.second;
    const double c = static_cast<double> (s.count);
    const Eigen::Vector3d m = s.sum / c;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> ls (s.outer / c - m * m.transpose ());
    s.normal = ls.eigenvectors ().col (0);
    s.offset = (m - f.mean).dot (s.normal);
    if (s.offset < 0.0)
    {
      s.normal = -s.normal;
      s.offset = -s.offset;
    }
    const Eigen::Vector3d lev = ls.eigenvalues ().cwiseMax (0.0);
    s.area = std::sqrt (lev[1] * lev[2]);
  }
  const auto boundary = [&] (const LabelShape& s) {
    return s.count >= 3 && static_cast<double> (s.count) >= 0.005 * n && s.offset > 0.2 * f.radius &&
           s.area >= 0.3 * f.area;
  };
  // Only planes with a counterpart on the far side enclose anything: an open scene (a wall and
  // its floor, a facade) is never cut away.
  for (auto& a : f.shapes)
  {
    if (!boundary (a.second))
      continue;
    for (const auto& b : f.shapes)
      if (b.first != a.first && boundary (b.second) && a.second.normal.dot (b.second.normal) < -0.8)
      {
        a.second.enclosing = true;
        break;
      }
  }
}

/** \brief Draw the scene seen from direction \a to_camera into the panel of \a image that starts
  * at column \a x0 and is \a pw x \a ph pixels (\a image is \a width pixels wide, RGB).
  *
  * Enclosing planes that face the camera (a room's ceiling and near walls) are left out, so the
  * inside stays visible; the other panel shows them. */
inline void
renderView (const pcl::PointCloud<pcl::PointXYZ>& cloud, const std::vector<std::uint32_t>& labels,
            const SceneFrame& f, const Eigen::Vector3d& to_camera, std::vector<std::uint8_t>& image, int width,
            int x0, int pw, int ph)
{
  if (f.valid.empty () || pw < 1 || ph < 1)
    return;
  const double cam_dist = 3.0 * f.radius;
  const Eigen::Vector3d camera = f.mean + cam_dist * to_camera;  // relative to the centre
  const Eigen::Vector3d forward = -to_camera;
  Eigen::Vector3d right = forward.cross (f.small_axis);
  if (right.norm () < 1e-6)
    right = forward.cross (f.large_axis);
  right.normalize ();
  const Eigen::Vector3d up = right.cross (forward);

  // Per label: shade by how squarely the plane faces the camera; cut away near boundary planes.
  struct LabelLook
  {
    double shade = 0.85;
    bool hidden = false;
  };
  std::map<std::uint32_t, LabelLook> looks;
  for (const auto& entry : f.shapes)
  {
    const LabelShape& s = entry.second;
    const double facing = s.normal.dot (to_camera);
    LabelLook& look = looks[entry.first];
    look.shade = 0.62 + 0.38 * std::abs (facing);
    look.hidden = s.enclosing && facing > 0.25;
  }

  struct Projected
  {
    float x, y, z;
    std::uint32_t label;
    std::uint8_t rgb[3];
    bool hidden;
  };
  std::vector<Projected> proj;
  proj.reserve (f.valid.size ());
  std::vector<double> xs, ys, zs;
  xs.reserve (f.valid.size ());
  ys.reserve (f.valid.size ());
  zs.reserve (f.valid.size ());
  std::size_t drawn = 0;
  for (const std::size_t i : f.valid)
  {
    const Eigen::Vector3d v = cloud[i].getVector3fMap ().cast<double> () - f.centre - camera;
    const double z = v.dot (forward);
    if (z <= 1e-6 * cam_dist)
      continue;  // behind the camera: only far outliers
    Projected p;
    p.x = static_cast<float> (v.dot (right) / z);
    p.y = static_cast<float> (v.dot (up) / z);
    p.z = static_cast<float> (z);
    p.label = labels[i];
    const auto it = p.label ? looks.find (p.label) : looks.end ();
    p.hidden = it != looks.end () && it->second.hidden;
    const double shade = it != looks.end () ? it->second.shade : 0.85;
    const auto colour = labelColour (p.label);
    for (int k = 0; k < 3; ++k)
      p.rgb[k] = static_cast<std::uint8_t> (std::min (255.0, colour[k] * shade));
    proj.push_back (p);
    // Frame on every point, hidden or not, so that both panels show the scene at one scale.
    xs.push_back (p.x);
    ys.push_back (p.y);
    if (!p.hidden)
    {
      zs.push_back (p.z);
      ++drawn;
    }
  }
  if (proj.empty ())
    return;

  const double fx0 = quantile (xs, 0.005), fx1 = quantile (xs, 0.995);
  const double fy0 = quantile (ys, 0.005), fy1 = quantile (ys, 0.995);
  const double z0 = quantile (zs, 0.01), z1 = quantile (zs, 0.99);
  const double margin = 0.05;
  const double sx = (fx1 > fx0) ? pw * (1.0 - 2.0 * margin) / (fx1 - fx0) : 1.0;
  const double sy = (fy1 > fy0) ? ph * (1.0 - 2.0 * margin) / (fy1 - fy0) : 1.0;
  double scale = std::min (sx, sy);
  if (!(scale > 0.0) || !std::isfinite (scale))
    scale = 1.0;
  const double cx = 0.5 * (fx0 + fx1), cy = 0.5 * (fy0 + fy1);

  // Splat side from the pixels per point in the framed area: dense clouds get single pixels,
  // sparse ones squares or discs large enough to close most gaps.
  const double framed = std::max (1.0, (fx1 - fx0) * scale * (fy1 - fy0) * scale);
  const double spacing = std::sqrt (framed / static_cast<double> (std::max<std::size_t> (drawn, 1)));
  const int max_side = std::max (1, std::min (pw, ph) / 60);
  const int side = std::max (1, std::min (max_side, static_cast<int> (std::lround (2.2 * spacing))));
  const int lo = -(side - 1) / 2, hi = side / 2;
  const double disc_r2 = 0.25 * side * side + 0.5;
  const double zspan = z1 > z0 ? z1 - z0 : 1.0;

  const std::size_t npix = static_cast<std::size_t> (pw) * static_cast<std::size_t> (ph);
  std::vector<float> zbuf (npix, std::numeric_limits<float>::infinity ());
  std::vector<std::uint32_t> lbuf (npix, 0);  // label + 1; 0 marks an empty pixel
  std::vector<std::uint8_t> front (npix * 3, 0);
  for (const Projected& p : proj)
  {
    if (p.hidden)
      continue;
    const double px = 0.5 * pw + (p.x - cx) * scale;
    const double py = 0.5 * ph - (p.y - cy) * scale;
    if (!(px > -side && px < pw + side && py > -side && py < ph + side))
      continue;
    const int ix = static_cast<int> (std::floor (px)), iy = static_cast<int> (std::floor (py));
    // Nearer is brighter; a gentle ramp keeps far colours recognisable.
    const double t = std::min (1.0, std::max (0.0, (p.z - z0) / zspan));
    const double depth_shade = 1.0 - 0.4 * t;
    std::uint8_t rgb[3];
    for (int k = 0; k < 3; ++k)
      rgb[k] = static_cast<std::uint8_t> (p.rgb[k] * depth_shade);
    for (int dy = lo; dy <= hi; ++dy)
    {
      const int y = iy + dy;
      if (y < 0 || y >= ph)
        continue;
      for (int dx = lo; dx <= hi; ++dx)
      {
        const int x = ix + dx;
        if (x < 0 || x >= pw)
          continue;
        const double ddx = dx - 0.5 * (lo + hi), ddy = dy - 0.5 * (lo + hi);
        if (side >= 4 && ddx * ddx + ddy * ddy > disc_r2)
          continue;  // round splats once they are big enough for corners to show
        const std::size_t k = static_cast<std::size_t> (y) * pw + x;
        if (p.z < zbuf[k])
        {
          zbuf[k] = p.z;
          std::memcpy (&front[k * 3], rgb, 3);
          lbuf[k] = p.label + 1;
        }
      }
    }
  }

  // Close single-pixel holes between splats (random sampling leaves some even at the right
  // density): an empty pixel mostly surrounded by points takes their mean colour and the label
  // of the nearest of them.
  {
    const std::vector<float> z_in = zbuf;
    const std::vector<std::uint32_t> l_in = lbuf;
    const std::vector<std::uint8_t> c_in = front;
    for (int y = 1; y + 1 < ph; ++y)
    {
      for (int x = 1; x + 1 < pw; ++x)
      {
        const std::size_t k = static_cast<std::size_t> (y) * pw + x;
        if (l_in[k] != 0)
          continue;
        int covered = 0;
        int sum[3] = {0, 0, 0};
        std::size_t nearest = k;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
          {
            const std::size_t q = static_cast<std::size_t> (y + dy) * pw + (x + dx);
            if (l_in[q] == 0)
              continue;
            ++covered;
            for (int c = 0; c < 3; ++c)
              sum[c] += c_in[q * 3 + c];
            if (nearest == k || z_in[q] < z_in[nearest])
              nearest = q;
          }
        if (covered < 5)
          continue;
        for (int c = 0; c < 3; ++c)
          front[k * 3 + c] = static_cast<std::uint8_t> (sum[c] / covered);
        lbuf[k] = l_in[nearest];
      }
    }
  }

  // Compose into the panel, with dark outlines where the label changes.
  for (int y = 0; y < ph; ++y)
  {
    for (int x = 0; x < pw; ++x)
    {
      const std::size_t k = static_cast<std::size_t> (y) * pw + x;
      if (lbuf[k] == 0)
        continue;
      std::uint8_t* out = &image[(static_cast<std::size_t> (y) * width + x0 + x) * 3];
      std::memcpy (out, &front[k * 3], 3);
      const bool edge = (x + 1 < pw && lbuf[k + 1] != 0 && lbuf[k + 1] != lbuf[k]) ||
                        (y + 1 < ph && lbuf[k + pw] != 0 && lbuf[k + pw] != lbuf[k]);
      if (edge)
        for (int c = 0; c < 3; ++c)
          out[c] = static_cast<std::uint8_t> (out[c] * 0.45);
    }
  }
}
} // namespace detail

/** \brief Render \a cloud coloured by \a labels into a PNG file.
  *
  * Two perspective views side by side, each looking at the scene's middle: the left one from
  * 45° above the plane of the two largest principal axes (above in +z when the thinnest axis is
  * roughly vertical), turned 35° off the largest axis so that two walls of a room show; the
  * right one from the opposite direction (below and behind). In each view, the planes that enclose
  * the scene (large, at its boundary, with a counterpart across it) and face the camera, such as a
  * room's ceiling and near walls, are cut away so the inside is visible; the other view shows them. Every plane label thus appears at least once.
  * Colours come from labelColour() (grey for label 0), shaded by depth and by the plane's
  * orientation, with dark outlines between labels. Splat size follows panel size and point
  * count; framing ignores the 0.5 % most extreme points so stray outliers do not shrink the scene.
  *
  * \param[in] cloud the points (non-finite ones are skipped)
  * \param[in] labels one per point, 0 = no plane
  * \param[in] path the PNG to write (atomically: temporary file, then rename)
  * \param[in] width image width in pixels (16..16384), split between the two views
  * \param[in] height image height in pixels (16..16384)
  * \param[out] error message on failure
  * \return true on success
  */
inline bool
renderPng (const pcl::PointCloud<pcl::PointXYZ>& cloud, const std::vector<std::uint32_t>& labels,
           const std::string& path, int width, int height, std::string& error)
{
  if (width < 16 || height < 16 || width > 16384 || height > 16384)
  {
    error = path + ": image size " + std::to_string (width) + "x" + std::to_string (height) +
            " out of range (16..16384)";
    return false;
  }
  if (labels.size () != cloud.size ())
  {
    error = path + ": " + std::to_string (labels.size ()) + " labels for " + std::to_string (cloud.size ()) + " points";
    return false;
  }
  const std::size_t npix = static_cast<std::size_t> (width) * static_cast<std::size_t> (height);
  const std::uint8_t background[3] = {24, 26, 30};
  std::vector<std::uint8_t> image (npix * 3);
  for (std::size_t i = 0; i < npix; ++i)
    std::memcpy (&image[i * 3], background, 3);

  detail::SceneFrame frame;
  detail::analyseScene (cloud, labels, frame);
  const double deg = 3.14159265358979323846 / 180.0;
  const Eigen::Vector3d horizontal =
      std::cos (35.0 * deg) * frame.large_axis + std::sin (35.0 * deg) * frame.mid_axis;
  const Eigen::Vector3d from_above =
      (std::sin (45.0 * deg) * frame.small_axis + std::cos (45.0 * deg) * horizontal).normalized ();
  const int separator = 2;
  const int left = (width - separator) / 2;
  const int right = width - separator - left;
  detail::renderView (cloud, labels, frame, from_above, image, width, 0, left, height);
  detail::renderView (cloud, labels, frame, -from_above, image, width, left + separator, right, height);
  for (int y = 0; y < height; ++y)
    for (int x = left; x < left + separator; ++x)
      std::memset (&image[(static_cast<std::size_t> (y) * width + x) * 3], 70, 3);

  std::vector<png_bytep> rows (static_cast<std::size_t> (height));
  for (int y = 0; y < height; ++y)
    rows[static_cast<std::size_t> (y)] = &image[static_cast<std::size_t> (y) * width * 3];
  std::string tmp;
  if (!createTempFileFor (path, tmp, error))
    return false;
  detail::PngErrorState state;
  state.message[0] = '\0';
  if (!detail::writePngRgb (tmp.c_str (), width, height, rows.data (), &state))
  {
    discardTempFile (tmp);
    error = path + ": writing the PNG failed: " + state.message;
    return false;
  }
  return commitTempFile (tmp, path, error);
}

} // namespace rspd_tools
