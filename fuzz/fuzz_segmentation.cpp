/*
 * pcl_rspd fuzz target: bytes -> a small cloud (with or without normals and indices, with NaN,
 * duplicates and degenerate geometry) -> pcl::RobustPlaneSegmentation. Aborts when an invariant of
 * the class's contract is broken; sanitizers catch the rest.
 *
 * Built two ways (fuzz/CMakeLists.txt): with clang and libFuzzer (scripts/fuzz.sh), and with the
 * normal compiler plus fuzz/replay_main.cpp, which ctest runs over fuzz/corpus/segmentation and
 * fuzz/regressions/segmentation.
 *
 * Input layout (bytes past the end read as 0, so every input is valid):
 *   0-1  n = (b0 | (b1 & 1) << 8) % 401 points
 *   2    k = b2 % 59: 0 automatic, else 2 + b2 % 59 (setNumberOfNeighbours, 3..60)
 *   3    flags: 1 normals given, 2 indices given, 4 KdTree search method, 8 epsilon set directly,
 *        16 paper's letter (zero floors), 32 no normal alignment, 64 NaN/Inf/huge values,
 *        128 run twice (second object, SAC-style segment) and compare
 *   4    bits 0-2 geometry, 3-4 normal mode, 5 organized, 6 out-of-range indices, 7 jitter
 *   5    lattice size L = 1 + b5 % 40 (values per axis)
 *   6    scale 10^(b6 % 13 - 6)
 *   7    offset magnitude (b7 % 8: 0, 1, 1e2 .. 1e6) and signs per axis (bits 3-5)
 *   8    epsilon (3 + b8 % 40 when flag 8); if b8 & 128, grow-merge cap 1 + (b8 >> 5 & 3)
 *   9    sensor origin (b9 & 3); b9 & 4: setSmallPlaneSeeding (false); b9 & 8: setNormalScale (Adaptive,
 *        or Automatic with b9 & 16); b9 & 32: setCoplanarMerge (false), setDropOutlierSeeds (false),
 *        setDetectionFrame (InputAxes), setNormalFit (Pca), setRimCellRetest (false) and
 *        setFarMemberRelease (false), setEdgeSides (false), setConnectedParts (false),
 *        setBentPlaneSplit (false), setReleasedPlaneSeeding (false), setSupportCheck (false),
 *        setStepSides (false), setThickCellJoin (false);
 *        b9 & 64: setCurvedPlaneCheck (true) and setNormalFit (TrimmedPlane); b9 & 128: setFinalAssignment (All;
 *        None with b9 & 32, else Edges with b9 & 64; the default is Tails); b9 & 16 without b9 & 64:
 *        setLeftNormalRefit (true)
 *   10   slopes of the tilted plane
 *   11   index count (b11 * n / 128), jitter amplitude (b11 & 7), normals size mismatch (b11 & 128
 *        together with out-of-range indices)
 *   then per point: 3 coordinate bytes, 3 jitter bytes if jitter, 3 normal bytes if normals;
 *   then 2 bytes per index.
 * RSPD_FUZZ_VERBOSE=1 in the environment prints one line per input (size, outcome, planes) and
 * PCL's messages down to PCL_DEBUG.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/robust_plane_segmentation.h>

#include <pcl/console/print.h>
#include <pcl/search/kdtree.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

namespace
{
using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Normals = pcl::PointCloud<pcl::Normal>;
using Seg = pcl::RobustPlaneSegmentation<pcl::PointXYZ, pcl::Normal>;

/** Bytes in order; 0 once they run out. */
class Bytes
{
public:
  Bytes (const std::uint8_t* data, std::size_t size) : data_ (data), size_ (size) {}
  std::uint8_t
  next ()
  {
    return pos_ < size_ ? data_[pos_++] : 0;
  }

private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

[[noreturn]] void
fail (const char* what)
{
  std::fprintf (stderr, "fuzz_segmentation: invariant violated: %s\n", what);
  std::abort ();
}

#define FUZZ_CHECK(cond)                                                                           \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
      fail (#cond);                                                                                \
  } while (0)

/** A special value for a coordinate byte when NaN/Inf injection is on, else nothing (false). */
bool
specialValue (std::uint8_t b, float& v)
{
  switch (b)
  {
    case 255: v = std::numeric_limits<float>::quiet_NaN (); return true;
    case 254: v = std::numeric_limits<float>::infinity (); return true;
    case 253: v = -std::numeric_limits<float>::infinity (); return true;
    case 252: v = 1e30f; return true;  // finite but huge
    case 251: v = -3e38f; return true; // near the float limit
    case 250: v = std::numeric_limits<float>::denorm_min (); return true;
    default: return false;
  }
}

bool
sameBytes (const void* a, const void* b, std::size_t n)
{
  return n == 0 || std::memcmp (a, b, n) == 0;
}

bool
sameCloud (const Cloud& a, const Cloud& b)
{
  return a.size () == b.size () && a.width == b.width && a.height == b.height && a.is_dense == b.is_dense &&
         sameBytes (a.points.data (), b.points.data (), a.size () * sizeof (pcl::PointXYZ)) &&
         sameBytes (a.sensor_origin_.data (), b.sensor_origin_.data (), sizeof (float) * 4) &&
         sameBytes (a.sensor_orientation_.coeffs ().data (), b.sensor_orientation_.coeffs ().data (), sizeof (float) * 4);
}

bool
sameNormals (const Normals& a, const Normals& b)
{
  return a.size () == b.size () && a.width == b.width && a.height == b.height &&
         sameBytes (a.points.data (), b.points.data (), a.size () * sizeof (pcl::Normal));
}

bool
finite3 (const Eigen::Vector3d& v)
{
  return std::isfinite (v.x ()) && std::isfinite (v.y ()) && std::isfinite (v.z ());
}

/** The checks every successful or failed run must pass. */
void
checkResult (const Cloud& cloud, const std::vector<bool>& valid, bool expected_ok, Seg& seg,
             const std::vector<pcl::ModelCoefficients>& coefficients, const std::vector<pcl::PointIndices>& planes)
{
  FUZZ_CHECK (coefficients.size () == planes.size ());
  pcl::PointCloud<pcl::Label> labels;
  seg.getLabels (labels);
  const std::vector<pcl::RobustPlane>& detail = seg.getPlanes ();
  if (!seg.hasResult ())
  {
    FUZZ_CHECK (!expected_ok);
    FUZZ_CHECK (coefficients.empty ());
    FUZZ_CHECK (planes.empty ());
    FUZZ_CHECK (labels.empty ());
    FUZZ_CHECK (detail.empty ());
    FUZZ_CHECK (seg.getColoredCloud () == nullptr);
    return;
  }
  FUZZ_CHECK (expected_ok);
  const std::size_t n = cloud.size ();
  FUZZ_CHECK (labels.size () == n);
  FUZZ_CHECK (labels.width == cloud.width && labels.height == cloud.height);
  FUZZ_CHECK (detail.size () == planes.size ());

  std::vector<std::uint32_t> owner (n, 0);
  std::size_t members = 0;
  for (std::size_t p = 0; p < planes.size (); ++p)
  {
    const auto& idx = planes[p].indices;
    FUZZ_CHECK (!idx.empty ());
    FUZZ_CHECK (p == 0 || idx.size () <= planes[p - 1].indices.size ()); // largest first
    FUZZ_CHECK (detail[p].indices.indices == idx);
    for (std::size_t j = 0; j < idx.size (); ++j)
    {
      const pcl::index_t i = idx[j];
      FUZZ_CHECK (i >= 0 && static_cast<std::size_t> (i) < n);
      FUZZ_CHECK (j == 0 || idx[j - 1] < i); // ascending, hence unique within the plane
      FUZZ_CHECK (owner[i] == 0);           // unique across planes
      FUZZ_CHECK (valid[i]);                // only valid samples are ever assigned
      owner[i] = static_cast<std::uint32_t> (p + 1);
      FUZZ_CHECK (labels[i].label == p + 1);
      ++members;
    }
    const auto& c = coefficients[p].values;
    FUZZ_CHECK (c.size () == 4);
    FUZZ_CHECK (detail[p].coefficients.values == c);
    for (const float v : c)
      FUZZ_CHECK (std::isfinite (v));
    const double norm = std::sqrt (double (c[0]) * c[0] + double (c[1]) * c[1] + double (c[2]) * c[2]);
    FUZZ_CHECK (std::abs (norm - 1.0) < 1e-5);

    const pcl::RobustPlane& d = detail[p];
    FUZZ_CHECK (finite3 (d.center) && finite3 (d.normal) && finite3 (d.centroid));
    FUZZ_CHECK (std::abs (d.normal.norm () - 1.0) < 1e-9);
    FUZZ_CHECK (d.covariance.allFinite ());
    FUZZ_CHECK (std::isfinite (d.mdp) && d.mdp >= 0.0);
    FUZZ_CHECK (std::isfinite (d.mnd) && d.mnd >= 0.0);
    FUZZ_CHECK (finite3 (d.rect_center) && finite3 (d.rect_axes[0]) && finite3 (d.rect_axes[1]));
    FUZZ_CHECK (d.rect_size.allFinite () && d.rect_size[0] >= d.rect_size[1] && d.rect_size[1] >= 0.0);
    for (const auto& h : d.hull)
      FUZZ_CHECK (finite3 (h));
    // Oriented towards the sensor origin (the documented convention); a plane through the origin
    // may go either way.
    const Eigen::Vector3d to_origin = cloud.sensor_origin_.head<3> ().cast<double> () - d.center;
    FUZZ_CHECK (to_origin.dot (d.normal) >= -1e-9 * to_origin.norm ());
  }
  std::size_t labelled = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    FUZZ_CHECK (labels[i].label == owner[i]);
    labelled += labels[i].label != 0;
  }
  FUZZ_CHECK (labelled == members);
  // The valid samples the detection used are exactly the valid candidates.
  std::size_t n_valid = 0;
  for (std::size_t i = 0; i < n; ++i)
    n_valid += valid[i];
  FUZZ_CHECK (seg.getValidIndices ().size () == n_valid);
  FUZZ_CHECK (seg.getUsedNormals ().size () == n_valid);
  for (const auto& nn : seg.getUsedNormals ())
    FUZZ_CHECK (std::abs (nn.norm () - 1.f) < 1e-4f);
  // The adaptive normal scale accounts for every sample once.
  const auto& scales = seg.getNormalScaleStatistics ().samples_per_scale;
  if (!scales.empty ())
  {
    std::size_t total = 0;
    for (const auto c : scales)
      total += c;
    FUZZ_CHECK (total == n_valid);
  }
}

void
configure (Seg& seg, int k, std::uint8_t flags, std::uint8_t b8, std::uint8_t origin_code)
{
  if (origin_code & 4)
    seg.setSmallPlaneSeeding (false);
  if (origin_code & 8)
    seg.setNormalScale ((origin_code & 16) ? pcl::rspd::NormalScale::Automatic : pcl::rspd::NormalScale::Adaptive);
  if (origin_code & 32)
  {
    seg.setCoplanarMerge (false);
    seg.setDropOutlierSeeds (false);
    seg.setDetectionFrame (pcl::rspd::DetectionFrame::InputAxes);
    seg.setNormalFit (pcl::rspd::NormalFit::Pca);
    seg.setRimCellRetest (false);
    seg.setFarMemberRelease (false);
    seg.setEdgeSides (false);
    seg.setConnectedParts (false);
    seg.setBentPlaneSplit (false);
    seg.setReleasedPlaneSeeding (false);
    seg.setSupportCheck (false);
    seg.setStepSides (false);
    seg.setThickCellJoin (false);
  }
  if (origin_code & 64)
  {
    seg.setCurvedPlaneCheck (true);
    seg.setNormalFit (pcl::rspd::NormalFit::TrimmedPlane);
  }
  if ((origin_code & 16) && !(origin_code & 64))
    seg.setLeftNormalRefit (true);
  if (origin_code & 128)
    seg.setFinalAssignment ((origin_code & 32)   ? pcl::rspd::FinalAssignment::None
                            : (origin_code & 64) ? pcl::rspd::FinalAssignment::Edges
                                                 : pcl::rspd::FinalAssignment::All);
  seg.setNumberOfThreads (1);
  seg.setNumberOfNeighbours (k);
  if (flags & 8)
    seg.setMinPatchSize (3 + b8 % 40);
  if (flags & 16)
  {
    seg.setDistanceFloorRatio (0.0);
    seg.setNormalDeviationFloor (0.0);
  }
  if (flags & 32)
    seg.setAlignNormalsBeforeMedian (false);
  if (b8 & 128)
    seg.setMaxGrowMergeIterations (1 + (b8 >> 5 & 3));
}
} // namespace

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static const bool verbose = [] {
    const bool v = std::getenv ("RSPD_FUZZ_VERBOSE") != nullptr;
    pcl::console::setVerbosityLevel (v ? pcl::console::L_DEBUG : pcl::console::L_ALWAYS);
    return v;
  }();

  Bytes in (data, size);
  const std::uint8_t b0 = in.next (), b1 = in.next ();
  const std::size_t n = (b0 | (static_cast<std::size_t> (b1 & 1) << 8)) % 401;
  const int kb = in.next () % 59;
  const int k = kb == 0 ? 0 : 2 + kb; // 0: automatic
  const std::uint8_t flags = in.next ();
  const std::uint8_t shape = in.next ();
  const int lattice = 1 + in.next () % 40;
  const double scale = std::pow (10.0, static_cast<int> (in.next () % 13) - 6);
  const std::uint8_t offset_code = in.next ();
  const std::uint8_t b8 = in.next ();
  const std::uint8_t origin_code = in.next ();
  const std::uint8_t slopes = in.next ();
  const std::uint8_t b11 = in.next ();

  const bool with_normals = flags & 1, with_indices = flags & 2, with_search = flags & 4;
  const bool specials = flags & 64, rerun = flags & 128;
  const int geometry = shape & 7, normal_mode = shape >> 3 & 3;
  const bool organized = shape & 32, out_of_range = shape & 64, jitter = shape & 128;

  static const double kOffsets[8] = {0.0, 1.0, 1e2, 1e3, 1e4, 1e5, 1e6, 0.5};
  double offset[3];
  for (int a = 0; a < 3; ++a)
    offset[a] = kOffsets[offset_code & 7] * ((offset_code >> (3 + a) & 1) ? -1.0 : 1.0);
  const double jitter_amp = std::pow (10.0, -1.0 - (b11 & 7)); // in lattice units
  const int slope_a = (slopes & 7) - 3, slope_b = (slopes >> 3 & 7) - 3;

  auto cloud = std::make_shared<Cloud> ();
  cloud->resize (n);
  auto normals = std::make_shared<Normals> ();
  if (with_normals)
    normals->resize (n);
  const double half = 0.5 * (lattice - 1);
  for (std::size_t i = 0; i < n; ++i)
  {
    std::uint8_t c[3] = {in.next (), in.next (), in.next ()};
    double v[3];
    for (int a = 0; a < 3; ++a)
      v[a] = (c[a] % lattice) - half;
    switch (geometry)
    {
      case 0: break;                                        // free lattice: duplicates, noise
      case 1: v[2] = 0.0; break;                            // one plane
      case 2: v[1] = v[2] = (c[1] & 1) ? v[0] : 0.0; break; // collinear (axis or diagonal)
      case 3: v[c[2] % 3] = (c[2] & 8) ? half : -half; break; // faces of a box
      case 4: v[2] = slope_a * v[0] + slope_b * v[1]; break;  // tilted plane
      case 5: v[2] = (c[2] & 1) ? half : -half; break;        // two parallel planes
      case 6:                                                 // many exact repeats
        if (i > 0 && c[2] < 192)
        {
          const pcl::PointXYZ& q = (*cloud)[c[0] % i];
          v[0] = q.x, v[1] = q.y, v[2] = q.z; // already scaled and offset: copied as is below
        }
        break;
      default: v[0] = v[1] = v[2] = (c[0] & 3) ? 0.0 : half; break; // (nearly) all identical
    }
    const bool copied = geometry == 6 && i > 0 && c[2] < 192;
    if (jitter)
      for (int a = 0; a < 3; ++a)
        v[a] += (in.next () - 128) / 128.0 * jitter_amp;
    pcl::PointXYZ& p = (*cloud)[i];
    float* out[3] = {&p.x, &p.y, &p.z};
    for (int a = 0; a < 3; ++a)
    {
      float s = 0.0f;
      if (specials && specialValue (c[a], s))
        *out[a] = s;
      else
        *out[a] = copied ? static_cast<float> (v[a]) : static_cast<float> (v[a] * scale + offset[a]);
    }
    if (with_normals)
    {
      std::uint8_t m[3] = {in.next (), in.next (), in.next ()};
      float nv[3] = {0.0f, 0.0f, 0.0f};
      switch (normal_mode)
      {
        case 0: // arbitrary, including the zero vector at (128, 128, 128)
          for (int a = 0; a < 3; ++a)
            nv[a] = (m[a] - 128) / 127.0f;
          break;
        case 1: // an axis, either sign
          nv[m[0] % 3] = (m[0] & 4) ? -1.0f : 1.0f;
          break;
        case 2: // z, either sign, unnormalized length
          nv[2] = ((m[0] & 1) ? -1.0f : 1.0f) * (1 + m[1] % 4);
          break;
        default: // almost z, tiny perturbations
          nv[0] = (m[0] - 128) * 1e-4f;
          nv[1] = (m[1] - 128) * 1e-4f;
          nv[2] = 1.0f;
          break;
      }
      pcl::Normal& q = (*normals)[i];
      q.normal_x = nv[0];
      q.normal_y = nv[1];
      q.normal_z = nv[2];
      if (specials)
      {
        float s = 0.0f;
        if (specialValue (m[2], s))
          q.normal_z = s;
      }
      q.curvature = 0.0f;
    }
  }
  if (organized && n >= 4 && n % 2 == 0)
  {
    cloud->width = static_cast<std::uint32_t> (n / 2);
    cloud->height = 2;
  }
  cloud->is_dense = !specials;
  // Sensor origin: at the origin, far on an axis, or inside the cloud.
  switch (origin_code & 3)
  {
    case 0: break;
    case 1: cloud->sensor_origin_ = Eigen::Vector4f (0.0f, 0.0f, static_cast<float> (1e3 * scale), 0.0f); break;
    case 2: cloud->sensor_origin_ = Eigen::Vector4f (static_cast<float> (offset[0]), static_cast<float> (offset[1]),
                                                     static_cast<float> (offset[2]), 0.0f); break;
    default: cloud->sensor_origin_ = Eigen::Vector4f (static_cast<float> (-1e6), 0.0f, 0.0f, 0.0f); break;
  }

  pcl::IndicesPtr indices;
  bool indices_in_range = true;
  if (with_indices)
  {
    indices = std::make_shared<pcl::Indices> ();
    const std::size_t m = static_cast<std::size_t> (b11 >> 3) * (n + 2) / 16; // 0 .. ~2n, repeats likely
    for (std::size_t j = 0; j < m; ++j)
    {
      const std::uint32_t r = in.next () | static_cast<std::uint32_t> (in.next ()) << 8;
      pcl::index_t i = 0;
      if (out_of_range)
        i = static_cast<pcl::index_t> (r % (n + 4)) - 2; // -2 .. n+1
      else if (n > 0)
        i = static_cast<pcl::index_t> (r % n);
      if (i < 0 || static_cast<std::size_t> (i) >= n)
        indices_in_range = false;
      indices->push_back (i);
    }
  }
  bool normals_mismatch = false;
  if (with_normals && out_of_range && (b11 & 128) && n > 0)
  {
    normals->resize (n - 1); // one short
    normals_mismatch = true;
  }

  // What the class must do: succeed exactly when the indices are in range, the normals fit and
  // more than k valid samples remain.
  std::vector<bool> valid (n, false);
  std::vector<bool> candidate (n, !with_indices);
  if (with_indices)
    for (const auto i : *indices)
      if (i >= 0 && static_cast<std::size_t> (i) < n)
        candidate[i] = true;
  std::size_t n_valid = 0;
  bool extreme = false, beyond_half_range = false;
  for (std::size_t i = 0; i < n; ++i)
  {
    const pcl::PointXYZ& p = (*cloud)[i];
    if (!candidate[i] || !std::isfinite (p.x) || !std::isfinite (p.y) || !std::isfinite (p.z))
      continue;
    if (with_normals && !normals_mismatch)
    {
      const pcl::Normal& q = (*normals)[i];
      const double len2 = double (q.normal_x) * q.normal_x + double (q.normal_y) * q.normal_y +
                          double (q.normal_z) * q.normal_z;
      if (!std::isfinite (len2) || !(len2 > 0.0))
        continue;
    }
    valid[i] = true;
    ++n_valid;
    extreme = extreme || std::abs (p.x) > 1e15f || std::abs (p.y) > 1e15f || std::abs (p.z) > 1e15f;
    const float half_range = 0.5f * std::numeric_limits<float>::max ();
    beyond_half_range = beyond_half_range || !(std::abs (p.x) < half_range && std::abs (p.y) < half_range &&
                                               std::abs (p.z) < half_range);
  }
  // With a search method, coordinates beyond half the float range are refused: FLANN cannot split
  // them (fuzz/regressions/README.md).
  // k = 0: the automatic k of the resolved ε (0.1 % of the valid samples, at least 10, or set), or
  // the paper's 50 with given normals.
  const std::size_t epsilon = (flags & 8) ? std::size_t (3 + b8 % 40) : std::max<std::size_t> (10, (n_valid + 999) / 1000);
  const int k_used = k > 0 ? k : (with_normals ? pcl::rspd::kPaperNeighbours : pcl::rspd::automaticNumberOfNeighbours (epsilon));
  bool expected_ok = n > 0 && indices_in_range && !normals_mismatch && n_valid > static_cast<std::size_t> (k_used) &&
                     !(with_search && beyond_half_range);
  // FLANN (the KdTree search method) cannot rank neighbours whose squared distances overflow a
  // float, and then returns fewer than k: the class must fail cleanly, which is checked, but
  // success is not promised.
  const bool success_optional = with_search && extreme;

  // Copies of everything the caller owns, to check that nothing is modified.
  const Cloud cloud_copy = *cloud;
  const Normals normals_copy = *normals;
  const pcl::Indices indices_copy = indices ? *indices : pcl::Indices ();

  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> planes;
  Seg seg;
  configure (seg, k, flags, b8, origin_code);
  seg.setInputCloud (cloud);
  if (with_normals)
    seg.setInputNormals (normals);
  if (indices)
    seg.setIndices (indices);
  if (with_search)
    seg.setSearchMethod (std::make_shared<pcl::search::KdTree<pcl::PointXYZ>> ());
  seg.segment (coefficients, planes);
  if (success_optional && !seg.hasResult ())
    expected_ok = false;
  if (verbose)
    std::fprintf (stderr, "n %zu, valid %zu, k %d, normals %d, indices %d, search %d, geometry %d: %s, %zu planes\n",
                  n, n_valid, k_used, with_normals, with_indices, with_search, geometry,
                  seg.hasResult () ? "ok" : "failed", planes.size ());
  checkResult (*cloud, valid, expected_ok, seg, coefficients, planes);
  FUZZ_CHECK (!seg.hasResult () || seg.getNumberOfNeighboursUsed () == k_used);

  FUZZ_CHECK (sameCloud (*cloud, cloud_copy));
  FUZZ_CHECK (sameNormals (*normals, normals_copy));
  FUZZ_CHECK (!indices || *indices == indices_copy);

  if (rerun)
  {
    // The cached result again, then a fresh object: the same planes (deterministic), and the
    // SACSegmentation-style call gives the largest one.
    std::vector<pcl::ModelCoefficients> c2;
    std::vector<pcl::PointIndices> p2;
    seg.segment (c2, p2);
    FUZZ_CHECK (p2.size () == planes.size ());
    Seg again;
    configure (again, k, flags, b8, origin_code);
    again.setInputCloud (cloud);
    if (with_normals)
      again.setInputNormals (normals);
    if (indices)
      again.setIndices (indices);
    if (with_search)
      again.setSearchMethod (std::make_shared<pcl::search::KdTree<pcl::PointXYZ>> ());
    pcl::PointIndices largest;
    pcl::ModelCoefficients largest_c;
    again.segment (largest, largest_c);
    FUZZ_CHECK (again.hasResult () == seg.hasResult ());
    if (planes.empty ())
      FUZZ_CHECK (largest.indices.empty () && largest_c.values.empty ());
    else
    {
      FUZZ_CHECK (largest.indices == planes.front ().indices);
      FUZZ_CHECK (largest_c.values == coefficients.front ().values);
    }
    std::vector<pcl::ModelCoefficients> c3;
    std::vector<pcl::PointIndices> p3;
    again.segment (c3, p3);
    FUZZ_CHECK (p3.size () == planes.size ());
    for (std::size_t p = 0; p < p3.size (); ++p)
    {
      FUZZ_CHECK (p3[p].indices == planes[p].indices);
      FUZZ_CHECK (c3[p].values == coefficients[p].values);
    }
    FUZZ_CHECK (sameCloud (*cloud, cloud_copy));
    FUZZ_CHECK (sameNormals (*normals, normals_copy));
  }
  return 0;
}
