/*
 * pcl_rspd tools: run a piece of work in a forked child process and bring back its result, its
 * peak memory and its CPU time. Shared by rspd_compare and the benchmark runner.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Header-only (inline) so that a tool can use it without a change to the CMake target list.
 */
#pragma once

#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <functional>
#include <new>
#include <string>
#include <vector>

namespace rspd_tools
{
/** \brief Appends plain values to a byte string. Parent and child are the same program on the same
  * machine, so host byte order and layout are fine. */
struct ByteWriter
{
  std::string bytes;

  template <typename T> void
  put (const T& v) { bytes.append (reinterpret_cast<const char*> (&v), sizeof (T)); }

  template <typename T> void
  putVector (const std::vector<T>& v)
  {
    put<std::uint64_t> (v.size ());
    bytes.append (reinterpret_cast<const char*> (v.data ()), v.size () * sizeof (T));
  }

  void
  putString (const std::string& s)
  {
    put<std::uint64_t> (s.size ());
    bytes += s;
  }
};

/** \brief Reads what ByteWriter wrote; every get fails (returns false) past the end. */
struct ByteReader
{
  const std::string& bytes;
  std::size_t pos = 0;

  template <typename T> bool
  get (T& v)
  {
    if (bytes.size () - pos < sizeof (T))
      return false;
    std::memcpy (&v, bytes.data () + pos, sizeof (T));
    pos += sizeof (T);
    return true;
  }

  template <typename T> bool
  getVector (std::vector<T>& v)
  {
    std::uint64_t n = 0;
    if (!get (n) || n > (bytes.size () - pos) / sizeof (T))
      return false;
    v.resize (n);
    std::memcpy (v.data (), bytes.data () + pos, n * sizeof (T));
    pos += n * sizeof (T);
    return true;
  }

  bool
  getString (std::string& s)
  {
    std::uint64_t n = 0;
    if (!get (n) || n > bytes.size () - pos)
      return false;
    s.assign (bytes, pos, n);
    pos += n;
    return true;
  }
};

/** \brief Outcome of one child process. */
struct ChildOutcome
{
  bool ok = false;
  std::string error;        ///< why not ok
  std::string payload;      ///< what the work returned (ok only)
  double peak_mb = 0.0;     ///< the child's own peak RSS (from wait4)
  double start_mb = 0.0;    ///< the child's RSS before the work: what it maps of the parent at once
  double cpu_seconds = 0.0; ///< user + system CPU time of the child, all its threads (from wait4)
};

/** \brief Resident set size of this process now, MB (0 if /proc is unavailable). */
inline double
currentRssMb ()
{
  std::ifstream status ("/proc/self/status");
  std::string line;
  while (std::getline (status, line))
    if (line.compare (0, 6, "VmRSS:") == 0)
      return std::strtod (line.c_str () + 6, nullptr) / 1024.0;  // "VmRSS:   1234 kB"
  return 0.0;
}

/** \brief Write all of \a data to \a fd, retrying on EINTR and short writes. */
inline bool
writeAll (int fd, const char* data, std::size_t size)
{
  while (size > 0)
  {
    const ssize_t w = ::write (fd, data, size);
    if (w < 0 && errno == EINTR)
      continue;
    if (w <= 0)
      return false;
    data += w;
    size -= static_cast<std::size_t> (w);
  }
  return true;
}

/** \brief Run \a work in a forked child and bring back its result through a pipe.
  *
  * A process per run gives each its own peak memory (wait4 reports the child's ru_maxrss, not a
  * maximum shared with earlier children) and keeps a crash or an out-of-memory kill of one run
  * from taking the tool down. The child writes 'O', its RSS before the work, and the payload, or
  * 'E' and a message if \a work threw, and leaves with _exit so that nothing of the parent (stdio
  * buffers, atexit handlers) runs twice.
  *
  * The child's RSS starts with what it inherits mapped from the parent and touches (e.g. a cloud
  * the parent loaded), not with the parent's whole RSS: pages are counted only once the child
  * touches them. Hence the start size is measured and reported along with the peak.
  *
  * The parent itself must never run an OpenMP parallel region: GNU libgomp does not survive fork()
  * once its thread pool exists (the child hangs at its first parallel region). Whatever needs
  * OpenMP (normal estimation, detection) belongs in a child.
  *
  * \param[in] name what the child does, matched against the test hook below
  * \param[in] work the work; its return value is the payload
  * \param[in] kill_hook_env name of an environment variable (or null): a child whose \a name it
  *            holds kills itself with SIGKILL before working, so tests can check that failures
  *            are reported
  */
inline ChildOutcome
runInChild (const std::string& name, const std::function<std::string ()>& work,
            const char* kill_hook_env = nullptr)
{
  ChildOutcome out;
  int fds[2];
  if (::pipe2 (fds, O_CLOEXEC) != 0)
  {
    out.error = std::string ("pipe: ") + std::strerror (errno);
    return out;
  }
  // Anything buffered now would otherwise be printed again by the child.
  std::fflush (stdout);
  std::fflush (stderr);
  const pid_t pid = ::fork ();
  if (pid < 0)
  {
    out.error = std::string ("fork: ") + std::strerror (errno);
    ::close (fds[0]);
    ::close (fds[1]);
    return out;
  }
  if (pid == 0)
  {
    ::close (fds[0]);
    const char* kill_hook = kill_hook_env ? std::getenv (kill_hook_env) : nullptr;
    if (kill_hook && name == kill_hook)
      ::raise (SIGKILL);
    std::string message;
    int status = 0;
    try
    {
      const double start_mb = currentRssMb ();
      message = "O" + std::string (reinterpret_cast<const char*> (&start_mb), sizeof (start_mb)) + work ();
    }
    catch (const std::bad_alloc&)
    {
      message = "Eout of memory";
      status = 3;
    }
    catch (const std::exception& e)
    {
      message = std::string ("E") + e.what ();
      status = 3;
    }
    catch (...)
    {
      message = "Eunknown exception";
      status = 3;
    }
    if (!writeAll (fds[1], message.data (), message.size ()))
      status = 4;
    ::close (fds[1]);
    ::_exit (status);
  }

  // Parent: drain the pipe first (a child blocked on a full pipe would never exit), then reap.
  ::close (fds[1]);
  std::string message;
  char buffer[1 << 16];
  for (;;)
  {
    const ssize_t r = ::read (fds[0], buffer, sizeof (buffer));
    if (r < 0 && errno == EINTR)
      continue;
    if (r <= 0)
      break;
    message.append (buffer, static_cast<std::size_t> (r));
  }
  ::close (fds[0]);
  int status = 0;
  struct rusage usage;
  std::memset (&usage, 0, sizeof (usage));
  while (::wait4 (pid, &status, 0, &usage) < 0)
    if (errno != EINTR)
    {
      out.error = std::string ("wait4: ") + std::strerror (errno);
      return out;
    }
  out.peak_mb = static_cast<double> (usage.ru_maxrss) / 1024.0;  // Linux: KiB
  out.cpu_seconds = static_cast<double> (usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                    1e-6 * static_cast<double> (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  if (WIFSIGNALED (status))
  {
    const int sig = WTERMSIG (status);
    out.error = "killed by signal " + std::to_string (sig) + " (" + ::strsignal (sig) + ")";
  }
  else if (!WIFEXITED (status))
    out.error = "ended abnormally";
  else if (WEXITSTATUS (status) != 0 || message.size () < 1 + sizeof (double) || message[0] != 'O')
  {
    if (!message.empty () && message[0] == 'E')
      out.error = message.substr (1);
    else
      out.error = "exited with status " + std::to_string (WEXITSTATUS (status)) + " without a result";
  }
  else
  {
    out.ok = true;
    std::memcpy (&out.start_mb, message.data () + 1, sizeof (double));
    out.payload = message.substr (1 + sizeof (double));
  }
  return out;
}

} // namespace rspd_tools
