/*
 * rspd_benchmark: end-to-end timing and peak memory of RSPD against pcl::RegionGrowing on generated
 * scenes, each run read -> detect -> write in a process of its own (issue #5).
 * SPDX-License-Identifier: BSD-3-Clause
 *
 *   rspd_benchmark [--scenes cube,room] [--sizes 100000,1000000,4000000] [--repeats 3] [--threads N]
 *                  [--methods rspd,rg] [--markdown] [--tmpdir DIR] [--keep]
 *   rspd_benchmark --threads-compare [--sizes 1000000] [--repeats 3] [--threads 2]
 *   rspd_benchmark --smoke
 *
 * Each scene is generated once (pcl::rspd::makeScene, seed 1) and saved as a binary PCD in a
 * temporary directory. Every run is a forked child that does what a user's program does:
 *  - rspd: read the PCD (rspd_tools::loadCloud), pcl::RobustPlaneSegmentation with its defaults (its
 *          own k = 50 graph and PCA normals), write the labelled PCD (rspd_tools::writeLabeledCloud),
 *          as rspd_segment does;
 *  - rg:   read the PCD, pcl::NormalEstimationOMP (k = 50), pcl::RegionGrowing (30 neighbours, 3 deg,
 *          curvature 1.0, minimum cluster max(10, 0.1 % of the points)), write the labelled PCD.
 * The child reports the wall time of each stage through a pipe; its peak RSS comes from wait4.
 * Rows show medians over the repeats. Nothing here asserts a time: the exit status is 0 when every
 * run finished, 1 when a run failed or thread counts gave different outputs, 2 on a usage error.
 */

#include "child_process.h"
#include "cloud_io.h"
#include "command_line.h"

#include <pcl_rspd/robust_plane_segmentation.h>
#include <pcl_rspd/synthetic_scenes.h>

#include <pcl/PointIndices.h>
#include <pcl/console/print.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/io/pcd_io.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/region_growing.h>

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
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
    "usage: rspd_benchmark [--scenes LIST] [--sizes LIST] [--repeats N] [--threads N] [--methods rspd,rg]\n"
    "                      [--markdown] [--tmpdir DIR] [--keep]\n"
    "       rspd_benchmark --threads-compare [--scenes cube] [--sizes 1000000] [--repeats N] [--threads 2]\n"
    "       rspd_benchmark --smoke";

const char* const kHelp =
    "End-to-end benchmark: read a PCD, detect planes, write the labelled PCD, each run in a process\n"
    "of its own; RSPD (pcl::RobustPlaneSegmentation, defaults) against pcl::RegionGrowing with its own\n"
    "NormalEstimationOMP normals (k = 50; 30 neighbours, 3 deg, curvature 1.0, min cluster 0.1 %).\n"
    "\n"
    "  --scenes LIST     generated scenes (cube, room, staircase, facade, industrial, plane); without\n"
    "                    --sizes: cube at 100000, 1000000 and 4000000 points, room at 300000, any other\n"
    "                    scene at its default size. Default: cube and room\n"
    "  --sizes LIST      points per scene, e.g. 100000,1000000 (k and M suffixes allowed: 100k,1M);\n"
    "                    applies to every scene of --scenes\n"
    "  --repeats N       runs per method and scene; rows show medians (default 3)\n"
    "  --threads N       OpenMP threads for both methods (default: OpenMP's default)\n"
    "  --methods LIST    subset of rspd,rg (default both)\n"
    "  --seed S          scene random seed (default 1)\n"
    "  --noise S         noise sigma of every scene, in its units (default: the scene's own, e.g. 0.01 m\n"
    "                    for the cube). The default is fixed while the spacing shrinks with more points:\n"
    "                    at 1M points the cube's 0.01 m is as wide as a 50-neighbourhood: k-scale\n"
    "                    normals are noise there (RegionGrowing and the paper's fixed scale find no\n"
    "                    plane; RSPD's default automatic normal scale widens them)\n"
    "  --markdown        print the tables as markdown\n"
    "  --threads-compare instead of the table: RSPD with 1 thread and with --threads N (default 2)\n"
    "                    threads on the cube at 1000000 points (or --scenes/--sizes), speedup and\n"
    "                    whether every run wrote a byte-identical labelled PCD\n"
    "  --smoke           a few seconds: cube at 20000 points, 1 run, both methods, then the thread\n"
    "                    comparison at 20000 points (what ctest runs)\n"
    "  --tmpdir DIR      where the scenes and outputs go (default $TMPDIR or /tmp); removed at exit\n"
    "  --keep            keep the temporary directory\n"
    "\n"
    "Stages (seconds, wall): read = loading the PCD; prepare, graph, normals, split, grow/merge,\n"
    "outputs = the class's DetectorStatistics; other = the rest of segment() (result copies);\n"
    "write = per-point labels and the labelled PCD. total = read to written, in the child. peak =\n"
    "the child's maximum RSS (wait4). Progress goes to stderr, tables to stdout.\n"
    "\n"
    "Exit status: 0 all runs finished, 1 a run failed or outputs differ across thread counts,\n"
    "2 usage error.\n";

/** \brief One scene at one size. */
struct Job
{
  std::string scene;
  std::size_t size = 0;   ///< requested points (0: the scene's default)
};

/** \brief Command line. */
struct Options
{
  std::vector<Job> jobs;
  int repeats = 3;
  int threads = 0;                         ///< 0: OpenMP's default
  std::vector<std::string> methods{"rspd", "rg"};
  std::uint32_t seed = 1;
  double noise = -1.0;                     ///< scene noise sigma in scene units (< 0: the scene's default)
  bool markdown = false;
  bool threads_compare = false;
  bool smoke = false;
  std::string tmpdir;
  bool keep = false;
  bool help = false;
};

/** \brief Split "a,b,c" at commas (empty items kept, so that the caller can refuse them). */
std::vector<std::string>
splitList (const std::string& text)
{
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= text.size ())
  {
    const std::size_t comma = std::min (text.find (',', start), text.size ());
    items.push_back (text.substr (start, comma - start));
    start = comma + 1;
  }
  return items;
}

/** \brief Parse a point count: "300000", "300k" or "1M". */
bool
parseSize (std::string s, std::size_t& size)
{
  long long scale = 1;
  if (!s.empty () && (s.back () == 'k' || s.back () == 'M'))
  {
    scale = s.back () == 'k' ? 1000 : 1000000;
    s.pop_back ();
  }
  long long value = 0;
  if (!parseInteger (s, 1, 100000000 / scale, value))
    return false;
  size = static_cast<std::size_t> (value * scale);
  return true;
}

/** \brief The default sizes of a scene in the table: the cube series, the room at 300k. */
std::vector<std::size_t>
defaultSizes (const std::string& scene)
{
  if (scene == "cube")
    return {100000, 1000000, 4000000};
  if (scene == "room")
    return {300000};
  return {0};
}

Options
parseArguments (int argc, char** argv)
{
  Options o;
  std::vector<std::string> scenes;
  std::vector<std::size_t> sizes;
  for (int i = 1; i < argc; ++i)
  {
    OptionArgument option (argc, argv, i);
    const std::string& arg = option.name ();
    const auto value = [&] { return option.value (); };
    const auto flag = [&] {
      option.noValue ();
      return true;
    };
    long long number = 0;
    if (arg == "-h" || arg == "--help")
      o.help = flag ();
    else if (arg == "--markdown")
      o.markdown = flag ();
    else if (arg == "--threads-compare")
      o.threads_compare = flag ();
    else if (arg == "--smoke")
      o.smoke = flag ();
    else if (arg == "--keep")
      o.keep = flag ();
    else if (arg == "--tmpdir")
    {
      o.tmpdir = value ();
      if (o.tmpdir.empty ())
        throw UsageError{"--tmpdir needs a directory"};
    }
    else if (arg == "--scenes")
    {
      scenes = splitList (value ());
      const std::vector<std::string> known = pcl::rspd::sceneNames ();
      for (const std::string& s : scenes)
        if (std::find (known.begin (), known.end (), s) == known.end ())
          throw UsageError{"--scenes: unknown scene '" + s + "'"};
    }
    else if (arg == "--sizes")
    {
      sizes.clear ();
      for (const std::string& s : splitList (value ()))
      {
        std::size_t n = 0;
        if (!parseSize (s, n) || n < 100)
          throw UsageError{"--sizes needs point counts from 100 to 100000000 (got '" + s + "')"};
        sizes.push_back (n);
      }
    }
    else if (arg == "--repeats")
    {
      const std::string v = value ();
      if (!parseInteger (v, 1, 1000, number))
        throw UsageError{"--repeats needs an integer from 1 to 1000 (got '" + v + "')"};
      o.repeats = static_cast<int> (number);
    }
    else if (arg == "--threads" || arg == "-t")
    {
      const std::string v = value ();
      if (!parseInteger (v, 1, 1024, number))
        throw UsageError{"--threads needs an integer from 1 to 1024 (got '" + v + "')"};
      o.threads = static_cast<int> (number);
    }
    else if (arg == "--seed")
    {
      const std::string v = value ();
      if (!parseInteger (v, 0, std::numeric_limits<std::uint32_t>::max (), number))
        throw UsageError{"--seed needs an integer from 0 to 4294967295 (got '" + v + "')"};
      o.seed = static_cast<std::uint32_t> (number);
    }
    else if (arg == "--noise")
    {
      const std::string v = value ();
      char* end = nullptr;
      o.noise = std::strtod (v.c_str (), &end);
      if (v.empty () || *end != '\0' || !std::isfinite (o.noise) || o.noise < 0.0)
        throw UsageError{"--noise needs a number >= 0 (got '" + v + "')"};
    }
    else if (arg == "--methods")
    {
      o.methods.clear ();
      for (const std::string& m : splitList (value ()))
      {
        if (m != "rspd" && m != "rg")
          throw UsageError{"--methods takes a comma-separated subset of rspd,rg (got '" + m + "')"};
        if (std::find (o.methods.begin (), o.methods.end (), m) != o.methods.end ())
          throw UsageError{"--methods names '" + m + "' twice"};
        o.methods.push_back (m);
      }
    }
    else
      throw UsageError{"unknown option '" + arg + "'"};
  }
  if (o.help)
    return o;

  if (o.smoke)
  {
    if (!scenes.empty () || !sizes.empty () || o.threads_compare)
      throw UsageError{"--smoke chooses its own scene, size and mode"};
    o.jobs = {{"cube", 20000}};
    o.repeats = 1;
    o.methods = {"rspd", "rg"};
    return o;
  }
  if (o.threads_compare)
  {
    // The criterion is about the 1M cube; --scenes/--sizes pick another.
    if (scenes.empty ())
      scenes = {"cube"};
    if (sizes.empty ())
      sizes = {1000000};
  }
  if (scenes.empty ())
    scenes = sizes.empty () ? std::vector<std::string>{"cube", "room"} : std::vector<std::string>{"cube"};
  for (const std::string& s : scenes)
    for (const std::size_t n : sizes.empty () ? defaultSizes (s) : sizes)
      o.jobs.push_back ({s, n});
  return o;
}

// ---------------------------------------------------------------------------------------------
// Runs. Everything below that touches OpenMP (detection, normals) runs in a child process; the
// parent only forks, collects and prints (see rspd_tools::runInChild).
// ---------------------------------------------------------------------------------------------

/** \brief Seconds since \a start. */
double
secondsSince (const std::chrono::steady_clock::time_point& start)
{
  return std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
}

/** \brief Stage names of each method, in the order its child reports them. */
const std::vector<std::string>&
stageNames (const std::string& method)
{
  static const std::vector<std::string> rspd{"read",       "prepare", "graph", "normals", "split",
                                             "grow/merge", "outputs", "other", "write"};
  static const std::vector<std::string> rg{"read", "normals", "region growing", "write"};
  return method == "rspd" ? rspd : rg;
}

/** \brief What one run reports. */
struct RunRecord
{
  bool ok = false;
  std::string error;
  std::vector<double> stages;   ///< seconds, as stageNames (method)
  double total = 0.0;           ///< read to written, seconds
  std::uint64_t planes = 0;
  std::uint64_t points = 0;
  double peak_mb = 0.0;
  double start_mb = 0.0;
  double cpu_seconds = 0.0;
};

/** \brief A generated scene on disk. */
struct SceneFile
{
  Job job;
  std::string path;
  std::size_t points = 0;
  int truth_planes = 0;
  bool ok = false;
  std::string error;
};

/** \brief Generate \a job's scene and save it as binary PCD, in a child so that the parent never
  * holds (or inherits into the runs) a multi-million point cloud. */
SceneFile
generateScene (const Job& job, const Options& o, const std::string& dir)
{
  SceneFile f;
  f.job = job;
  f.path = dir + "/" + job.scene + "_" + std::to_string (job.size) + ".pcd";
  const auto work = [&] () {
    pcl::rspd::SceneOptions options;
    options.num_points = job.size;
    options.seed = o.seed;
    options.noise = o.noise;
    const pcl::rspd::Scene scene = pcl::rspd::makeScene (job.scene, options);
    if (pcl::io::savePCDFileBinary (f.path, scene.cloud) != 0)
      throw std::runtime_error ("cannot write " + f.path);
    rspd_tools::ByteWriter w;
    w.put<std::uint64_t> (scene.cloud.size ());
    w.put<std::int32_t> (scene.num_planes);
    return w.bytes;
  };
  const rspd_tools::ChildOutcome child = rspd_tools::runInChild ("generate", work);
  std::uint64_t points = 0;
  std::int32_t planes = 0;
  rspd_tools::ByteReader r{child.payload};
  if (!child.ok)
    f.error = child.error;
  else if (!r.get (points) || !r.get (planes))
    f.error = "malformed result";
  else
  {
    f.ok = true;
    f.points = static_cast<std::size_t> (points);
    f.truth_planes = planes;
  }
  return f;
}

/** \brief Label i = i-th region (regions given largest first), 0 elsewhere. */
std::vector<std::uint32_t>
labelsOf (std::size_t n, const std::vector<const pcl::Indices*>& regions)
{
  std::vector<std::uint32_t> labels (n, 0);
  for (std::size_t r = 0; r < regions.size (); ++r)
    for (const pcl::index_t i : *regions[r])
      if (i >= 0 && static_cast<std::size_t> (i) < n && labels[i] == 0)
        labels[i] = static_cast<std::uint32_t> (r + 1);
  return labels;
}

/** \brief RSPD end to end, as rspd_segment -o: read, segment, label, write. Runs in a child. */
std::string
runRspd (const std::string& input, const std::string& output, int threads)
{
  const auto t0 = std::chrono::steady_clock::now ();
  std::string error;
  rspd_tools::LoadedCloud cloud;
  if (!rspd_tools::loadCloud (input, cloud, error))
    throw std::runtime_error (error);
  const double t_read = secondsSince (t0);

  const auto t1 = std::chrono::steady_clock::now ();
  pcl::RobustPlaneSegmentation<pcl::PointXYZ, pcl::Normal> seg;
  seg.setInputCloud (cloud.xyz);
  if (threads > 0)
    seg.setNumberOfThreads (static_cast<unsigned int> (threads));
  const std::vector<pcl::RobustPlane>& planes = seg.getPlanes (); // runs the detection, as rspd_segment
  if (!seg.hasResult ())
    throw std::runtime_error ("RobustPlaneSegmentation failed");
  const double t_detect = secondsSince (t1);
  const pcl::rspd::DetectorStatistics& stats = seg.getStatistics ();

  const auto t2 = std::chrono::steady_clock::now ();
  std::vector<const pcl::Indices*> regions;
  for (const pcl::RobustPlane& p : planes)
    regions.push_back (&p.indices.indices);
  const std::vector<std::uint32_t> labels = labelsOf (cloud.size (), regions);
  if (!rspd_tools::writeLabeledCloud (output, cloud, labels, error))
    throw std::runtime_error (error);
  const double t_write = secondsSince (t2);

  const double inner = stats.prepare_seconds + stats.graph_seconds + stats.normals_seconds + stats.split_seconds +
                       stats.grow_merge_seconds + stats.output_seconds;
  rspd_tools::ByteWriter w;
  w.putVector (std::vector<double>{t_read, stats.prepare_seconds, stats.graph_seconds, stats.normals_seconds,
                                   stats.split_seconds, stats.grow_merge_seconds, stats.output_seconds,
                                   std::max (0.0, t_detect - inner), t_write});
  w.put (secondsSince (t0));
  w.put<std::uint64_t> (planes.size ());
  w.put<std::uint64_t> (cloud.size ());
  return w.bytes;
}

/** \brief pcl::RegionGrowing end to end with its own normals: read, NormalEstimationOMP (k = 50),
  * RegionGrowing, label, write. One KdTree object serves both, as in PCL's region growing tutorial
  * (each rebuilds it over its input). Runs in a child. */
std::string
runRegionGrowing (const std::string& input, const std::string& output, int threads)
{
  const auto t0 = std::chrono::steady_clock::now ();
  std::string error;
  rspd_tools::LoadedCloud cloud;
  if (!rspd_tools::loadCloud (input, cloud, error))
    throw std::runtime_error (error);
  const double t_read = secondsSince (t0);

  auto finite = pcl::make_shared<pcl::Indices> ();
  for (std::size_t i = 0; i < cloud.xyz->size (); ++i)
    if (pcl::isFinite ((*cloud.xyz)[i]))
      finite->push_back (static_cast<pcl::index_t> (i));
  const std::size_t min_cluster =
      std::max<std::size_t> (10, static_cast<std::size_t> (std::ceil (0.001 * static_cast<double> (finite->size ()))));

  const auto t1 = std::chrono::steady_clock::now ();
  auto tree = pcl::make_shared<pcl::search::KdTree<pcl::PointXYZ>> ();
  auto normals = pcl::make_shared<pcl::PointCloud<pcl::Normal>> ();
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> ne;
  ne.setNumberOfThreads (static_cast<unsigned int> (std::max (0, threads)));
  ne.setInputCloud (cloud.xyz);
  ne.setSearchMethod (tree);
  ne.setKSearch (50);
  ne.setViewPoint (cloud.origin[0], cloud.origin[1], cloud.origin[2]);
  ne.compute (*normals);  // one per point (NaN where the point is not finite)
  const double t_normals = secondsSince (t1);

  const auto t2 = std::chrono::steady_clock::now ();
  pcl::RegionGrowing<pcl::PointXYZ, pcl::Normal> rg;
  rg.setInputCloud (cloud.xyz);
  rg.setIndices (finite);
  rg.setInputNormals (normals);
  rg.setSearchMethod (tree);
  rg.setNumberOfNeighbours (30);
  rg.setSmoothnessThreshold (static_cast<float> (3.0 * std::acos (-1.0) / 180.0));
  rg.setCurvatureThreshold (1.0f);
  rg.setMinClusterSize (static_cast<pcl::uindex_t> (min_cluster));
  rg.setMaxClusterSize (std::numeric_limits<pcl::uindex_t>::max ());
  std::vector<pcl::PointIndices> clusters;
  rg.extract (clusters);
  const double t_rg = secondsSince (t2);

  const auto t3 = std::chrono::steady_clock::now ();
  // Largest region first, as RSPD numbers its planes, so both files mean the same thing.
  std::vector<const pcl::Indices*> regions;
  for (const pcl::PointIndices& c : clusters)
    regions.push_back (&c.indices);
  std::stable_sort (regions.begin (), regions.end (),
                    [] (const pcl::Indices* a, const pcl::Indices* b) { return a->size () > b->size (); });
  const std::vector<std::uint32_t> labels = labelsOf (cloud.size (), regions);
  if (!rspd_tools::writeLabeledCloud (output, cloud, labels, error))
    throw std::runtime_error (error);
  const double t_write = secondsSince (t3);

  rspd_tools::ByteWriter w;
  w.putVector (std::vector<double>{t_read, t_normals, t_rg, t_write});
  w.put (secondsSince (t0));
  w.put<std::uint64_t> (clusters.size ());
  w.put<std::uint64_t> (cloud.size ());
  return w.bytes;
}

/** \brief One run of \a method on \a input in a child process. */
RunRecord
runOnce (const std::string& method, const std::string& input, const std::string& output, int threads)
{
  const auto work = [&] () {
    return method == "rspd" ? runRspd (input, output, threads) : runRegionGrowing (input, output, threads);
  };
  const rspd_tools::ChildOutcome child = rspd_tools::runInChild (method, work);
  RunRecord r;
  r.peak_mb = child.peak_mb;
  r.start_mb = child.start_mb;
  r.cpu_seconds = child.cpu_seconds;
  if (!child.ok)
  {
    r.error = child.error;
    return r;
  }
  rspd_tools::ByteReader in{child.payload};
  if (!in.getVector (r.stages) || !in.get (r.total) || !in.get (r.planes) || !in.get (r.points) ||
      r.stages.size () != stageNames (method).size ())
  {
    r.error = "malformed result";
    return r;
  }
  r.ok = true;
  return r;
}

/** \brief Median of \a v (mean of the middle two for an even count; 0 when empty). */
double
median (std::vector<double> v)
{
  if (v.empty ())
    return 0.0;
  std::sort (v.begin (), v.end ());
  const std::size_t m = v.size () / 2;
  return v.size () % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

/** \brief Medians over the successful runs of one method on one scene. */
struct Summary
{
  bool ran = false;             ///< the method was asked for
  int ok_runs = 0;
  int failed_runs = 0;
  std::string error;            ///< of the last failed run
  std::vector<double> stages;
  double total = 0.0;
  double peak_mb = 0.0;
  double cpu_seconds = 0.0;
  std::uint64_t planes = 0;     ///< of the first successful run (the output is deterministic)
  bool planes_vary = false;     ///< a run found a different number of planes
};

Summary
summarise (const std::vector<RunRecord>& runs)
{
  Summary s;
  s.ran = !runs.empty ();
  std::vector<double> total, peak, cpu;
  std::vector<std::vector<double>> stages;
  for (const RunRecord& r : runs)
  {
    if (!r.ok)
    {
      ++s.failed_runs;
      s.error = r.error;
      continue;
    }
    if (s.ok_runs == 0)
    {
      s.planes = r.planes;
      stages.resize (r.stages.size ());
    }
    else if (r.planes != s.planes)
      s.planes_vary = true;
    ++s.ok_runs;
    total.push_back (r.total);
    peak.push_back (r.peak_mb);
    cpu.push_back (r.cpu_seconds);
    for (std::size_t j = 0; j < r.stages.size (); ++j)
      stages[j].push_back (r.stages[j]);
  }
  s.total = median (total);
  s.peak_mb = median (peak);
  s.cpu_seconds = median (cpu);
  for (const auto& st : stages)
    s.stages.push_back (median (st));
  return s;
}

/** \brief Whether two files hold the same bytes. */
bool
sameFileBytes (const std::string& a, const std::string& b)
{
  std::ifstream fa (a, std::ios::binary), fb (b, std::ios::binary);
  if (!fa || !fb)
    return false;
  std::vector<char> ba (1 << 20), bb (1 << 20);
  for (;;)
  {
    fa.read (ba.data (), static_cast<std::streamsize> (ba.size ()));
    fb.read (bb.data (), static_cast<std::streamsize> (bb.size ()));
    const std::streamsize na = fa.gcount (), nb = fb.gcount ();
    if (na != nb || !std::equal (ba.begin (), ba.begin () + na, bb.begin ()))
      return false;
    if (na == 0)
      return true;
  }
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

/** \brief The machine's 1-minute load average (the runs share the cores with whatever else runs). */
std::string
loadAverage ()
{
  std::ifstream in ("/proc/loadavg");
  std::string one;
  in >> one;
  return one.empty () ? std::string ("?") : one;
}

/** \brief A table printed as aligned text or as markdown. */
class Table
{
public:
  Table (std::vector<std::string> header, bool markdown) : header_ (std::move (header)), markdown_ (markdown) {}

  void
  add (std::vector<std::string> row) { rows_.push_back (std::move (row)); }

  void
  print () const
  {
    if (markdown_)
    {
      printRow (header_, {});
      std::string rule = "|";
      for (std::size_t j = 0; j < header_.size (); ++j)
        rule += j == 0 ? "---|" : "--:|";
      std::printf ("%s\n", rule.c_str ());
      for (const auto& r : rows_)
        printRow (r, {});
      return;
    }
    std::vector<std::size_t> width (header_.size (), 0);
    for (std::size_t j = 0; j < header_.size (); ++j)
    {
      width[j] = header_[j].size ();
      for (const auto& r : rows_)
        width[j] = std::max (width[j], j < r.size () ? r[j].size () : 0);
    }
    printRow (header_, width);
    for (const auto& r : rows_)
      printRow (r, width);
  }

private:
  void
  printRow (const std::vector<std::string>& row, const std::vector<std::size_t>& width) const
  {
    std::string line = markdown_ ? "|" : "";
    for (std::size_t j = 0; j < header_.size (); ++j)
    {
      const std::string cell = j < row.size () ? row[j] : std::string ();
      if (markdown_)
        line += " " + cell + " |";
      else if (j == 0)  // names left-aligned, numbers right-aligned
        line += cell + std::string (width[j] - cell.size (), ' ');
      else
        line += "  " + std::string (width[j] - cell.size (), ' ') + cell;
    }
    std::printf ("%s\n", line.c_str ());
  }

  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
  bool markdown_;
};

/** \brief The temporary directory, removed when the benchmark ends (unless kept). */
class ScratchDir
{
public:
  ScratchDir (const std::string& parent, bool keep) : keep_ (keep)
  {
    std::string base = parent;
    if (base.empty ())
    {
      const char* env = std::getenv ("TMPDIR");
      base = env && *env ? env : "/tmp";
    }
    std::string tmpl = base + "/rspd_benchmark_XXXXXX";
    if (::mkdtemp (&tmpl[0]))
      path_ = tmpl;
  }
  ~ScratchDir ()
  {
    if (path_.empty ())
      return;
    if (keep_)
      std::fprintf (stderr, "rspd_benchmark: kept %s\n", path_.c_str ());
    else
    {
      std::error_code ec;
      std::filesystem::remove_all (path_, ec);
    }
  }
  ScratchDir (const ScratchDir&) = delete;
  ScratchDir&
  operator= (const ScratchDir&) = delete;

  const std::string&
  path () const { return path_; }

private:
  std::string path_;
  bool keep_;
};

std::string
threadsText (int threads)
{
  return threads > 0 ? std::to_string (threads) : std::string ("OpenMP default");
}

std::string
secondsText (double s)
{
  return format ("%.3f", s);
}

/** \brief The table of issue #5: per scene and size, our medians per stage, RG's, and the ratio. */
int
runTable (const Options& o, const std::string& dir)
{
  int status = 0;
  const bool has_rspd = std::find (o.methods.begin (), o.methods.end (), "rspd") != o.methods.end ();
  const bool has_rg = std::find (o.methods.begin (), o.methods.end (), "rg") != o.methods.end ();
  const std::string load_before = loadAverage ();

  struct Row
  {
    SceneFile scene;
    Summary rspd, rg;
  };
  std::vector<Row> rows;
  for (const Job& job : o.jobs)
  {
    std::fprintf (stderr, "rspd_benchmark: generating %s (%s points)\n", job.scene.c_str (),
                  job.size ? std::to_string (job.size).c_str () : "default");
    Row row;
    row.scene = generateScene (job, o, dir);
    if (!row.scene.ok)
    {
      std::fprintf (stderr, "rspd_benchmark: error: %s: %s\n", job.scene.c_str (), row.scene.error.c_str ());
      status = 1;
      rows.push_back (row);
      continue;
    }
    // Methods alternate within a repeat, so that a slow spell of the machine hits both alike.
    std::vector<RunRecord> rspd_runs, rg_runs;
    for (int rep = 0; rep < o.repeats; ++rep)
      for (const std::string& method : o.methods)
      {
        const RunRecord r = runOnce (method, row.scene.path, dir + "/out_" + method + ".pcd", o.threads);
        (method == "rspd" ? rspd_runs : rg_runs).push_back (r);
        if (r.ok)
          std::fprintf (stderr, "rspd_benchmark: %s %zu %s run %d/%d: %.3f s, peak %.1f MB, cpu %.2f s, %llu planes\n",
                        job.scene.c_str (), row.scene.points, method.c_str (), rep + 1, o.repeats, r.total, r.peak_mb,
                        r.cpu_seconds, static_cast<unsigned long long> (r.planes));
        else
        {
          std::fprintf (stderr, "rspd_benchmark: %s %zu %s run %d/%d failed: %s (peak %.1f MB)\n", job.scene.c_str (),
                        row.scene.points, method.c_str (), rep + 1, o.repeats, r.error.c_str (), r.peak_mb);
          status = 1;
        }
      }
    row.rspd = summarise (rspd_runs);
    row.rg = summarise (rg_runs);
    std::error_code ec;
    std::filesystem::remove (row.scene.path, ec);  // a 4M scene is ~50 MB; keep the disk use flat
    rows.push_back (row);
  }

  std::printf ("rspd_benchmark: medians of %d run%s per method; threads: %s (%ld online processors); "
               "1-min load average %s before, %s after\n",
               o.repeats, o.repeats == 1 ? "" : "s", threadsText (o.threads).c_str (), ::sysconf (_SC_NPROCESSORS_ONLN),
               load_before.c_str (), loadAverage ().c_str ());
  std::printf ("scenes: pcl::rspd::makeScene, seed %u, noise %s\n", o.seed,
               o.noise < 0.0 ? "the scene's default" : format ("%g", o.noise).c_str ());
  std::printf ("rspd = read PCD, pcl::RobustPlaneSegmentation (defaults: own k = 50 graph and normals), write "
               "labelled PCD; rg = read PCD, NormalEstimationOMP k = 50, RegionGrowing 30 neighbours / 3 deg / "
               "curvature 1.0 / min cluster 0.1 %%, write labelled PCD; times in s (wall); cpu = the child's user + system "
               "time, all threads (cpu > total: threads ran in parallel; cpu < total: the child waited for a core); "
               "peak = child's max RSS\n\n");

  const auto failedCell = [] (const Summary& s) {
    return s.failed_runs > 0 ? format ("failed (%d/%d)", s.failed_runs, s.failed_runs + s.ok_runs) : std::string ();
  };
  std::vector<std::string> header{"scene", "points", "truth"};
  if (has_rspd)
  {
    header.push_back ("rspd total");
    for (const std::string& s : stageNames ("rspd"))
      header.push_back (s);
    header.push_back ("cpu s");
    header.push_back ("peak MB");
    header.push_back ("planes");
  }
  if (has_rg)
  {
    header.push_back ("rg total");
    header.push_back ("rg peak MB");
    header.push_back ("rg planes");
  }
  if (has_rspd && has_rg)
    header.push_back ("rspd/rg time");
  Table table (header, o.markdown);
  for (const Row& row : rows)
  {
    std::vector<std::string> cells{row.scene.job.scene, row.scene.ok ? std::to_string (row.scene.points) : "?",
                                   row.scene.ok ? std::to_string (row.scene.truth_planes) : "?"};
    if (!row.scene.ok)
    {
      cells.push_back ("scene failed: " + row.scene.error);
      table.add (cells);
      continue;
    }
    if (has_rspd)
    {
      if (row.rspd.ok_runs == 0)
      {
        cells.push_back (failedCell (row.rspd));
        cells.resize (cells.size () + stageNames ("rspd").size () + 3);
      }
      else
      {
        cells.push_back (secondsText (row.rspd.total) + (row.rspd.failed_runs ? " (" + failedCell (row.rspd) + ")" : ""));
        for (const double t : row.rspd.stages)
          cells.push_back (secondsText (t));
        cells.push_back (format ("%.2f", row.rspd.cpu_seconds));
        cells.push_back (format ("%.0f", row.rspd.peak_mb));
        cells.push_back (std::to_string (row.rspd.planes) + (row.rspd.planes_vary ? " (varies)" : ""));
      }
    }
    if (has_rg)
    {
      if (row.rg.ok_runs == 0)
        cells.insert (cells.end (), {failedCell (row.rg), "", ""});
      else
        cells.insert (cells.end (),
                      {secondsText (row.rg.total) + (row.rg.failed_runs ? " (" + failedCell (row.rg) + ")" : ""),
                       format ("%.0f", row.rg.peak_mb),
                       std::to_string (row.rg.planes) + (row.rg.planes_vary ? " (varies)" : "")});
    }
    if (has_rspd && has_rg)
      cells.push_back (row.rspd.ok_runs && row.rg.ok_runs && row.rg.total > 0.0
                           ? format ("%.2f", row.rspd.total / row.rg.total)
                           : std::string ());
    table.add (cells);
  }
  table.print ();

  // Where region growing spends its time, for the same runs.
  if (has_rg)
  {
    std::printf ("\n");
    std::vector<std::string> rg_header{"scene", "points", "rg total"};
    for (const std::string& s : stageNames ("rg"))
      rg_header.push_back (s);
    rg_header.push_back ("peak MB");
    rg_header.push_back ("cpu s");
    Table rg_table (rg_header, o.markdown);
    for (const Row& row : rows)
    {
      if (!row.scene.ok || row.rg.ok_runs == 0)
        continue;
      std::vector<std::string> cells{row.scene.job.scene, std::to_string (row.scene.points), secondsText (row.rg.total)};
      for (const double t : row.rg.stages)
        cells.push_back (secondsText (t));
      cells.push_back (format ("%.0f", row.rg.peak_mb));
      cells.push_back (format ("%.2f", row.rg.cpu_seconds));
      rg_table.add (cells);
    }
    rg_table.print ();
  }

  // Scaling: time(4M) / time(1M) for every scene that ran at both sizes (issue #5: <= 4.5).
  std::printf ("\n");
  for (const Row& big : rows)
    for (const Row& small : rows)
      if (big.scene.ok && small.scene.ok && big.scene.job.scene == small.scene.job.scene &&
          big.scene.points == 4000000 && small.scene.points == 1000000)
      {
        if (has_rspd && big.rspd.ok_runs && small.rspd.ok_runs)
        {
          const auto detect = [] (const Summary& s) { return s.total - s.stages.front () - s.stages.back (); };
          std::printf ("time(4M)/time(1M), %s, rspd: %.2f end to end, %.2f without read and write (issue #5 "
                       "target: <= 4.5)\n",
                       big.scene.job.scene.c_str (), big.rspd.total / small.rspd.total,
                       detect (big.rspd) / detect (small.rspd));
        }
        if (has_rg && big.rg.ok_runs && small.rg.ok_runs)
          std::printf ("time(4M)/time(1M), %s, rg: %.2f end to end\n", big.scene.job.scene.c_str (),
                       big.rg.total / small.rg.total);
      }

  // A run that finds nothing skips growth and merging: its time is not the method's.
  for (const Row& row : rows)
    if (row.scene.ok && has_rspd && row.rspd.ok_runs && row.rspd.planes == 0)
      std::printf ("note: rspd found no plane in %s at %zu points, so grow/merge did not run and its time is not "
                   "representative (scene noise too large for this density? see --noise)\n",
                   row.scene.job.scene.c_str (), row.scene.points);

  // The targets that these rows measure, for the reader; nothing depends on them.
  for (const Row& row : rows)
  {
    if (!row.scene.ok || !has_rspd || row.rspd.ok_runs == 0)
      continue;
    const std::string& s = row.scene.job.scene;
    const std::size_t n = row.scene.points;
    const auto verdict = [] (bool met) { return met ? "met" : "missed"; };
    if (s == "cube" && n == 1000000)
      std::printf ("issue #5 target, cube 1M: <= 3 s and <= 250 MB: %.2f s (%s), %.0f MB (%s)\n", row.rspd.total,
                   verdict (row.rspd.total <= 3.0), row.rspd.peak_mb, verdict (row.rspd.peak_mb <= 250.0));
    if (s == "cube" && n == 4000000)
      std::printf ("issue #5 target, 4M: <= 14 s and <= 1 GB: %.2f s (%s), %.0f MB (%s)\n", row.rspd.total,
                   verdict (row.rspd.total <= 14.0), row.rspd.peak_mb, verdict (row.rspd.peak_mb <= 1024.0));
    if (n == 10000000)
      std::printf ("issue #5 target, 10M: <= 3 GB: %.0f MB (%s)\n", row.rspd.peak_mb,
                   verdict (row.rspd.peak_mb <= 3072.0));
    if (s == "room" && n == 300000 && has_rg && row.rg.ok_runs)
      std::printf ("issue #5 target, room 300k: <= 0.25x RegionGrowing's time: %.2fx (%s)\n",
                   row.rspd.total / row.rg.total, verdict (row.rspd.total <= 0.25 * row.rg.total));
  }
  return status;
}

/** \brief RSPD with 1 thread and with \a o.threads (default 2) on each job: speedup, and whether
  * every run wrote the same bytes (the library promises output independent of the thread count). */
int
runThreadsCompare (const Options& o, const std::string& dir)
{
  int status = 0;
  const int many = o.threads > 0 ? o.threads : 2;
  for (const Job& job : o.jobs)
  {
    std::fprintf (stderr, "rspd_benchmark: generating %s (%s points)\n", job.scene.c_str (),
                  job.size ? std::to_string (job.size).c_str () : "default");
    const SceneFile scene = generateScene (job, o, dir);
    if (!scene.ok)
    {
      std::fprintf (stderr, "rspd_benchmark: error: %s: %s\n", job.scene.c_str (), scene.error.c_str ());
      status = 1;
      continue;
    }
    const std::string reference = dir + "/threads_reference.pcd", output = dir + "/threads_out.pcd";
    bool have_reference = false, identical = true;
    int compared = 0;
    std::vector<RunRecord> runs[2];
    const int counts[2] = {1, many};
    for (int rep = 0; rep < o.repeats; ++rep)
      for (int t = 0; t < 2; ++t)
      {
        const RunRecord r = runOnce ("rspd", scene.path, have_reference ? output : reference, counts[t]);
        runs[t].push_back (r);
        if (!r.ok)
        {
          std::fprintf (stderr, "rspd_benchmark: %s %zu rspd %d thread(s) run %d/%d failed: %s\n", job.scene.c_str (),
                        scene.points, counts[t], rep + 1, o.repeats, r.error.c_str ());
          status = 1;
          continue;
        }
        std::fprintf (stderr, "rspd_benchmark: %s %zu rspd %d thread(s) run %d/%d: %.3f s, peak %.1f MB, cpu %.2f s\n",
                      job.scene.c_str (), scene.points, counts[t], rep + 1, o.repeats, r.total, r.peak_mb,
                      r.cpu_seconds);
        if (!have_reference)
          have_reference = true;
        else
        {
          ++compared;
          if (!sameFileBytes (reference, output))
            identical = false;
        }
      }
    std::error_code ec;
    std::filesystem::remove (scene.path, ec);

    const Summary s1 = summarise (runs[0]), sn = summarise (runs[1]);
    std::printf ("threads comparison: %s, %zu points, noise %s, rspd end to end, medians of %d run%s; "
                 "1-min load average %s\n",
                 job.scene.c_str (), scene.points, o.noise < 0.0 ? "default" : format ("%g", o.noise).c_str (),
                 o.repeats, o.repeats == 1 ? "" : "s", loadAverage ().c_str ());
    std::vector<std::string> columns{"threads", "total"};
    for (const auto& name : stageNames ("rspd"))
      columns.push_back (name);
    for (const char* c : {"detection", "cpu s", "peak MB", "planes"})
      columns.push_back (c);
    Table table (columns, o.markdown);
    // Detection: every stage but reading and writing the files.
    const auto detection = [] (const Summary& s) {
      double sum = 0.0;
      for (std::size_t j = 1; j + 1 < s.stages.size (); ++j)
        sum += s.stages[j];
      return sum;
    };
    for (int t = 0; t < 2; ++t)
    {
      const Summary& s = t == 0 ? s1 : sn;
      std::vector<std::string> cells{std::to_string (counts[t])};
      if (s.ok_runs == 0)
        cells.push_back ("failed: " + s.error);
      else
      {
        cells.push_back (secondsText (s.total));
        for (const double v : s.stages)
          cells.push_back (secondsText (v));
        cells.push_back (secondsText (detection (s)));
        cells.push_back (format ("%.2f", s.cpu_seconds));
        cells.push_back (format ("%.0f", s.peak_mb));
        cells.push_back (std::to_string (s.planes));
      }
      table.add (cells);
    }
    table.print ();
    const std::string outputs = compared == 0 ? std::string ("nothing to compare")
                                : identical   ? format ("byte-identical (%d run%s against the first)", compared, compared == 1 ? "" : "s")
                                              : std::string ("DIFFER");
    if (s1.ok_runs && sn.ok_runs)
      std::printf ("speedup %d vs 1 thread: %.2fx end to end, %.2fx detection (issue #5 target: >= 1.6x); "
                   "labelled PCDs: %s\n",
                   many, s1.total / sn.total, detection (s1) / detection (sn), outputs.c_str ());
    else
      std::printf ("labelled PCDs: %s\n", outputs.c_str ());
    if (!identical)
      status = 1;
  }
  return status;
}
} // namespace

int
main (int argc, char** argv)
{
  Options o;
  try
  {
    o = parseArguments (argc, argv);
  }
  catch (const UsageError& e)
  {
    std::fprintf (stderr, "rspd_benchmark: %s\n%s\n", e.message.c_str (), kUsage);
    return 2;
  }
  if (o.help)
  {
    std::printf ("%s\n\n%s", kUsage, kHelp);
    return 0;
  }
  // Our own lines say what failed; PCL's warnings would only interleave with the progress.
  pcl::console::setVerbosityLevel (pcl::console::L_ERROR);
  try
  {
    ScratchDir dir (o.tmpdir, o.keep);
    if (dir.path ().empty ())
    {
      std::fprintf (stderr, "rspd_benchmark: error: cannot create a temporary directory\n");
      return 1;
    }
    if (o.smoke)
    {
      const int table_status = runTable (o, dir.path ());
      std::printf ("\n");
      return std::max (table_status, runThreadsCompare (o, dir.path ()));
    }
    return o.threads_compare ? runThreadsCompare (o, dir.path ()) : runTable (o, dir.path ());
  }
  catch (const std::bad_alloc&)
  {
    std::fprintf (stderr, "rspd_benchmark: error: out of memory\n");
    return 1;
  }
  catch (const std::exception& e)
  {
    std::fprintf (stderr, "rspd_benchmark: error: %s\n", e.what ());
    return 1;
  }
}
