#!/usr/bin/env bash
# Numbers under a German locale (issue 20 §2, D-013): with LC_ALL=de_DE.UTF-8
# machine data, tool data, zero offsets and a program's values round-trip
# exactly through mtc200-cli, the files keep '.', a decimal comma is refused.
source "$(dirname "$0")/common.bash"
if ! locale -a 2>/dev/null | grep -qi '^de_DE\.utf-\?8$'; then
  echo "SKIP: locale de_DE.UTF-8 is not installed (scripts/setup.sh installs it)"
  exit 0
fi
export LC_ALL=de_DE.UTF-8
[ "$(locale decimal_point)" = "," ] && pass "the locale's decimal point is a comma" \
  || fail "de_DE.UTF-8 does not switch the decimal point"
export XDG_STATE_HOME="$TEST_TMP/state"
data="$TEST_TMP/cell.mdt"

# Machine data: SPS value with decimals, an operator value rounded to its type.
expect_rc 0 "md set 180 2 612.25" --process 1 --data "$data" md set 180 2 612.25 --as sps
expect_rc 0 "md set 30 10 with decimals" --data "$data" md set 30 10 12.75 --password MTC200
expect_rc 0 "md get 180 --json" --json --process 1 --data "$data" md get 180
json_check "612.25 read back" 'd["subs"][0]["elements"][1]["value"] == 612.25'
expect_rc 0 "md get 30 --json" --json --data "$data" md get 30
json_check "12.8 (PERC, one decimal) read back" 'd["subs"][0]["elements"][9]["value"] == 12.8'
expect_rc 0 "md get 30 table" --data "$data" md get 30
text_check "table shows 12.8 with a point" " 12\.8 "
grep -q '^1 180 0 2 612\.25$' "$data" && pass "data file line with '.'" || fail "data file: $(grep ' 180 ' "$data")"
grep -q '[0-9],[0-9]' "$data" && fail "a decimal comma in the data file" || pass "no decimal comma in the data file"
expect_rc 2 "decimal comma refused" --process 1 --data "$data" md set 180 2 612,5 --as sps

# Tool data and zero offsets.
expect_rc 0 "tools set with decimals" --data "$data" tools set T5 radius=0.4 l3=82.125 l1_wear=-0.012
expect_rc 0 "tools get T5 --json" --json --data "$data" tools get T5
json_check "T5 radius, l3, l1_wear exact" 'd["tools"][0]["edges"][0]["radius"] == 0.4 and d["tools"][0]["edges"][0]["l3"] == 82.125 and d["tools"][0]["edges"][0]["l1_wear"] == -0.012'
expect_rc 0 "tools get T5" --data "$data" tools get T5
text_check "tool table with points" "0\.40000"
grep -q 'radius=0\.4 ' "$TEST_TMP/cell.tools" && pass "tools file keeps '.'" || fail "tools file: $(grep '^T5' "$TEST_TMP/cell.tools")"
expect_rc 1 "tool decimal comma refused" --data "$data" tools set T5 radius=0,5
expect_rc 0 "offsets set G54 X=-140.5" --data "$data" offsets set G54 X=-140.5 Y=0.125
expect_rc 0 "offsets get --json" --json --data "$data" offsets get G54
json_check "G54 exact" 'd["offsets"]["G54"]["X"] == -140.5 and d["offsets"]["G54"]["Y"] == 0.125'

# A program's values, in the motion records and the text output.
prog="$TEST_TMP/values.nc"
printf 'N0001 G1 G90 X12.345 Y-0.5 F1500.5\nN0002 @1=2.25\nN0003 X@1 Y7.125\nN0004 M30\n' > "$prog"
expect_rc 0 "run --json" --json run "$prog"
json_check "end points and feed exact" 'd["motion"][0]["end"]["X"] == 12.345 and d["motion"][0]["end"]["Y"] == -0.5 and d["motion"][0]["feed"] == 1500.5 and d["motion"][1]["end"]["X"] == 2.25 and d["motion"][1]["end"]["Y"] == 7.125'
expect_rc 0 "run (text)" run "$prog"
printf '%s' "$OUT" | grep -q '[0-9],[0-9]' && fail "a decimal comma in the run output" || pass "run output uses '.'"
finish
