#!/usr/bin/env bash
# Adaptive feed control in `mtc200-cli run` (seed 002, issue 15): bad
# B062..B069 values refused with file, line, key, value and range (no
# crash).
source "$(dirname "$0")/common.bash"
cell="$MTC_SOURCE_DIR/resources/machines/demo-cell.cfg"

# B063..B069 out of range or not a number: exit 2 with the line, not SIGSEGV.
for bad in "B065 = 600" "B064 = lots" "B069 = 1.5" "B063 = 13" "B062 = maybe"; do
  sed "s/^B063 = 10 .*/$bad/" "$cell" >"$TEST_TMP/bad.cfg"
  line=$(grep -n "^$bad\$" "$TEST_TMP/bad.cfg" | head -1 | cut -d: -f1)
  key=${bad%% *}
  value=${bad##* }
  printf 'N0010 G1 X10 F100\nN0020 M30\n' >"$TEST_TMP/plain.nc"
  expect_rc 2 "$bad refused" --machine "$TEST_TMP/bad.cfg" run "$TEST_TMP/plain.nc"
  text_check "$bad: file named" "bad.cfg has errors"
  text_check "$bad: key and value named" "$key = '$value'"
  text_check "$bad: line $line" "line $line"
  [ "$key" = B065 ] && text_check "B065: allowed range given" "0.0 ... 500.0 % (minimum machining torque)"
  expect_rc 2 "$bad refused (json)" --json --machine "$TEST_TMP/bad.cfg" run "$TEST_TMP/plain.nc"
  json_check "$bad: CFG_VALUE at line $line" \
    "any(x['code'] == 'CFG_VALUE' and x['line'] == $line and 'allowed' in x['message'] for x in d['diagnostics'])"
done

finish
