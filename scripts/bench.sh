#!/usr/bin/env bash
# Benchmark of issues 3 and 21 (not part of ctest).
#   scripts/bench.sh [BLOCKS]      default 1000000 blocks
# 1. builds Release with MTC_BUILD_BENCH=ON in build/bench,
# 2. generates a program of BLOCKS G1/G2/G3 moves with block numbers and feeds
#    (plain file of blocks; MTC200 syntax, and the same path in ISO syntax),
# 3. runs the Google Benchmark binary mtc_bench (parse MB/s, blocks/s),
# 4. times `mtc200-cli run --no-motion` as a whole process with /usr/bin/time -v
#    (wall time, CPU time = user + sys, peak RSS against the source size), and
#    `rs274 -g` on the ISO file when LinuxCNC's standalone interpreter is
#    installed (`scripts/setup.sh bench` installs it: Debian's linuxcnc-uspace).
# Each is run 3 times, the best CPU time counts. The speed-up is given by CPU
# time (on a shared machine wall time includes waiting for a core) and by wall
# time. Targets (issue 21): mtc200-cli >= 40x faster than rs274 on the same
# path, peak memory <= 2x the source size. rs274's reference figure from issue
# 3, used when rs274 is not installed: 3.9 s per 1,000,000 blocks.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
blocks="${1:-1000000}"
build="$here/build/bench"
data="$build/bench-data"
jobs=$(nproc 2>/dev/null || echo 2)

for tool in /usr/bin/time awk; do
  [ -x "$(command -v "$tool")" ] || { echo "bench: $tool is needed" >&2; exit 2; }
done

echo "== build (Release, MTC_BUILD_BENCH=ON) in $build"
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMTC_BUILD_BENCH=ON >/dev/null
targets=(mtc200-cli)
if cmake --build "$build" --target help | grep -q '^mtc_bench:'; then targets+=(mtc_bench); fi
cmake --build "$build" -j "$jobs" --target "${targets[@]}"
cli="$build/app/mtc200-cli"

mkdir -p "$data"
mtc="$data/bench-$blocks.nc"
iso="$data/bench-$blocks-iso.ngc"
"$here/scripts/gen-bench-program.sh" mtc "$blocks" "$mtc"
"$here/scripts/gen-bench-program.sh" iso "$blocks" "$iso"
source_bytes=$(stat -c %s "$mtc")
echo "== program: $blocks blocks, $source_bytes bytes ($mtc)"

# Runs a command under /usr/bin/time -v; prints
# "wall_seconds cpu_seconds peak_rss_kib exit" (cpu = user + sys).
measure() {
  local log="$data/time.log" rc=0
  /usr/bin/time -v -o "$log" "$@" >/dev/null 2>"$data/stderr.log" || rc=$?
  awk -v rc="$rc" '
    /Elapsed \(wall clock\) time/ { n = split($NF, t, ":"); s = 0
      for (i = 1; i <= n; i++) s = s * 60 + t[i]; wall = s }
    /User time \(seconds\)/ { cpu += $NF }
    /System time \(seconds\)/ { cpu += $NF }
    /Maximum resident set size/ { rss = $NF }
    END { printf "%.3f %.3f %d %d\n", wall, cpu, rss, rc }' "$log"
}

# Best of 3 runs of a command by CPU time; prints "wall cpu rss exit" of it
# (a failing run is printed at once).
best_of_3() {
  local best="" wall cpu rss rc
  for _ in 1 2 3; do
    read -r wall cpu rss rc < <(measure "$@")
    echo "   wall ${wall} s, cpu ${cpu} s, peak RSS ${rss} KiB, exit ${rc}" >&2
    if [ "$rc" != 0 ]; then echo "$wall $cpu $rss $rc"; return; fi
    if [ -z "$best" ] || awk -v a="$cpu" -v b="${best#* }" 'BEGIN{split(b, f, " "); exit !(a < f[1])}'; then
      best="$wall $cpu $rss $rc"
    fi
  done
  echo "$best"
}

if [ -x "$build/bench/mtc_bench" ]; then
  echo "== Google Benchmark (mtc_bench)"
  MTC_BENCH_BLOCKS="$blocks" MTC_BENCH_PROGRAM="$mtc" "$build/bench/mtc_bench" \
    --benchmark_counters_tabular=true || echo "bench: mtc_bench failed (exit $?)"
else
  echo "== mtc_bench not built (no bench/*.cpp yet)"
fi

echo "== whole process: mtc200-cli run --no-motion (best of 3 by CPU time)"
read -r best_wall best_cpu best_rss best_rc < <(best_of_3 "$cli" run --no-motion "$mtc")
if [ "$best_rc" != 0 ]; then
  echo "bench: mtc200-cli exited $best_rc:"; head -20 "$data/stderr.log"
  best_wall=""
fi
read -r empty_wall _ empty_rss _ < <(measure "$cli" run --no-motion "$here/resources/programs/N1010001.DAT")
echo "   (demo program N1010001 for scale: wall ${empty_wall} s, peak RSS ${empty_rss} KiB)"
read -r motion_wall _ motion_rss motion_rc < <(measure "$cli" --json run "$mtc")
echo "== with the motion list streamed as JSON to /dev/null: wall ${motion_wall} s," \
     "peak RSS ${motion_rss} KiB, exit ${motion_rc}"

rs_wall=""; rs_cpu=""
if command -v rs274 >/dev/null 2>&1; then
  echo "== rs274 -g on the same path in ISO syntax (best of 3 by CPU time)"
  read -r rs_wall rs_cpu rs_rss rs_rc < <(best_of_3 rs274 -g "$iso")
  [ "$rs_rc" = 0 ] || { echo "   rs274 exited $rs_rc"; rs_wall=""; rs_cpu=""; }
else
  echo "== rs274 not installed (scripts/setup.sh bench installs linuxcnc-uspace);" \
       "using issue 3's 3.9 s per 1,000,000 blocks"
fi

[ -n "$best_wall" ] || { echo "bench: no successful mtc200-cli run"; exit 1; }
awk -v blocks="$blocks" -v wall="$best_wall" -v cpu="$best_cpu" -v rss="$best_rss" \
    -v src="$source_bytes" -v rs="$rs_wall" -v rscpu="$rs_cpu" 'BEGIN {
  measured = (rs != "")
  ref_wall = measured ? rs : 3.9 * blocks / 1000000
  ref_cpu = measured ? rscpu : ref_wall
  src_kib = src / 1024
  by_cpu = (cpu > 0) ? ref_cpu / cpu : 0
  by_wall = (wall > 0) ? ref_wall / wall : 0
  printf "== summary\n"
  printf "   mtc200-cli run --no-motion: cpu %.3f s, wall %.3f s, %.0f blocks/s (cpu)\n", cpu, wall,
         (cpu > 0 ? blocks / cpu : 0)
  printf "   rs274 %s: cpu %.3f s, wall %.3f s\n", (measured ? "measured" : "(issue 3 figure)"),
         ref_cpu, ref_wall
  printf "   speed-up by cpu %.1fx, by wall %.1fx (target >= 40x): %s\n", by_cpu, by_wall,
         (by_cpu >= 40 ? "MET" : "MISSED")
  printf "   peak RSS %d KiB = %.2fx the source (%d KiB; target <= 2x): %s\n", rss, rss / src_kib,
         src_kib, (rss <= 2 * src_kib ? "MET" : "MISSED")
}'
