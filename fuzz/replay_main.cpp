/*
 * pcl_rspd: replays fuzz inputs without libFuzzer, for ctest. Calls LLVMFuzzerTestOneInput on every
 * file in the directories (or on the files) named on the command line, in sorted order; hidden
 * files (.gitkeep) and README files are skipped. A broken invariant aborts inside the target, so
 * the test fails on the input that broke it (printed before it runs).
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size);

namespace fs = std::filesystem;

namespace
{
bool
skipped (const fs::path& p)
{
  const std::string name = p.filename ().string ();
  return name.empty () || name[0] == '.' || name.rfind ("README", 0) == 0;
}
} // namespace

int
main (int argc, char** argv)
{
  if (argc < 2)
  {
    std::fprintf (stderr, "usage: %s DIR_OR_FILE...\n", argv[0]);
    return 2;
  }
  std::vector<fs::path> inputs;
  for (int a = 1; a < argc; ++a)
  {
    const fs::path arg (argv[a]);
    std::error_code ec;
    if (fs::is_directory (arg, ec))
    {
      std::vector<fs::path> files;
      for (const auto& entry : fs::directory_iterator (arg, ec))
        if (entry.is_regular_file () && !skipped (entry.path ()))
          files.push_back (entry.path ());
      if (ec)
      {
        std::fprintf (stderr, "%s: cannot list: %s\n", argv[a], ec.message ().c_str ());
        return 2;
      }
      std::sort (files.begin (), files.end ());
      std::printf ("%s: %zu inputs\n", argv[a], files.size ());
      inputs.insert (inputs.end (), files.begin (), files.end ());
    }
    else if (fs::is_regular_file (arg, ec))
      inputs.push_back (arg);
    else
    {
      std::fprintf (stderr, "%s: no such file or directory\n", argv[a]);
      return 2;
    }
  }
  for (const auto& p : inputs)
  {
    std::ifstream in (p, std::ios::binary);
    if (!in)
    {
      std::fprintf (stderr, "%s: cannot read\n", p.string ().c_str ());
      return 2;
    }
    const std::vector<char> bytes ((std::istreambuf_iterator<char> (in)), std::istreambuf_iterator<char> ());
    std::printf ("replay %s (%zu bytes)\n", p.string ().c_str (), bytes.size ());
    std::fflush (stdout);
    LLVMFuzzerTestOneInput (reinterpret_cast<const std::uint8_t*> (bytes.data ()), bytes.size ());
  }
  std::printf ("%zu inputs replayed, no invariant broken\n", inputs.size ());
  return 0;
}
