/*
 * bench_kernels: Google Benchmark timings of the method's kernels on generated scenes (issue #5).
 * SPDX-License-Identifier: BSD-3-Clause
 *
 *   bench_kernels [--sizes 100000,1000000 | --large] [--threads N] [--noise S] [--smoke] [--benchmark_* flags]
 *
 * Kernels, each on a noisy cube (pcl::rspd::makeScene ("cube")) of every requested size. The noise
 * sigma defaults to 0.01 * min (1, sqrt (100000 / n)): the cube's own 0.01 m up to 100k points,
 * shrunk with the point spacing above, so that larger sizes keep the 100k cube's noise per
 * neighbourhood. With the scene's fixed 0.01 m,
 * at 1M points a 50-neighbourhood is no wider than the noise, no cell passes the planarity test and
 * split, grow and merge would time an empty pipeline.
 *  - knn_graph/ours          pcl::rspd::buildKnnGraph, k = 50 (grid build and queries)
 *  - knn_graph/kdtree_flann  the same graph from pcl::KdTreeFLANN: tree build, then k + 1 nearest per
 *                            sample (the sample itself dropped), OpenMP over samples like ours
 *  - normals                 pcl::rspd::estimateNormals over the graph's neighbourhoods
 *  - planarity_test          pcl::rspd::robustPlanarityTest on one cell of 4 eps samples on a face
 *  - split                   pcl::rspd::splitPhase (Algorithm 1)
 *  - grow_merge_round        one growPatches + mergePatches round on the split's patches
 *  - detect_planes           pcl::rspd::detectPlanes: split, grow/merge until stable, small-plane pass
 * Everything a kernel needs (scene, centred samples, graph, normals, seeds) is built once per size
 * and shared, outside the timed loops. Times are wall clock (the kernels run OpenMP threads).
 */

#include <pcl_rspd/neighbor_graph.h>
#include <pcl_rspd/normal_estimation.h>
#include <pcl_rspd/octree_split.h>
#include <pcl_rspd/patch_growth.h>
#include <pcl_rspd/patch_merge.h>
#include <pcl_rspd/planar_patch.h>
#include <pcl_rspd/plane_detector.h>
#include <pcl_rspd/point_set.h>
#include <pcl_rspd/robust_plane_segmentation.h>
#include <pcl_rspd/synthetic_scenes.h>

#include <pcl/console/print.h>
#include <pcl/kdtree/kdtree_flann.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
/** \brief This program's own flags; the rest go to Google Benchmark. */
struct KernelOptions
{
  std::vector<std::size_t> sizes{100000};
  int threads = 0;     ///< OpenMP threads for the parallel kernels (0: OpenMP's default)
  double noise = -1.0; ///< noise sigma in metres (< 0: 0.01 * min (1, sqrt (100000 / n)))
  bool smoke = false;  ///< 20k points, one iteration each: only checks that every kernel runs
};

KernelOptions bench_options;

/** \brief Neighbours per sample, as RobustPlaneSegmentation's default. */
constexpr int kNeighbours = 50;

/** \brief The cube's noise sigma at \a n points (see the file comment). */
double
noiseFor (std::size_t n)
{
  return bench_options.noise >= 0.0 ? bench_options.noise
                                    : 0.01 * std::min (1.0, std::sqrt (1e5 / static_cast<double> (n)));
}

/** \brief What every kernel of one scene size works on, built once (not timed). */
struct Fixture
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;    ///< the scene as generated
  pcl::rspd::PointSet points;                   ///< centred samples with PCA normals
  pcl::rspd::NeighborGraph graph;               ///< k = 50
  pcl::rspd::DetectorParameters params;         ///< as RobustPlaneSegmentation resolves its defaults
  std::vector<std::uint32_t> cell;              ///< samples of one cell for the planarity test
  std::vector<pcl::rspd::PlanarPatch> seeds;    ///< the split's patches
  std::vector<std::uint32_t> seed_labels;       ///< their per-sample labels
};

/** \brief The fixture for \a n points, built on first use. Benchmark functions are called more
  * than once (Google Benchmark's iteration estimate), so the expensive setup is cached. */
const Fixture&
fixture (std::size_t n)
{
  static std::map<std::size_t, std::unique_ptr<Fixture>> cache;
  std::unique_ptr<Fixture>& slot = cache[n];
  if (slot)
    return *slot;
  slot = std::make_unique<Fixture> ();
  Fixture& f = *slot;

  pcl::rspd::SceneOptions scene_options;
  scene_options.num_points = n;
  scene_options.noise = noiseFor (n);
  pcl::rspd::Scene scene = pcl::rspd::makeScene ("cube", scene_options);
  f.cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> (std::move (scene.cloud));

  // The samples exactly as RobustPlaneSegmentation prepares them: its own order of the valid
  // samples (which may differ from the cloud's, e.g. a spatial one) and its own PCA normals, taken
  // from one full run rather than re-implemented here. Positions are centred on the bounding box's
  // middle in double precision, as the class does.
  pcl::RobustPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (f.cloud);
  seg.setNumberOfNeighbours (kNeighbours);
  if (bench_options.threads > 0)
    seg.setNumberOfThreads (static_cast<unsigned int> (bench_options.threads));
  pcl::PointIndices largest;
  pcl::ModelCoefficients coefficients;
  seg.segment (largest, coefficients);
  if (!seg.hasResult ())
    throw std::runtime_error ("RobustPlaneSegmentation failed on the benchmark scene");
  Eigen::Vector3d lo = Eigen::Vector3d::Constant (HUGE_VAL), hi = -lo;
  for (const pcl::PointXYZ& p : *f.cloud)
  {
    lo = lo.cwiseMin (Eigen::Vector3d (p.x, p.y, p.z));
    hi = hi.cwiseMax (Eigen::Vector3d (p.x, p.y, p.z));
  }
  f.points.offset = 0.5 * (lo + hi);
  f.points.input_indices = seg.getValidIndices ();
  f.points.normals = seg.getUsedNormals ();
  for (const pcl::index_t i : f.points.input_indices)
  {
    const pcl::PointXYZ& p = (*f.cloud)[i];
    f.points.points.push_back ((Eigen::Vector3d (p.x, p.y, p.z) - f.points.offset).cast<float> ());
  }
  if (!pcl::rspd::buildKnnGraph (f.points.points, kNeighbours, bench_options.threads, f.graph))
    throw std::runtime_error ("buildKnnGraph failed on the benchmark scene");

  f.params.min_patch_size =
      std::max<std::size_t> (10, static_cast<std::size_t> (std::ceil (0.001 * static_cast<double> (n))));
  f.params.small_cell_size = kNeighbours + 1;  // the class's default small-plane pass
  f.params.num_threads = bench_options.threads;

  // One cell: the 4 eps samples nearest (max norm, so a square as an octree cell cuts it) to the
  // middle of the cube's top face - the size of a cell the split typically tests.
  const Eigen::Vector3f top (0.0f, 0.0f, static_cast<float> (0.5 * (hi.z () - lo.z ())));
  std::vector<std::pair<float, std::uint32_t>> by_distance;
  by_distance.reserve (f.points.size ());
  for (std::uint32_t i = 0; i < f.points.size (); ++i)
    by_distance.emplace_back ((f.points.points[i] - top).cwiseAbs ().maxCoeff (), i);
  const std::size_t cell_size = std::min (by_distance.size (), 4 * f.params.min_patch_size);
  std::nth_element (by_distance.begin (), by_distance.begin () + cell_size - 1, by_distance.end ());
  for (std::size_t j = 0; j < cell_size; ++j)
    f.cell.push_back (by_distance[j].second);
  std::sort (f.cell.begin (), f.cell.end ());

  f.seeds = pcl::rspd::splitPhase (f.points, f.params);
  f.seed_labels = pcl::rspd::labelSamples (f.points.size (), f.seeds);
  return f;
}

/** \brief Samples per second, reported next to each time. */
void
setRate (benchmark::State& state, std::size_t items)
{
  state.counters["samples/s"] =
      benchmark::Counter (static_cast<double> (items), benchmark::Counter::kIsIterationInvariantRate);
}

void
knnGraphOurs (benchmark::State& state, std::size_t n)
{
  const Fixture& f = fixture (n);
  for (auto _ : state)
  {
    pcl::rspd::NeighborGraph graph;
    pcl::rspd::buildKnnGraph (f.points.points, kNeighbours, bench_options.threads, graph);
    benchmark::DoNotOptimize (graph.size ());
  }
  setRate (state, n);
}

/** The same k = 50 graph the way a PCL user gets it: KdTreeFLANN, k + 1 nearest (the first is the
  * sample itself), copied into one flat array as ours stores it; parallel over samples like ours. */
void
knnGraphKdTreeFlann (benchmark::State& state, std::size_t n)
{
  const Fixture& f = fixture (n);
  std::vector<std::uint32_t> flat (n * kNeighbours);
  const int threads = pcl::rspd::resolveThreads (bench_options.threads);
  for (auto _ : state)
  {
    pcl::KdTreeFLANN<pcl::PointXYZ> tree;
    tree.setInputCloud (f.cloud);
    const std::ptrdiff_t count = static_cast<std::ptrdiff_t> (n);
#pragma omp parallel num_threads(threads)
    {
      pcl::Indices nn;
      std::vector<float> d2;
#pragma omp for schedule(dynamic, 256)
      for (std::ptrdiff_t i = 0; i < count; ++i)
      {
        tree.nearestKSearch ((*f.cloud)[i], kNeighbours + 1, nn, d2);
        std::uint32_t* row = flat.data () + static_cast<std::size_t> (i) * kNeighbours;
        int j = 0;
        for (const pcl::index_t q : nn)
          if (q != i && j < kNeighbours)
            row[j++] = static_cast<std::uint32_t> (q);
      }
    }
    benchmark::DoNotOptimize (flat.data ());
  }
  setRate (state, n);
}

void
normals (benchmark::State& state, std::size_t n)
{
  const Fixture& f = fixture (n);
  std::vector<Eigen::Vector3f> out;
  for (auto _ : state)
  {
    pcl::rspd::estimateNormals (f.points.points, f.graph, bench_options.threads, out);
    benchmark::DoNotOptimize (out.data ());
  }
  setRate (state, n);
}

void
planarityTest (benchmark::State& state, std::size_t n)
{
  const Fixture& f = fixture (n);
  for (auto _ : state)
  {
    pcl::rspd::PlanarityResult r = pcl::rspd::robustPlanarityTest (f.points, f.cell, f.params);
    benchmark::DoNotOptimize (r.verdict);
  }
  state.counters["cell"] = static_cast<double> (f.cell.size ());
  setRate (state, f.cell.size ());
}

void
split (benchmark::State& state, std::size_t n)
{
  const Fixture& f = fixture (n);
  std::size_t patches = 0;
  for (auto _ : state)
  {
    std::vector<pcl::rspd::PlanarPatch> seeds = pcl::rspd::splitPhase (f.points, f.params);
    patches = seeds.size ();
    benchmark::DoNotOptimize (seeds.data ());
  }
  state.counters["patches"] = static_cast<double> (patches);
  setRate (state, n);
}

/** One round of Sec. 3.3-3.4 from the split's seeds; the copy of the seeds is not timed. */
void
growMergeRound (benchmark::State& state, std::size_t n)
{
  const Fixture& f = fixture (n);
  std::size_t patches = 0;
  for (auto _ : state)
  {
    state.PauseTiming ();
    std::vector<pcl::rspd::PlanarPatch> work = f.seeds;
    std::vector<std::uint32_t> labels = f.seed_labels;
    state.ResumeTiming ();
    pcl::rspd::growPatches (f.points, f.graph, work, labels);
    pcl::rspd::mergePatches (f.points, f.graph, work, labels);
    patches = work.size ();
    benchmark::DoNotOptimize (labels.data ());
  }
  state.counters["seeds"] = static_cast<double> (f.seeds.size ());
  state.counters["patches"] = static_cast<double> (patches);
  setRate (state, n);
}

void
detectPlanes (benchmark::State& state, std::size_t n)
{
  const Fixture& f = fixture (n);
  std::size_t planes = 0;
  for (auto _ : state)
  {
    std::vector<pcl::rspd::DetectedPatch> patches;
    pcl::rspd::detectPlanes (f.points, f.graph, f.params, patches);
    planes = patches.size ();
    benchmark::DoNotOptimize (patches.data ());
  }
  state.counters["planes"] = static_cast<double> (planes);
  setRate (state, n);
}

/** \brief Parse "100000,1000000" (k and M suffixes allowed). \return false on a malformed list */
bool
parseSizes (const std::string& text, std::vector<std::size_t>& sizes)
{
  sizes.clear ();
  std::size_t start = 0;
  while (start <= text.size ())
  {
    const std::size_t comma = std::min (text.find (',', start), text.size ());
    std::string item = text.substr (start, comma - start);
    std::size_t scale = 1;
    if (!item.empty () && (item.back () == 'k' || item.back () == 'M'))
    {
      scale = item.back () == 'k' ? 1000 : 1000000;
      item.pop_back ();
    }
    std::size_t value = 0;
    const auto r = std::from_chars (item.data (), item.data () + item.size (), value);
    if (item.empty () || r.ec != std::errc () || r.ptr != item.data () + item.size () || value == 0 ||
        value > 100000000 / scale || value * scale <= static_cast<std::size_t> (kNeighbours))
      return false;
    sizes.push_back (value * scale);
    start = comma + 1;
  }
  return true;
}

/** \brief Take this program's flags out of argv (Google Benchmark rejects flags it does not know).
  * \return false on a malformed value (message printed) */
bool
takeOwnFlags (int& argc, char** argv)
{
  int out = 1;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const auto value = [&] (const char* name) -> const char* {
      const std::string prefix = std::string (name) + "=";
      if (arg.compare (0, prefix.size (), prefix) == 0)
        return argv[i] + prefix.size ();
      return i + 1 < argc ? argv[++i] : nullptr;
    };
    if (arg == "--smoke")
      bench_options.smoke = true;
    else if (arg == "--large")
      bench_options.sizes = {100000, 1000000};
    else if (arg == "--sizes" || arg.compare (0, 8, "--sizes=") == 0)
    {
      const char* v = value ("--sizes");
      if (!v || !parseSizes (v, bench_options.sizes))
      {
        std::fprintf (stderr, "bench_kernels: --sizes needs a comma-separated list of point counts > %d\n",
                      kNeighbours);
        return false;
      }
    }
    else if (arg == "--noise" || arg.compare (0, 8, "--noise=") == 0)
    {
      const char* v = value ("--noise");
      char* end = nullptr;
      bench_options.noise = v ? std::strtod (v, &end) : -1.0;
      if (!v || end == v || *end != '\0' || !std::isfinite (bench_options.noise) || bench_options.noise < 0.0)
      {
        std::fprintf (stderr, "bench_kernels: --noise needs a number >= 0 (metres)\n");
        return false;
      }
    }
    else if (arg == "--threads" || arg.compare (0, 10, "--threads=") == 0)
    {
      const char* v = value ("--threads");
      const std::size_t len = v ? std::strlen (v) : 0;
      const auto r = v ? std::from_chars (v, v + len, bench_options.threads) : std::from_chars_result{};
      if (!v || len == 0 || r.ec != std::errc () || r.ptr != v + len || bench_options.threads < 1)
      {
        std::fprintf (stderr, "bench_kernels: --threads needs a positive integer\n");
        return false;
      }
    }
    else
      argv[out++] = argv[i];
  }
  argc = out;
  argv[argc] = nullptr;
  return true;
}
} // namespace

int
main (int argc, char** argv)
{
  if (!takeOwnFlags (argc, argv))
    return 2;
  pcl::console::setVerbosityLevel (pcl::console::L_ERROR);
  if (bench_options.smoke)
    bench_options.sizes = {20000};

  using Kernel = void (*) (benchmark::State&, std::size_t);
  const std::pair<const char*, Kernel> kernels[] = {
      {"knn_graph/ours", knnGraphOurs}, {"knn_graph/kdtree_flann", knnGraphKdTreeFlann},
      {"normals", normals},             {"planarity_test", planarityTest},
      {"split", split},                 {"grow_merge_round", growMergeRound},
      {"detect_planes", detectPlanes}};
  for (const std::size_t n : bench_options.sizes)
    for (const auto& kernel : kernels)
    {
      const Kernel fn = kernel.second;
      auto* b = benchmark::RegisterBenchmark (
          (std::string (kernel.first) + "/cube:" + std::to_string (n)).c_str (),
          [fn, n] (benchmark::State& state) { fn (state, n); });
      b->Unit (benchmark::kMillisecond)->UseRealTime ();
      if (bench_options.smoke)
        b->Iterations (1);
    }

  benchmark::Initialize (&argc, argv);
  if (benchmark::ReportUnrecognizedArguments (argc, argv))
    return 2;
  benchmark::AddCustomContext ("threads", bench_options.threads > 0 ? std::to_string (bench_options.threads)
                                                                : std::string ("OpenMP default"));
  benchmark::AddCustomContext ("scene", "pcl::rspd::makeScene (\"cube\"), seed 1, k = 50");
  for (const std::size_t n : bench_options.sizes)
    benchmark::AddCustomContext ("noise sigma at " + std::to_string (n) + " points", std::to_string (noiseFor (n)));
  benchmark::RunSpecifiedBenchmarks ();
  benchmark::Shutdown ();
  return 0;
}
