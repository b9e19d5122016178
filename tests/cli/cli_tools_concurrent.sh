#!/usr/bin/env bash
# One writer at a time for the tool and offset files (issue 22 §4, TOOL-006):
# two `tools set` (and two `offsets set`) on one data file at the same
# moment, each changing another process, 20 rounds; after every round both
# values are in the file. Without the lock and the take-over, the second
# save wrote its stale copy of the other process back.
source "$(dirname "$0")/common.bash"
export XDG_STATE_HOME="$TEST_TMP/state"
data="$TEST_TMP/shared.mdt"
rounds=20
lost=0
for round in $(seq 1 $rounds); do
  "$MTC_CLI" --data "$data" tools set T1 radius="$round" >/dev/null 2>"$TEST_TMP/a.err" &
  a=$!
  "$MTC_CLI" --data "$data" --process 1 tools set T2 radius="$((round + 100))" >/dev/null 2>"$TEST_TMP/b.err" &
  b=$!
  "$MTC_CLI" --data "$data" offsets set G56 X="$round" >/dev/null 2>"$TEST_TMP/c.err" &
  c=$!
  "$MTC_CLI" --data "$data" --process 1 offsets set G56 Z="$((round + 100))" >/dev/null 2>"$TEST_TMP/d.err" &
  d=$!
  for job in a b c d; do
    wait "${!job}" || { lost=$((lost + 1)); cat "$TEST_TMP/$job.err"; }
  done
  tools="$(cat "$TEST_TMP/shared.tools")"
  offsets="$(cat "$TEST_TMP/shared.offsets")"
  # process 0 comes first in each file, process 1 after it
  p0t="$(printf '%s\n' "$tools" | sed -n '/^\[process 0\]/,/^\[process 1\]/p' | grep -c "^T1 E1 radius=$round ")"
  p1t="$(printf '%s\n' "$tools" | sed -n '/^\[process 1\]/,$p' | grep -c "^T2 E1 radius=$((round + 100)) ")"
  p0o="$(printf '%s\n' "$offsets" | sed -n '/^\[process 0\]/,/^\[process 1\]/p' | grep -c "^G56 X=$round\$")"
  p1o="$(printf '%s\n' "$offsets" | sed -n '/^\[process 1\]/,$p' | grep -c "^G56 Z=$((round + 100))\$")"
  if [ "$p0t$p1t$p0o$p1o" != "1111" ]; then
    lost=$((lost + 1)); echo "round $round: found $p0t $p1t $p0o $p1o"
  fi
done
echo "[ measured ] $rounds rounds of four concurrent tools/offsets set: $lost lost or failed"
[ "$lost" -eq 0 ] && pass "no value lost in $rounds rounds" || fail "$lost values lost"
finish
