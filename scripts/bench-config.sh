#!/usr/bin/env bash
# Whole-process speed of the machine configuration reader (issue 22 §2):
#   scripts/bench-config.sh [TOOLS]      default 1200000 tools (about 50 MB)
# builds Release in build/bench, writes the demo cell with TOOLS tools in
# process 0, and times `mtc200-cli --machine FILE check 1` (wall time, peak
# RSS) with /usr/bin/time; then runs the reader's Google Benchmark.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tools="${1:-1200000}"
build="$here/build/bench"
cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMTC_BUILD_BENCH=ON >/dev/null
cmake --build "$build" -j "$(nproc)" --target mtc200-cli mtc_bench
cfg="$build/bench-data/tools-$tools.cfg"
mkdir -p "$(dirname "$cfg")"
awk -v tools="$tools" '
  /^T1 = / && !done { for (t = 1; t <= tools; ++t)
                        printf "T%d = radius %d.5 length %d name tool%d\n", t, t % 50, 60 + t % 100, t
                      done = 1; skipping = 1; next }
  skipping && /^T[0-9]+ = / { next }
  { skipping = 0; print }' "$here/resources/machines/demo-cell.cfg" >"$cfg"
echo "== $(stat -c %s "$cfg") bytes, $tools tools: $cfg"
for run in 1 2 3; do
  /usr/bin/time -f "run $run: %e s wall, %M KiB peak" "$build/app/mtc200-cli" --machine "$cfg" check 1 >/dev/null
done
"$build/bench/mtc_bench" --benchmark_filter=BM_ReadMachineConfigTools
