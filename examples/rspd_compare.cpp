/*
 * rspd_compare: run RSPD and two classic PCL plane detectors on the same cloud with the same
 * normals, each in a process of its own, and compare time, peak memory and the paper's scores.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 *   rspd_compare CLOUD [TRUTH] [-k 50] [--threads N] [--voxel 0.01] [--phases N] [--methods rspd,sac,rg,...] [--json]
 *   rspd_compare --scene NAME [-n N] [--seed S] [...same options]
 *
 * Methods:
 *  - rspd: pcl::RobustPlaneSegmentation with its defaults and the shared normals;
 *  - sac:  pcl::SACSegmentation (RANSAC, plane) in the usual extract-and-repeat loop;
 *  - rg:   pcl::RegionGrowing with the shared normals, one least-squares plane per region;
 *  - cgal_rg, cgal_ransac: CGAL's region growing and Efficient RANSAC (cgal_peers.h), in builds
 *    made where CGAL is installed; the settings of issue #6's peer table.
 * Every method labels the points 0 (no plane) and 1..K by decreasing plane size.
 *
 * Exit status: 0 when the comparison was printed (a method whose process crashed or was killed is
 * reported as failed, the others still run), 1 on an unreadable cloud or truth or when the
 * normals cannot be computed, 2 on a usage error. Errors are one line on stderr.
 */

#include "cgal_peers.h"
#include "child_process.h"
#include "cloud_io.h"
#include "command_line.h"
#include "label_io.h"

#include <pcl_rspd/plane_evaluation.h>
#include <pcl_rspd/robust_plane_segmentation.h>
#include <pcl_rspd/synthetic_scenes.h>

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/common/common.h>
#include <pcl/console/print.h>
#include <pcl/features/normal_3d.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/region_growing.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <limits>
#include <new>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using rspd_tools::OptionArgument;
using rspd_tools::UsageError;

/** \brief Parse the whole string as an integer in [lo, hi]. */
bool
parseInteger (const std::string& s, long long lo, long long hi, long long& value)
{
  return rspd_tools::parseInteger (s, lo, hi, value);
}

const char* const kUsage =
    "usage: rspd_compare CLOUD [TRUTH] [-k 50] [--threads N] [--voxel 0.01] [--phases N] [--methods LIST]\n"
    "                    [--json]\n"
    "       rspd_compare --scene NAME [-n N] [--seed S] [options]";

const char* const kHelp =
    "Compare RSPD with RANSAC extract-and-repeat and region growing on the same cloud and normals.\n"
    "Each method runs in a process of its own; its time is the wall time of the detection in that\n"
    "process and its memory the peak resident set size of that process.\n"
    "\n"
    "  CLOUD            .pcd or .ply; normal_x/y/z are used by every method if present\n"
    "  TRUTH            per-point ground truth: PCD with a 'label' field, or raw uint32 LE (.gt)\n"
    "  --scene NAME     use a generated scene with its truth instead of CLOUD (cube, room, staircase,\n"
    "                   facade, industrial, boxes, plane); -n N points, --seed S random seed,\n"
    "                   --layout L the scene's dimensions drawn from L (0: the documented ones)\n"
    "  -k N             neighbours for the shared normal estimation (default 50)\n"
    "  --threads N      OpenMP threads for the normals and rspd (default: OpenMP's default)\n"
    "  --voxel F        evaluation voxel edge as a fraction of the largest extent (default 0.01)\n"
    "  --phases N       also score every method on N grids (1..1000), the paper's and N - 1 shifted\n"
    "                   by fixed fractions of a voxel (as rspd_evaluate --phases): F1's median and\n"
    "                   lowest over them, since where bands or rims lie near voxel boundaries F1\n"
    "                   moves with the grid alone\n"
    "  --methods LIST   comma-separated subset of rspd,sac,rg,cgal_rg,cgal_ransac, run in that order\n"
    "                   (default rspd,sac,rg; the cgal_ methods only in builds with CGAL)\n"
    "  --json           print one JSON object instead of the table\n"
    "\n"
    "Exit status: 0 success (failed methods are reported as such), 1 bad input, 2 usage error.\n";

// ---------------------------------------------------------------------------------------------
// Command line
// ---------------------------------------------------------------------------------------------

/** \brief Command line. */
struct Options
{
  std::string cloud;
  std::string truth;
  std::string scene;
  long long scene_points = 0;   // 0: the scene's default
  long long scene_seed = 1;
  long long scene_layout = 0;
  bool scene_points_set = false;
  bool scene_seed_set = false;
  bool scene_layout_set = false;
  int k = 50;
  int threads = 0;              // 0: OpenMP's default
  double voxel = 0.01;
  long long phases = 0;         // 0: the paper's grid only
  std::vector<std::string> methods{"rspd", "sac", "rg"};
  bool json = false;
  bool help = false;
};

Options
parseArguments (int argc, char** argv)
{
  Options o;
  std::vector<std::string> positional;
  bool positional_only = false;
  for (int i = 1; i < argc; ++i)
  {
    std::string arg = argv[i];
    if (positional_only || arg.empty () || arg[0] != '-' || arg == "-")
    {
      positional.push_back (arg);
      continue;
    }
    if (arg == "--")
    {
      positional_only = true;
      continue;
    }
    OptionArgument option (argc, argv, i);
    arg = option.name ();
    const auto value = [&] { return option.value (); };
    const auto no_value = [&] { option.noValue (); };
    long long number = 0;
    if (arg == "-h" || arg == "--help")
    {
      no_value ();
      o.help = true;
    }
    else if (arg == "--json")
    {
      no_value ();
      o.json = true;
    }
    else if (arg == "--scene")
    {
      o.scene = value ();
      if (o.scene.empty ())
        throw UsageError{"--scene needs a scene name"};
    }
    else if (arg == "-n" || arg == "--points")
    {
      const std::string v = value ();
      if (!parseInteger (v, 1, 100000000, number))
        throw UsageError{"-n needs an integer from 1 to 100000000 (got '" + v + "')"};
      o.scene_points = number;
      o.scene_points_set = true;
    }
    else if (arg == "--seed")
    {
      const std::string v = value ();
      if (!parseInteger (v, 0, std::numeric_limits<std::uint32_t>::max (), number))
        throw UsageError{"--seed needs an integer from 0 to 4294967295 (got '" + v + "')"};
      o.scene_seed = number;
      o.scene_seed_set = true;
    }
    else if (arg == "--layout")
    {
      const std::string v = value ();
      if (!parseInteger (v, 0, std::numeric_limits<std::uint32_t>::max (), number))
        throw UsageError{"--layout needs an integer from 0 to 4294967295 (got '" + v + "')"};
      o.scene_layout = number;
      o.scene_layout_set = true;
    }
    else if (arg == "-k" || arg == "--neighbours" || arg == "--neighbors")
    {
      const std::string v = value ();
      if (!parseInteger (v, 3, 1000, number))
        throw UsageError{"-k needs an integer from 3 to 1000 (got '" + v + "')"};
      o.k = static_cast<int> (number);
    }
    else if (arg == "--threads" || arg == "-t")
    {
      const std::string v = value ();
      if (!parseInteger (v, 1, 1024, number))
        throw UsageError{"--threads needs an integer from 1 to 1024 (got '" + v + "')"};
      o.threads = static_cast<int> (number);
    }
    else if (arg == "--voxel")
    {
      const std::string v = value ();
      char* end = nullptr;
      errno = 0;
      o.voxel = std::strtod (v.c_str (), &end);
      if (v.empty () || *end != '\0' || errno == ERANGE || !std::isfinite (o.voxel) || !(o.voxel > 0.0) ||
          o.voxel > 1.0)
        throw UsageError{"--voxel needs a number in (0, 1] (got '" + v + "')"};
    }
    else if (arg == "--phases")
    {
      const std::string v = value ();
      if (!parseInteger (v, 1, 1000, o.phases))
        throw UsageError{"--phases needs an integer from 1 to 1000 (got '" + v + "')"};
    }
    else if (arg == "--methods")
    {
      const std::string v = value ();
      o.methods.clear ();
      std::size_t start = 0;
      while (start <= v.size ())
      {
        const std::size_t comma = std::min (v.find (',', start), v.size ());
        const std::string name = v.substr (start, comma - start);
        const bool cgal = name == "cgal_rg" || name == "cgal_ransac";
        if (name != "rspd" && name != "sac" && name != "rg" && !cgal)
          throw UsageError{"--methods takes a comma-separated subset of rspd,sac,rg,cgal_rg,cgal_ransac (got '" +
                           v + "')"};
        if (cgal && !rspd_tools::haveCgalPeers ())
          throw UsageError{"--methods " + name + ": this rspd_compare was built without CGAL (install libcgal-dev "
                           "and rebuild)"};
        if (std::find (o.methods.begin (), o.methods.end (), name) != o.methods.end ())
          throw UsageError{"--methods names '" + name + "' twice"};
        o.methods.push_back (name);
        start = comma + 1;
      }
    }
    else
      throw UsageError{"unknown option '" + arg + "'"};
  }
  if (o.help)
    return o;

  if (!o.scene.empty ())
  {
    if (!positional.empty ())
      throw UsageError{"give either CLOUD [TRUTH] or --scene NAME, not both (the scene has its own truth)"};
  }
  else
  {
    if (o.scene_points_set || o.scene_seed_set || o.scene_layout_set)
      throw UsageError{"-n, --seed and --layout only apply to --scene"};
    if (positional.empty ())
      throw UsageError{"no input: give CLOUD or --scene NAME"};
    if (positional.size () > 2)
      throw UsageError{"too many file arguments (expected CLOUD [TRUTH])"};
    o.cloud = positional[0];
    if (positional.size () == 2)
      o.truth = positional[1];
  }
  return o;
}

// ---------------------------------------------------------------------------------------------
// Shared input and settings
// ---------------------------------------------------------------------------------------------

/** \brief What every method is given: the same cloud, points, normals and peer settings. */
struct Context
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;   ///< every point, NaNs kept, original order
  pcl::IndicesPtr finite;                      ///< indices of the points with finite x, y, z
  pcl::PointCloud<pcl::Normal>::Ptr normals;   ///< one per point (NaN where none), same order
  double extent = 0.0;                         ///< largest side of the finite points' bounding box
  int threads = 0;                             ///< OpenMP threads for rspd (0: default)

  /** Smallest plane worth reporting, for sac and rg: max(10, ceil(0.1 % of the finite points)),
    * the ε that RSPD derives by default, so that no method is allowed smaller planes. */
  std::size_t min_plane_points = 10;
  double sac_threshold = 0.0;                  ///< 1 % of extent
  int sac_max_iterations = 1000;
  std::size_t sac_max_planes = 200;
  unsigned int rg_neighbours = 30;
  double rg_smoothness_deg = 3.0;
  double rg_curvature = 1.0;
  /** cgal_rg: k 12, 25°, distance 1 % of extent and min region min_plane_points (set with them). */
  rspd_tools::CgalPeerSettings cgal_rg;
};

/** \brief What a method hands back from its process. */
struct Detection
{
  std::vector<std::uint32_t> labels;   ///< one per point: 0 = none, 1..K by decreasing size
  std::vector<float> planes;           ///< [a b c d] per plane (label i at 4 (i - 1))
  double seconds = 0.0;                ///< wall time of the detection in the child
  std::string note;                    ///< e.g. why the sac loop stopped

  std::size_t
  numPlanes () const { return planes.size () / 4; }
};

/** \brief One row of the comparison. */
struct MethodResult
{
  std::string name;
  bool ok = false;
  std::string failure;                 ///< why the method failed (ok == false)
  Detection detection;
  double peak_mb = 0.0;                ///< peak RSS of the method's process
  double start_mb = 0.0;               ///< its RSS before the detection started
  double rms = 0.0;                    ///< RMS distance of plane points to their own plane
  bool evaluated = false;
  pcl::rspd::EvaluationResult scores;
  pcl::rspd::PhaseScores phase_scores; ///< phases == 0 unless --phases
};

/** \brief Seconds since \a start. */
double
secondsSince (const std::chrono::steady_clock::time_point& start)
{
  return std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
}

/** \brief Renumber the planes 1..K by decreasing size (ties: the lower old label first) and drop
  * empty ones, so that labels mean the same thing for every method; plane coefficients follow. */
void
sortPlanesBySize (Detection& d)
{
  const std::size_t k = d.numPlanes ();
  std::vector<std::size_t> size (k + 1, 0);
  for (const std::uint32_t l : d.labels)
    if (l > 0 && l <= k)
      ++size[l];
  std::vector<std::uint32_t> order (k);
  std::iota (order.begin (), order.end (), 1u);
  std::stable_sort (order.begin (), order.end (),
                    [&] (std::uint32_t a, std::uint32_t b) { return size[a] > size[b]; });
  std::vector<std::uint32_t> new_label (k + 1, 0);
  std::vector<float> planes;
  for (std::size_t i = 0; i < k && size[order[i]] > 0; ++i)
  {
    new_label[order[i]] = static_cast<std::uint32_t> (i + 1);
    planes.insert (planes.end (), d.planes.begin () + 4 * (order[i] - 1), d.planes.begin () + 4 * order[i]);
  }
  for (std::uint32_t& l : d.labels)
    l = l <= k ? new_label[l] : 0;
  d.planes.swap (planes);
}

// ---------------------------------------------------------------------------------------------
// The methods. Each runs in a child process; it may use OpenMP there (see runInChild).
// ---------------------------------------------------------------------------------------------

/** \brief RSPD with its defaults and the shared normals. */
Detection
runRspd (const Context& c)
{
  Detection d;
  const auto t0 = std::chrono::steady_clock::now ();
  pcl::RobustPlaneSegmentation<pcl::PointXYZ, pcl::Normal> seg;
  seg.setInputCloud (c.cloud);
  seg.setInputNormals (c.normals);
  if (c.threads > 0)
    seg.setNumberOfThreads (static_cast<unsigned int> (c.threads));
  pcl::PointCloud<pcl::Label> labels;
  seg.getLabels (labels);
  if (!seg.hasResult () || labels.size () != c.cloud->size ())
    throw std::runtime_error ("RobustPlaneSegmentation found no result");
  const std::vector<pcl::RobustPlane>& planes = seg.getPlanes ();
  d.seconds = secondsSince (t0);

  d.labels.resize (labels.size ());
  for (std::size_t i = 0; i < labels.size (); ++i)
    d.labels[i] = labels[i].label;
  for (const pcl::RobustPlane& p : planes)
    for (int j = 0; j < 4; ++j)
      d.planes.push_back (p.coefficients.values.size () >= 4 ? p.coefficients.values[j]
                                                              : std::numeric_limits<float>::quiet_NaN ());
  d.note = "eps " + std::to_string (seg.getResolvedMinPatchSize ());
  return d;
}

/** \brief RANSAC extract-and-repeat: find the best plane among the points left, label its inliers,
  * remove them, repeat. Deterministic: SACSegmentation (random = false) seeds its generator with
  * the fixed value 12345 at every segment() call. */
Detection
runSac (const Context& c)
{
  Detection d;
  const auto t0 = std::chrono::steady_clock::now ();
  d.labels.assign (c.cloud->size (), 0);
  pcl::SACSegmentation<pcl::PointXYZ> seg (false);
  seg.setModelType (pcl::SACMODEL_PLANE);
  seg.setMethodType (pcl::SAC_RANSAC);
  seg.setOptimizeCoefficients (true);
  seg.setDistanceThreshold (c.sac_threshold);
  seg.setMaxIterations (c.sac_max_iterations);
  seg.setInputCloud (c.cloud);

  // Index bookkeeping instead of copying the cloud: the inliers come back as indices into the
  // full cloud, so labels need no mapping.
  auto remaining = pcl::make_shared<pcl::Indices> (*c.finite);
  for (;;)
  {
    if (d.numPlanes () >= c.sac_max_planes)
    {
      d.note = "stopped at the cap of " + std::to_string (c.sac_max_planes) + " planes";
      break;
    }
    if (remaining->size () < c.min_plane_points)
    {
      d.note = "stopped: " + std::to_string (remaining->size ()) + " points left";
      break;
    }
    pcl::PointIndices inliers;
    pcl::ModelCoefficients coefficients;
    seg.setIndices (remaining);
    seg.segment (inliers, coefficients);
    if (inliers.indices.size () < c.min_plane_points || coefficients.values.size () < 4)
    {
      d.note = "stopped: best plane of the " + std::to_string (remaining->size ()) + " points left has " +
               std::to_string (inliers.indices.size ()) + " inliers";
      break;
    }
    const auto label = static_cast<std::uint32_t> (d.numPlanes () + 1);
    for (const pcl::index_t i : inliers.indices)
      d.labels[i] = label;
    d.planes.insert (d.planes.end (), coefficients.values.begin (), coefficients.values.begin () + 4);
    remaining->erase (std::remove_if (remaining->begin (), remaining->end (),
                                      [&] (pcl::index_t i) { return d.labels[i] != 0; }),
                      remaining->end ());
  }
  // Later planes can be larger than earlier ones (RANSAC keeps the first good-enough model).
  sortPlanesBySize (d);
  d.seconds = secondsSince (t0);
  return d;
}

/** \brief Give the points \a members (cloud indices) the next label of \a d, with their least-squares
  * plane (pcl::computePointNormal), as the region-based methods report their regions. */
void
addRegion (const Context& c, const pcl::Indices& members, Detection& d)
{
  Eigen::Vector4f plane;
  float curvature = 0.0f;
  pcl::computePointNormal (*c.cloud, members, plane, curvature);
  d.planes.insert (d.planes.end (), plane.data (), plane.data () + 4);
  const auto label = static_cast<std::uint32_t> (d.numPlanes ());
  for (const pcl::index_t i : members)
    d.labels[i] = label;
}

/** \brief Region growing on the shared normals; every region becomes a plane, fitted by least
  * squares (pcl::computePointNormal) so that the method delivers plane equations like the others. */
Detection
runRegionGrowing (const Context& c)
{
  Detection d;
  const auto t0 = std::chrono::steady_clock::now ();
  pcl::RegionGrowing<pcl::PointXYZ, pcl::Normal> rg;
  rg.setInputCloud (c.cloud);
  rg.setIndices (c.finite);
  rg.setInputNormals (c.normals);
  rg.setSearchMethod (pcl::make_shared<pcl::search::KdTree<pcl::PointXYZ>> ());
  rg.setNumberOfNeighbours (c.rg_neighbours);
  rg.setSmoothnessThreshold (static_cast<float> (c.rg_smoothness_deg * std::acos (-1.0) / 180.0));
  rg.setCurvatureThreshold (static_cast<float> (c.rg_curvature));
  rg.setMinClusterSize (static_cast<pcl::uindex_t> (c.min_plane_points));
  rg.setMaxClusterSize (std::numeric_limits<pcl::uindex_t>::max ());
  std::vector<pcl::PointIndices> regions;
  rg.extract (regions);

  d.labels.assign (c.cloud->size (), 0);
  for (const pcl::PointIndices& region : regions)
    addRegion (c, region.indices, d);
  sortPlanesBySize (d);
  d.seconds = secondsSince (t0);
  return d;
}

/** \brief One of CGAL's detectors (cgal_peers.h) on the finite points with finite shared normals;
  * every region becomes a plane, fitted by least squares as for rg. */
Detection
runCgal (const Context& c, bool region_growing)
{
  Detection d;
  const auto t0 = std::chrono::steady_clock::now ();
  std::vector<float> xyz, nxyz;
  std::vector<pcl::index_t> source; // the cloud's index of each point handed to CGAL
  for (const pcl::index_t i : *c.finite)
  {
    const pcl::Normal& n = (*c.normals)[i];
    if (!std::isfinite (n.normal_x) || !std::isfinite (n.normal_y) || !std::isfinite (n.normal_z))
      continue;
    const pcl::PointXYZ& p = (*c.cloud)[i];
    xyz.insert (xyz.end (), {p.x, p.y, p.z});
    nxyz.insert (nxyz.end (), {n.normal_x, n.normal_y, n.normal_z});
    source.push_back (i);
  }
  const std::vector<std::vector<std::size_t>> regions = region_growing
                                                            ? rspd_tools::cgalRegionGrowing (xyz, nxyz, c.cgal_rg)
                                                            : rspd_tools::cgalEfficientRansac (xyz, nxyz);
  d.labels.assign (c.cloud->size (), 0);
  pcl::Indices members;
  for (const std::vector<std::size_t>& region : regions)
  {
    members.clear ();
    for (const std::size_t j : region)
      members.push_back (source[j]);
    addRegion (c, members, d);
  }
  sortPlanesBySize (d);
  d.seconds = secondsSince (t0);
  if (source.size () < c.finite->size ())
    d.note = std::to_string (c.finite->size () - source.size ()) + " points without a normal left out";
  return d;
}

// ---------------------------------------------------------------------------------------------
// Child processes
// ---------------------------------------------------------------------------------------------

// The fork/pipe/wait4 machinery lives in child_process.h (shared with the benchmark runner).
using rspd_tools::ByteReader;
using rspd_tools::ByteWriter;
using rspd_tools::ChildOutcome;

/** \brief Run \a work in a child process (rspd_tools::runInChild), with this tool's test hook:
  * RSPD_COMPARE_KILL_METHOD=NAME makes the child NAME kill itself, to check that failures are reported. */
ChildOutcome
runInChild (const std::string& name, const std::function<std::string ()>& work)
{
  return rspd_tools::runInChild (name, work, "RSPD_COMPARE_KILL_METHOD");
}

/** \brief Estimate the normals once for all methods (in a child: see runInChild), on the finite
  * points, k nearest neighbours through a KdTree, oriented towards the sensor origin. */
bool
estimateNormals (Context& c, int k, const Eigen::Vector4f& origin, double& seconds, double& peak_mb,
                 std::string& error)
{
  const auto work = [&] () {
    const auto t0 = std::chrono::steady_clock::now ();
    pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> ne;
    ne.setNumberOfThreads (static_cast<unsigned int> (std::max (0, c.threads)));
    ne.setInputCloud (c.cloud);
    ne.setIndices (c.finite);
    ne.setSearchMethod (pcl::make_shared<pcl::search::KdTree<pcl::PointXYZ>> ());
    ne.setKSearch (k);
    ne.setViewPoint (origin[0], origin[1], origin[2]);
    pcl::PointCloud<pcl::Normal> normals;
    ne.compute (normals);  // one per finite index, in the order of the indices
    const double t = secondsSince (t0);
    ByteWriter w;
    w.put (t);
    std::vector<float> values;
    values.reserve (4 * normals.size ());
    for (const pcl::Normal& n : normals)
      values.insert (values.end (), {n.normal_x, n.normal_y, n.normal_z, n.curvature});
    w.putVector (values);
    return w.bytes;
  };
  const ChildOutcome child = runInChild ("normals", work);
  peak_mb = child.peak_mb;
  if (!child.ok)
  {
    error = "normal estimation failed: " + child.error;
    return false;
  }
  ByteReader r{child.payload};
  std::vector<float> values;
  if (!r.get (seconds) || !r.getVector (values) || values.size () != 4 * c.finite->size ())
  {
    error = "normal estimation returned a malformed result";
    return false;
  }
  // Every method wants one normal per point of the cloud: NaN where there is no point.
  const float nan = std::numeric_limits<float>::quiet_NaN ();
  c.normals = pcl::make_shared<pcl::PointCloud<pcl::Normal>> ();
  c.normals->resize (c.cloud->size (), pcl::Normal (nan, nan, nan, nan));
  c.normals->width = c.cloud->width;
  c.normals->height = c.cloud->height;
  c.normals->is_dense = false;
  for (std::size_t j = 0; j < c.finite->size (); ++j)
    (*c.normals)[(*c.finite)[j]] =
        pcl::Normal (values[4 * j], values[4 * j + 1], values[4 * j + 2], values[4 * j + 3]);
  return true;
}

/** \brief Run one method in its own process and collect its row. */
MethodResult
runMethod (const std::string& name, const Context& c)
{
  const auto work = [&] () {
    const Detection d = name == "rspd"          ? runRspd (c)
                        : name == "sac"         ? runSac (c)
                        : name == "rg"          ? runRegionGrowing (c)
                        : name == "cgal_rg"     ? runCgal (c, true)
                                                : runCgal (c, false);
    ByteWriter w;
    w.put (d.seconds);
    w.putVector (d.labels);
    w.putVector (d.planes);
    w.putString (d.note);
    return w.bytes;
  };
  MethodResult m;
  m.name = name;
  const ChildOutcome child = runInChild (name, work);
  m.peak_mb = child.peak_mb;
  m.start_mb = child.start_mb;
  if (!child.ok)
  {
    m.failure = child.error;
    return m;
  }
  ByteReader r{child.payload};
  Detection& d = m.detection;
  if (!r.get (d.seconds) || !r.getVector (d.labels) || !r.getVector (d.planes) || !r.getString (d.note) ||
      d.labels.size () != c.cloud->size () || d.planes.size () % 4 != 0)
  {
    m.failure = "malformed result";
    return m;
  }
  m.ok = true;
  return m;
}

/** \brief RMS distance of every labelled point to its own plane's equation: how tight the planes
  * a method reports are (sac's are bounded by its threshold, the others' are not). */
double
planeRms (const pcl::PointCloud<pcl::PointXYZ>& cloud, const Detection& d)
{
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < d.labels.size (); ++i)
  {
    const std::uint32_t l = d.labels[i];
    if (l == 0 || l > d.numPlanes ())
      continue;
    const float* p = &d.planes[4 * (l - 1)];
    const double norm = std::sqrt (double (p[0]) * p[0] + double (p[1]) * p[1] + double (p[2]) * p[2]);
    if (!(norm > 0.0) || !std::isfinite (norm))
      continue;
    const pcl::PointXYZ& q = cloud[i];
    const double dist = (p[0] * double (q.x) + p[1] * double (q.y) + p[2] * double (q.z) + p[3]) / norm;
    sum += dist * dist;
    ++count;
  }
  return count > 0 ? std::sqrt (sum / static_cast<double> (count)) : 0.0;
}

// ---------------------------------------------------------------------------------------------
// Output
// ---------------------------------------------------------------------------------------------

/** \brief \a s as a JSON string literal. */
std::string
jsonString (const std::string& s)
{
  std::string out = "\"";
  for (const char ch : s)
  {
    const auto c = static_cast<unsigned char> (ch);
    if (c == '"' || c == '\\')
      (out += '\\') += ch;
    else if (c == '\n')
      out += "\\n";
    else if (c == '\t')
      out += "\\t";
    else if (c < 0x20)
    {
      char esc[8];
      std::snprintf (esc, sizeof (esc), "\\u%04x", c);
      out += esc;
    }
    else
      out += ch;
  }
  return out + "\"";
}

/** \brief printf into a std::string. */
template <typename... Args> std::string
format (const char* fmt, Args... args)
{
  const int size = std::snprintf (nullptr, 0, fmt, args...);
  if (size <= 0)
    return std::string ();
  std::string out (static_cast<std::size_t> (size) + 1, '\0');
  std::snprintf (&out[0], out.size (), fmt, args...);
  out.pop_back ();
  return out;
}

/** \brief Everything printed besides the rows. */
struct Summary
{
  std::string source;          ///< file name or "scene NAME"
  std::size_t points = 0;
  std::size_t finite = 0;
  bool has_truth = false;
  int truth_planes = 0;
  int k = 50;
  bool file_normals = false;
  double normals_seconds = 0.0;
  double normals_peak_mb = 0.0;
  double voxel = 0.01;
  std::size_t phases = 0;
};

void
printText (const Summary& s, const Context& c, const std::vector<MethodResult>& results)
{
  std::printf ("cloud: %s, %zu points (%zu finite), largest extent %.6g%s\n", s.source.c_str (), s.points, s.finite,
               c.extent, s.has_truth ? format (", truth %d planes", s.truth_planes).c_str () : ", no truth");
  if (s.file_normals)
    std::printf ("normals: from the file, shared by all methods\n");
  else
    std::printf ("normals: %.3f s, peak %.1f MB; estimated once, shared by all methods: pcl::NormalEstimationOMP, "
                 "k = %d, KdTree, finite points, oriented towards the sensor origin\n",
                 s.normals_seconds, s.normals_peak_mb, s.k);
  std::printf ("parameters: rspd: pcl::RobustPlaneSegmentation defaults (k = 50 graph, eps = max(10, 0.1 %% of "
               "points)), shared normals, threads %s\n",
               c.threads > 0 ? std::to_string (c.threads).c_str () : "OpenMP default");
  std::printf ("parameters: sac: pcl::SACSegmentation SACMODEL_PLANE, SAC_RANSAC, distance threshold %.6g "
               "(1 %% of the largest extent), max %d iterations, optimized coefficients, fixed seed 12345; "
               "extract and repeat while the best plane has >= %zu inliers (max(10, 0.1 %% of points)), "
               "at most %zu planes\n",
               c.sac_threshold, c.sac_max_iterations, c.min_plane_points, c.sac_max_planes);
  std::printf ("parameters: rg: pcl::RegionGrowing %u neighbours (KdTree), smoothness %g deg, curvature %g, "
               "min cluster %zu points (max(10, 0.1 %% of points)), shared normals; least-squares plane per "
               "region (pcl::computePointNormal)\n",
               c.rg_neighbours, c.rg_smoothness_deg, c.rg_curvature, c.min_plane_points);
  const auto cgal = [] (const MethodResult& m) { return m.name.rfind ("cgal", 0) == 0; };
  if (std::any_of (results.begin (), results.end (), cgal))
    std::printf ("parameters: cgal_rg: CGAL Shape_detection region growing, least-squares plane fit region and "
                 "sorting, k = %zu (its K_neighbor_query), distance %.6g (1 %% of the largest extent), %g deg, "
                 "min region %zu points; cgal_ransac: CGAL Efficient_RANSAC, planes, its defaults (probability "
                 "0.01, min points 1 %% of points, epsilon and cluster epsilon 1 %% of the bounding box "
                 "diagonal, normal threshold 0.9), fixed seed 12345; both on the shared normals, points "
                 "without one left out, a least-squares plane per region\n",
                 c.cgal_rg.rg_neighbours, c.cgal_rg.rg_max_distance, c.cgal_rg.rg_max_angle_deg,
                 c.cgal_rg.min_region_size);
  std::printf ("parameters: labels 0 = none, 1..K by decreasing size; time = detection wall time in the method's "
               "own process; peak = that process's max RSS (wait4), start = its RSS before the detection "
               "(inherited cloud and normals)%s\n",
               s.has_truth ? format ("; scores: voxel %g of the largest extent (Sec. 4.2)%s", s.voxel,
                                     s.phases > 0 ? format (", F1 median and min over %zu grid phases", s.phases).c_str ()
                                                  : "").c_str ()
                           : "");

  int width = 6;
  for (const MethodResult& m : results)
    width = std::max (width, static_cast<int> (m.name.size ()));
  std::printf ("%-*s %7s %9s %8s %8s %10s", width, "method", "planes", "time (s)", "peak MB", "start MB", "rms");
  if (s.has_truth)
    std::printf (" %9s %7s %7s %7s %9s %5s", "precision", "recall", "F1", "found", "fragments", "false");
  if (s.has_truth && s.phases > 0)
    std::printf (" %9s %7s", "F1 median", "F1 min");
  std::printf ("  note\n");
  for (const MethodResult& m : results)
  {
    if (!m.ok)
    {
      std::printf ("%-*s failed: %s (peak %.1f MB)\n", width, m.name.c_str (), m.failure.c_str (), m.peak_mb);
      continue;
    }
    std::printf ("%-*s %7zu %9.3f %8.1f %8.1f %10.4g", width, m.name.c_str (), m.detection.numPlanes (),
                 m.detection.seconds, m.peak_mb, m.start_mb, m.rms);
    if (m.evaluated)
      std::printf (" %9.4f %7.4f %7.4f %7s %9d %5d", m.scores.precision, m.scores.recall, m.scores.f1,
                   format ("%d/%d", m.scores.found, m.scores.planes).c_str (), m.scores.fragments,
                   m.scores.false_planes);
    if (m.evaluated && s.phases > 0)
      std::printf (" %9.4f %7.4f", m.phase_scores.f1_median, m.phase_scores.f1_min);
    std::printf ("  %s\n", m.detection.note.c_str ());
  }
}

void
printJson (const Summary& s, const Context& c, const std::vector<MethodResult>& results)
{
  std::string j = "{";
  j += "\"cloud\": " + jsonString (s.source);
  j += format (", \"points\": %zu, \"finite_points\": %zu, \"largest_extent\": %.10g", s.points, s.finite, c.extent);
  j += s.has_truth ? format (", \"truth_planes\": %d", s.truth_planes) : std::string (", \"truth_planes\": null");
  j += format (", \"normals\": \"%s\", \"normals_seconds\": %.6f, \"normals_peak_mb\": %.3f, \"normals_k\": %d",
               s.file_normals ? "file" : "estimated", s.normals_seconds, s.normals_peak_mb, s.k);
  j += format (", \"voxel_ratio\": %.10g", s.voxel);
  j += format (", \"parameters\": {\"threads\": %d, \"min_plane_points\": %zu, \"sac_threshold\": %.10g, "
               "\"sac_threshold_ratio\": 0.01, \"sac_max_iterations\": %d, \"sac_max_planes\": %zu, "
               "\"sac_seed\": 12345, \"rg_neighbours\": %u, \"rg_smoothness_deg\": %g, \"rg_curvature\": %g, "
               "\"cgal_rg_neighbours\": %zu, \"cgal_rg_distance\": %.10g, \"cgal_rg_angle_deg\": %g}",
               c.threads, c.min_plane_points, c.sac_threshold, c.sac_max_iterations, c.sac_max_planes,
               c.rg_neighbours, c.rg_smoothness_deg, c.rg_curvature, c.cgal_rg.rg_neighbours,
               c.cgal_rg.rg_max_distance, c.cgal_rg.rg_max_angle_deg);
  j += ", \"methods\": [";
  for (std::size_t i = 0; i < results.size (); ++i)
  {
    const MethodResult& m = results[i];
    j += i ? ", {" : "{";
    j += "\"name\": " + jsonString (m.name);
    if (!m.ok)
    {
      j += ", \"status\": \"failed\", \"error\": " + jsonString (m.failure);
      j += format (", \"peak_mb\": %.3f}", m.peak_mb);
      continue;
    }
    j += format (", \"status\": \"ok\", \"planes\": %zu, \"seconds\": %.6f, \"peak_mb\": %.3f, \"start_mb\": %.3f, "
                 "\"rms\": %.10g",
                 m.detection.numPlanes (), m.detection.seconds, m.peak_mb, m.start_mb, m.rms);
    if (m.evaluated)
      j += format (", \"precision\": %.10g, \"recall\": %.10g, \"f1\": %.10g, \"found\": %d, \"truth_planes\": %d, "
                   "\"detected\": %d, \"fragments\": %d, \"false_planes\": %d",
                   m.scores.precision, m.scores.recall, m.scores.f1, m.scores.found, m.scores.planes,
                   m.scores.detected, m.scores.fragments, m.scores.false_planes);
    if (m.evaluated && s.phases > 0)
      j += format (", \"phases\": %zu, \"f1_phase_median\": %.10g, \"f1_phase_min\": %.10g, \"f1_phase_max\": %.10g, "
                   "\"found_phase_min\": %d",
                   m.phase_scores.phases, m.phase_scores.f1_median, m.phase_scores.f1_min, m.phase_scores.f1_max,
                   m.phase_scores.found_min);
    j += ", \"note\": " + jsonString (m.detection.note) + "}";
  }
  j += "]}\n";
  std::fputs (j.c_str (), stdout);
}

// ---------------------------------------------------------------------------------------------

/** \brief Report a usage error in one line; exit status 2. */
int
usageError (const std::string& message)
{
  std::fprintf (stderr, "rspd_compare: %s (see --help)\n", message.c_str ());
  return 2;
}

/** \brief Report a data error in one line; exit status 1. */
int
fail (const std::string& message)
{
  std::fprintf (stderr, "rspd_compare: error: %s\n", message.c_str ());
  return 1;
}

int
run (const Options& o)
{
  std::string error;
  Summary s;
  s.k = o.k;
  s.voxel = o.voxel;
  s.phases = static_cast<std::size_t> (o.phases);

  // --- input and truth
  rspd_tools::LoadedCloud loaded;
  std::vector<std::uint32_t> truth;
  if (!o.scene.empty ())
  {
    pcl::rspd::SceneOptions options;
    options.num_points = static_cast<std::size_t> (o.scene_points);
    options.seed = static_cast<std::uint32_t> (o.scene_seed);
    options.layout = static_cast<std::uint32_t> (o.scene_layout);
    pcl::rspd::Scene scene;
    try
    {
      scene = pcl::rspd::makeScene (o.scene, options);
    }
    catch (const std::invalid_argument& e)
    {
      return usageError (e.what ());
    }
    rspd_tools::makeLoadedCloud (scene.cloud, loaded);
    truth = scene.labels;
    s.source = "scene " + o.scene + " (seed " + std::to_string (o.scene_seed) +
               (o.scene_layout != 0 ? ", layout " + std::to_string (o.scene_layout) : std::string ()) + ")";
  }
  else
  {
    if (!rspd_tools::loadCloud (o.cloud, loaded, error))
      return fail (error);
    if (!o.truth.empty () && !rspd_tools::readLabels (o.truth, loaded.size (), truth, error))
      return fail (error);
    s.source = o.cloud;
  }
  s.has_truth = !truth.empty ();
  if (s.has_truth)
  {
    std::vector<std::uint32_t> distinct (truth);
    std::sort (distinct.begin (), distinct.end ());
    distinct.erase (std::unique (distinct.begin (), distinct.end ()), distinct.end ());
    s.truth_planes = static_cast<int> (distinct.size ()) - (distinct.front () == 0 ? 1 : 0);
  }

  // --- shared context
  Context c;
  c.cloud = loaded.xyz;
  c.threads = o.threads;
  c.finite = pcl::make_shared<pcl::Indices> ();
  for (std::size_t i = 0; i < c.cloud->size (); ++i)
    if (pcl::isFinite ((*c.cloud)[i]))
      c.finite->push_back (static_cast<pcl::index_t> (i));
  s.points = c.cloud->size ();
  s.finite = c.finite->size ();
  if (s.finite == 0)
    return fail (s.source + ": the cloud has no point with finite x, y and z");
  Eigen::Vector4f lo, hi;
  pcl::getMinMax3D (*c.cloud, *c.finite, lo, hi);
  c.extent = (hi - lo).head<3> ().maxCoeff ();
  c.sac_threshold = 0.01 * c.extent;
  c.min_plane_points =
      std::max<std::size_t> (10, static_cast<std::size_t> (std::ceil (0.001 * static_cast<double> (s.finite))));
  c.cgal_rg.rg_max_distance = 0.01 * c.extent;
  c.cgal_rg.min_region_size = c.min_plane_points;

  // --- normals, once for everybody
  if (loaded.normals)
  {
    c.normals = loaded.normals;
    s.file_normals = true;
  }
  else if (!estimateNormals (c, o.k, loaded.origin, s.normals_seconds, s.normals_peak_mb, error))
    return fail (error);

  // --- the methods, one process each; scored only once all have run, so that nothing the parent
  // does in between (should it ever use OpenMP) can break the next fork (see runInChild).
  std::vector<MethodResult> results;
  for (const std::string& name : o.methods)
    results.push_back (runMethod (name, c));
  for (MethodResult& m : results)
  {
    if (!m.ok)
      continue;
    m.rms = planeRms (*c.cloud, m.detection);
    if (s.has_truth)
    {
      m.scores = pcl::rspd::evaluatePlaneDetection (*c.cloud, truth, m.detection.labels, o.voxel);
      if (s.phases > 0)
        m.phase_scores = pcl::rspd::evaluateOverGridPhases (*c.cloud, truth, m.detection.labels, o.voxel, s.phases);
      m.evaluated = true;
    }
  }

  if (o.json)
    printJson (s, c, results);
  else
    printText (s, c, results);
  return 0;
}
} // namespace

int
main (int argc, char** argv)
{
  Options options;
  try
  {
    options = parseArguments (argc, argv);
  }
  catch (const UsageError& e)
  {
    return usageError (e.message);
  }
  if (options.help)
  {
    std::printf ("%s\n\n%s", kUsage, kHelp);
    return 0;
  }
  // PCL's own messages (e.g. RANSAC's "no solution found" that ends the sac loop) are not errors here.
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  try
  {
    return run (options);
  }
  catch (const std::bad_alloc&)
  {
    return fail ("out of memory");
  }
  catch (const std::exception& e)
  {
    return fail (e.what ());
  }
}
