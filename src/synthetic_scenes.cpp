// SPDX-License-Identifier: BSD-3-Clause
/*
 * pcl_rspd: synthetic scenes with per-point plane ground truth.
 *
 * Every random number is derived from std::mt19937 (whose output sequence is fixed by the
 * standard) through the small transforms in SceneRandom below, never through the standard
 * distributions, whose algorithms are implementation-defined. A seed therefore gives the same
 * scene with any conforming standard library.
 */

#include <pcl_rspd/synthetic_scenes.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace pcl
{
namespace rspd
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

/** \brief Portable random numbers on top of std::mt19937. */
class SceneRandom
{
  public:
    explicit SceneRandom (std::uint32_t seed) : engine_ (seed) {}

    /** \brief Uniform double in [0, 1) with 53 random bits. */
    double
    uniform ()
    {
      const std::uint64_t a = engine_ () >> 5;  // 27 bits
      const std::uint64_t b = engine_ () >> 6;  // 26 bits
      return static_cast<double> ((a << 26) | b) * (1.0 / 9007199254740992.0);
    }

    /** \brief Uniform double in [lo, hi). */
    double
    uniform (double lo, double hi)
    {
      return lo + (hi - lo) * uniform ();
    }

    /** \brief Uniform index in [0, n); n must be > 0. */
    std::size_t
    index (std::size_t n)
    {
      const auto i = static_cast<std::size_t> (uniform () * static_cast<double> (n));
      return std::min (i, n - 1);
    }

    /** \brief Standard normal sample (Box-Muller; the second value of each pair is kept). */
    double
    normal ()
    {
      if (has_spare_)
      {
        has_spare_ = false;
        return spare_;
      }
      // 1 - u lies in (0, 1], so the logarithm stays finite.
      const double radius = std::sqrt (-2.0 * std::log (1.0 - uniform ()));
      const double angle = 2.0 * kPi * uniform ();
      spare_ = radius * std::sin (angle);
      has_spare_ = true;
      return radius * std::cos (angle);
    }

    /** \brief Direction uniformly distributed on the unit sphere (Archimedes: z is uniform). */
    Eigen::Vector3d
    unitVector ()
    {
      const double z = uniform (-1.0, 1.0);
      const double phi = uniform (0.0, 2.0 * kPi);
      const double r = std::sqrt (std::max (0.0, 1.0 - z * z));
      return {r * std::cos (phi), r * std::sin (phi), z};
    }

  private:
    std::mt19937 engine_;
    double spare_ = 0.0;
    bool has_spare_ = false;
};

/** \brief A scene's dimensions: the documented value for layout 0, else drawn uniformly from a
  * range by a stream of its own, so that the layout never changes the samples' random numbers
  * beyond what the geometry itself changes. */
class LayoutDraw
{
  public:
    explicit LayoutDraw (std::uint32_t layout)
      : varied_ (layout != 0), rng_ (layout * 0x9e3779b1u ^ 0x68e31da4u) {}

    /** \brief \a nominal for layout 0, else uniform in [lo, hi). */
    double
    operator() (double nominal, double lo, double hi)
    {
      return varied_ ? rng_.uniform (lo, hi) : nominal;
    }

    /** \brief \a nominal for layout 0, else uniform in [lo, hi] (hi < lo counts as lo). */
    int
    count (int nominal, int lo, int hi)
    {
      if (!varied_)
        return nominal;
      return lo + static_cast<int> (rng_.index (static_cast<std::size_t> (std::max (hi - lo, 0) + 1)));
    }

    bool
    varied () const
    {
      return varied_;
    }

  private:
    bool varied_;
    SceneRandom rng_;
};

/** \brief One generated sample before it is written into the cloud. */
struct Sample
{
  Eigen::Vector3d p;
  std::uint32_t label;  ///< candidate plane id (1-based, creation order) or 0
  SurfaceKind kind;
};

/** \brief A parallelogram (rectangle in practice): origin + a * u + b * v, a, b in [0, 1]. */
struct Rect
{
  Eigen::Vector3d origin = Eigen::Vector3d::Zero ();
  Eigen::Vector3d u = Eigen::Vector3d::Zero ();
  Eigen::Vector3d v = Eigen::Vector3d::Zero ();

  Eigen::Vector3d
  normal () const
  {
    return u.cross (v).normalized ();
  }

  double
  area () const
  {
    return u.cross (v).norm ();
  }
};

/** \brief Axis-aligned rectangle given by its fixed axis, the fixed coordinate and the ranges of
  * the two other axes, in increasing axis order (x-y for axis 2, x-z for axis 1, y-z for axis 0).
  */
Rect
axisRect (int axis, double value, double lo0, double hi0, double lo1, double hi1)
{
  const int i0 = (axis == 0) ? 1 : 0;
  const int i1 = (axis == 2) ? 1 : 2;
  Rect r;
  r.origin = Eigen::Vector3d::Zero ();
  r.origin[axis] = value;
  r.origin[i0] = lo0;
  r.origin[i1] = lo1;
  r.u = Eigen::Vector3d::Zero ();
  r.u[i0] = hi0 - lo0;
  r.v = Eigen::Vector3d::Zero ();
  r.v[i1] = hi1 - lo1;
  return r;
}

/** \brief A region a plane sample must not fall into, because another object covers it there:
  * an axis-aligned box, or a finite cylinder when radius > 0. */
struct Exclusion
{
  Eigen::Vector3d box_min = Eigen::Vector3d::Zero ();
  Eigen::Vector3d box_max = Eigen::Vector3d::Zero ();
  Eigen::Vector3d base = Eigen::Vector3d::Zero ();   ///< cylinder base centre
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ ();  ///< unit cylinder axis
  double length = 0.0;                               ///< cylinder length along the axis
  double radius = 0.0;                               ///< 0 for a box

  static Exclusion
  box (const Eigen::Vector3d& lo, const Eigen::Vector3d& hi)
  {
    Exclusion e;
    e.box_min = lo;
    e.box_max = hi;
    return e;
  }

  static Exclusion
  cylinder (const Eigen::Vector3d& base, const Eigen::Vector3d& axis, double length, double radius)
  {
    Exclusion e;
    e.base = base;
    e.axis = axis.normalized ();
    e.length = length;
    e.radius = radius;
    return e;
  }

  bool
  contains (const Eigen::Vector3d& p) const
  {
    if (radius <= 0.0)
      return (p.array () >= box_min.array ()).all () && (p.array () <= box_max.array ()).all ();
    const Eigen::Vector3d d = p - base;
    const double h = d.dot (axis);
    if (h < 0.0 || h > length)
      return false;
    return (d - h * axis).squaredNorm () < radius * radius;
  }
};

/** \brief A surface sampled uniformly by area (for every scene except the scanned room). */
struct Surface
{
  double area = 0.0;           ///< area actually exposed (exclusions already subtracted)
  std::uint32_t label = 0;     ///< candidate plane id, 0 for curved surfaces
  SurfaceKind kind = SurfaceKind::Plane;
  /** Draws one noise-free point and its unit normal; the caller adds the noise. */
  std::function<void (SceneRandom&, Eigen::Vector3d&, Eigen::Vector3d&)> draw;
};

Surface
planeSurface (const Rect& rect, std::uint32_t label, std::vector<Exclusion> exclusions = {},
              double excluded_area = 0.0)
{
  Surface s;
  s.area = rect.area () - excluded_area;
  s.label = label;
  s.kind = SurfaceKind::Plane;
  const Eigen::Vector3d n = rect.normal ();
  s.draw = [rect, n, exclusions] (SceneRandom& rng, Eigen::Vector3d& p, Eigen::Vector3d& normal)
  {
    // Rejection sampling keeps the density uniform over the exposed part; the exposed share is
    // large for every surface built here, so the loop ends quickly.
    for (int attempt = 0; attempt < 100000; ++attempt)
    {
      const double a = rng.uniform ();
      const double b = rng.uniform ();
      p = rect.origin + a * rect.u + b * rect.v;
      const bool hidden = std::any_of (exclusions.begin (), exclusions.end (),
                                       [&p] (const Exclusion& e) { return e.contains (p); });
      if (!hidden)
      {
        normal = n;
        return;
      }
    }
    throw std::logic_error ("synthetic scene: a plane surface is entirely excluded");
  };
  return s;
}

/** \brief Side of a finite open cylinder (no caps). */
Surface
cylinderSurface (const Eigen::Vector3d& base, const Eigen::Vector3d& axis, double length,
                 double radius)
{
  Surface s;
  s.area = 2.0 * kPi * radius * length;
  s.kind = SurfaceKind::Curved;
  const Eigen::Vector3d a = axis.normalized ();
  const Eigen::Vector3d e1 = a.unitOrthogonal ();
  const Eigen::Vector3d e2 = a.cross (e1);
  s.draw = [=] (SceneRandom& rng, Eigen::Vector3d& p, Eigen::Vector3d& normal)
  {
    const double angle = rng.uniform (0.0, 2.0 * kPi);
    const double h = rng.uniform (0.0, length);
    normal = std::cos (angle) * e1 + std::sin (angle) * e2;
    p = base + h * a + radius * normal;
  };
  return s;
}

/** \brief Upper (+z) half of a sphere, e.g. a tank's dome. */
Surface
domeSurface (const Eigen::Vector3d& centre, double radius)
{
  Surface s;
  s.area = 2.0 * kPi * radius * radius;
  s.kind = SurfaceKind::Curved;
  s.draw = [=] (SceneRandom& rng, Eigen::Vector3d& p, Eigen::Vector3d& normal)
  {
    // Height uniform in [0, 1) gives uniform area density on a sphere zone.
    const double z = rng.uniform ();
    const double phi = rng.uniform (0.0, 2.0 * kPi);
    const double r = std::sqrt (std::max (0.0, 1.0 - z * z));
    normal = Eigen::Vector3d (r * std::cos (phi), r * std::sin (phi), z);
    p = centre + radius * normal;
  };
  return s;
}

/** \brief Split \a total into counts proportional to \a weights, summing exactly to \a total
  * (largest remainder; ties go to the earlier entry so the result is deterministic). */
std::vector<std::size_t>
apportion (std::size_t total, const std::vector<double>& weights)
{
  std::vector<std::size_t> counts (weights.size (), 0);
  double sum = 0.0;
  for (double w : weights)
    sum += w;
  if (weights.empty () || sum <= 0.0)
    return counts;
  std::vector<std::pair<double, std::size_t>> remainders;
  std::size_t assigned = 0;
  for (std::size_t i = 0; i < weights.size (); ++i)
  {
    const double exact = static_cast<double> (total) * weights[i] / sum;
    counts[i] = static_cast<std::size_t> (std::floor (exact));
    assigned += counts[i];
    remainders.emplace_back (exact - static_cast<double> (counts[i]), i);
  }
  std::stable_sort (remainders.begin (), remainders.end (),
                    [] (const auto& l, const auto& r) { return l.first > r.first; });
  for (std::size_t k = 0; assigned < total; ++k, ++assigned)
    ++counts[remainders[k % remainders.size ()].second];
  return counts;
}

/** \brief Gaussian noise of \a sigma per axis. */
Eigen::Vector3d
isotropicNoise (double sigma, SceneRandom& rng)
{
  Eigen::Vector3d e;
  for (int a = 0; a < 3; ++a)
    e[a] = sigma * rng.normal ();
  return e;
}

/** \brief Draw \a count samples from \a surfaces proportionally to area, in surface order, with
  * Gaussian noise of \a sigma along each sample's normal (per axis if \a isotropic). */
void
sampleSurfaces (const std::vector<Surface>& surfaces, std::size_t count, double sigma, bool isotropic,
                SceneRandom& rng, std::vector<Sample>& out)
{
  std::vector<double> areas;
  for (const auto& s : surfaces)
    areas.push_back (s.area);
  const std::vector<std::size_t> counts = apportion (count, areas);
  Eigen::Vector3d p, n;
  for (std::size_t i = 0; i < surfaces.size (); ++i)
    for (std::size_t k = 0; k < counts[i]; ++k)
    {
      surfaces[i].draw (rng, p, n);
      if (sigma > 0.0)
        p += isotropic ? isotropicNoise (sigma, rng) : Eigen::Vector3d (sigma * rng.normal () * n);
      out.push_back ({p, surfaces[i].label, surfaces[i].kind});
    }
}

/** \brief Nominal extent and centre of a scene's geometry (before noise and options). */
struct Extent
{
  Eigen::Vector3d min_pt;
  Eigen::Vector3d max_pt;

  Eigen::Vector3d
  centre () const
  {
    return 0.5 * (min_pt + max_pt);
  }
};

/** \brief Outliers uniform in the scene box grown by 5 % of its diagonal on every side, so that
  * some fall off the surfaces in every direction, including thin scenes such as the facade. */
void
addOutliers (const Extent& extent, std::size_t count, SceneRandom& rng, std::vector<Sample>& out)
{
  const double margin = 0.05 * (extent.max_pt - extent.min_pt).norm ();
  const Eigen::Vector3d lo = extent.min_pt.array () - margin;
  const Eigen::Vector3d hi = extent.max_pt.array () + margin;
  for (std::size_t k = 0; k < count; ++k)
  {
    Eigen::Vector3d p;
    for (int d = 0; d < 3; ++d)
      p[d] = rng.uniform (lo[d], hi[d]);
    out.push_back ({p, 0u, SurfaceKind::Outlier});
  }
}

/** \brief What a scene builder returns before the common post-processing. */
struct Generated
{
  std::vector<Sample> samples;
  Extent extent;
  std::uint32_t num_candidates = 0;  ///< candidate plane ids are 1..num_candidates
  std::size_t min_plane_samples = 1; ///< planes with fewer samples are not ground truth
  bool has_sensor = false;           ///< scanned scene: the samples were seen from \a sensor
  Eigen::Vector3d sensor = Eigen::Vector3d::Zero ();
};

/** \brief Resolved option values shared by the builders. */
struct Params
{
  std::size_t num_points;
  std::size_t num_outliers;
  double noise;
  bool isotropic;        ///< SceneOptions::isotropic_noise
  std::uint32_t layout;  ///< SceneOptions::layout
  bool scan_grid;        ///< SceneOptions::scan_grid
};

// ---------------------------------------------------------------------------------------------
// Area-sampled scenes

/** \brief Cube [-0.5, 0.5]^3 (a box of edges 0.5-1.5 for layout > 0, centred on the origin):
  * 6 face planes. */
Generated
buildCube (const Params& prm, SceneRandom& rng)
{
  LayoutDraw draw (prm.layout);
  Eigen::Vector3d half;
  for (int d = 0; d < 3; ++d)
    half[d] = 0.5 * draw (1.0, 0.5, 1.5);
  Generated g;
  g.extent = {-half, half};
  std::vector<Surface> surfaces;
  std::uint32_t label = 0;
  for (int axis = 0; axis < 3; ++axis)
  {
    const int a0 = axis == 0 ? 1 : 0, a1 = axis == 2 ? 1 : 2;  // the two other axes, in order
    for (double side : {-1.0, 1.0})
      surfaces.push_back (planeSurface (
        axisRect (axis, side * half[axis], -half[a0], half[a0], -half[a1], half[a1]), ++label));
  }
  g.num_candidates = label;
  sampleSurfaces (surfaces, prm.num_points - prm.num_outliers, prm.noise, prm.isotropic, rng, g.samples);
  return g;
}

/** \brief Staircase of 15 steps, 0.3 m deep x 0.18 m high x 1.0 m wide, rising along +x; each
  * step has a riser (vertical, label 2i + 1) and a tread (horizontal, label 2i + 2): 30 planes.
  * For layout > 0: 8-20 steps, 0.22-0.36 m deep, 0.14-0.21 m high, 0.8-1.6 m wide. */
Generated
buildStaircase (const Params& prm, SceneRandom& rng)
{
  LayoutDraw draw (prm.layout);
  const int steps = draw.count (15, 8, 20);
  const double depth = draw (0.3, 0.22, 0.36), rise = draw (0.18, 0.14, 0.21);
  const double width = draw (1.0, 0.8, 1.6);
  Generated g;
  g.extent = {Eigen::Vector3d::Zero (), Eigen::Vector3d (steps * depth, width, steps * rise)};
  std::vector<Surface> surfaces;
  std::uint32_t label = 0;
  for (int i = 0; i < steps; ++i)
  {
    const double x0 = i * depth, z0 = i * rise;
    surfaces.push_back (planeSurface (axisRect (0, x0, 0.0, width, z0, z0 + rise), ++label));
    surfaces.push_back (
      planeSurface (axisRect (2, z0 + rise, x0, x0 + depth, 0.0, width), ++label));
  }
  g.num_candidates = label;
  sampleSurfaces (surfaces, prm.num_points - prm.num_outliers, prm.noise, prm.isotropic, rng, g.samples);
  return g;
}

/** \brief Boxes of rising roughness: a floor 12 x 12 m (z = 0) and a wall 12 x 3 m (y = 6) at the
  * scene's noise, and six boxes 1.5 x 1.0 m, 0.8 to 1.8 m tall, in two rows, whose four sides and
  * top have 1, 3, 5, 7.5, 10 and 15 times that noise (2 mm to 3 cm by default): noise that differs
  * from surface to surface, as between materials and ranges in a scan. 32 planes. For layout > 0
  * the boxes' footprints are 1.0-2.0 x 0.7-1.3 m. */
Generated
buildBoxes (const Params& prm, SceneRandom& rng)
{
  const double roughness[6] = {1.0, 3.0, 5.0, 7.5, 10.0, 15.0};
  LayoutDraw draw (prm.layout);
  Generated g;
  g.extent = {Eigen::Vector3d (-6.0, -6.0, 0.0), Eigen::Vector3d (6.0, 6.0, 3.0)};
  std::vector<std::vector<Surface>> groups (7); // 0: floor and wall; 1-6: the boxes
  std::vector<Exclusion> footprints;
  double covered = 0.0;
  std::uint32_t label = 2; // 1: floor, 2: wall
  for (int i = 0; i < 6; ++i)
  {
    const Eigen::Vector3d lo (-5.25 + (i % 3) * 4.0, -3.0 + (i / 3) * 5.0, 0.0);
    const Eigen::Vector3d hi =
      lo + Eigen::Vector3d (draw (1.5, 1.0, 2.0), draw (1.0, 0.7, 1.3), 0.8 + 0.2 * i);
    footprints.push_back (Exclusion::box (Eigen::Vector3d (lo.x (), lo.y (), -1.0), hi));
    covered += (hi.x () - lo.x ()) * (hi.y () - lo.y ());
    auto& box = groups[i + 1];
    box.push_back (planeSurface (axisRect (0, lo.x (), lo.y (), hi.y (), lo.z (), hi.z ()), ++label));
    box.push_back (planeSurface (axisRect (0, hi.x (), lo.y (), hi.y (), lo.z (), hi.z ()), ++label));
    box.push_back (planeSurface (axisRect (1, lo.y (), lo.x (), hi.x (), lo.z (), hi.z ()), ++label));
    box.push_back (planeSurface (axisRect (1, hi.y (), lo.x (), hi.x (), lo.z (), hi.z ()), ++label));
    box.push_back (planeSurface (axisRect (2, hi.z (), lo.x (), hi.x (), lo.y (), hi.y ()), ++label));
  }
  groups[0].push_back (planeSurface (axisRect (2, 0.0, -6.0, 6.0, -6.0, 6.0), 1, footprints, covered));
  groups[0].push_back (planeSurface (axisRect (1, 6.0, -6.0, 6.0, 0.0, 3.0), 2));
  g.num_candidates = label;
  std::vector<double> areas;
  for (const auto& group : groups)
  {
    double a = 0.0;
    for (const auto& s : group)
      a += s.area;
    areas.push_back (a);
  }
  const std::vector<std::size_t> counts = apportion (prm.num_points - prm.num_outliers, areas);
  for (std::size_t k = 0; k < groups.size (); ++k)
    sampleSurfaces (groups[k], counts[k], k == 0 ? prm.noise : roughness[k - 1] * prm.noise, prm.isotropic,
                    rng, g.samples);
  return g;
}

/** \brief Facade 20 m wide x 10 m tall in the plane y = 0, with 5 x 3 windows of 1.6 x 1.6 m
  * whose glass is recessed 0.2 m (y = 0.2). Planes: the wall (with the window openings cut out)
  * and the 15 recessed window planes, 16 in all. The reveals (the recess side faces) are left
  * out on purpose: at 0.2 m x 1.6 m they would add 60 tiny planes, and a head-on scan sees
  * little of them. For layout > 0: 12-30 m x 6-14 m, windows of 0.9-2.0 x 1.0-2.2 m recessed
  * 0.1-0.35 m, in an even grid of at least 2 x 2 with 0.8 m or more of wall between them. */
Generated
buildFacade (const Params& prm, SceneRandom& rng)
{
  LayoutDraw draw (prm.layout);
  const double wall_w = draw (20.0, 12.0, 30.0), wall_h = draw (10.0, 6.0, 14.0);
  const double recess = draw (0.2, 0.1, 0.35);
  const double win_w = draw (1.6, 0.9, 2.0), win_h = draw (1.6, 1.0, 2.2);
  std::vector<double> col_centres {2.0, 6.0, 10.0, 14.0, 18.0};
  std::vector<double> row_centres {2.0, 5.0, 8.0};
  if (draw.varied ())
  {
    // Evenly spaced, at least 0.8 m of wall between windows and around them.
    const int cols = draw.count (0, 2, static_cast<int> (wall_w / (win_w + 0.8)));
    const int rows = draw.count (0, 2, static_cast<int> (wall_h / (win_h + 0.8)));
    col_centres.clear ();
    row_centres.clear ();
    for (int i = 0; i < cols; ++i)
      col_centres.push_back ((i + 0.5) * wall_w / cols);
    for (int i = 0; i < rows; ++i)
      row_centres.push_back ((i + 0.5) * wall_h / rows);
  }
  Generated g;
  g.extent = {Eigen::Vector3d::Zero (), Eigen::Vector3d (wall_w, recess, wall_h)};

  std::vector<Exclusion> openings;
  std::vector<Surface> windows;
  std::uint32_t label = 1;  // the wall is label 1
  for (double zc : row_centres)
    for (double xc : col_centres)
    {
      const double x0 = xc - 0.5 * win_w, z0 = zc - 0.5 * win_h;
      openings.push_back (Exclusion::box (Eigen::Vector3d (x0, -1.0, z0),
                                          Eigen::Vector3d (x0 + win_w, 1.0, z0 + win_h)));
      windows.push_back (
        planeSurface (axisRect (1, recess, x0, x0 + win_w, z0, z0 + win_h), ++label));
    }
  std::vector<Surface> surfaces;
  surfaces.push_back (planeSurface (axisRect (1, 0.0, 0.0, wall_w, 0.0, wall_h), 1, openings,
                                    static_cast<double> (openings.size ()) * win_w * win_h));
  surfaces.insert (surfaces.end (), windows.begin (), windows.end ());
  g.num_candidates = label;
  sampleSurfaces (surfaces, prm.num_points - prm.num_outliers, prm.noise, prm.isotropic, rng, g.samples);
  return g;
}

/** \brief Industrial yard, 20 x 20 m: ground, two 6 m walls meeting in a corner, a 6 x 6 x 2 m
  * platform in that corner (top and its two exposed sides) -- 6 planes -- plus curved clutter:
  * two tanks (radius 1.5 m, 8 m tall, hemispherical dome, no flat top) and four pipes
  * (two horizontal, two vertical, radius 0.1 - 0.25 m). For layout > 0: a 14-26 m yard, walls
  * 4-8 m, a platform a fifth to a third of the yard wide and 1-3 m high, tanks of radius 0.8-1.5 m
  * and 5-10 m tall, pipes of radius 0.05-0.3 m, every position scaled with the yard. */
Generated
buildIndustrial (const Params& prm, SceneRandom& rng)
{
  LayoutDraw draw (prm.layout);
  const double size = draw (20.0, 14.0, 26.0), wall_h = draw (6.0, 4.0, 8.0);
  // Platform x in [0, plat], y in [size - plat, size].
  const double plat = draw (6.0, 0.2 * size, 0.3 * size), plat_h = draw (2.0, 1.0, 3.0);
  const double tank_r = draw (1.5, 0.8, 1.5), tank_h = draw (8.0, 5.0, 10.0);
  // For other layouts every position keeps its share of the yard and of the wall height.
  const double f = size / 20.0, h = wall_h / 6.0;
  const Eigen::Vector3d tanks[] = {{11.0 * f, 15.0 * f, 0.0}, {16.0 * f, 15.0 * f, 0.0}};
  struct Pipe { Eigen::Vector3d base, axis; double length, radius; };
  const Pipe pipes[] = {
    // horizontal, from the side wall
    {{0.0, 6.0 * f, 3.0 * h}, Eigen::Vector3d::UnitX (), size, draw (0.2, 0.05, 0.3)},
    // horizontal, into the back wall
    {{19.0 * f, 0.0, 2.0 * h}, Eigen::Vector3d::UnitY (), size, draw (0.15, 0.05, 0.3)},
    // vertical risers
    {{4.0 * f, 9.0 * f, 0.0}, Eigen::Vector3d::UnitZ (), wall_h, draw (0.25, 0.05, 0.3)},
    {{8.0 * f, 3.0 * f, 0.0}, Eigen::Vector3d::UnitZ (), 5.0 * h, draw (0.1, 0.05, 0.3)}};

  Generated g;
  g.extent = {Eigen::Vector3d::Zero (), Eigen::Vector3d (size, size, tank_h + tank_r)};

  // Parts of the planes covered by the platform, tank bottoms and pipe ends carry no samples.
  const Exclusion platform = Exclusion::box (Eigen::Vector3d (-1.0, size - plat, -1.0),
                                             Eigen::Vector3d (plat, size + 1.0, plat_h));
  std::vector<Exclusion> ground_ex {platform};
  double ground_hidden = plat * plat;
  for (const auto& t : tanks)
  {
    ground_ex.push_back (Exclusion::cylinder (t, Eigen::Vector3d::UnitZ (), tank_h, tank_r));
    ground_hidden += kPi * tank_r * tank_r;
  }
  std::vector<Exclusion> side_ex {platform}, back_ex {platform};
  double side_hidden = plat * plat_h, back_hidden = plat * plat_h;
  for (const auto& p : pipes)
  {
    const Exclusion e = Exclusion::cylinder (p.base, p.axis, p.length, p.radius);
    const double disc = kPi * p.radius * p.radius;
    if (p.axis.z () > 0.5)
    {
      ground_ex.push_back (e);
      ground_hidden += disc;
    }
    else if (p.axis.x () > 0.5)
    {
      side_ex.push_back (e);
      side_hidden += disc;
    }
    else
    {
      back_ex.push_back (e);
      back_hidden += disc;
    }
  }

  std::vector<Surface> surfaces;
  surfaces.push_back (planeSurface (axisRect (2, 0.0, 0.0, size, 0.0, size), 1, ground_ex,
                                    ground_hidden));
  surfaces.push_back (planeSurface (axisRect (1, size, 0.0, size, 0.0, wall_h), 2, back_ex,
                                    back_hidden));
  surfaces.push_back (planeSurface (axisRect (0, 0.0, 0.0, size, 0.0, wall_h), 3, side_ex,
                                    side_hidden));
  surfaces.push_back (planeSurface (axisRect (2, plat_h, 0.0, plat, size - plat, size), 4));
  surfaces.push_back (planeSurface (axisRect (1, size - plat, 0.0, plat, 0.0, plat_h), 5));
  surfaces.push_back (planeSurface (axisRect (0, plat, size - plat, size, 0.0, plat_h), 6));
  g.num_candidates = 6;
  for (const auto& t : tanks)
  {
    surfaces.push_back (cylinderSurface (t, Eigen::Vector3d::UnitZ (), tank_h, tank_r));
    surfaces.push_back (domeSurface (t + Eigen::Vector3d (0.0, 0.0, tank_h), tank_r));
  }
  for (const auto& p : pipes)
    surfaces.push_back (cylinderSurface (p.base, p.axis, p.length, p.radius));
  sampleSurfaces (surfaces, prm.num_points - prm.num_outliers, prm.noise, prm.isotropic, rng, g.samples);
  return g;
}

/** \brief One noise-free (by default) 1 x 1 square in the plane z = 0, centred on the origin. */
Generated
buildPlane (const Params& prm, SceneRandom& rng)
{
  Generated g;
  g.extent = {Eigen::Vector3d (-0.5, -0.5, 0.0), Eigen::Vector3d (0.5, 0.5, 0.0)};
  std::vector<Surface> surfaces {planeSurface (axisRect (2, 0.0, -0.5, 0.5, -0.5, 0.5), 1)};
  g.num_candidates = 1;
  sampleSurfaces (surfaces, prm.num_points - prm.num_outliers, prm.noise, prm.isotropic, rng, g.samples);
  return g;
}

// ---------------------------------------------------------------------------------------------
// Scanned room

/** \brief Something a ray can hit in the room. */
struct RayTarget
{
  enum class Type { Rect, VerticalCylinder, Sphere } type = Type::Rect;
  Rect rect;                 ///< for Rect
  /** Cylinder base centre (its z is the bottom) or sphere centre. */
  Eigen::Vector3d centre = Eigen::Vector3d::Zero ();
  double radius = 0.0;
  double height = 0.0;       ///< cylinder height
  std::uint32_t label = 0;   ///< candidate plane id, 0 for curved targets
  Eigen::Vector3d rect_normal = Eigen::Vector3d::Zero ();  ///< u x v, cached for the rays
  double inv_uu = 0.0;       ///< 1 / |u|^2
  double inv_vv = 0.0;       ///< 1 / |v|^2

  /** \brief Ray parameter of the first hit with t > 0, or +inf. \a d is a unit direction. */
  double
  intersect (const Eigen::Vector3d& s, const Eigen::Vector3d& d) const
  {
    const double inf = std::numeric_limits<double>::infinity ();
    switch (type)
    {
      case Type::Rect:
      {
        const double denom = rect_normal.dot (d);
        if (std::abs (denom) < 1e-12)
          return inf;
        const double t = rect_normal.dot (rect.origin - s) / denom;
        if (t <= 1e-9)
          return inf;
        const Eigen::Vector3d q = s + t * d - rect.origin;
        const double a = q.dot (rect.u) * inv_uu;
        const double b = q.dot (rect.v) * inv_vv;
        return (a >= 0.0 && a <= 1.0 && b >= 0.0 && b <= 1.0) ? t : inf;
      }
      case Type::VerticalCylinder:
      {
        // Only the near (outside) wall: the sensor is outside and the caps touch floor/ceiling.
        const Eigen::Vector2d o = s.head<2> () - centre.head<2> ();
        const Eigen::Vector2d dd = d.head<2> ();
        const double a = dd.squaredNorm ();
        if (a < 1e-12)
          return inf;
        const double b = o.dot (dd);
        const double c = o.squaredNorm () - radius * radius;
        const double disc = b * b - a * c;
        if (disc < 0.0)
          return inf;
        const double t = (-b - std::sqrt (disc)) / a;
        if (t <= 1e-9)
          return inf;
        const double z = s.z () + t * d.z ();
        return (z >= centre.z () && z <= centre.z () + height) ? t : inf;
      }
      case Type::Sphere:
      {
        const Eigen::Vector3d o = s - centre;
        const double b = o.dot (d);
        const double c = o.squaredNorm () - radius * radius;
        const double disc = b * b - c;
        if (disc < 0.0)
          return inf;
        const double t = -b - std::sqrt (disc);
        return (t > 1e-9) ? t : inf;
      }
    }
    return inf;
  }
};

RayTarget
rectTarget (const Rect& r, std::uint32_t label)
{
  RayTarget t;
  t.type = RayTarget::Type::Rect;
  t.rect = r;
  t.label = label;
  t.rect_normal = r.u.cross (r.v);
  t.inv_uu = 1.0 / r.u.squaredNorm ();
  t.inv_vv = 1.0 / r.v.squaredNorm ();
  return t;
}

/** \brief Room of 6 x 5 x 3 m (x, y, z) scanned from one position, sensor at (1.5, 1.5, 1.6).
  *
  * Rays leave the sensor in uniformly random directions and keep their first hit, so the density
  * falls with the squared distance and occluded surfaces stay empty, as in a real single scan.
  * Noise is applied along the ray (range noise). Candidate planes: floor, ceiling, 4 walls, a
  * door 0.9 x 2.0 m standing 2 cm proud of the far wall, a table top and its front panel, and a
  * cabinet against the near wall (front, side and top visible) -- 12 in all. Curved: a pillar
  * (cylinder r = 0.3 m, floor to ceiling) and a ball (sphere r = 0.3 m on the floor). For
  * layout > 0: 4.5-8 x 4-6.5 x 2.4-3.5 m, the sensor 1.3-1.8 m high, the table 0.7-0.8 m and the
  * cabinet 0.8-1.2 m high, pillar radius 0.15-0.4 m, ball radius 0.2-0.45 m, every x and y
  * position scaled with the room. */
Generated
buildRoom (const Params& prm, SceneRandom& rng)
{
  LayoutDraw draw (prm.layout);
  const double lx = draw (6.0, 4.5, 8.0), ly = draw (5.0, 4.0, 6.5), lz = draw (3.0, 2.4, 3.5);
  // For other layouts x and y positions keep their share of the room; heights are drawn.
  const double fx = lx / 6.0, fy = ly / 5.0;
  const Eigen::Vector3d sensor (1.5 * fx, 1.5 * fy, draw (1.6, 1.3, 1.8));
  const double table_h = draw (0.75, 0.7, 0.8), cabinet_h = draw (1.0, 0.8, 1.2);
  Generated g;
  g.extent = {Eigen::Vector3d::Zero (), Eigen::Vector3d (lx, ly, lz)};
  g.has_sensor = true;
  g.sensor = sensor;

  std::vector<RayTarget> targets;
  std::uint32_t label = 0;
  targets.push_back (rectTarget (axisRect (2, 0.0, 0.0, lx, 0.0, ly), ++label));   // floor
  targets.push_back (rectTarget (axisRect (2, lz, 0.0, lx, 0.0, ly), ++label));    // ceiling
  targets.push_back (rectTarget (axisRect (0, 0.0, 0.0, ly, 0.0, lz), ++label));   // wall x = 0
  targets.push_back (rectTarget (axisRect (0, lx, 0.0, ly, 0.0, lz), ++label));    // wall x = 6
  targets.push_back (rectTarget (axisRect (1, 0.0, 0.0, lx, 0.0, lz), ++label));   // wall y = 0
  targets.push_back (rectTarget (axisRect (1, ly, 0.0, lx, 0.0, lz), ++label));    // wall y = 5
  // Door on the far wall, 2 cm proud of it (one slab face; its 2 cm edges are negligible).
  targets.push_back (rectTarget (axisRect (1, ly - 0.02, 3.5 * fx, 4.4 * fx, 0.0, 2.0), ++label));
  // Table: 1.2 x 0.8 m top at 0.75 m, with a modesty panel under its sensor-facing edge.
  targets.push_back (
    rectTarget (axisRect (2, table_h, 3.0 * fx, 4.2 * fx, 2.5 * fy, 3.3 * fy), ++label));
  targets.push_back (
    rectTarget (axisRect (1, 2.5 * fy, 3.0 * fx, 4.2 * fx, 0.05, table_h), ++label));
  // Cabinet 0.8 x 0.8 x 1.0 m against wall y = 0, low enough for the sensor to see its top; the
  // faces the sensor cannot see are not modelled.
  targets.push_back (
    rectTarget (axisRect (0, 3.0 * fx, 0.0, 0.8 * fy, 0.0, cabinet_h), ++label));      // front
  targets.push_back (
    rectTarget (axisRect (1, 0.8 * fy, 3.0 * fx, 3.8 * fx, 0.0, cabinet_h), ++label)); // side
  targets.push_back (
    rectTarget (axisRect (2, cabinet_h, 3.0 * fx, 3.8 * fx, 0.0, 0.8 * fy), ++label)); // top
  g.num_candidates = label;

  RayTarget pillar;
  pillar.type = RayTarget::Type::VerticalCylinder;
  pillar.centre = Eigen::Vector3d (4.8 * fx, 3.8 * fy, 0.0);
  pillar.radius = draw (0.3, 0.15, 0.4);
  pillar.height = lz;
  targets.push_back (pillar);
  RayTarget ball;
  ball.type = RayTarget::Type::Sphere;
  ball.radius = draw (0.3, 0.2, 0.45);
  ball.centre = Eigen::Vector3d (1.0 * fx, 3.8 * fy, ball.radius);
  targets.push_back (ball);

  const std::size_t rays = prm.num_points - prm.num_outliers;
  // Scan grid: equal steps in azimuth and elevation, about as many as the rays over the sphere
  // (2 pi^2 / step^2 of them), column by column; the last column is cut where the rays run out.
  // A ray lost at a corner is replaced by the grid's next (past the last column, the first again).
  const double step = rays > 0 ? M_PI * std::sqrt (2.0 / static_cast<double> (rays)) : 1.0;
  const std::size_t rows = std::max<std::size_t> (1, static_cast<std::size_t> (std::lround (M_PI / step)));
  const std::size_t columns = (rays + rows - 1) / rows;
  std::size_t cast = 0;
  g.samples.reserve (prm.num_points);
  while (g.samples.size () < rays)
  {
    Eigen::Vector3d d;
    if (prm.scan_grid)
    {
      const double azimuth = 2.0 * M_PI * (static_cast<double> (cast / rows) + 0.5) / static_cast<double> (columns);
      const double elevation = M_PI * ((static_cast<double> (cast % rows) + 0.5) / static_cast<double> (rows) - 0.5);
      d = Eigen::Vector3d (std::cos (elevation) * std::cos (azimuth), std::cos (elevation) * std::sin (azimuth),
                           std::sin (elevation));
      ++cast;
    }
    else
      d = rng.unitVector ();
    double best = std::numeric_limits<double>::infinity ();
    const RayTarget* hit = nullptr;
    for (const auto& t : targets)
    {
      const double tt = t.intersect (sensor, d);
      if (tt < best)
      {
        best = tt;
        hit = &t;
      }
    }
    if (hit == nullptr)  // the room is closed, so this only guards against rounding at corners
      continue;
    const double range = best + (prm.noise > 0.0 && !prm.isotropic ? prm.noise * rng.normal () : 0.0);
    const Eigen::Vector3d e = prm.noise > 0.0 && prm.isotropic ? isotropicNoise (prm.noise, rng) : Eigen::Vector3d::Zero ();
    g.samples.push_back ({sensor + range * d + e, hit->label,
                          hit->label > 0 ? SurfaceKind::Plane : SurfaceKind::Curved});
  }
  // A plane seen by only a handful of rays is not a fair detection target: count a plane only
  // with at least 0.1 % of the scene's samples (200 at the default size), and never under 20.
  g.min_plane_samples = std::max<std::size_t> (20, prm.num_points / 1000);
  return g;
}

// ---------------------------------------------------------------------------------------------

struct SceneSpec
{
  const char* name;
  std::size_t default_points;
  double default_noise;
  double default_outliers;
  Generated (*build) (const Params&, SceneRandom&);
};

const SceneSpec kScenes[] = {
  {"cube", 100000, 0.01, 0.0, &buildCube},
  {"room", 200000, 0.005, 0.0, &buildRoom},
  {"staircase", 100000, 0.002, 0.0, &buildStaircase},
  {"facade", 200000, 0.03, 0.15, &buildFacade},
  {"industrial", 300000, 0.005, 0.0, &buildIndustrial},
  {"boxes", 300000, 0.002, 0.0, &buildBoxes},
  {"plane", 10000, 0.0, 0.0, &buildPlane},
};

/** \brief Random rotation, uniform over SO(3): a normalised 4-D Gaussian is a uniform unit
  * quaternion. */
Eigen::Matrix3d
randomRotation (SceneRandom& rng)
{
  Eigen::Vector4d q;
  do
  {
    for (int i = 0; i < 4; ++i)
      q[i] = rng.normal ();
  } while (q.norm () < 1e-6);
  q.normalize ();
  return Eigen::Quaterniond (q[0], q[1], q[2], q[3]).toRotationMatrix ();
}

} // namespace

std::vector<std::string>
sceneNames ()
{
  std::vector<std::string> names;
  for (const auto& s : kScenes)
    names.emplace_back (s.name);
  return names;
}

Scene
makeScene (const std::string& name, const SceneOptions& options)
{
  const SceneSpec* spec = nullptr;
  for (const auto& s : kScenes)
    if (name == s.name)
      spec = &s;
  if (spec == nullptr)
    throw std::invalid_argument ("unknown scene '" + name + "'");
  if (!std::isfinite (options.noise))
    throw std::invalid_argument ("scene noise must be finite");
  if (!std::isfinite (options.outlier_ratio) || options.outlier_ratio > 1.0)
    throw std::invalid_argument ("scene outlier ratio must be at most 1");
  if (!std::isfinite (options.scale) || options.scale <= 0.0)
    throw std::invalid_argument ("scene scale must be positive and finite");
  if (!options.offset.allFinite ())
    throw std::invalid_argument ("scene offset must be finite");
  if (options.scan_grid && name != "room")
    throw std::invalid_argument ("a scan grid applies to the scanned room only");

  Params prm;
  prm.num_points = options.num_points > 0 ? options.num_points : spec->default_points;
  prm.noise = options.noise >= 0.0 ? options.noise : spec->default_noise;
  prm.isotropic = options.isotropic_noise;
  prm.layout = options.layout;
  prm.scan_grid = options.scan_grid;
  const double ratio = options.outlier_ratio >= 0.0 ? options.outlier_ratio
                                                    : spec->default_outliers;
  prm.num_outliers = std::min (prm.num_points, static_cast<std::size_t> (
                                 std::llround (ratio * static_cast<double> (prm.num_points))));

  // Independent streams for geometry, rotation and order, so that e.g. turning shuffling off
  // or changing the rotation keeps the same samples.
  SceneRandom rng (options.seed);
  SceneRandom rotation_rng (options.seed ^ 0x9e3779b9u);
  SceneRandom shuffle_rng (options.seed ^ 0x85ebca6bu);

  Generated g = spec->build (prm, rng);
  addOutliers (g.extent, prm.num_outliers, rng, g.samples);

  // Renumber the planes that received enough samples as 1..K in candidate order; samples of a
  // plane that did not count become clutter, so that Plane always means label > 0.
  std::vector<std::size_t> counts (g.num_candidates + 1, 0);
  for (const auto& s : g.samples)
    ++counts[s.label];
  std::vector<std::uint32_t> relabel (g.num_candidates + 1, 0);
  std::uint32_t num_planes = 0;
  for (std::uint32_t c = 1; c <= g.num_candidates; ++c)
    if (counts[c] > 0 && counts[c] >= g.min_plane_samples)
      relabel[c] = ++num_planes;
  for (auto& s : g.samples)
  {
    if (s.label == 0)
      continue;
    s.label = relabel[s.label];
    if (s.label == 0)
      s.kind = SurfaceKind::Outlier;
  }

  const Eigen::Vector3d centre = g.extent.centre ();
  const Eigen::Matrix3d rotation = options.random_rotation ? randomRotation (rotation_rng)
                                                           : Eigen::Matrix3d::Identity ();
  auto transform = [&] (const Eigen::Vector3d& p) -> Eigen::Vector3d {
    const Eigen::Vector3d q =
      options.random_rotation ? Eigen::Vector3d (rotation * (p - centre) + centre) : p;
    return options.scale * q + options.offset;
  };
  for (auto& s : g.samples)
    s.p = transform (s.p);

  if (options.shuffle)
    for (std::size_t i = g.samples.size (); i > 1; --i)
      std::swap (g.samples[i - 1], g.samples[shuffle_rng.index (i)]);

  Scene scene;
  scene.name = spec->name;
  scene.num_planes = static_cast<int> (num_planes);
  scene.cloud.resize (g.samples.size ());
  scene.labels.resize (g.samples.size ());
  scene.kinds.resize (g.samples.size ());
  for (std::size_t i = 0; i < g.samples.size (); ++i)
  {
    const Eigen::Vector3f p = g.samples[i].p.cast<float> ();
    scene.cloud[i].x = p.x ();
    scene.cloud[i].y = p.y ();
    scene.cloud[i].z = p.z ();
    scene.labels[i] = g.samples[i].label;
    scene.kinds[i] = g.samples[i].kind;
  }
  scene.cloud.width = static_cast<std::uint32_t> (g.samples.size ());
  scene.cloud.height = 1;
  scene.cloud.is_dense = true;
  // Normal orientation and viewpoint-aware tools can use the scanner position.
  if (g.has_sensor)
    scene.cloud.sensor_origin_.head<3> () = transform (g.sensor).cast<float> ();
  return scene;
}

void
transformCloud (pcl::PointCloud<pcl::PointXYZ>& cloud, const SceneOptions& options)
{
  if (!(options.scale > 0.0) || !std::isfinite (options.scale))
    throw std::invalid_argument ("scene scale must be positive and finite");
  if (!options.offset.allFinite ())
    throw std::invalid_argument ("scene offset must be finite");
  // The same draw as makeScene's for this seed.
  SceneRandom rotation_rng (options.seed ^ 0x9e3779b9u);
  const Eigen::Matrix3d rotation = options.random_rotation ? randomRotation (rotation_rng)
                                                           : Eigen::Matrix3d::Identity ();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant (HUGE_VAL), hi = -lo;
  for (const auto& p : cloud)
    if (std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z))
    {
      lo = lo.cwiseMin (p.getVector3fMap ().cast<double> ());
      hi = hi.cwiseMax (p.getVector3fMap ().cast<double> ());
    }
  const Eigen::Vector3d centre = lo.allFinite () ? Eigen::Vector3d (0.5 * (lo + hi)) : Eigen::Vector3d::Zero ();
  const auto move = [&] (const Eigen::Vector3d& p) -> Eigen::Vector3d {
    return options.scale * (rotation * (p - centre) + centre) + options.offset;
  };
  for (auto& p : cloud)
    if (std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z))
      p.getVector3fMap () = move (p.getVector3fMap ().cast<double> ()).cast<float> ();
  cloud.sensor_origin_.head<3> () = move (cloud.sensor_origin_.head<3> ().cast<double> ()).cast<float> ();
}

} // namespace rspd
} // namespace pcl
