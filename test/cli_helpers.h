/*
 * pcl_rspd tests: run a built command-line tool and collect its exit status and output.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace rspd_test
{
/** Exit status (128 + signal when killed) and captured streams of one run. */
struct ToolRun
{
  int status = -1;
  std::string out, err;
};

/** Path of a tool in the build tree, empty when it was not built. */
inline std::string
toolPath (const std::string& name)
{
  const std::string path = std::string (PCL_RSPD_BINARY_DIR) + "/" + name;
  return ::access (path.c_str (), X_OK) == 0 ? path : std::string ();
}

inline std::string
shellQuoted (const std::string& s)
{
  std::string q = "'";
  for (const char c : s)
    q += c == '\'' ? std::string ("'\\''") : std::string (1, c);
  return q + "'";
}

inline std::string
fileText (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf ();
  return ss.str ();
}

/** A fresh scratch directory under /tmp (removed by the destructor). */
class TempDir
{
public:
  TempDir ()
  {
    char tmpl[] = "/tmp/rspd_test_XXXXXX";
    if (::mkdtemp (tmpl))
      path_ = tmpl;
  }
  ~TempDir ()
  {
    if (!path_.empty ())
      std::system (("rm -rf " + shellQuoted (path_)).c_str ());
  }
  std::string
  file (const std::string& name) const { return path_ + "/" + name; }
  bool
  ok () const { return !path_.empty (); }

private:
  std::string path_;
};

/** Run \a tool with \a args (after an optional VAR=value environment prefix), stdout and stderr
  * captured. */
inline ToolRun
runTool (const std::string& tool, const std::vector<std::string>& args, const std::string& env = "")
{
  ToolRun r;
  TempDir dir;
  std::string cmd = (env.empty () ? std::string () : env + " ") + shellQuoted (tool);
  for (const auto& a : args)
    cmd += " " + shellQuoted (a);
  cmd += " > " + shellQuoted (dir.file ("out")) + " 2> " + shellQuoted (dir.file ("err")) + " < /dev/null";
  const int status = std::system (cmd.c_str ());
  r.status = WIFEXITED (status) ? WEXITSTATUS (status) : 128 + WTERMSIG (status);
  r.out = fileText (dir.file ("out"));
  r.err = fileText (dir.file ("err"));
  return r;
}

/** Number of lines of \a s. */
inline int
lineCount (const std::string& s)
{
  int n = 0;
  for (const char c : s)
    n += c == '\n';
  return n;
}
} // namespace rspd_test
