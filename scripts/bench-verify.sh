#!/usr/bin/env bash
# Benchmark of the restart verifier (issue 15 §3; not part of ctest).
#   scripts/bench-verify.sh [BLOCKS] [CLI]   default 10000 blocks, build/release's CLI
# Generates a mill program of BLOCKS blocks (scripts/gen-restart-program.sh:
# tool changes through program 99, spindle, coolant, G1/G2/G3 laps; every
# block one target) and times `mtc200-cli verify-restart PROG --adjust` as a
# whole process, best of 3: wall and CPU seconds, peak RSS, the coverage line.
# Target: a 10,000-block program verifies in well under a minute.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
blocks="${1:-10000}"
cli="${2:-$here/build/release/app/mtc200-cli}"
[ -x "$cli" ] || { echo "bench-verify: no mtc200-cli at $cli (build first)" >&2; exit 2; }
command -v /usr/bin/time >/dev/null || { echo "bench-verify: /usr/bin/time is needed" >&2; exit 2; }
data="$(mktemp -d)"
trap 'rm -rf "$data"' EXIT
program="$data/verify-$blocks.nc"
"$here/scripts/gen-restart-program.sh" "$blocks" "$program"
echo "== program: $blocks blocks ($(stat -c %s "$program") bytes)"
best=""
for round in 1 2 3; do
  rc=0
  /usr/bin/time -f "%e %U %M" -o "$data/time" "$cli" verify-restart "$program" --adjust \
    >"$data/out" 2>"$data/err" || rc=$?
  read -r wall user rss <"$data/time"
  echo "round $round: wall ${wall} s, cpu ${user} s, peak ${rss} KiB, exit $rc"
  if [ -z "$best" ] || awk -v a="$wall" -v b="$best" 'BEGIN { exit !(a < b) }'; then
    best="$wall"; bestline="wall ${wall} s, cpu ${user} s, peak ${rss} KiB"
  fi
done
grep '^verify-restart:' "$data/out" | cut -c1-200
echo "== best: $bestline (load $(cut -d' ' -f1-3 /proc/loadavg))"
