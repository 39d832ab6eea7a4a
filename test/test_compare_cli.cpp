/*
 * pcl_rspd tests: the rspd_compare command-line tool, run as a separate program.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "cli_helpers.h"

#include <pcl_rspd/synthetic_scenes.h>

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
const std::string kCompare = std::string (PCL_RSPD_BINARY_DIR) + "/rspd_compare";

using RunResult = rspd_test::ToolRun;
using ScratchDir = rspd_test::TempDir;

/** \brief Run rspd_compare with \a args (and optional VAR=value environment prefix). */
RunResult
runCompare (const std::vector<std::string>& args, const std::string& env = "")
{
  return rspd_test::runTool (kCompare, args, env);
}

/** \brief The table row of \a method split into words, empty if there is none. */
std::vector<std::string>
row (const std::string& out, const std::string& method)
{
  std::istringstream lines (out);
  std::string line;
  while (std::getline (lines, line))
  {
    std::istringstream words (line);
    std::vector<std::string> w;
    std::string word;
    while (words >> word)
      w.push_back (word);
    if (!w.empty () && w[0] == method)
      return w;
  }
  return {};
}


/** \brief Skip unless the real tool is there (not absent, not a placeholder). */
#define REQUIRE_COMPARE_BINARY()                                                               \
  do                                                                                           \
  {                                                                                            \
    if (::access (kCompare.c_str (), X_OK) != 0)                                               \
      GTEST_SKIP () << kCompare << " not built";                                               \
    if (runCompare ({"--help"}).out.find ("usage:") == std::string::npos)                      \
      GTEST_SKIP () << kCompare << " is not the real tool yet";                                \
  } while (0)

// Table columns with truth: method planes time peak start rms precision recall F1 found fragments false
constexpr std::size_t kPlanes = 1, kF1 = 8, kFound = 9;
} // namespace

TEST (CompareCli, CubeSceneComparesThreeMethods)
{
  REQUIRE_COMPARE_BINARY ();
  const RunResult r = runCompare ({"--scene", "cube", "-n", "20000"});
  ASSERT_EQ (r.status, 0) << r.err;
  // The header names the peer settings.
  EXPECT_NE (r.out.find ("NormalEstimationOMP"), std::string::npos);
  EXPECT_NE (r.out.find ("1 % of the largest extent"), std::string::npos);
  EXPECT_NE (r.out.find ("smoothness 3 deg"), std::string::npos);
  EXPECT_NE (r.out.find ("F1"), std::string::npos);
  for (const char* method : {"rspd", "sac", "rg"})
  {
    const std::vector<std::string> w = row (r.out, method);
    ASSERT_GT (w.size (), kFound) << "no complete row for " << method << " in:\n" << r.out;
    const double f1 = std::stod (w[kF1]);
    EXPECT_GE (f1, 0.0) << method;
    EXPECT_LE (f1, 1.0) << method;
    EXPECT_GT (f1, 0.5) << method << ": every method should find the cube's faces";
  }
  const std::vector<std::string> rspd = row (r.out, "rspd");
  ASSERT_GT (rspd.size (), kFound);
  EXPECT_EQ (rspd[kPlanes], "6");
  EXPECT_EQ (rspd[kFound], "6/6");
}

TEST (CompareCli, JsonHasMethods)
{
  REQUIRE_COMPARE_BINARY ();
  const RunResult r = runCompare ({"--scene", "cube", "-n", "5000", "--json"});
  ASSERT_EQ (r.status, 0) << r.err;
  ASSERT_FALSE (r.out.empty ());
  EXPECT_EQ (r.out[0], '{');
  EXPECT_EQ (rspd_test::lineCount (r.out), 1);
  EXPECT_NE (r.out.find ("\"methods\": ["), std::string::npos);
  EXPECT_NE (r.out.find ("\"normals_seconds\""), std::string::npos);
  for (const char* method : {"rspd", "sac", "rg"})
    EXPECT_NE (r.out.find (std::string ("\"name\": \"") + method + "\""), std::string::npos) << method;
  EXPECT_NE (r.out.find ("\"f1\""), std::string::npos);
  EXPECT_NE (r.out.find ("\"peak_mb\""), std::string::npos);
}

TEST (CompareCli, PhasesAddTheMedianAndLowestF1)
{
  REQUIRE_COMPARE_BINARY ();
  const RunResult r = runCompare ({"--scene", "cube", "-n", "5000", "--methods", "rspd", "--phases", "4"});
  ASSERT_EQ (r.status, 0) << r.err;
  EXPECT_NE (r.out.find ("F1 median  F1 min"), std::string::npos) << r.out;
  EXPECT_NE (r.out.find ("F1 median and min over 4 grid phases"), std::string::npos) << r.out;
  const RunResult j = runCompare ({"--scene", "cube", "-n", "5000", "--methods", "rspd", "--phases", "4", "--json"});
  ASSERT_EQ (j.status, 0) << j.err;
  EXPECT_NE (j.out.find ("\"phases\": 4, \"f1_phase_median\""), std::string::npos) << j.out;
}

TEST (CompareCli, MethodSubsetInOrder)
{
  REQUIRE_COMPARE_BINARY ();
  const RunResult r = runCompare ({"--scene", "cube", "-n", "5000", "--methods", "rg,rspd"});
  ASSERT_EQ (r.status, 0) << r.err;
  EXPECT_TRUE (row (r.out, "sac").empty ());
  const std::size_t rg = r.out.find ("\nrg "), rspd = r.out.find ("\nrspd ");
  ASSERT_NE (rg, std::string::npos);
  ASSERT_NE (rspd, std::string::npos);
  EXPECT_LT (rg, rspd);
}

// CGAL's region growing and Efficient RANSAC run as further peers where the build has CGAL, and are
// refused with a usage error naming the cause where it has not.
TEST (CompareCli, CgalPeers)
{
  REQUIRE_COMPARE_BINARY ();
  const RunResult r = runCompare ({"--scene", "cube", "-n", "20000", "--methods", "cgal_rg,cgal_ransac,rspd"});
#ifdef PCL_RSPD_CGAL_PEERS
  ASSERT_EQ (r.status, 0) << r.err;
  EXPECT_NE (r.out.find ("CGAL Efficient_RANSAC"), std::string::npos) << r.out;
  for (const char* method : {"cgal_rg", "cgal_ransac"})
  {
    const std::vector<std::string> w = row (r.out, method);
    ASSERT_GT (w.size (), kFound) << "no complete row for " << method << " in:\n" << r.out;
    // A cube's six large faces: each peer finds most of them, and labels stay in range.
    EXPECT_GT (std::stod (w[kF1]), 0.5) << method;
    EXPECT_GE (std::stoi (w[kPlanes]), 4) << method;
  }
  const RunResult j = runCompare ({"--scene", "cube", "-n", "5000", "--methods", "cgal_rg", "--json"});
  ASSERT_EQ (j.status, 0) << j.err;
  EXPECT_NE (j.out.find ("\"name\": \"cgal_rg\""), std::string::npos) << j.out;
  EXPECT_NE (j.out.find ("\"cgal_rg_angle_deg\": 25"), std::string::npos) << j.out;

  // A cloud whose file normals are missing on some points: CGAL gets the others, and the row says so.
  ScratchDir dir;
  ASSERT_TRUE (dir.ok ());
  pcl::rspd::SceneOptions options;
  options.num_points = 3000;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("cube", options);
  pcl::PointCloud<pcl::PointNormal> with_normals;
  for (std::size_t i = 0; i < scene.cloud.size (); ++i)
  {
    pcl::PointNormal p;
    p.x = scene.cloud[i].x;
    p.y = scene.cloud[i].y;
    p.z = scene.cloud[i].z;
    const float nan = std::numeric_limits<float>::quiet_NaN ();
    p.normal_x = i < 100 ? nan : 0.0f;
    p.normal_y = i < 100 ? nan : 0.0f;
    p.normal_z = i < 100 ? nan : 1.0f;
    with_normals.push_back (p);
  }
  const std::string cloud = dir.file ("normals.pcd");
  ASSERT_EQ (pcl::io::savePCDFileBinary (cloud, with_normals), 0);
  for (const char* method : {"cgal_rg", "cgal_ransac"})
  {
    const RunResult f = runCompare ({cloud, "--methods", method});
    ASSERT_EQ (f.status, 0) << f.err;
    EXPECT_NE (f.out.find ("100 points without a normal left out"), std::string::npos) << method << ":\n" << f.out;
  }
#else
  EXPECT_EQ (r.status, 2);
  EXPECT_NE (r.err.find ("built without CGAL"), std::string::npos) << r.err;
#endif
}

TEST (CompareCli, KilledMethodIsReportedNotFatal)
{
  REQUIRE_COMPARE_BINARY ();
  // Test hook: the child of the named method kills itself with SIGKILL, as an OOM kill would.
  const RunResult r = runCompare ({"--scene", "cube", "-n", "5000", "--methods", "sac,rg"},
                                  "RSPD_COMPARE_KILL_METHOD=sac");
  ASSERT_EQ (r.status, 0) << r.err;
  const std::vector<std::string> sac = row (r.out, "sac");
  ASSERT_GE (sac.size (), 2u) << r.out;
  EXPECT_EQ (sac[1], "failed:");
  EXPECT_GT (row (r.out, "rg").size (), kFound) << r.out;
}

TEST (CompareCli, CloudFileWithTruth)
{
  REQUIRE_COMPARE_BINARY ();
  ScratchDir dir;
  ASSERT_TRUE (dir.ok ());
  pcl::rspd::SceneOptions options;
  options.num_points = 3000;
  const pcl::rspd::Scene scene = pcl::rspd::makeScene ("cube", options);
  const std::string cloud = dir.file ("cube.pcd"), truth = dir.file ("cube.gt"), short_truth = dir.file ("short.gt");
  ASSERT_EQ (pcl::io::savePCDFileBinary (cloud, scene.cloud), 0);
  const auto writeLabels = [] (const std::string& path, const std::vector<std::uint32_t>& labels) {
    std::ofstream out (path, std::ios::binary);
    for (const std::uint32_t l : labels)
    {
      const unsigned char b[4] = {static_cast<unsigned char> (l), static_cast<unsigned char> (l >> 8),
                                  static_cast<unsigned char> (l >> 16), static_cast<unsigned char> (l >> 24)};
      out.write (reinterpret_cast<const char*> (b), 4);
    }
  };
  writeLabels (truth, scene.labels);
  writeLabels (short_truth, std::vector<std::uint32_t> (scene.labels.begin (), scene.labels.end () - 1));

  const RunResult good = runCompare ({cloud, truth, "--methods", "rspd"});
  ASSERT_EQ (good.status, 0) << good.err;
  const std::vector<std::string> rspd = row (good.out, "rspd");
  ASSERT_GT (rspd.size (), kFound) << good.out;
  EXPECT_EQ (rspd[kFound], "6/6");

  // Without truth there are no scores, but the run still succeeds.
  const RunResult no_truth = runCompare ({cloud, "--methods", "rg"});
  ASSERT_EQ (no_truth.status, 0) << no_truth.err;
  EXPECT_EQ (no_truth.out.find ("precision"), std::string::npos);

  const RunResult mismatch = runCompare ({cloud, short_truth});
  EXPECT_EQ (mismatch.status, 1);
  EXPECT_EQ (rspd_test::lineCount (mismatch.err), 1) << mismatch.err;
  EXPECT_TRUE (mismatch.out.empty ());
}

TEST (CompareCli, MissingFileExitsOne)
{
  REQUIRE_COMPARE_BINARY ();
  const RunResult r = runCompare ({"/nonexistent/cloud.pcd"});
  EXPECT_EQ (r.status, 1);
  EXPECT_EQ (rspd_test::lineCount (r.err), 1) << r.err;
  EXPECT_NE (r.err.find ("/nonexistent/cloud.pcd"), std::string::npos);
  EXPECT_TRUE (r.out.empty ());
}

TEST (CompareCli, UsageErrorsExitTwo)
{
  REQUIRE_COMPARE_BINARY ();
  const std::vector<std::vector<std::string>> bad = {
      {},                                            // no input
      {"--scene", "no-such-scene"},                  // unknown scene
      {"--scene", "cube", "extra.pcd"},              // scene and file
      {"a.pcd", "--methods", "rspd,magic"},          // unknown method
      {"a.pcd", "--methods", "rg,rg"},               // duplicate method
      {"a.pcd", "-k", "zero"},                       // bad number
      {"a.pcd", "--voxel", "-1"},                    // bad voxel
      {"a.pcd", "--phases", "0"},                    // no grid
      {"a.pcd", "-n", "100"},                        // -n without --scene
      {"a.pcd", "--layout", "2"},                    // --layout without --scene
      {"--scene", "cube", "--layout", "x"},          // bad layout
      {"a.pcd", "b.gt", "c.gt"},                     // too many files
      {"a.pcd", "--frobnicate"},                     // unknown option
  };
  for (const auto& args : bad)
  {
    const RunResult r = runCompare (args);
    std::string joined;
    for (const auto& a : args)
      joined += a + " ";
    EXPECT_EQ (r.status, 2) << joined;
    EXPECT_EQ (rspd_test::lineCount (r.err), 1) << joined << ": " << r.err;
  }
}
