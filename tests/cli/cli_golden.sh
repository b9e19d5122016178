#!/usr/bin/env bash
# Golden transcripts: every tests/golden/cli/NAME.nc is run (or checked) with
# --json and compared, canonicalised, with NAME.json. Regenerate on purpose
# with scripts/update-golden.sh and review the diff.
source "$(dirname "$0")/common.bash"
source "$(dirname "$0")/golden.bash"
dir="$MTC_GOLDEN/cli"
cases=0
for program in "$dir"/*.nc; do
  name="$(basename "$program" .nc)"
  cases=$((cases + 1))
  if [ ! -f "$dir/$name.json" ]; then
    RC=-; OUT=""; ERR=""; fail "$name: no $name.json (run scripts/update-golden.sh)"; continue
  fi
  golden_transcript "$dir" "$name" >"$TEST_TMP/actual.json"
  golden_canonical "$dir/$name.json" >"$TEST_TMP/expected.json"
  if diff -u "$TEST_TMP/expected.json" "$TEST_TMP/actual.json" >"$TEST_TMP/diff"; then
    pass "$name"
  else
    RC=-; OUT="$(head -c 3000 "$TEST_TMP/diff")"; ERR=""; fail "$name differs from $name.json"
  fi
done
if [ "$cases" -lt 1 ]; then RC=-; OUT=""; ERR=""; fail "no golden cases in $dir"; fi
finish
