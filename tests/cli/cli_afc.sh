#!/usr/bin/env bash
# Adaptive feed control in `mtc200-cli run` (seed 002, issue 15): bad
# B062..B069 values refused with file, line, key, value and range (no
# crash); --no-motion changes the output only; the motion record and the
# final position show where errors stopped the axes; absurd durations stop
# with a diagnostic instead of costing CPU time.
source "$(dirname "$0")/common.bash"
cell="$MTC_SOURCE_DIR/resources/machines/demo-cell.cfg"

# B063..B069 out of range or not a number: exit 2 with the line, not SIGSEGV.
for bad in "B065 = 600" "B064 = lots" "B069 = 1.5" "B063 = 13" "B062 = maybe"; do
  key=${bad%% *}
  # the key's own line when the demo cell has one (a second line would be a
  # duplicate key, CF-006), else the first B063 line
  if grep -q "^$key = " "$cell"; then from="^$key = .*"; else from="^B063 = 10 .*"; fi
  sed "0,/$from/s//$bad/" "$cell" >"$TEST_TMP/bad.cfg"
  line=$(grep -n "^$bad\$" "$TEST_TMP/bad.cfg" | head -1 | cut -d: -f1)
  value=${bad##* }
  printf 'N0010 G1 X10 F100\nN0020 M30\n' >"$TEST_TMP/plain.nc"
  expect_rc 2 "$bad refused" --machine "$TEST_TMP/bad.cfg" run "$TEST_TMP/plain.nc"
  text_check "$bad: file named" "bad.cfg has errors"
  text_check "$bad: key and value named" "$key = '$value'"
  text_check "$bad: line $line" "line $line"
  [ "$key" = B065 ] && text_check "B065: allowed range given" "allowed: 0 … 500 %"
  expect_rc 2 "$bad refused (json)" --json --machine "$TEST_TMP/bad.cfg" run "$TEST_TMP/plain.nc"
  json_check "$bad: CFG_VALUE at line $line" \
    "any(x['code'] == 'CFG_VALUE' and x['line'] == $line and 'allowed' in x['message'] for x in d['diagnostics'])"
done

# --no-motion: the same adaptive feed control (page 30, time), only no motion list.
expect_rc 0 "demo slot with motion" --json run 2
full="$OUT"
expect_rc 0 "demo slot --no-motion" --json run --no-motion 2
OUT2="$OUT"
OUT="$(printf '{"a": %s, "b": %s}' "$full" "$OUT2")"
json_check "--no-motion keeps adaptive feed control" \
  'd["a"]["afc"] == d["b"]["afc"] and d["b"]["afc"]["012_peak_feed_reduction"] > 50'
json_check "--no-motion keeps the simulated time" 'd["a"]["simulated_time"] == d["b"]["simulated_time"]'
json_check "--no-motion leaves the motion out" '"motion" not in d["b"]'

# Error 509: the record and the final position show where the axes stopped.
printf 'N0010 S1=4000 M3\nN0020 MTD(30,0,2)=10 MTD(30,0,6)=2.0\nN0030 G1 X100 F1000 ITM\nN0040 M30\n' \
  >"$TEST_TMP/e509.nc"
expect_rc 1 "error 509" --json run "$TEST_TMP/e509.nc"
json_check "509 reported" 'd["diagnostics"][-1]["code"] == "AFC_ERROR_509"'
json_check "record ends where the axes stopped" \
  'd["motion"][-1]["afc_stopped"] and 0 < d["motion"][-1]["end"]["X"] < 10'
json_check "final position is the stop point" \
  'd["final"]["position"]["X"] == d["motion"][-1]["end"]["X"]'
expect_rc 1 "error 509 (text)" run "$TEST_TMP/e509.nc"
text_check "text record marked" "N0030 L3 linear X=3.*stopped"

# One G26 block of 400 mm at F1 (24000 s): stopped after an hour, quickly.
printf 'N0010 S1=4000 M3\nN0020 G1 G26 X400 F1\nN0030 M30\n' >"$TEST_TMP/slow.nc"
expect_rc 1 "absurd duration" --json run "$TEST_TMP/slow.nc"
json_check "AFC_MOVE_TOO_LONG of N0020" \
  'd["diagnostics"][-1]["code"] == "AFC_MOVE_TOO_LONG" and d["diagnostics"][-1]["block"] == "N0020"'
json_check "axes stand at X60" 'abs(d["final"]["position"]["X"] - 60) < 1e-6'
finish
