/*
 * pcl_rspd fuzz target: the file reading path of rspd_segment (rspd_tools::loadCloud: header, size
 * and compressed-block checks in front of PCL's PCD and PLY readers).
 *
 * Input: the first byte chooses how the rest is offered, the rest is the file's content.
 *   byte 0, bits 0-1: file name extension .pcd, .ply, .PLY (case) or .cloud (format sniffed)
 *   bit 2: also read it with loadPcdBlob (rspd_evaluate's label reader, x/y/z optional)
 *   bit 3: after a successful read, write it back with writeLabeledCloud (rspd_segment's output)
 *          and read that again
 * loadCloud must return false with one printable line of error and an empty cloud, or true with a
 * consistent cloud. Built with libFuzzer (scripts/fuzz.sh) and, for ctest's replay of
 * fuzz/corpus/cloud_reader and fuzz/regressions/cloud_reader, with fuzz/replay_main.cpp.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "cloud_io.h"

#include <pcl/console/print.h>

#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{
[[noreturn]] void
fail (const char* what, const std::string& detail = std::string ())
{
  std::fprintf (stderr, "fuzz_cloud_reader: invariant violated: %s %s\n", what, detail.c_str ());
  std::abort ();
}

#define FUZZ_CHECK(cond)                                                                           \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
      fail (#cond);                                                                                \
  } while (0)

/** A private scratch directory for this process, removed at exit. */
class Scratch
{
public:
  Scratch ()
  {
    const char* base = std::getenv ("TMPDIR");
    std::string templ = std::string (base && *base ? base : "/tmp") + "/rspd_fuzz_reader.XXXXXX";
    std::vector<char> buf (templ.begin (), templ.end ());
    buf.push_back ('\0');
    if (!::mkdtemp (buf.data ()))
    {
      std::perror ("fuzz_cloud_reader: mkdtemp");
      std::abort ();
    }
    dir_ = buf.data ();
  }
  ~Scratch ()
  {
    for (const char* name : {"input.pcd", "input.ply", "input.PLY", "input.cloud", "labeled.pcd"})
      ::unlink ((dir_ + "/" + name).c_str ());
    ::rmdir (dir_.c_str ());
  }
  std::string
  path (const char* name) const
  {
    return dir_ + "/" + name;
  }

private:
  std::string dir_;
};

const Scratch&
scratch ()
{
  static const Scratch s;
  return s;
}

bool
writeFile (const std::string& path, const std::uint8_t* data, std::size_t size)
{
  std::FILE* f = std::fopen (path.c_str (), "wb");
  if (!f)
    return false;
  const bool ok = (size == 0 || std::fwrite (data, 1, size, f) == size);
  return std::fclose (f) == 0 && ok;
}

void
checkError (const std::string& error)
{
  if (error.empty ())
    fail ("the error is empty");
  for (const char c : error)
    if (c < 32 || c > 126)
      fail ("the error is not one printable line:", error);
}

bool
sameFloat (float a, float b)
{
  return (std::isnan (a) && std::isnan (b)) || std::memcmp (&a, &b, sizeof (float)) == 0;
}

/** A successful read: every view agrees with the blob. */
void
checkCloud (const rspd_tools::LoadedCloud& c)
{
  const std::size_t n = c.size ();
  FUZZ_CHECK (n > 0);
  FUZZ_CHECK (c.xyz != nullptr);
  FUZZ_CHECK (c.xyz->size () == n);
  FUZZ_CHECK (c.xyz->width == c.blob.width && c.xyz->height == c.blob.height);
  FUZZ_CHECK (c.format.rfind ("pcd ", 0) == 0 || c.format.rfind ("ply ", 0) == 0);
  FUZZ_CHECK (c.blob.row_step >= static_cast<std::uint64_t> (c.blob.width) * c.blob.point_step);
  FUZZ_CHECK (c.blob.data.size () >= (static_cast<std::uint64_t> (c.blob.height) - 1) * c.blob.row_step +
                                         static_cast<std::uint64_t> (c.blob.width) * c.blob.point_step);
  bool dense = true;
  for (const auto& p : c.xyz->points)
    dense = dense && std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z);
  FUZZ_CHECK (c.xyz->is_dense == dense);
  FUZZ_CHECK (rspd_tools::countFinite (*c.xyz) <= n);
  if (c.normals)
  {
    FUZZ_CHECK (c.normals->size () == n);
    FUZZ_CHECK (c.normals->width == c.blob.width && c.normals->height == c.blob.height);
  }
}

void
checkEmpty (const rspd_tools::LoadedCloud& c)
{
  FUZZ_CHECK (c.xyz == nullptr);
  FUZZ_CHECK (c.normals == nullptr);
  FUZZ_CHECK (c.blob.data.empty () && c.blob.fields.empty ());
  FUZZ_CHECK (c.size () == 0);
  FUZZ_CHECK (c.format.empty ());
}
} // namespace

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static const bool quiet = [] {
    pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
    return true;
  }();
  (void) quiet;
  if (size == 0)
    return 0;
  const std::uint8_t mode = data[0];
  static const char* const kNames[4] = {"input.pcd", "input.ply", "input.PLY", "input.cloud"};
  const std::string path = scratch ().path (kNames[mode & 3]);
  if (!writeFile (path, data + 1, size - 1))
    fail ("cannot write the scratch file", path);

  rspd_tools::LoadedCloud cloud;
  std::string error = "stale";
  const bool ok = rspd_tools::loadCloud (path, cloud, error);
  if (ok)
  {
    FUZZ_CHECK (error.empty ());
    checkCloud (cloud);
  }
  else
  {
    checkError (error);
    checkEmpty (cloud);
  }

  if (mode & 4)
  {
    pcl::PCLPointCloud2 blob;
    std::string blob_error;
    const bool blob_ok = rspd_tools::loadPcdBlob (path, blob, blob_error);
    if (blob_ok)
      FUZZ_CHECK (blob.width > 0 && blob.height > 0 &&
                  blob.data.size () >= (static_cast<std::uint64_t> (blob.height) - 1) * blob.row_step +
                                           static_cast<std::uint64_t> (blob.width) * blob.point_step);
    else
      checkError (blob_error);
    // A PCD with x, y and z that loadCloud takes must be taken by the x/y/z-optional reader too.
    if (ok && cloud.format.rfind ("pcd ", 0) == 0)
      FUZZ_CHECK (blob_ok);
  }

  if (ok && (mode & 8))
  {
    const std::string out = scratch ().path ("labeled.pcd");
    std::vector<std::uint32_t> labels (cloud.size ());
    for (std::size_t i = 0; i < labels.size (); ++i)
      labels[i] = static_cast<std::uint32_t> (i % 3);
    std::string write_error;
    if (!rspd_tools::writeLabeledCloud (out, cloud, labels, write_error))
      fail ("writeLabeledCloud refused a cloud loadCloud returned:", write_error);
    rspd_tools::LoadedCloud back;
    std::string back_error;
    if (!rspd_tools::loadCloud (out, back, back_error))
      fail ("cannot read back the labelled cloud:", back_error);
    checkCloud (back);
    FUZZ_CHECK (back.blob.width == cloud.blob.width && back.blob.height == cloud.blob.height);
    for (std::size_t i = 0; i < cloud.size (); ++i)
    {
      const pcl::PointXYZ &a = (*cloud.xyz)[i], &b = (*back.xyz)[i];
      FUZZ_CHECK (sameFloat (a.x, b.x) && sameFloat (a.y, b.y) && sameFloat (a.z, b.z));
    }
    ::unlink (out.c_str ());
  }
  return 0;
}
