#!/usr/bin/python3
"""Choose the tests the sanitizer step runs: every test that is cheap under ASan, plus the fewest
costly ones (weighed by their ASan seconds) that execute every line of the project's code that the
costly ones execute. Lines are gcov's, from a build with coverage instrumentation.

  scripts/sanitizer_subset.py COVERAGE_BUILD TIMES [--cheap SECONDS] [--out FILE]

COVERAGE_BUILD: a built build directory of this project configured with
  -DCMAKE_CXX_FLAGS="--coverage -fprofile-update=single" -DCMAKE_EXE_LINKER_FLAGS=--coverage
  -DCMAKE_SHARED_LINKER_FLAGS=--coverage
(-fopenmp implies -pthread, whose default atomic counters made the tests about 20 times slower).
TIMES: seconds per test under the sanitizers, either ctest's CTestCostData.txt of a whole run
(PCL_RSPD_SANITIZE_ALL=1 bash scripts/test_sanitizers.sh; build-asan/Testing/Temporary/) or
scripts/sanitizer_times.txt, in the same format; a test missing from it counts as cheap. Each costly
test runs alone, under its own GCOV_PREFIX, so that its lines are its own; the cheap ones run
together. Prints the lines each part covers and writes the costly tests not chosen, one per line, to
--out (scripts/sanitizer_skip.txt, which scripts/test_sanitizers.sh leaves out). Run it again when
the code changes: a line only a skipped test reaches is a line the sanitizers no longer see."""
import argparse, glob, json, os, re, shutil, subprocess, sys, tempfile
from concurrent.futures import ThreadPoolExecutor

ap = argparse.ArgumentParser()
ap.add_argument("build")
ap.add_argument("times")
ap.add_argument("--cheap", type=float, default=10.0)
ap.add_argument("--out", default="-")
ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
ap.add_argument("--save", help="also write the lines each costly test adds, as JSON")
a = ap.parse_args()
build = os.path.abspath(a.build)
source = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
times = {}  # CTestCostData.txt: "name runs seconds" lines, then "---" and the failed tests' names
for row in open(a.times):
    f = row.split()
    if len(f) == 3 and not f[0].startswith("#"):
        times[f[0]] = float(f[2])

names = re.findall(r"^\s*Test\s+#\d+: (\S+)$",
                   subprocess.run(["ctest", "--test-dir", build, "-N"], capture_output=True,
                                  text=True, check=True).stdout, re.M)
costly = [n for n in names if times.get(n, 0.0) >= a.cheap]
work = tempfile.mkdtemp(prefix="rspd_cov_")
gcnos = glob.glob(os.path.join(build, "**", "*.gcno"), recursive=True)


def run(prefix, args):
    # One OpenMP thread per test unless told otherwise: the tests run --jobs at a time.
    env = dict(os.environ, GCOV_PREFIX=prefix, GCOV_PREFIX_STRIP="0")
    env.setdefault("OMP_NUM_THREADS", "1")
    r = subprocess.run(["ctest", "--test-dir", build, "--output-on-failure"] + args, env=env,
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.stderr.write(r.stdout[-3000:])
    return r.returncode == 0


def lines(prefix):
    """(file, line) pairs of the project's own sources (not its tests) executed under prefix."""
    got = set()
    for gcno in gcnos:
        gcda = prefix + gcno[:-5] + ".gcda"
        if not os.path.exists(gcda):
            continue
        shutil.copy(gcno, gcda[:-5] + ".gcno")
        out = subprocess.run(["gcov", "-t", "--json-format", gcda], capture_output=True,
                             cwd=os.path.dirname(gcda)).stdout
        for doc in out.decode(errors="replace").splitlines():
            if not doc.strip():
                continue
            for f in json.loads(doc)["files"]:
                path = os.path.normpath(os.path.join(build, f["file"]))
                rel = os.path.relpath(path, source)
                if rel.startswith(("src/", "include/", "examples/")):
                    got.update((rel, l["line_number"]) for l in f["lines"] if l["count"] > 0)
    return got


pattern = lambda ns: "^(" + "|".join(re.escape(n) for n in ns) + ")$"
ok = run(os.path.join(work, "cheap"), ["-j", str(a.jobs), "-E", pattern(costly)] if costly else [])
base = lines(os.path.join(work, "cheap"))


def one(i):
    p = os.path.join(work, "costly%03d" % i)
    return run(p, ["-R", pattern([costly[i]])]), lines(p)


with ThreadPoolExecutor(a.jobs) as pool:
    results = list(pool.map(one, range(len(costly))))
if not ok or not all(r[0] for r in results):
    sys.exit("some test failed in the coverage build")
cover = {costly[i]: results[i][1] - base for i in range(len(costly))}
if a.save:
    json.dump({n: sorted(v) for n, v in cover.items() if v}, open(a.save, "w"), indent=0)
left = set().union(*cover.values()) if cover else set()
print("cheap tests: %d, lines %d; lines only costly tests reach: %d" %
      (len(names) - len(costly), len(base), len(left)))
chosen = []
while left:
    best = max(cover, key=lambda n: (len(cover[n] & left) / max(times[n], 1e-3), n))
    gain = cover[best] & left
    if not gain:
        break
    chosen.append(best)
    left -= gain
    print("  + %-90s %7.1f s  %4d lines" % (best, times[best], len(gain)))
print("costly tests chosen: %d of %d, %.0f ASan-seconds of %.0f" %
      (len(chosen), len(costly), sum(times[n] for n in chosen), sum(times[n] for n in costly)))
skipped = sorted(set(costly) - set(chosen))
text = ("# Written by scripts/sanitizer_subset.py (--cheap %g): tests that scripts/test_sanitizers.sh\n"
        "# leaves out. Each took %g s or more under ASan + UBSan, and the tests that do run there\n"
        "# execute every line of src/, include/ and examples/ that it executes (gcov).\n" % (a.cheap, a.cheap)
        + "".join(n + "\n" for n in skipped))
if a.out == "-":
    sys.stdout.write(text)
else:
    open(a.out, "w").write(text)
shutil.rmtree(work)
