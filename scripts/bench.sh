#!/usr/bin/env bash
# Benchmark of issue 3 item 7 (not part of ctest).
#   scripts/bench.sh [BLOCKS]      default 1000000 blocks
# 1. builds Release with MTC_BUILD_BENCH=ON in build/bench,
# 2. generates a program of BLOCKS G1/G2/G3 moves with block numbers and feeds
#    (plain file of blocks; MTC200 syntax, and the same path in ISO syntax),
# 3. runs the Google Benchmark binary mtc_bench (parse MB/s, blocks/s),
# 4. times `mtc200-cli run --no-motion` as a whole process with /usr/bin/time -v
#    (wall time, peak RSS against the source size), and `rs274 -g` on the ISO
#    file when LinuxCNC's standalone interpreter is installed.
# Target (issue 3): mtc200-cli >= 20x faster than rs274 on the same path, peak
# memory < 4x the source size. rs274's reference figure from the issue, used
# when rs274 is not installed: 3.9 s per 1,000,000 blocks.
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

# Runs a command under /usr/bin/time -v; prints "wall_seconds peak_rss_kib exit".
measure() {
  local log="$data/time.log" rc=0
  /usr/bin/time -v -o "$log" "$@" >/dev/null 2>"$data/stderr.log" || rc=$?
  awk -v rc="$rc" '
    /Elapsed \(wall clock\) time/ { n = split($NF, t, ":"); s = 0
      for (i = 1; i <= n; i++) s = s * 60 + t[i]; wall = s }
    /Maximum resident set size/ { rss = $NF }
    END { printf "%.3f %d %d\n", wall, rss, rc }' "$log"
}

if [ -x "$build/bench/mtc_bench" ]; then
  echo "== Google Benchmark (mtc_bench)"
  MTC_BENCH_BLOCKS="$blocks" MTC_BENCH_PROGRAM="$mtc" "$build/bench/mtc_bench" \
    --benchmark_counters_tabular=true || echo "bench: mtc_bench failed (exit $?)"
else
  echo "== mtc_bench not built (no bench/*.cpp yet)"
fi

echo "== whole process: mtc200-cli run --no-motion (best of 3)"
best_wall=""; best_rss=""
for _ in 1 2 3; do
  read -r wall rss rc < <(measure "$cli" run --no-motion "$mtc")
  echo "   wall ${wall} s, peak RSS ${rss} KiB, exit ${rc}"
  if [ "$rc" != 0 ]; then
    echo "bench: mtc200-cli exited $rc:"; head -20 "$data/stderr.log"
    "$cli" run --no-motion "$mtc" | head -20 || true
    break
  fi
  if [ -z "$best_wall" ] || awk -v a="$wall" -v b="$best_wall" 'BEGIN{exit !(a < b)}'; then
    best_wall=$wall; best_rss=$rss
  fi
done
read -r empty_wall empty_rss _ < <(measure "$cli" run --no-motion "$here/resources/programs/N1010001.DAT")
echo "   (demo program N1010001 for scale: wall ${empty_wall} s, peak RSS ${empty_rss} KiB)"
read -r motion_wall motion_rss motion_rc < <(measure "$cli" --json run "$mtc")
echo "== with the motion list streamed as JSON to /dev/null: wall ${motion_wall} s," \
     "peak RSS ${motion_rss} KiB, exit ${motion_rc}"

rs_wall=""
if command -v rs274 >/dev/null 2>&1; then
  echo "== rs274 -g on the same path in ISO syntax"
  read -r rs_wall rs_rss rs_rc < <(measure rs274 -g "$iso")
  echo "   wall ${rs_wall} s, peak RSS ${rs_rss} KiB, exit ${rs_rc}"
else
  echo "== rs274 not installed (Debian package linuxcnc-uspace); using the issue's 3.9 s per 1,000,000 blocks"
fi

[ -n "$best_wall" ] || { echo "bench: no successful mtc200-cli run"; exit 1; }
awk -v blocks="$blocks" -v wall="$best_wall" -v rss="$best_rss" -v src="$source_bytes" \
    -v rs="$rs_wall" 'BEGIN {
  ref = (rs != "") ? rs : 3.9 * blocks / 1000000
  src_kib = src / 1024
  speed = (wall > 0) ? ref / wall : 0
  printf "== summary\n"
  printf "   mtc200-cli run --no-motion: %.3f s, %.0f blocks/s\n", wall, (wall > 0 ? blocks / wall : 0)
  printf "   rs274 %s: %.3f s\n", (rs != "" ? "measured" : "(issue figure)"), ref
  printf "   speed-up %.1fx (target >= 20x): %s\n", speed, (speed >= 20 ? "MET" : "MISSED")
  printf "   peak RSS %d KiB = %.2fx the source (%d KiB; target < 4x): %s\n", rss, rss / src_kib,
         src_kib, (rss < 4 * src_kib ? "MET" : "MISSED")
}'
