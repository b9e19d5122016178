#!/usr/bin/env bash
# The fuzz campaign of issue 22 §7 (not part of ctest; see docs/FUZZING.md).
#   scripts/fuzz.sh [SECONDS] [TARGET...]
#     SECONDS  per target (default 60); 0 = only replay seeds and regressions
#     TARGET   parser compiler gne machine_config machine_data target_path mdi removal
#              reentry
#              (default: all, one after the other)
#   MTC_FUZZ_RUNS=N  stop a target after N executions instead of SECONDS
#   MTC_FUZZ_JOBS=N  build jobs (default 2)
#   MTC_FUZZ_NICE=N  niceness of the fuzzer (default 19)
# 1. builds the libFuzzer targets (preset fuzz: clang, ASan+UBSan, core only),
# 2. assembles each target's seeds in build/fuzz/seeds/<target> from the
#    project's own programs (resources/programs, tests/golden inputs), the
#    hand-written tests/fuzz/seeds/<target> and tests/fuzz/regressions/<target>,
# 3. replays seeds and regressions once, then fuzzes with the NC dictionary
#    (tests/fuzz/nc.dict) and the number mutator, one process at a time
#    (the equivalent of -jobs=1) under nice, with leak detection; the growing
#    corpus stays in build/fuzz/corpus/<target>. libFuzzer's timeout counts
#    wall time, which on a shared machine says little: it is 60 s (a hang);
#    every unit libFuzzer reports as the slowest so far, and every wall-time
#    timeout, is timed again alone in CPU time: 1 s or more is a finding,
# 4. copies every crash, timeout, leak or out-of-memory input to
#    tests/fuzz/regressions/<target>/ (replayed by ctest's fuzz_replay_tests
#    until the finding is fixed) and prints one line of figures per target.
# Exit status 1 when a target found something.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
shift || true
all_targets=(parser compiler gne machine_config machine_data target_path mdi removal reentry)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")
build="$here/build/fuzz"
fuzz="$here/tests/fuzz"

for t in "${targets[@]}"; do
  [[ " ${all_targets[*]} " == *" $t "* ]] || { echo "fuzz: unknown target '$t'" >&2; exit 2; }
done
command -v clang++ >/dev/null || { echo "fuzz: clang++ is needed (scripts/setup.sh tools)" >&2; exit 2; }

echo "== build (preset fuzz) in $build"
cmake --preset fuzz -S "$here" >/dev/null
cmake --build "$build" -j "${MTC_FUZZ_JOBS:-2}" --target "${targets[@]/#/fuzz_}"

# Seeds: the files of the given folders (and single files), copied flat.
add_seeds() {
  local dest="$1"; shift
  local f
  for f in "$@"; do
    [ -f "$f" ] && cp "$f" "$dest/$(basename "$(dirname "$f")")_$(basename "$f")"
  done
  return 0
}
assemble_seeds() {
  local t="$1" dest="$build/seeds/$1"
  rm -rf "$dest" && mkdir -p "$dest"
  shopt -s nullglob
  local programs=("$here"/resources/programs/* "$here"/tests/golden/compiler/*.DAT
                  "$here"/tests/golden/compiler/*.NCO "$here"/tests/golden/interp/*.nc
                  "$here"/tests/golden/cli/*.nc "$here"/tests/golden/restart/*.nc
                  "$here"/tests/golden/restart/programs/*)
  case "$t" in
    parser|compiler|removal) add_seeds "$dest" "${programs[@]}" ;;
    reentry) ;;  # hand-written seeds only: the stock and target lines come first
    gne) add_seeds "$dest" $(grep -l -E 'CONT|FORM_|CYCLE_' "${programs[@]}" /dev/null || true) ;;
    machine_config) add_seeds "$dest" "$here"/resources/machines/* ;;
    mdi)  # the first lines of the golden interpreter programs, as typed in MDI
      local f
      for f in "$here"/tests/golden/interp/*.nc; do
        grep -v '^%\|^iMTc' "$f" | head -n 12 > "$dest/interp_$(basename "$f")"
      done ;;
  esac
  add_seeds "$dest" "$fuzz"/seeds/"$t"/* "$fuzz"/regressions/"$t"/*
  shopt -u nullglob
}

status=0
summary=()
export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
for t in "${targets[@]}"; do
  binary="$build/tests/fuzz/fuzz_$t"
  assemble_seeds "$t"
  corpus="$build/corpus/$t"
  findings="$build/findings/$t"
  mkdir -p "$corpus" "$findings"
  echo "== $t: replay of $(ls "$build/seeds/$t" | wc -l) seeds and regressions"
  if ! "$binary" -timeout=60 -rss_limit_mb=2048 "$build/seeds/$t"/* >"$build/replay-$t.log" 2>&1; then
    echo "fuzz: $t fails on a seed or regression input, see $build/replay-$t.log" >&2
    tail -n 30 "$build/replay-$t.log" >&2
    status=1
    continue
  fi
  [ "$seconds" = 0 ] && continue
  limit=(-max_total_time="$seconds")
  [ -n "${MTC_FUZZ_RUNS:-}" ] && limit=(-runs="$MTC_FUZZ_RUNS")
  log="$build/fuzz-$t.log"
  echo "== $t: fuzzing (${limit[*]}), log $log"
  # earlier findings were copied to tests/fuzz/regressions when found
  find "$findings" -type f -delete
  set +e
  nice -n "${MTC_FUZZ_NICE:-19}" "$binary" "$corpus" "$build/seeds/$t" -dict="$fuzz/nc.dict" \
    "${limit[@]}" -timeout=60 -report_slow_units=1 -rss_limit_mb=2048 -malloc_limit_mb=2048 \
    -max_len=2048 -detect_leaks=1 -print_final_stats=1 -artifact_prefix="$findings/" >"$log" 2>&1
  rc=$?
  set -e
  # slow units and wall-time timeouts: timed alone in CPU seconds; under 1 s
  # they are no finding (the machine was busy)
  slowest=0
  for f in "$findings"/slow-unit-* "$findings"/timeout-[0-9a-f]*; do
    [ -f "$f" ] || continue
    cpu=$( { /usr/bin/time -f '%U %S' "$binary" "$f" >/dev/null 2>/dev/null; } 2>&1 | tail -n 1 |
          awk '{ print $1 + $2 }')
    if awk -v c="$cpu" 'BEGIN { exit !(c >= 1.0) }'; then
      mv "$f" "$findings/cpu-timeout-$(basename "$f" | sed "s/^[a-z-]*-//")"
    else
      rm -f "$f"
    fi
    slowest=$(awk -v a="$slowest" -v b="$cpu" 'BEGIN { print (b > a ? b : a) }')
  done
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
  found=$(find "$findings" -type f | wc -l)
  # libFuzzer stops at a wall-time timeout; when its input took less than
  # 1 s of CPU alone (above: the machine was busy or the fuzzer was paused)
  # that stop is no finding.
  if [ "$rc" -ne 0 ] && [ "$found" -eq 0 ] && grep -q '^SUMMARY: libFuzzer: timeout' "$log"; then
    echo "fuzz: $t stopped at a wall-time timeout whose input takes under 1 s of CPU: no finding" >&2
    rc=0
  fi
  if [ "$rc" -ne 0 ] || [ "$found" -gt 0 ]; then
    status=1
    mkdir -p "$fuzz/regressions/$t"
    for f in "$findings"/*; do
      [ -f "$f" ] || continue
      [ -f "$fuzz/regressions/$t/$(basename "$f")" ] || cp "$f" "$fuzz/regressions/$t/"
    done
    echo "fuzz: $t found something (exit $rc): inputs in $findings, copied to tests/fuzz/regressions/$t" >&2
    grep -m 3 -E 'ERROR|SUMMARY|contract broken|runtime error' "$log" >&2 || true
  fi
  line="$t executions=${runs:-?} exec/s=${rate:-?} corpus=$(ls "$corpus" | wc -l)"
  line+=" slowest-cpu-s=$slowest findings=$found"
  summary+=("$line")
  echo "$(date -u +%FT%TZ) $line" >>"$build/figures.log"
done

echo "== figures"
printf '%s\n' "${summary[@]}"
exit "$status"
