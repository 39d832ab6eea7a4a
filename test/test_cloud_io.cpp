/*
 * pcl_rspd: tests of the tools' file layer (cloud_io) and of the rspd_segment command line.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "cloud_io.h"
#ifdef PCL_RSPD_TEST_RENDER_PNG
#include "render_png.h"
#endif

#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using rspd_tools::LoadedCloud;

namespace
{
/** \brief A fresh directory per test, removed afterwards. */
class TempDir
{
public:
  TempDir ()
  {
    std::string tmpl = (fs::temp_directory_path () / "rspd_io_test_XXXXXX").string ();
    std::vector<char> buf (tmpl.begin (), tmpl.end ());
    buf.push_back ('\0');
    if (::mkdtemp (buf.data ()))
      path_ = buf.data ();
  }
  ~TempDir ()
  {
    std::error_code ec;
    if (!path_.empty ())
    {
      // A test may have made it read-only.
      ::chmod (path_.c_str (), 0700);
      fs::remove_all (path_, ec);
    }
  }
  std::string
  operator/ (const std::string& name) const { return path_ + "/" + name; }
  const std::string&
  path () const { return path_; }
  /** \brief Names of the files in the directory. */
  std::set<std::string>
  list () const
  {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator (path_))
      names.insert (e.path ().filename ().string ());
    return names;
  }

private:
  std::string path_;
};

std::string
readFile (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  return std::string (std::istreambuf_iterator<char> (in), std::istreambuf_iterator<char> ());
}

void
writeFile (const std::string& path, const std::string& content)
{
  std::ofstream out (path, std::ios::binary | std::ios::trunc);
  out.write (content.data (), static_cast<std::streamsize> (content.size ()));
}

/** \brief A small cloud with distinct coordinates (and normals), optionally organized. */
pcl::PointCloud<pcl::PointNormal>
makeCloud (std::uint32_t width, std::uint32_t height = 1)
{
  pcl::PointCloud<pcl::PointNormal> c;
  c.width = width;
  c.height = height;
  c.resize (static_cast<std::size_t> (width) * height);
  for (std::size_t i = 0; i < c.size (); ++i)
  {
    auto& p = c[i];
    p.x = 0.25f * static_cast<float> (i % 17);
    p.y = -1.5f + 0.125f * static_cast<float> (i / 17);
    p.z = 2.0f + 0.001f * static_cast<float> (i);
    p.normal_x = 0.0f;
    p.normal_y = (i % 2) ? 1.0f : 0.0f;
    p.normal_z = (i % 2) ? 0.0f : 1.0f;
    p.curvature = 0.01f * static_cast<float> (i % 5);
  }
  c.width = width;
  c.height = height;
  c.is_dense = true;
  return c;
}

pcl::PointCloud<pcl::PointXYZ>
toXYZ (const pcl::PointCloud<pcl::PointNormal>& in)
{
  pcl::PointCloud<pcl::PointXYZ> out;
  pcl::copyPointCloud (in, out);
  return out;
}

/** \brief Expect a refusal: false, a message naming the problem, nothing left in \a out. */
void
expectRefused (const std::string& path, const std::string& fragment = "")
{
  LoadedCloud out;
  std::string error;
  const bool ok = rspd_tools::loadCloud (path, out, error);
  EXPECT_FALSE (ok) << path;
  EXPECT_FALSE (error.empty ()) << path;
  EXPECT_EQ (error.find ('\n'), std::string::npos) << error;
  if (!fragment.empty ())
  {
    EXPECT_NE (error.find (fragment), std::string::npos) << "message: " << error;
  }
  EXPECT_FALSE (out.xyz) << path;
  EXPECT_TRUE (out.blob.data.empty ()) << path;
  EXPECT_FALSE (out.normals) << path;
}

/** \brief Replace the first occurrence of \a from in the file's header. */
void
editHeader (const std::string& path, const std::string& from, const std::string& to)
{
  std::string s = readFile (path);
  const std::size_t at = s.find (from);
  ASSERT_NE (at, std::string::npos) << from;
  s.replace (at, from.size (), to);
  writeFile (path, s);
}

std::size_t
dataOffset (const std::string& content)
{
  const std::size_t at = content.find ("\nDATA ");
  const std::size_t nl = content.find ('\n', at + 1);
  return nl + 1;
}

/** \brief Quiet PCL for the whole program: refusals are expected here. */
class QuietPcl : public ::testing::Environment
{
public:
  void
  SetUp () override { pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS); }
};
const auto* const quiet_env = ::testing::AddGlobalTestEnvironment (new QuietPcl);

} // namespace

// ---------------------------------------------------------------------------------------------
// Reading valid files
// ---------------------------------------------------------------------------------------------

TEST (CloudIO, ReadsThreePcdEncodings)
{
  TempDir dir;
  const auto cloud = toXYZ (makeCloud (53));
  ASSERT_EQ (pcl::io::savePCDFileASCII (dir / "a.pcd", cloud), 0);
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "b.pcd", cloud), 0);
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (dir / "c.pcd", cloud), 0);
  for (const char* name : {"a.pcd", "b.pcd", "c.pcd"})
  {
    LoadedCloud in;
    std::string error;
    ASSERT_TRUE (rspd_tools::loadCloud (dir / name, in, error)) << name << ": " << error;
    EXPECT_TRUE (error.empty ());
    ASSERT_TRUE (in.xyz);
    ASSERT_EQ (in.xyz->size (), cloud.size ());
    EXPECT_EQ (in.size (), cloud.size ());
    EXPECT_EQ (in.xyz->width, 53u);
    EXPECT_EQ (in.xyz->height, 1u);
    EXPECT_FALSE (in.normals);
    for (std::size_t i = 0; i < cloud.size (); ++i)
    {
      EXPECT_NEAR ((*in.xyz)[i].x, cloud[i].x, 1e-5);
      EXPECT_NEAR ((*in.xyz)[i].y, cloud[i].y, 1e-5);
      EXPECT_NEAR ((*in.xyz)[i].z, cloud[i].z, 1e-5);
    }
  }
  LoadedCloud in;
  std::string error;
  ASSERT_TRUE (rspd_tools::loadCloud (dir / "c.pcd", in, error));
  EXPECT_EQ (in.format, "pcd binary_compressed");
}

TEST (CloudIO, ReadsNormalsAndKeepsAllFields)
{
  TempDir dir;
  const auto cloud = makeCloud (40);
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "n.pcd", cloud), 0);
  LoadedCloud in;
  std::string error;
  ASSERT_TRUE (rspd_tools::loadCloud (dir / "n.pcd", in, error)) << error;
  ASSERT_TRUE (in.normals);
  ASSERT_EQ (in.normals->size (), cloud.size ());
  for (std::size_t i = 0; i < cloud.size (); ++i)
  {
    EXPECT_FLOAT_EQ ((*in.normals)[i].normal_y, cloud[i].normal_y);
    EXPECT_FLOAT_EQ ((*in.normals)[i].normal_z, cloud[i].normal_z);
    EXPECT_FLOAT_EQ ((*in.normals)[i].curvature, cloud[i].curvature);
  }
  std::set<std::string> names;
  for (const auto& f : in.blob.fields)
    names.insert (f.name);
  for (const char* f : {"x", "y", "z", "normal_x", "normal_y", "normal_z", "curvature"})
    EXPECT_TRUE (names.count (f)) << f;
}

TEST (CloudIO, KeepsOrganizedLayoutNaNAndSensorPose)
{
  TempDir dir;
  auto cloud = toXYZ (makeCloud (8, 5));
  cloud[3].x = cloud[3].y = cloud[3].z = std::numeric_limits<float>::quiet_NaN ();
  cloud[17].z = std::numeric_limits<float>::quiet_NaN ();
  cloud.is_dense = false;
  cloud.sensor_origin_ = Eigen::Vector4f (1.0f, 2.0f, 3.0f, 0.0f);
  cloud.sensor_orientation_ = Eigen::Quaternionf (Eigen::AngleAxisf (0.5f, Eigen::Vector3f::UnitZ ()));
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "o.pcd", cloud), 0);
  LoadedCloud in;
  std::string error;
  ASSERT_TRUE (rspd_tools::loadCloud (dir / "o.pcd", in, error)) << error;
  EXPECT_EQ (in.xyz->width, 8u);
  EXPECT_EQ (in.xyz->height, 5u);
  EXPECT_TRUE (std::isnan ((*in.xyz)[3].x));
  EXPECT_TRUE (std::isnan ((*in.xyz)[17].z));
  EXPECT_FALSE (in.xyz->is_dense);
  EXPECT_EQ (rspd_tools::countFinite (*in.xyz), 38u);
  EXPECT_TRUE (in.origin.isApprox (cloud.sensor_origin_));
  EXPECT_TRUE (in.orientation.isApprox (cloud.sensor_orientation_, 1e-5f));
  EXPECT_TRUE (in.xyz->sensor_origin_.isApprox (cloud.sensor_origin_));
}

TEST (CloudIO, ConvertsDoubleAndIntegerCoordinates)
{
  // pcl::fromPCLPointCloud2 would leave these at zero: x/y/z are not float32.
  TempDir dir;
  writeFile (dir / "d.pcd",
             "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 8 8 2\nTYPE F F I\nCOUNT 1 1 1\n"
             "WIDTH 3\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\nDATA ascii\n"
             "1.5 2.25 -3\n100000.125 -7 12\n0 0 0\n");
  LoadedCloud in;
  std::string error;
  ASSERT_TRUE (rspd_tools::loadCloud (dir / "d.pcd", in, error)) << error;
  ASSERT_EQ (in.xyz->size (), 3u);
  EXPECT_FLOAT_EQ ((*in.xyz)[0].x, 1.5f);
  EXPECT_FLOAT_EQ ((*in.xyz)[0].y, 2.25f);
  EXPECT_FLOAT_EQ ((*in.xyz)[0].z, -3.0f);
  EXPECT_FLOAT_EQ ((*in.xyz)[1].x, 100000.125f);
  EXPECT_FLOAT_EQ ((*in.xyz)[1].z, 12.0f);
}

TEST (CloudIO, ReadsPly)
{
  TempDir dir;
  const auto cloud = makeCloud (31);
  ASSERT_EQ (pcl::io::savePLYFileBinary (dir / "b.ply", cloud), 0);
  ASSERT_EQ (pcl::io::savePLYFileASCII (dir / "a.ply", toXYZ (cloud)), 0);
  for (const char* name : {"a.ply", "b.ply"})
  {
    LoadedCloud in;
    std::string error;
    ASSERT_TRUE (rspd_tools::loadCloud (dir / name, in, error)) << name << ": " << error;
    ASSERT_EQ (in.xyz->size (), cloud.size ()) << name;
    for (std::size_t i = 0; i < cloud.size (); ++i)
    {
      EXPECT_NEAR ((*in.xyz)[i].x, cloud[i].x, 1e-5);
      EXPECT_NEAR ((*in.xyz)[i].z, cloud[i].z, 1e-5);
    }
    EXPECT_EQ (in.format.compare (0, 3, "ply"), 0);
  }
  LoadedCloud in;
  std::string error;
  ASSERT_TRUE (rspd_tools::loadCloud (dir / "b.ply", in, error));
  EXPECT_TRUE (in.normals);
  // Extension unknown: sniffed from the first bytes.
  fs::copy_file (dir / "b.ply", dir / "b.cloud");
  ASSERT_TRUE (rspd_tools::loadCloud (dir / "b.cloud", in, error)) << error;
  EXPECT_EQ (in.xyz->size (), cloud.size ());
}

// ---------------------------------------------------------------------------------------------
// Refusals
// ---------------------------------------------------------------------------------------------

TEST (CloudIO, RefusesMissingEmptyDirectoryAndUnreadable)
{
  TempDir dir;
  expectRefused (dir / "missing.pcd", "no such file");
  expectRefused (dir.path (), "directory");
  writeFile (dir / "empty.pcd", "");
  expectRefused (dir / "empty.pcd", "empty");
  writeFile (dir / "empty.ply", "");
  expectRefused (dir / "empty.ply", "empty");
  expectRefused ("", "");
  if (::geteuid () != 0)  // root reads anything
  {
    ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "locked.pcd", toXYZ (makeCloud (10))), 0);
    ::chmod ((dir / "locked.pcd").c_str (), 0);
    expectRefused (dir / "locked.pcd");
  }
}

TEST (CloudIO, RefusesTruncatedBinary)
{
  TempDir dir;
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "b.pcd", toXYZ (makeCloud (100))), 0);
  const std::string full = readFile (dir / "b.pcd");
  const std::size_t data = dataOffset (full);
  for (const std::size_t keep : {full.size () - 1, full.size () - 12, data + (full.size () - data) / 2, data})
  {
    writeFile (dir / "t.pcd", full.substr (0, keep));
    expectRefused (dir / "t.pcd", "truncated");
  }
  // Cut inside the header.
  writeFile (dir / "h.pcd", full.substr (0, data / 2));
  expectRefused (dir / "h.pcd");
}

TEST (CloudIO, RefusesLyingPointCount)
{
  TempDir dir;
  const auto cloud = toXYZ (makeCloud (100));
  ASSERT_EQ (pcl::io::savePCDFileASCII (dir / "a.pcd", cloud), 0);
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "b.pcd", cloud), 0);
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (dir / "c.pcd", cloud), 0);
  for (const char* name : {"a.pcd", "b.pcd", "c.pcd"})
  {
    editHeader (dir / name, "WIDTH 100", "WIDTH 150");
    editHeader (dir / name, "POINTS 100", "POINTS 150");
    expectRefused (dir / name);
  }
  // POINTS and WIDTH x HEIGHT disagree.
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "m.pcd", cloud), 0);
  editHeader (dir / "m.pcd", "POINTS 100", "POINTS 99");
  expectRefused (dir / "m.pcd", "POINTS");
  // A count so large that POINTS * point size overflows 32 bits.
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "huge.pcd", cloud), 0);
  editHeader (dir / "huge.pcd", "WIDTH 100", "WIDTH 4294967295");
  editHeader (dir / "huge.pcd", "POINTS 100", "POINTS 4294967295");
  expectRefused (dir / "huge.pcd", "truncated");
}

TEST (CloudIO, RefusesCloudWithoutXYZ)
{
  TempDir dir;
  pcl::PointCloud<pcl::Normal> normals;
  normals.resize (20);
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "n.pcd", normals), 0);
  expectRefused (dir / "n.pcd", "'x'");
  writeFile (dir / "xy.pcd", "VERSION 0.7\nFIELDS x y\nSIZE 4 4\nTYPE F F\nCOUNT 1 1\nWIDTH 2\nHEIGHT 1\n"
                             "POINTS 2\nDATA ascii\n1 2\n3 4\n");
  expectRefused (dir / "xy.pcd", "'z'");
  writeFile (dir / "noz.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                              "end_header\n1 2\n3 4\n");
  expectRefused (dir / "noz.ply", "'z'");
}

TEST (CloudIO, RefusesInconsistentHeaders)
{
  TempDir dir;
  const std::string tail = "WIDTH 1\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 1\nDATA ascii\n1 2 3\n";
  const std::vector<std::string> headers = {
      "FIELDS x y z\nSIZE 4 4\nTYPE F F F\nCOUNT 1 1 1\n",     // SIZE too short
      "FIELDS x y z\nSIZE 4 4 4\nTYPE F F\nCOUNT 1 1 1\n",     // TYPE too short
      "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1\n",     // COUNT too short
      "FIELDS x y z\nSIZE 4 3 4\nTYPE F F F\nCOUNT 1 1 1\n",   // size 3
      "FIELDS x y z\nSIZE 4 4 4\nTYPE F X F\nCOUNT 1 1 1\n",   // type X
      "FIELDS x y z\nSIZE 4 4 2\nTYPE F F F\nCOUNT 1 1 1\n",   // half float
      "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 0 1\n",   // count 0
      "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 -1\n",  // negative count
      "FIELDS x y z\nTYPE F F F\nCOUNT 1 1 1\n",               // no SIZE
      "SIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n",                 // no FIELDS
      "FIELDS x y z\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n",  // twice
      "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nGARBAGE 1\n",     // unknown line
  };
  for (std::size_t i = 0; i < headers.size (); ++i)
  {
    const std::string name = dir / ("h" + std::to_string (i) + ".pcd");
    writeFile (name, "VERSION 0.7\n" + headers[i] + tail);
    SCOPED_TRACE (headers[i]);
    expectRefused (name);
  }
  const std::string good = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  writeFile (dir / "nodata.pcd", good + "WIDTH 1\nHEIGHT 1\nPOINTS 1\n1 2 3\n");
  expectRefused (dir / "nodata.pcd");
  writeFile (dir / "baddata.pcd", good + "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA binary_foo\n1 2 3\n");
  expectRefused (dir / "baddata.pcd", "DATA");
  writeFile (dir / "negwidth.pcd", good + "WIDTH -1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n");
  expectRefused (dir / "negwidth.pcd", "WIDTH");
  writeFile (dir / "zero.pcd", good + "WIDTH 0\nHEIGHT 1\nPOINTS 0\nDATA ascii\n");
  expectRefused (dir / "zero.pcd", "no points");
  writeFile (dir / "short_row.pcd", good + "WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n1 2 3\n4 5\n");
  expectRefused (dir / "short_row.pcd", "values");
  writeFile (dir / "blank_row.pcd", good + "WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n1 2 3\n  \n4 5 6\n");
  expectRefused (dir / "blank_row.pcd");
  // The same header with enough rows is accepted (the checks are not over-eager).
  writeFile (dir / "ok.pcd", good + "WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n1 2 3\n\n4 5 6\n");
  LoadedCloud in;
  std::string error;
  EXPECT_TRUE (rspd_tools::loadCloud (dir / "ok.pcd", in, error)) << error;
}

TEST (CloudIO, RefusesCorruptCompressedBlock)
{
  TempDir dir;
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (dir / "c.pcd", makeCloud (200)), 0);
  const std::string full = readFile (dir / "c.pcd");
  const std::size_t data = dataOffset (full);
  ASSERT_GT (full.size (), data + 16);
  const auto with = [&] (std::size_t at, const std::string& bytes) {
    std::string s = full;
    s.replace (at, bytes.size (), bytes);
    return s;
  };
  const auto u32 = [] (std::uint32_t v) { return std::string (reinterpret_cast<const char*> (&v), 4); };
  std::uint32_t compressed = 0, uncompressed = 0;
  std::memcpy (&compressed, full.data () + data, 4);
  std::memcpy (&uncompressed, full.data () + data + 4, 4);

  writeFile (dir / "big_c.pcd", with (data, u32 (compressed + 1000)));
  expectRefused (dir / "big_c.pcd", "corrupt");
  writeFile (dir / "huge_c.pcd", with (data, u32 (0xFFFFFFF0u)));
  expectRefused (dir / "huge_c.pcd", "corrupt");
  writeFile (dir / "zero_c.pcd", with (data, u32 (0)));
  expectRefused (dir / "zero_c.pcd", "corrupt");
  writeFile (dir / "u_small.pcd", with (data + 4, u32 (uncompressed - 4)));
  expectRefused (dir / "u_small.pcd", "corrupt");
  writeFile (dir / "u_big.pcd", with (data + 4, u32 (uncompressed * 4)));
  expectRefused (dir / "u_big.pcd", "corrupt");
  // A stream that starts with a back-reference cannot decode.
  writeFile (dir / "stream.pcd", with (data + 8, std::string (16, '\xFF')));
  expectRefused (dir / "stream.pcd", "LZF");
  // Block cut short.
  writeFile (dir / "cut.pcd", full.substr (0, data + 8 + compressed / 2));
  expectRefused (dir / "cut.pcd", "corrupt");
  writeFile (dir / "sizes_only.pcd", full.substr (0, data + 5));
  expectRefused (dir / "sizes_only.pcd", "truncated");
  // Every cut of the file is refused without a crash.
  for (std::size_t keep = 0; keep < full.size (); keep += 7)
  {
    writeFile (dir / "k.pcd", full.substr (0, keep));
    expectRefused (dir / "k.pcd");
  }
}

TEST (CloudIO, RefusesBadPly)
{
  TempDir dir;
  writeFile (dir / "empty_v.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                                  "property float z\nend_header\n");
  expectRefused (dir / "empty_v.ply", "no vertices");
  writeFile (dir / "faces_only.ply", "ply\nformat ascii 1.0\nelement face 1\n"
                                     "property list uchar int vertex_indices\nend_header\n3 0 1 2\n");
  expectRefused (dir / "faces_only.ply", "no vertices");
  writeFile (dir / "noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n");
  expectRefused (dir / "noend.ply", "end_header");
  writeFile (dir / "short_ascii.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                      "property float y\nproperty float z\nend_header\n1 2 3\n4 5 6\n");
  expectRefused (dir / "short_ascii.ply", "truncated");
  ASSERT_EQ (pcl::io::savePLYFileBinary (dir / "b.ply", toXYZ (makeCloud (50))), 0);
  const std::string full = readFile (dir / "b.ply");
  writeFile (dir / "cut.ply", full.substr (0, full.size () - 5));
  expectRefused (dir / "cut.ply", "truncated");
  writeFile (dir / "notply.ply", "PCD or something else\n");
  expectRefused (dir / "notply.ply", "PLY");
}

TEST (CloudIO, RefusesRandomBytes)
{
  TempDir dir;
  for (std::uint32_t seed = 1; seed <= 24; ++seed)
  {
    std::mt19937 rng (seed);
    const std::size_t size = 1024 + rng () % (63 * 1024);
    std::string bytes (size, '\0');
    for (char& c : bytes)
      c = static_cast<char> (rng () & 0xFF);
    for (const char* ext : {".pcd", ".ply", ".bin"})
    {
      const std::string name = dir / ("r" + std::to_string (seed) + ext);
      writeFile (name, bytes);
      SCOPED_TRACE (name);
      expectRefused (name);
    }
    // A plausible magic line followed by noise.
    writeFile (dir / "rp.ply", "ply\n" + bytes);
    expectRefused (dir / "rp.ply");
    writeFile (dir / "rp.pcd", "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n" + bytes);
    expectRefused (dir / "rp.pcd");
  }
}

TEST (CloudIO, SurvivesMutatedHeaders)
{
  // Flip bytes of valid headers: any outcome is fine except a crash or a silent wrong size.
  TempDir dir;
  const auto cloud = makeCloud (64);
  ASSERT_EQ (pcl::io::savePCDFileASCII (dir / "a.pcd", cloud), 0);
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "b.pcd", cloud), 0);
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (dir / "c.pcd", cloud), 0);
  ASSERT_EQ (pcl::io::savePLYFileBinary (dir / "p.ply", cloud), 0);
  std::mt19937 rng (7);
  for (const char* name : {"a.pcd", "b.pcd", "c.pcd", "p.ply"})
  {
    const std::string full = readFile (dir / name);
    const std::size_t header = std::min (full.size (), std::max (dataOffset (full), full.find ("end_header") + 11));
    for (int trial = 0; trial < 150; ++trial)
    {
      std::string s = full;
      const int flips = 1 + static_cast<int> (rng () % 3);
      for (int f = 0; f < flips; ++f)
        s[rng () % header] = static_cast<char> (rng () & 0xFF);
      const std::string mutated = dir / (std::string ("m_") + name);
      writeFile (mutated, s);
      LoadedCloud in;
      std::string error;
      if (rspd_tools::loadCloud (mutated, in, error))
      {
        ASSERT_TRUE (in.xyz);
        EXPECT_EQ (in.xyz->size (), in.size ());
        EXPECT_GT (in.size (), 0u);
      }
      else
        EXPECT_FALSE (error.empty ());
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Writing
// ---------------------------------------------------------------------------------------------

TEST (CloudIO, LabelledRoundTripKeepsEverything)
{
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZI> cloud;
  cloud.width = 6;
  cloud.height = 4;
  cloud.resize (24);
  for (std::size_t i = 0; i < cloud.size (); ++i)
  {
    cloud[i].x = static_cast<float> (i);
    cloud[i].y = static_cast<float> (i) * 2.0f;
    cloud[i].z = -static_cast<float> (i);
    cloud[i].intensity = 0.5f * static_cast<float> (i);
  }
  cloud.width = 6;
  cloud.height = 4;
  cloud[5].x = std::numeric_limits<float>::quiet_NaN ();
  cloud.is_dense = false;
  cloud.sensor_origin_ = Eigen::Vector4f (0.5f, -1.0f, 2.0f, 0.0f);
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (dir / "in.pcd", cloud), 0);

  LoadedCloud in;
  std::string error;
  ASSERT_TRUE (rspd_tools::loadCloud (dir / "in.pcd", in, error)) << error;
  std::vector<std::uint32_t> labels (24);
  for (std::size_t i = 0; i < labels.size (); ++i)
    labels[i] = static_cast<std::uint32_t> (i % 4);
  ASSERT_TRUE (rspd_tools::writeLabeledCloud (dir / "out.pcd", in, labels, error)) << error;
  EXPECT_EQ (dir.list (), (std::set<std::string>{"in.pcd", "out.pcd"}));  // no temporary left
  EXPECT_NE (readFile (dir / "out.pcd").find ("DATA binary\n"), std::string::npos);

  pcl::PCLPointCloud2 blob;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  ASSERT_EQ (pcl::io::loadPCDFile (dir / "out.pcd", blob, origin, orientation), 0);
  EXPECT_EQ (blob.width, 6u);
  EXPECT_EQ (blob.height, 4u);
  EXPECT_TRUE (origin.isApprox (cloud.sensor_origin_));
  std::vector<std::string> names;
  for (const auto& f : blob.fields)
    names.push_back (f.name);
  EXPECT_EQ (names, (std::vector<std::string>{"x", "y", "z", "intensity", "label", "rgb"}));

  pcl::PointCloud<pcl::PointXYZRGBL> out;
  pcl::fromPCLPointCloud2 (blob, out);
  pcl::PointCloud<pcl::PointXYZI> out_i;
  pcl::fromPCLPointCloud2 (blob, out_i);
  ASSERT_EQ (out.size (), 24u);
  for (std::size_t i = 0; i < out.size (); ++i)
  {
    if (i == 5)
      EXPECT_TRUE (std::isnan (out[i].x));
    else
      EXPECT_EQ (out[i].x, cloud[i].x);
    EXPECT_EQ (out[i].y, cloud[i].y);
    EXPECT_EQ (out[i].z, cloud[i].z);
    EXPECT_EQ (out_i[i].intensity, cloud[i].intensity);
    EXPECT_EQ (out[i].label, labels[i]);
    const auto colour = rspd_tools::labelColour (labels[i]);
    EXPECT_EQ (out[i].r, colour[0]);
    EXPECT_EQ (out[i].g, colour[1]);
    EXPECT_EQ (out[i].b, colour[2]);
  }
  EXPECT_EQ (out[0].r, 128);  // label 0: grey
  EXPECT_EQ (out[0].g, 128);
  EXPECT_EQ (out[0].b, 128);

  // The labelled file reads back through loadCloud too.
  LoadedCloud again;
  ASSERT_TRUE (rspd_tools::loadCloud (dir / "out.pcd", again, error)) << error;
  EXPECT_EQ (again.xyz->width, 6u);
  EXPECT_EQ (again.xyz->height, 4u);
}

TEST (CloudIO, ReplacesExistingLabelAndColour)
{
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZRGBL> cloud;
  cloud.resize (10);
  for (std::size_t i = 0; i < cloud.size (); ++i)
  {
    cloud[i].x = static_cast<float> (i);
    cloud[i].label = 77;
    cloud[i].r = 1;
    cloud[i].g = 2;
    cloud[i].b = 3;
  }
  ASSERT_EQ (pcl::io::savePCDFileASCII (dir / "in.pcd", cloud), 0);
  LoadedCloud in;
  std::string error;
  ASSERT_TRUE (rspd_tools::loadCloud (dir / "in.pcd", in, error)) << error;
  const std::vector<std::uint32_t> labels = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  ASSERT_TRUE (rspd_tools::writeLabeledCloud (dir / "out.pcd", in, labels, error)) << error;
  pcl::PCLPointCloud2 blob;
  ASSERT_EQ (pcl::io::loadPCDFile (dir / "out.pcd", blob), 0);
  std::multiset<std::string> names;
  for (const auto& f : blob.fields)
    names.insert (f.name);
  EXPECT_EQ (names.count ("label"), 1u);
  EXPECT_EQ (names.count ("rgb") + names.count ("rgba"), 1u);
  pcl::PointCloud<pcl::PointXYZRGBL> out;
  pcl::fromPCLPointCloud2 (blob, out);
  for (std::size_t i = 0; i < out.size (); ++i)
  {
    EXPECT_EQ (out[i].label, labels[i]);
    EXPECT_EQ (out[i].r, rspd_tools::labelColour (labels[i])[0]);
    EXPECT_EQ (out[i].b, rspd_tools::labelColour (labels[i])[2]);
    EXPECT_EQ (out[i].x, cloud[i].x);
  }

  // rgba stays rgba.
  pcl::PointCloud<pcl::PointXYZRGBA> rgba;
  rgba.resize (3);
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "rgba.pcd", rgba), 0);
  ASSERT_TRUE (rspd_tools::loadCloud (dir / "rgba.pcd", in, error)) << error;
  ASSERT_TRUE (rspd_tools::writeLabeledCloud (dir / "rgba_out.pcd", in, {1, 2, 0}, error)) << error;
  ASSERT_EQ (pcl::io::loadPCDFile (dir / "rgba_out.pcd", blob), 0);
  names.clear ();
  for (const auto& f : blob.fields)
    names.insert (f.name);
  EXPECT_EQ (names.count ("rgba"), 1u);
  EXPECT_EQ (names.count ("rgb"), 0u);
  pcl::PointCloud<pcl::PointXYZRGBA> rgba_out;
  pcl::fromPCLPointCloud2 (blob, rgba_out);
  EXPECT_EQ (rgba_out[1].g, rspd_tools::labelColour (2)[1]);
  EXPECT_EQ (rgba_out[2].r, 128);
}

TEST (CloudIO, WritesPlyInputAndInMemoryClouds)
{
  TempDir dir;
  const auto cloud = toXYZ (makeCloud (12));
  ASSERT_EQ (pcl::io::savePLYFileBinary (dir / "in.ply", cloud), 0);
  LoadedCloud in;
  std::string error;
  ASSERT_TRUE (rspd_tools::loadCloud (dir / "in.ply", in, error)) << error;
  std::vector<std::uint32_t> labels (12, 3);
  ASSERT_TRUE (rspd_tools::writeLabeledCloud (dir / "out.pcd", in, labels, error)) << error;
  pcl::PointCloud<pcl::PointXYZRGBL> out;
  ASSERT_EQ (pcl::io::loadPCDFile (dir / "out.pcd", out), 0);
  ASSERT_EQ (out.size (), 12u);
  EXPECT_EQ (out[7].label, 3u);
  EXPECT_EQ (out[7].x, cloud[7].x);

  LoadedCloud mem;
  rspd_tools::makeLoadedCloud (cloud, mem);
  ASSERT_TRUE (mem.xyz);
  EXPECT_EQ (mem.size (), 12u);
  ASSERT_TRUE (rspd_tools::writeLabeledCloud (dir / "mem.pcd", mem, labels, error)) << error;
  ASSERT_EQ (pcl::io::loadPCDFile (dir / "mem.pcd", out), 0);
  EXPECT_EQ (out.size (), 12u);
}

TEST (CloudIO, DetectsDataThatPclWouldReadAsHeader)
{
  const auto bytes = [] (const std::string& s) { return std::vector<std::uint8_t> (s.begin (), s.end ()); };
  EXPECT_FALSE (rspd_tools::pcdDataMisreadAsHeader ({}));
  EXPECT_FALSE (rspd_tools::pcdDataMisreadAsHeader ({0x00, 0x00, 0x80, 0x3f}));       // 1.0f
  EXPECT_TRUE (rspd_tools::pcdDataMisreadAsHeader (bytes ("DATA")));
  EXPECT_TRUE (rspd_tools::pcdDataMisreadAsHeader (bytes ("VIEWPOINT\x01\x02")));
  EXPECT_TRUE (rspd_tools::pcdDataMisreadAsHeader (bytes (" \tSIZEx")));            // leading blanks skipped
  EXPECT_TRUE (rspd_tools::pcdDataMisreadAsHeader (bytes ("\nWIDTH")));             // after an empty line
  EXPECT_TRUE (rspd_tools::pcdDataMisreadAsHeader (bytes ("#\x01\x02\nPOINTS")));     // after a comment line
  EXPECT_FALSE (rspd_tools::pcdDataMisreadAsHeader (bytes ("#\x01\x02\x03")));        // a comment, then the end
  EXPECT_FALSE (rspd_tools::pcdDataMisreadAsHeader (bytes ("  \nDATA")));           // blank line ends the header
  EXPECT_FALSE (rspd_tools::pcdDataMisreadAsHeader (bytes ("XDATA")));
}

TEST (CloudIO, RefusesPcdWhoseDataPclWouldReadAsHeader)
{
  // A valid-looking binary PCD whose first point spells "VIEWPOINT" plus seven words and then
  // header lines: PCL's reader would take them for the header (and lose the x field).
  TempDir dir;
  std::string file = "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                     "WIDTH 16\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 16\nDATA binary\n";
  std::string data = "VIEWPOINT 0 0 0 1 0 0 0\nFIELDS a b c\n";
  data.resize (16 * 12, '\x01');
  const std::string path = dir / "trap.pcd";
  {
    std::ofstream out (path, std::ios::binary);
    out << file << data;
  }
  LoadedCloud in;
  std::string error;
  EXPECT_FALSE (rspd_tools::loadCloud (path, in, error));
  EXPECT_NE (error.find ("header line"), std::string::npos) << error;
  EXPECT_EQ (error.find ('\n'), std::string::npos);
}

TEST (CloudIO, LabelledCloudReadsBackWhenItsFirstPointSpellsAKeyword)
{
  // The first point's x has the bytes "DATA" (13.2664...), y and z spell nothing: written x first,
  // PCL's reader would take the data for a header line (and throw). The writer must notice and
  // put another field first, and the file must read back with every value intact.
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (const char* word : {"DATA", "VIEW"})
  {
    float x;
    std::memcpy (&x, word, 4);
    cloud.push_back (pcl::PointXYZ (x, 1.0f, 2.0f));
  }
  cloud.push_back (pcl::PointXYZ (3.0f, 4.0f, 5.0f));
  for (std::size_t first = 0; first < 2; ++first)
  {
    pcl::PointCloud<pcl::PointXYZ> c = cloud;
    std::swap (c[0], c[first]);
    TempDir dir;
    LoadedCloud in;
    rspd_tools::makeLoadedCloud (c, in);
    std::string error;
    const std::vector<std::uint32_t> labels{7, 0, 1};
    ASSERT_TRUE (rspd_tools::writeLabeledCloud (dir / "out.pcd", in, labels, error)) << error;
    pcl::PointCloud<pcl::PointXYZRGBL> out;
    ASSERT_EQ (pcl::io::loadPCDFile (dir / "out.pcd", out), 0);
    ASSERT_EQ (out.size (), 3u);
    for (std::size_t i = 0; i < 3; ++i)
    {
      EXPECT_EQ (std::memcmp (&out[i].x, &c[i].x, 4), 0) << i;
      EXPECT_EQ (out[i].y, c[i].y);
      EXPECT_EQ (out[i].label, labels[i]);
    }
  }
}

TEST (CloudIO, RefusesUnwritableOutput)
{
  TempDir dir;
  LoadedCloud in;
  rspd_tools::makeLoadedCloud (toXYZ (makeCloud (5)), in);
  const std::vector<std::uint32_t> labels (5, 1);
  std::string error;
  EXPECT_FALSE (rspd_tools::writeLabeledCloud (dir / "no/such/dir/out.pcd", in, labels, error));
  EXPECT_FALSE (error.empty ());
  error.clear ();
  EXPECT_FALSE (rspd_tools::writeLabeledCloud (dir.path (), in, labels, error));
  EXPECT_NE (error.find ("directory"), std::string::npos) << error;
  error.clear ();
  EXPECT_FALSE (rspd_tools::writeLabeledCloud (dir / "short.pcd", in, {1, 2}, error));
  EXPECT_FALSE (error.empty ());
  EXPECT_TRUE (dir.list ().empty ());
  EXPECT_FALSE (rspd_tools::checkWritable (dir / "no/such/dir/x.csv", error));
  EXPECT_FALSE (rspd_tools::writeFileAtomically (dir / "no/such/dir/x.csv", "a\n", error));

  if (::geteuid () != 0)
  {
    ::mkdir ((dir / "ro").c_str (), 0555);
    error.clear ();
    EXPECT_FALSE (rspd_tools::writeLabeledCloud (dir / "ro/out.pcd", in, labels, error));
    EXPECT_FALSE (error.empty ());
    EXPECT_TRUE (fs::is_empty (dir / "ro"));
  }
}

TEST (CloudIO, OverwritesAtomicallyWithOrdinaryPermissions)
{
  TempDir dir;
  writeFile (dir / "out.pcd", "old content");
  LoadedCloud in;
  rspd_tools::makeLoadedCloud (toXYZ (makeCloud (5)), in);
  std::string error;
  ASSERT_TRUE (rspd_tools::writeLabeledCloud (dir / "out.pcd", in, std::vector<std::uint32_t> (5, 2), error));
  EXPECT_EQ (dir.list (), (std::set<std::string>{"out.pcd"}));
  struct stat st;
  ASSERT_EQ (::stat ((dir / "out.pcd").c_str (), &st), 0);
  const mode_t mask = ::umask (022);
  ::umask (mask);
  EXPECT_EQ (st.st_mode & 0777, 0666 & ~mask);
  ASSERT_TRUE (rspd_tools::writeFileAtomically (dir / "t.csv", "a,b\n1,2\n", error)) << error;
  EXPECT_EQ (readFile (dir / "t.csv"), "a,b\n1,2\n");
  EXPECT_EQ (dir.list (), (std::set<std::string>{"out.pcd", "t.csv"}));
}

TEST (CloudIO, PaletteIsDistinctAndDeterministic)
{
  const auto grey = rspd_tools::labelColour (0);
  EXPECT_EQ (grey, (std::array<std::uint8_t, 3>{128, 128, 128}));
  std::set<std::array<std::uint8_t, 3>> seen;
  for (std::uint32_t l = 1; l <= 64; ++l)
  {
    const auto c = rspd_tools::labelColour (l);
    EXPECT_EQ (c, rspd_tools::labelColour (l));
    EXPECT_TRUE (seen.insert (c).second) << "label " << l;
    const int spread = std::max ({c[0], c[1], c[2]}) - std::min ({c[0], c[1], c[2]});
    EXPECT_GT (spread, 40) << "label " << l << " is too grey";
  }
  // Consecutive labels (the largest planes) differ clearly.
  for (std::uint32_t l = 1; l < 20; ++l)
  {
    const auto a = rspd_tools::labelColour (l), b = rspd_tools::labelColour (l + 1);
    const int d = std::abs (a[0] - b[0]) + std::abs (a[1] - b[1]) + std::abs (a[2] - b[2]);
    EXPECT_GT (d, 80) << l;
  }
}

// ---------------------------------------------------------------------------------------------
// PNG rendering (needs libpng linked into this test: PCL_RSPD_TEST_RENDER_PNG)
// ---------------------------------------------------------------------------------------------

namespace
{
/** \brief Points on the six faces of a box, labelled by face (0 for a few stray points). */
[[maybe_unused]] void
makeBox (pcl::PointCloud<pcl::PointXYZ>& cloud, std::vector<std::uint32_t>& labels, std::size_t per_face)
{
  std::mt19937 rng (3);
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  const float size[3] = {5.0f, 4.0f, 3.0f};
  cloud.clear ();
  labels.clear ();
  for (std::uint32_t face = 0; face < 6; ++face)
  {
    const int axis = static_cast<int> (face / 2);
    for (std::size_t i = 0; i < per_face; ++i)
    {
      float p[3];
      for (int a = 0; a < 3; ++a)
        p[a] = u (rng) * size[a];
      p[axis] = (face % 2) ? size[axis] : 0.0f;
      cloud.push_back (pcl::PointXYZ (p[0], p[1], p[2]));
      labels.push_back (face + 1);
    }
  }
  for (int i = 0; i < 50; ++i)
  {
    cloud.push_back (pcl::PointXYZ (u (rng) * 5.0f, u (rng) * 4.0f, u (rng) * 3.0f));
    labels.push_back (0);
  }
  cloud.push_back (pcl::PointXYZ (std::numeric_limits<float>::quiet_NaN (), 0.0f, 0.0f));
  labels.push_back (0);
}

[[maybe_unused]] bool
hasPngSignature (const std::string& content)
{
  static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  return content.size () >= 8 && std::memcmp (content.data (), sig, 8) == 0;
}
} // namespace

#ifdef PCL_RSPD_TEST_RENDER_PNG
TEST (RenderPng, WritesValidPng)
{
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<std::uint32_t> labels;
  makeBox (cloud, labels, 3000);
  std::string error;
  ASSERT_TRUE (rspd_tools::renderPng (cloud, labels, dir / "box.png", 640, 480, error)) << error;
  const std::string png = readFile (dir / "box.png");
  EXPECT_TRUE (hasPngSignature (png));
  EXPECT_GT (png.size (), 2000u);
  EXPECT_EQ (dir.list (), (std::set<std::string>{"box.png"}));
  // Degenerate inputs still give a picture; bad arguments are refused.
  pcl::PointCloud<pcl::PointXYZ> one;
  one.push_back (pcl::PointXYZ (1.0f, 2.0f, 3.0f));
  EXPECT_TRUE (rspd_tools::renderPng (one, {1}, dir / "one.png", 64, 64, error)) << error;
  EXPECT_TRUE (hasPngSignature (readFile (dir / "one.png")));
  EXPECT_FALSE (rspd_tools::renderPng (one, {1, 2}, dir / "bad.png", 64, 64, error));
  EXPECT_FALSE (rspd_tools::renderPng (one, {1}, dir / "bad.png", 0, 64, error));
  EXPECT_FALSE (rspd_tools::renderPng (one, {1}, dir / "no/dir/x.png", 64, 64, error));
  EXPECT_FALSE (fs::exists (dir / "bad.png"));
}
#endif

// ---------------------------------------------------------------------------------------------
// rspd_segment command line
// ---------------------------------------------------------------------------------------------

namespace
{
const std::string kSegment = std::string (PCL_RSPD_BINARY_DIR) + "/rspd_segment";

struct RunResult
{
  int status = -1;  ///< exit status, or 128 + signal
  std::string out, err;
};

std::string
shellQuote (const std::string& s)
{
  std::string q = "'";
  for (const char c : s)
    q += (c == '\'') ? std::string ("'\\''") : std::string (1, c);
  return q + "'";
}

RunResult
runSegment (const TempDir& dir, const std::vector<std::string>& args, const std::string& cwd = "")
{
  RunResult r;
  const std::string out = dir / ".stdout", err = dir / ".stderr";
  std::string cmd = "cd " + shellQuote (cwd.empty () ? dir.path () : cwd) + " && " + shellQuote (kSegment);
  for (const auto& a : args)
    cmd += " " + shellQuote (a);
  cmd += " > " + shellQuote (out) + " 2> " + shellQuote (err);
  const int status = std::system (cmd.c_str ());
  r.status = WIFEXITED (status) ? WEXITSTATUS (status) : 128 + WTERMSIG (status);
  r.out = readFile (out);
  r.err = readFile (err);
  fs::remove (out);
  fs::remove (err);
  return r;
}

std::size_t
lineCount (const std::string& s)
{
  return static_cast<std::size_t> (std::count (s.begin (), s.end (), '\n'));
}

/** \brief Skip unless the real tool has been built (not absent, not a placeholder). */
#define REQUIRE_SEGMENT_BINARY()                                                                  \
  do                                                                                              \
  {                                                                                               \
    if (::access (kSegment.c_str (), X_OK) != 0)                                                  \
      GTEST_SKIP () << kSegment << " not built";                                                  \
    TempDir probe_dir;                                                                            \
    const RunResult probe = runSegment (probe_dir, {"--help"});                                   \
    if (probe.status != 0 || probe.out.find ("usage:") == std::string::npos)                     \
      GTEST_SKIP () << kSegment << " is not the real tool yet";                                   \
  } while (0)

/** \brief Three orthogonal faces of a box, sampled on a jittered grid: three clear planes. */
pcl::PointCloud<pcl::PointXYZ>
makeCorner (std::size_t per_face)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::mt19937 rng (11);
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  std::normal_distribution<float> noise (0.0f, 0.002f);
  for (int face = 0; face < 3; ++face)
    for (std::size_t i = 0; i < per_face; ++i)
    {
      float p[3] = {u (rng), u (rng), u (rng)};
      p[face] = noise (rng);
      cloud.push_back (pcl::PointXYZ (p[0], p[1], p[2]));
    }
  return cloud;
}
} // namespace

TEST (RspdSegmentCli, UsageErrorsExitTwo)
{
  REQUIRE_SEGMENT_BINARY ();
  TempDir dir;
  const std::vector<std::vector<std::string>> cases = {
      {"--no-such-option"}, {"-k"}, {"-k", "abc"}, {"-k", "1"}, {"--threads", "0"}, {"--threads", "x"},
      {"a.pcd", "b.pcd"}, {"--demo", "a.pcd"}, {"--png-size", "12"}, {"--demo=1"}, {"-o"},
      {"--coplanar-merge", "yes"}, {"--coplanar-merge"}, {"--outlier-seeds=on"}, {"--outlier-seeds", "again"}, {"--frame", "x"}, {"--frame"}, {"--normal-fit", "mcd"}, {"--normal-fit"}, {"--curved-check", "1"}, {"--curved-turn", "yes"}, {"--curved-fold-sides", "2"}, {"--depth-levels", "on"}, {"--bend-test", "on"}, {"--bend-test"},
      {"--assign", "some"}, {"--assign"}, {"--assign", "tail"}, {"--rim-retest", "yes"}, {"--rim-retest", "twice"}, {"--hinge-normals", "yes"}, {"--rim-retest"},
      {"--release", "1"}, {"--release"}, {"--edge-sides", "yes"}, {"--edge-sides"}, {"--edge-corners", "yes"}, {"--edge-corners"}, {"--edge-wedges", "yes"}, {"--edge-wedges"}, {"--volume-layers", "yes"}, {"--volume-layers"}, {"--small-completion", "yes"}, {"--small-completion"}, {"--step-sides", "1"}, {"--step-sides"}, {"--thick-join", "yes"}, {"--thick-join"}, {"--small-thick-join", "yes"}, {"--small-thick-join"}, {"--noisy-groups", "yes"}, {"--noisy-groups"}, {"--noisy-lone", "1"}, {"--noisy-lone"}, {"--noisy-ladder", "yes"}, {"--noisy-ladder"}, {"--thick-follow", "yes"}, {"--thick-follow"}, {"--step-split", "yes"}, {"--step-split"}, {"--across-steps", "yes"}, {"--across-steps"}, {"--edge-normals", "yes"}, {"--edge-normals"}, {"--layer-merge", "yes"}, {"--layer-merge"}, {"--layer-steps", "yes"}, {"--layer-steps"}, {"--connected-parts", "1"}, {"--connected-parts"},
      {"--bent-split", "yes"}, {"--bent-split"}, {"--released-planes", "no"}, {"--released-planes"},
      {"--support", "yes"}, {"--support"}, {"--bounded-reestimate", "yes"}, {"--bounded-reestimate"}, {"--noisy-bent-split", "1"}, {"--noisy-bent-split"},
      {"--left-normals", "on"}, {"--left-normals"}, {"--bent-side-mnd", "yes"}, {"--bent-side-mnd"}, {"--bent-normals", "yes"}, {"--bent-normals"}, {"--rim-bands", "yes"}, {"--rim-bands"}, {"--given-normals", "on"}, {"--given-normals"},
      {"--position-surfaces", "yes"}, {"--position-surfaces"}, {"--position-normals", "1"}, {"--position-normals"}, {"--position-ladder", "up"}, {"--position-ladder"}, {"--ladder-rungs", "yes"}, {"--ladder-rungs"}, {"--position-join", "yes"}, {"--position-join"}, {"--step-regions", "1"}, {"--step-regions"}, {"--noisy-t2", "yes"}, {"--noisy-t2"}, {"--support-clutter", "1"}, {"--support-clutter"}, {"--final-parts", "1"}, {"--final-parts"}, {"--position-bend-band", "1"}, {"--position-bend-band"}, {"--position-bend-slabs", "yes"}, {"--position-bend-slabs"},
  };
  for (const auto& args : cases)
  {
    const RunResult r = runSegment (dir, args);
    EXPECT_EQ (r.status, 2) << args[0] << "\n" << r.err;
    EXPECT_NE (r.err.find ("usage:"), std::string::npos) << r.err;
    EXPECT_TRUE (r.out.empty ());
  }
  const RunResult help = runSegment (dir, {"--help"});
  EXPECT_EQ (help.status, 0);
}

TEST (RspdSegmentCli, BadInputsExitOneWithOneLine)
{
  REQUIRE_SEGMENT_BINARY ();
  TempDir dir;
  const auto cloud = toXYZ (makeCloud (100));
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "good.pcd", cloud), 0);
  const std::string good = readFile (dir / "good.pcd");
  writeFile (dir / "truncated.pcd", good.substr (0, good.size () - 100));
  writeFile (dir / "lying.pcd", good);
  editHeader (dir / "lying.pcd", "WIDTH 100", "WIDTH 1000");
  editHeader (dir / "lying.pcd", "POINTS 100", "POINTS 1000");
  pcl::PointCloud<pcl::Normal> normals;
  normals.resize (10);
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "noxyz.pcd", normals), 0);
  writeFile (dir / "empty.pcd", "");
  writeFile (dir / "zero.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 0\n"
                               "HEIGHT 1\nPOINTS 0\nDATA ascii\n");
  writeFile (dir / "emptyv.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                                 "property float z\nend_header\n");
  std::string noise (4096, '\0');
  std::mt19937 rng (5);
  for (char& c : noise)
    c = static_cast<char> (rng ());
  writeFile (dir / "random.pcd", noise);
  pcl::PointCloud<pcl::PointXYZ> nan_cloud;
  nan_cloud.resize (10);
  for (auto& p : nan_cloud)
    p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN ();
  nan_cloud.is_dense = false;
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "allnan.pcd", nan_cloud), 0);
  ::mkdir ((dir / "adir.pcd").c_str (), 0755);

  for (const char* name : {"missing.pcd", "truncated.pcd", "lying.pcd", "noxyz.pcd", "empty.pcd", "zero.pcd",
                           "emptyv.ply", "random.pcd", "allnan.pcd", "adir.pcd"})
  {
    const RunResult r = runSegment (dir, {name, "-o", "out.pcd", "--planes", "out.csv", "--png", "out.png"});
    EXPECT_EQ (r.status, 1) << name << "\n" << r.err;
    EXPECT_EQ (lineCount (r.err), 1u) << name << "\n" << r.err;
    EXPECT_NE (r.err.find ("error"), std::string::npos) << r.err;
    EXPECT_FALSE (fs::exists (dir / "out.pcd")) << name;
    EXPECT_FALSE (fs::exists (dir / "out.csv")) << name;
    EXPECT_FALSE (fs::exists (dir / "out.png")) << name;
  }
  // Unwritable outputs are found before the detection runs; nothing is left behind.
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"good.pcd", "-o", "no/such/dir/out.pcd"},
        std::vector<std::string>{"good.pcd", "--planes", "no/such/dir/out.csv"},
        std::vector<std::string>{"good.pcd", "--png", "adir.pcd"}})
  {
    const RunResult r = runSegment (dir, args);
    EXPECT_EQ (r.status, 1) << args[2] << "\n" << r.err;
    EXPECT_EQ (lineCount (r.err), 1u) << r.err;
  }
  for (const auto& name : dir.list ())
    EXPECT_EQ (name.find (".tmp-"), std::string::npos) << name;
}

TEST (RspdSegmentCli, SegmentsAFileAndWritesOutputs)
{
  REQUIRE_SEGMENT_BINARY ();
  TempDir dir;
  const auto cloud = makeCorner (4000);
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (dir / "corner.pcd", cloud), 0);
  const RunResult r = runSegment (dir, {"corner.pcd", "-o", "labels.pcd", "--planes", "planes.csv", "--png",
                                        "view.png", "--png-size", "320x240", "--threads", "1", "-v"});
  ASSERT_EQ (r.status, 0) << r.err;
  EXPECT_NE (r.out.find ("points: 12000"), std::string::npos) << r.out;
  EXPECT_NE (r.out.find ("valid points: 12000"), std::string::npos) << r.out;
  EXPECT_NE (r.out.find ("planes:"), std::string::npos) << r.out;
  for (const char* stage : {"read:", "detect:", "write:"})
    EXPECT_NE (r.err.find (stage), std::string::npos) << r.err;

  pcl::PointCloud<pcl::PointXYZRGBL> labelled;
  ASSERT_EQ (pcl::io::loadPCDFile (dir / "labels.pcd", labelled), 0);
  ASSERT_EQ (labelled.size (), cloud.size ());
  std::set<std::uint32_t> used;
  for (std::size_t i = 0; i < labelled.size (); ++i)
  {
    EXPECT_EQ (labelled[i].x, cloud[i].x);
    used.insert (labelled[i].label);
  }

  const std::string csv = readFile (dir / "planes.csv");
  EXPECT_EQ (csv.compare (0, csv.find ('\n'), "label,a,b,c,d,points,cx,cy,cz,extent_u,extent_v,mdp,mnd"), 0);
  const std::size_t rows = lineCount (csv) - 1;
  used.erase (0);
  EXPECT_EQ (rows, used.size ());
  EXPECT_EQ (rows, 3u) << r.out;  // three faces of a box corner
  EXPECT_TRUE (hasPngSignature (readFile (dir / "view.png")));
  EXPECT_GT (fs::file_size (dir / "view.png"), 1000u);
}

TEST (RspdSegmentCli, SaysWhenDepthsAreACamerasLevelsAndDithersThemOnRequest)
{
  // A wall 4 m in front of a camera looking along +z, turned 0.6 rad, its depths rounded to a
  // structured-light camera's levels (K / m for whole m, K = 357 m) and x, y moved along the rays.
  REQUIRE_SEGMENT_BINARY ();
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 120; ++i)
    for (int j = 0; j < 100; ++j)
    {
      const double a = -1.5 + 3.0 * i / 119.0, b = -1.5 + 3.0 * j / 99.0;
      const double z = 4.0 + a * std::sin (0.6), x = a * std::cos (0.6);
      const double level = 357.0 / std::round (357.0 / z);
      cloud.push_back (pcl::PointXYZ (static_cast<float> (x * level / z), static_cast<float> (b * level / z),
                                      static_cast<float> (level)));
    }
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "levels.pcd", cloud), 0);
  const RunResult hint = runSegment (dir, {"levels.pcd", "-v"});
  ASSERT_EQ (hint.status, 0) << hint.err;
  EXPECT_NE (hint.err.find ("--depth-levels dither"), std::string::npos) << hint.err;
  const RunResult dithered = runSegment (dir, {"levels.pcd", "--depth-levels", "dither", "-v"});
  ASSERT_EQ (dithered.status, 0) << dithered.err;
  EXPECT_NE (dithered.err.find ("distinct depths along the camera's axis, dithered"), std::string::npos) << dithered.err;
  EXPECT_NE (dithered.out.find ("planes: 1\n"), std::string::npos) << dithered.out;
  const RunResult as_given = runSegment (dir, {"levels.pcd"});
  ASSERT_EQ (as_given.status, 0) << as_given.err;
  EXPECT_EQ (as_given.out.find ("planes: 1\n"), std::string::npos) << as_given.out; // one per level
}

TEST (RspdSegmentCli, DemoWritesNothingUnlessAsked)
{
  REQUIRE_SEGMENT_BINARY ();
  TempDir dir;
  const RunResult r = runSegment (dir, {"--demo"});
  ASSERT_EQ (r.status, 0) << r.err;
  EXPECT_NE (r.out.find ("planes:"), std::string::npos);
  EXPECT_TRUE (r.err.empty ()) << r.err;
  EXPECT_TRUE (dir.list ().empty ());

  const RunResult p = runSegment (dir, {"--demo", "--png", "demo.png", "-o", "demo.pcd"});
  ASSERT_EQ (p.status, 0) << p.err;
  EXPECT_TRUE (hasPngSignature (readFile (dir / "demo.png")));
  EXPECT_GT (fs::file_size (dir / "demo.png"), 5000u);
  pcl::PCLPointCloud2 blob;
  ASSERT_EQ (pcl::io::loadPCDFile (dir / "demo.pcd", blob), 0);
  EXPECT_GT (blob.width * blob.height, 0u);
}

TEST (RspdSegmentCli, KeepsOrganizedCloudsOrganized)
{
  REQUIRE_SEGMENT_BINARY ();
  TempDir dir;
  // A 100 x 80 range image of a floor and a wall, a third of it missing (NaN).
  pcl::PointCloud<pcl::PointXYZ> cloud (100, 80);
  std::mt19937 rng (4);
  std::uniform_real_distribution<float> u (0.0f, 1.0f);
  for (std::uint32_t r = 0; r < cloud.height; ++r)
    for (std::uint32_t c = 0; c < cloud.width; ++c)
    {
      pcl::PointXYZ& p = cloud.at (c, r);
      if (u (rng) < 0.33f)
        p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN ();
      else if (r < cloud.height / 2)
        p = pcl::PointXYZ (3.0f, 0.02f * c, 0.03f * (cloud.height / 2 - r));
      else
        p = pcl::PointXYZ (0.5f + 0.04f * (r - cloud.height / 2), 0.02f * c, 0.0f);
    }
  cloud.is_dense = false;
  ASSERT_EQ (pcl::io::savePCDFileBinary (dir / "organized.pcd", cloud), 0);
  const RunResult r = runSegment (dir, {"organized.pcd", "-o", "out.pcd"});
  ASSERT_EQ (r.status, 0) << r.err;
  pcl::PCLPointCloud2 blob;
  ASSERT_EQ (pcl::io::loadPCDFile (dir / "out.pcd", blob), 0);
  EXPECT_EQ (blob.width, 100u);
  EXPECT_EQ (blob.height, 80u);
  pcl::PointCloud<pcl::PointXYZL> out;
  pcl::fromPCLPointCloud2 (blob, out);
  ASSERT_EQ (out.size (), cloud.size ());
  std::set<std::uint32_t> used;
  for (std::size_t i = 0; i < out.size (); ++i)
  {
    if (!std::isfinite (cloud[i].x))
    {
      EXPECT_TRUE (std::isnan (out[i].x));
      EXPECT_EQ (out[i].label, 0u);
    }
    else
      EXPECT_EQ (out[i].z, cloud[i].z);
    used.insert (out[i].label);
  }
  used.erase (0);
  EXPECT_EQ (used.size (), 2u) << r.out;
}

TEST (RspdSegmentCli, ReadsPlyWithNormals)
{
  REQUIRE_SEGMENT_BINARY ();
  TempDir dir;
  const auto corner = makeCorner (2000);
  pcl::PointCloud<pcl::PointNormal> cloud;
  for (std::size_t i = 0; i < corner.size (); ++i)
  {
    pcl::PointNormal p;
    p.x = corner[i].x;
    p.y = corner[i].y;
    p.z = corner[i].z;
    const int face = static_cast<int> (i / 2000);
    p.normal_x = face == 0 ? 1.0f : 0.0f;
    p.normal_y = face == 1 ? 1.0f : 0.0f;
    p.normal_z = face == 2 ? 1.0f : 0.0f;
    p.curvature = 0.0f;
    cloud.push_back (p);
  }
  ASSERT_EQ (pcl::io::savePLYFileBinary (dir / "corner.ply", cloud), 0);
  const RunResult r = runSegment (dir, {"corner.ply", "--planes", "planes.csv", "-v"});
  ASSERT_EQ (r.status, 0) << r.err;
  EXPECT_NE (r.out.find ("with normals"), std::string::npos) << r.out;
  EXPECT_EQ (lineCount (readFile (dir / "planes.csv")), 4u) << r.out;
}
