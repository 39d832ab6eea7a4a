/*
 * pcl_rspd: PCA normals over the growth graph's k-neighbourhoods, at the k-scale or at the finest
 * scale that resolves a surface.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <pcl_rspd/normal_estimation.h>
#include <pcl_rspd/robust_statistics.h> // medianInPlace

#include <pcl/common/eigen.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <utility>

namespace pcl
{
namespace rspd
{
namespace
{
/** Covariance of a sample and its neighbours about their mean (the sample counts once). Offsets are
  * taken from the sample itself so that precision does not depend on where the scene lies. */
template <typename ForEachNeighbour> Eigen::Matrix3d
neighbourhoodCovariance (const Eigen::Vector3f& self, int k, const std::vector<Eigen::Vector3f>& points,
                         ForEachNeighbour&& for_each)
{
  // Relative to the sample to keep precision; the six distinct sums of the symmetric matrix as
  // scalars (a full 3x3 update per neighbour made this stage twice as slow).
  const double ox = self.x (), oy = self.y (), oz = self.z ();
  double sx = 0.0, sy = 0.0, sz = 0.0, sxx = 0.0, sxy = 0.0, sxz = 0.0, syy = 0.0, syz = 0.0, szz = 0.0;
  for_each ([&] (std::uint32_t j) {
    const double dx = static_cast<double> (points[j].x ()) - ox;
    const double dy = static_cast<double> (points[j].y ()) - oy;
    const double dz = static_cast<double> (points[j].z ()) - oz;
    sx += dx;
    sy += dy;
    sz += dz;
    sxx += dx * dx;
    sxy += dx * dy;
    sxz += dx * dz;
    syy += dy * dy;
    syz += dy * dz;
    szz += dz * dz;
  });
  const double m = static_cast<double> (k + 1); // the sample itself contributes d = 0
  const Eigen::Vector3d mean (sx / m, sy / m, sz / m);
  Eigen::Matrix3d cov;
  cov << sxx / m, sxy / m, sxz / m, sxy / m, syy / m, syz / m, sxz / m, syz / m, szz / m;
  return cov - mean * mean.transpose ();
}

/** neighbourhoodCovariance of sample \a i and its graph row: the PCA neighbourhood at the graph's k. */
Eigen::Matrix3d
graphRowCovariance (const std::vector<Eigen::Vector3f>& points, const NeighborGraph& graph, std::size_t i)
{
  return neighbourhoodCovariance (points[i], graph.k (), points, [&] (auto&& add) { graph.forEachNeighbor (i, add); });
}

/** Unit eigenvector of the smallest eigenvalue (normal untouched if the samples coincide), and
  * λ0/λ1, smallest over middle eigenvalue: 0 for a flat neighbourhood, near 1 for one that fills a
  * ball. A neighbourhood without two independent directions (coincident or collinear samples) has no
  * surface normal: ratio 1. */
void
fitNormal (const Eigen::Matrix3d& cov, Eigen::Vector3f& normal, double& ratio, double* smallest = nullptr,
           double* middle = nullptr)
{
  ratio = 1.0;
  if (smallest)
    *smallest = 0.0;
  if (middle)
    *middle = 0.0;
  if (!(cov.cwiseAbs ().maxCoeff () > 0.0))
    return;
  double l0;
  Eigen::Vector3d eigen_vector;
  pcl::eigen33 (cov, l0, eigen_vector);
  const double norm = eigen_vector.norm ();
  if (!(norm > 0.0 && std::isfinite (norm)))
    return;
  normal = (eigen_vector / norm).cast<float> ();
  // λ1 and λ2 are the roots of x² - (c2 - λ0) x + (c1 - λ0 (c2 - λ0)), with c2 the trace and c1 the
  // sum of the principal 2x2 minors: no second solution of the cubic.
  const double c2 = cov.trace ();
  const double c1 = cov (0, 0) * cov (1, 1) - cov (0, 1) * cov (0, 1) + cov (0, 0) * cov (2, 2) -
                    cov (0, 2) * cov (0, 2) + cov (1, 1) * cov (2, 2) - cov (1, 2) * cov (1, 2);
  l0 = std::max (0.0, l0);
  const double sum = c2 - l0, product = c1 - l0 * sum;
  const double l1 = 0.5 * (sum - std::sqrt (std::max (0.0, sum * sum - 4.0 * product)));
  if (l1 > 0.0 && std::isfinite (l1))
    ratio = std::min (1.0, l0 / l1);
  if (smallest)
    *smallest = l0;
  if (middle)
    *middle = std::isfinite (l1) ? std::max (0.0, l1) : 0.0;
}

/** splitmix64: a tiny generator whose stream is the same on every platform (the standard
  * distributions are not), so the Monte Carlo quantile is too. */
struct SplitMix64
{
  std::uint64_t state;
  std::uint64_t
  next ()
  {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  /** Uniform in [-1, 1). */
  double
  symmetric ()
  {
    return static_cast<double> (next () >> 11) * (1.0 / 9007199254740992.0) * 2.0 - 1.0;
  }
};
} // namespace

int
resolveThreads (int requested)
{
  return requested > 0 ? requested : std::max (1, omp_get_max_threads ());
}

void
estimateNormals (const std::vector<Eigen::Vector3f>& points, const NeighborGraph& graph, int num_threads,
                 std::vector<Eigen::Vector3f>& normals)
{
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (points.size ());
  normals.assign (points.size (), Eigen::Vector3f::UnitZ ());
#pragma omp parallel for schedule(static, 4096) num_threads(resolveThreads (num_threads))
  for (std::ptrdiff_t i = 0; i < n; ++i)
  {
    double ratio;
    fitNormal (graphRowCovariance (points, graph, static_cast<std::size_t> (i)), normals[i], ratio); // degenerate: +Z
  }
}

double
isotropicEigenRatioQuantile (int k, double quantile)
{
  static std::mutex mutex;
  static std::map<std::pair<int, double>, double> cache;
  if (k < 2 || !(quantile > 0.0 && quantile < 1.0))
    return 0.0;
  const std::pair<int, double> key (k, quantile);
  {
    std::lock_guard<std::mutex> lock (mutex);
    const auto it = cache.find (key);
    if (it != cache.end ())
      return it->second;
  }
  // The null hypothesis "no surface at this scale": the k nearest samples of a sample inside a
  // uniformly filled volume are uniform in a ball around it.
  constexpr int kDraws = 4000;
  SplitMix64 rng{0x5eed5eed5eed5eedULL};
  std::vector<Eigen::Vector3f> ball (static_cast<std::size_t> (k) + 1);
  std::vector<double> ratios (kDraws);
  for (int d = 0; d < kDraws; ++d)
  {
    ball[0] = Eigen::Vector3f::Zero (); // the sample itself, at the centre
    for (int j = 1; j <= k; ++j)
    {
      Eigen::Vector3d p;
      do
        p = Eigen::Vector3d (rng.symmetric (), rng.symmetric (), rng.symmetric ());
      while (!(p.squaredNorm () < 1.0));
      ball[j] = p.cast<float> ();
    }
    const Eigen::Matrix3d cov = neighbourhoodCovariance (ball[0], k, ball, [&] (auto&& add) {
      for (int j = 1; j <= k; ++j)
        add (static_cast<std::uint32_t> (j));
    });
    Eigen::Vector3f normal;
    fitNormal (cov, normal, ratios[d]);
  }
  const std::size_t at = std::min<std::size_t> (kDraws - 1, static_cast<std::size_t> (quantile * kDraws));
  std::nth_element (ratios.begin (), ratios.begin () + static_cast<std::ptrdiff_t> (at), ratios.end ());
  const double value = ratios[at];
  std::lock_guard<std::mutex> lock (mutex);
  cache.emplace (key, value);
  return value;
}

bool
givenNormalsAreNoise (const std::vector<Eigen::Vector3f>& points, const NeighborGraph& graph, int num_threads,
                      const std::vector<Eigen::Vector3f>& given, GivenNormalCheck* check)
{
  GivenNormalCheck local;
  GivenNormalCheck& c = check ? *check : local;
  c.probes = c.unresolved = 0; // the fine_* fields are givenNormalsBlurFaces'
  c.given_spread = c.neighbourhood_spread = 0.0;
  const std::size_t n = points.size ();
  const int k = graph.k ();
  if (n == 0 || given.size () != n || k < 2)
    return false;
  const int threads = resolveThreads (num_threads);
  const double bound = isotropicEigenRatioQuantile (k, 0.05);
  // A few thousand probes tell the median sample's resolution and the spread of normals well enough,
  // at a small part of a normal stage's cost (the caller gave normals to spare it).
  const std::size_t stride = std::max<std::size_t> (1, n / 4096);
  std::vector<std::uint32_t> probes;
  for (std::size_t i = 0; i < n; i += stride)
    probes.push_back (static_cast<std::uint32_t> (i));
  c.probes = probes.size ();
  const auto pcaNormal = [&] (std::uint32_t i, double& ratio) {
    Eigen::Vector3f normal = Eigen::Vector3f::UnitZ ();
    fitNormal (graphRowCovariance (points, graph, i), normal, ratio);
    return normal;
  };
  std::size_t unresolved = 0;
#pragma omp parallel for schedule(static, 64) num_threads(threads) reduction(+ : unresolved)
  for (std::ptrdiff_t p = 0; p < static_cast<std::ptrdiff_t> (probes.size ()); ++p)
  {
    double ratio;
    pcaNormal (probes[p], ratio);
    unresolved += ratio < bound ? 0 : 1;
  }
  c.unresolved = unresolved;
  // Median angle of each probe's normal to its neighbours', then the median over the probes.
  const auto spread = [&] (const auto& normalOf) {
    std::vector<double> per (probes.size ());
#pragma omp parallel for schedule(static, 64) num_threads(threads)
    for (std::ptrdiff_t p = 0; p < static_cast<std::ptrdiff_t> (probes.size ()); ++p)
    {
      const Eigen::Vector3f own = normalOf (probes[p]);
      std::vector<double> angles;
      angles.reserve (static_cast<std::size_t> (k));
      graph.forEachNeighbor (probes[p], [&] (std::uint32_t j) {
        angles.push_back (std::acos (std::min (1.0, static_cast<double> (std::abs (own.dot (normalOf (j)))))));
      });
      per[p] = medianInPlace (angles);
    }
    return medianInPlace (per);
  };
  c.given_spread = spread ([&] (std::uint32_t i) { return given[i]; });
  if (2 * unresolved <= probes.size ())
    return false; // the k-scale resolves the median sample's surface: normals there can be trusted
  c.neighbourhood_spread = spread ([&] (std::uint32_t i) {
    double ratio;
    return pcaNormal (i, ratio);
  });
  return c.given_spread >= c.neighbourhood_spread;
}

bool
givenNormalsBlurFaces (const std::vector<Eigen::Vector3f>& points, const NeighborGraph& graph, int fine_k,
                       int num_threads, const std::vector<Eigen::Vector3f>& given, GivenNormalCheck* check)
{
  GivenNormalCheck local;
  GivenNormalCheck& c = check ? *check : local;
  c.fine_k = fine_k;
  c.fine_resolved = c.fine_tilted = c.graph_tilted = c.graph_and_given_tilted = 0;
  const std::size_t n = points.size ();
  const int k = graph.k ();
  if (n == 0 || given.size () != n || fine_k < 3 || fine_k >= k)
    return false;
  const double bound = isotropicEigenRatioQuantile (fine_k, 0.05);
  const std::size_t stride = std::max<std::size_t> (1, n / 4096);
  const std::ptrdiff_t probes = static_cast<std::ptrdiff_t> ((n + stride - 1) / stride);
  c.probes = static_cast<std::size_t> (probes); // as givenNormalsAreNoise's
  std::size_t resolved = 0, tilted = 0, graph_tilted = 0, both_tilted = 0;
#pragma omp parallel num_threads(resolveThreads (num_threads))
  {
    // The graph's rows are stored by index: the fine_k nearest are sorted out of each row.
    std::vector<std::pair<float, std::uint32_t>> row;
#pragma omp for schedule(static, 64) reduction(+ : resolved, tilted, graph_tilted, both_tilted)
    for (std::ptrdiff_t p = 0; p < probes; ++p)
    {
      const std::uint32_t i = static_cast<std::uint32_t> (static_cast<std::size_t> (p) * stride);
      row.clear ();
      graph.forEachNeighbor (i, [&] (std::uint32_t j) { row.emplace_back ((points[j] - points[i]).squaredNorm (), j); });
      std::partial_sort (row.begin (), row.begin () + fine_k, row.end ());
      const Eigen::Matrix3d cov = neighbourhoodCovariance (points[i], fine_k, points, [&] (auto&& add) {
        for (int t = 0; t < fine_k; ++t)
          add (row[static_cast<std::size_t> (t)].second);
      });
      Eigen::Vector3f normal = Eigen::Vector3f::UnitZ ();
      double ratio, l0, l1;
      fitNormal (cov, normal, ratio, &l0, &l1);
      if (!(ratio < bound))
        continue; // no surface at the finer scale either: nothing to compare with
      ++resolved;
      // A floor at the float rounding of the positions (1e-6 of the spread along the face, a
      // tilt of 0.06°): noise-free faces have no residual to compare with.
      const auto tiltedOff = [&] (const Eigen::Vector3d& v) { return v.dot (cov * v) > kBlurResidualRatio * l0 + 1e-6 * l1; };
      const bool given_off = tiltedOff (given[i].cast<double> ());
      tilted += given_off ? 1 : 0;
      // Where the graph's k-neighbourhood reaches past the face (an edge within it), its PCA normal
      // is tilted off: normals of that scale are told by being tilted there too.
      Eigen::Vector3f wide = Eigen::Vector3f::UnitZ ();
      double wide_ratio;
      fitNormal (graphRowCovariance (points, graph, i), wide, wide_ratio);
      if (tiltedOff (wide.cast<double> ()))
      {
        ++graph_tilted;
        both_tilted += given_off ? 1 : 0;
      }
    }
  }
  c.fine_resolved = resolved;
  c.fine_tilted = tilted;
  c.graph_tilted = graph_tilted;
  c.graph_and_given_tilted = both_tilted;
  if (!(2 * resolved > static_cast<std::size_t> (probes)))
    return false;
  return 2 * tilted > resolved || 2 * both_tilted > graph_tilted;
}

void
estimateAdaptiveScaleNormals (const std::vector<Eigen::Vector3f>& points, const NeighborGraph& graph,
                              int num_threads, std::vector<Eigen::Vector3f>& normals, NormalScaleStatistics* stats,
                              bool only_when_most_unresolved)
{
  NormalScaleStatistics local;
  NormalScaleStatistics& st = stats ? *stats : local;
  st = NormalScaleStatistics ();
  const std::size_t n = points.size ();
  const int k = graph.k ();
  const int threads = resolveThreads (num_threads);
  st.isotropic_ratio = isotropicEigenRatioQuantile (k, 0.05);
  const double bound = st.isotropic_ratio;
  normals.assign (n, Eigen::Vector3f::UnitZ ());

  // Scale 0: the graph's neighbourhoods, exactly as estimateNormals, plus the resolution test.
  std::vector<char> resolved (n, 0);
#pragma omp parallel for schedule(static, 4096) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < static_cast<std::ptrdiff_t> (n); ++i)
  {
    double ratio;
    fitNormal (graphRowCovariance (points, graph, static_cast<std::size_t> (i)), normals[i], ratio);
    resolved[i] = ratio < bound ? 1 : 0;
  }
  // Where most samples are unresolved at the k-scale, a test at the 5 % level still passes about one
  // in twenty of them by chance, and each would keep its noise-dominated normal (on the 1M-point
  // cube, 5 % of every face then failed its plane's MND). Resolution is a property of the surface
  // and the noise around a sample, not of the sample: one resolved while most of its neighbours are
  // not is taken for such a chance pass and widened too.
  std::size_t resolved_count = 0;
  for (std::size_t i = 0; i < n; ++i)
    resolved_count += static_cast<std::size_t> (resolved[i]);
  if (2 * resolved_count < n)
  {
    std::vector<char> coherent (n, 0);
    std::size_t chance = 0;
#pragma omp parallel for schedule(static, 4096) num_threads(threads) reduction(+ : chance)
    for (std::ptrdiff_t i = 0; i < static_cast<std::ptrdiff_t> (n); ++i)
    {
      if (!resolved[i])
        continue;
      int agree = 0, total = 0;
      graph.forEachNeighbor (static_cast<std::size_t> (i), [&] (std::uint32_t j) {
        agree += resolved[j] ? 1 : 0;
        ++total;
      });
      coherent[i] = 2 * agree >= total ? 1 : 0;
      chance += coherent[i] ? 0 : 1;
    }
    resolved.swap (coherent);
    st.chance_resolved = chance;
  }
  std::vector<std::uint32_t> pending;
  for (std::size_t i = 0; i < n; ++i)
    if (!resolved[i])
      pending.push_back (static_cast<std::uint32_t> (i));
  std::vector<char> ().swap (resolved);
  st.unresolved_at_k = pending.size ();
  st.samples_per_scale.push_back (n - pending.size ());
  // The median sample resolved at the k-scale: the scale fits the scene, and the few samples it
  // does not resolve are more likely outliers or clutter than a surface swamped by noise.
  if (only_when_most_unresolved && 2 * pending.size () <= n)
  {
    st.unresolved = pending.size ();
    st.samples_per_scale[0] = n;
    return;
  }
  st.widened_scales = !pending.empty ();

  // Wider scales, each for the samples the previous one left unresolved.
  std::vector<Eigen::Vector3f> sub, sub_normals;
  std::vector<char> is_query, sub_resolved;
  std::vector<std::uint32_t> representative (pending.size ());
  for (int s = 1; !pending.empty () && s < 32; ++s)
  {
    const std::size_t stride = std::size_t (1) << s;
    const std::size_t m = (n + stride - 1) / stride; // samples 0, stride, 2 stride, ...
    if (m <= static_cast<std::size_t> (k))
      break; // fewer than k + 1 samples: no k-neighbourhood at this scale
    sub.resize (m);
    for (std::size_t j = 0; j < m; ++j)
      sub[j] = points[j * stride];
    // Representatives are every other sample of the scale: a normal over k samples of the scale
    // changes over the neighbourhood's radius (about 4 of their spacings for k = 50), not from one
    // sample to the next, and this halves the searches (measured: the same planes).
    is_query.assign (m, 0);
    for (std::size_t p = 0; p < pending.size (); ++p)
    {
      const Eigen::Vector3f& q = points[pending[p]];
      std::size_t r = pending[p] / (2 * stride) * 2;
      if (r + 2 < m && (sub[r + 2] - q).squaredNorm () < (sub[r] - q).squaredNorm ())
        r += 2;
      representative[p] = static_cast<std::uint32_t> (r);
      is_query[r] = 1;
    }
    sub_normals.assign (m, Eigen::Vector3f::UnitZ ());
    sub_resolved.assign (m, 0);
    visitKnnRows (sub, k, threads, is_query, [&] (std::uint32_t q, const std::uint32_t* row) {
      const Eigen::Matrix3d cov = neighbourhoodCovariance (sub[q], k, sub, [&] (auto&& add) {
        for (int t = 0; t < k; ++t)
          add (row[t]);
      });
      double ratio;
      fitNormal (cov, sub_normals[q], ratio);
      sub_resolved[q] = ratio < bound ? 1 : 0;
    });
    std::size_t kept = 0, took = 0;
    for (std::size_t p = 0; p < pending.size (); ++p)
    {
      const std::uint32_t r = representative[p];
      if (sub_resolved[r])
      {
        normals[pending[p]] = sub_normals[r];
        ++took;
      }
      else
        pending[kept++] = pending[p];
    }
    pending.resize (kept);
    st.samples_per_scale.push_back (took);
  }
  st.unresolved = pending.size ();
  st.samples_per_scale[0] += pending.size ();
}

std::size_t
narrowNormalsAtEdges (const std::vector<Eigen::Vector3f>& points, const NeighborGraph& graph, int num_threads,
                      int k_min, std::vector<Eigen::Vector3f>& normals, std::vector<char>* narrowed_flags,
                      const std::vector<std::uint32_t>* subset)
{
  if (narrowed_flags)
    narrowed_flags->assign (points.size (), 0);
  const int k = graph.k ();
  if (points.size () != normals.size () || k_min < 2 || k <= k_min)
    return 0;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t> (subset ? subset->size () : points.size ());
  std::size_t narrowed = 0;
  const double resolved_below = isotropicEigenRatioQuantile (k_min, 0.05); // as estimateAdaptiveScaleNormals
#pragma omp parallel num_threads(resolveThreads (num_threads)) reduction(+ : narrowed)
  {
    std::vector<std::pair<float, std::uint32_t>> row;
    row.reserve (static_cast<std::size_t> (k));
#pragma omp for schedule(static, 4096)
    for (std::ptrdiff_t s = 0; s < n; ++s)
    {
      const std::size_t i = subset ? (*subset)[static_cast<std::size_t> (s)] : static_cast<std::size_t> (s);
      // The graph keeps a row as a set; the prefixes need it nearest first (ties by index).
      row.clear ();
      graph.forEachNeighbor (i, [&] (std::uint32_t j) {
        row.emplace_back ((points[j] - points[i]).squaredNorm (), j);
      });
      std::sort (row.begin (), row.end ());
      const auto fitPrefix = [&] (int m, Eigen::Vector3f& normal, double& l0, double& l1) {
        const Eigen::Matrix3d cov = neighbourhoodCovariance (points[i], m, points, [&] (auto&& add) {
          for (int t = 0; t < m; ++t)
            add (row[static_cast<std::size_t> (t)].second);
        });
        normal = Eigen::Vector3f::UnitZ ();
        double ratio;
        fitNormal (cov, normal, ratio, &l0, &l1);
        return ratio;
      };
      Eigen::Vector3f face_normal, normal;
      double reference, l0, l1;
      if (!(fitPrefix (k_min, face_normal, reference, l1) < resolved_below))
        continue; // the nearest few resolve no surface: no face to narrow to
      // Standard error (radians) of a PCA normal's tilt towards its least in-plane direction.
      double face_error = l1 > 0.0 ? std::sqrt (reference / (static_cast<double> (k_min + 1) * l1)) : HUGE_VAL;
      // The whole neighbourhood first: most samples lie on one face (its spread along the normal
      // is the noise's), and keep their k-normal after two fits.
      // (Its normal is normals[i], estimateNormals' over the same neighbours; only λ0 is new here.)
      double k_spread;
      fitPrefix (k, normal, k_spread, l0);
      if (!(k_spread > kEdgeSpreadRatio * reference))
        continue;
      // Widen from the k_min nearest while the spread along the normal stays the noise's; the first
      // prefix beyond it reaches across an edge, the one before is the sample's face.
      for (int m = k_min + kEdgeNormalStep; m < k; m += kEdgeNormalStep)
      {
        fitPrefix (m, normal, l0, l1);
        if (l0 > kEdgeSpreadRatio * reference)
          break;
        face_normal = normal;
        face_error = l1 > 0.0 ? std::sqrt (l0 / (static_cast<double> (m + 1) * l1)) : HUGE_VAL;
      }
      // The whole neighbourhood spreads more than the face along its normal; replace the k-normal
      // only if the face's normal turns from it by more than its own noise explains.
      const double cosine = std::min (1.0, static_cast<double> (std::abs (face_normal.dot (normals[i]))));
      if (std::acos (cosine) > kEdgeTurnErrors * face_error)
      {
        normals[i] = face_normal;
        ++narrowed;
        if (narrowed_flags)
          (*narrowed_flags)[i] = 1;
      }
    }
  }
  return narrowed;
}

} // namespace rspd
} // namespace pcl
