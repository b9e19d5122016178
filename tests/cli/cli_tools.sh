#!/usr/bin/env bash
# tools get|set and offsets get|set (issue 16 §4, docs/CLI.md, docs/TOOL-DATA.md):
# the configuration's data first, changes kept atomically beside the machine
# data file, strict refusals that change nothing, run/restart reading the
# files beside --data, a cut-off file refused with file and line.
source "$(dirname "$0")/common.bash"
export XDG_STATE_HOME="$TEST_TMP/state"
data="$TEST_TMP/cell.mdt"

expect_rc 0 "tools get (default location)" tools get
text_check "T1 of the demo mill" "T1 *E1 *3.50000"
expect_rc 0 "tools get --json" --json --data "$data" tools get
json_check "24 tools, T1 length is L3" 'len(d["tools"]) == 24 and d["tools"][0]["edges"][0]["l3"] == 82.5 and d["tools"][0]["name"] == "mill1"'
json_check "file beside the data file" 'd["file"].endswith("/cell.tools")'
expect_rc 0 "lathe tools" --json --process 1 --data "$data" tools get T1
json_check "lathe edge orientation 3, length L2 (radial)" 'd["tools"][0]["edges"][0]["orientation"] == 3 and d["tools"][0]["edges"][0]["l2"] == 61.5 and d["tools"][0]["edges"][0]["l1"] == 0'

expect_rc 0 "add edge E2 to T5" --json --data "$data" tools set T5 E2 radius=0.8 orientation=3 corner_angle=55 setting_angle=93 l1_wear=-0.02
json_check "T5 has two edges" '[e["e"] for e in d["tools"][0]["edges"]] == [1, 2] and d["tools"][0]["edges"][1]["corner_angle"] == 55'
[ -f "$TEST_TMP/cell.tools" ] && pass "cell.tools written" || fail "no cell.tools"
grep -q "^format = mtc200-tools 1$" "$TEST_TMP/cell.tools" && pass "format line" || fail "format line"
records="$(grep -c '^T' "$TEST_TMP/cell.tools")"
[ "$records" -gt 25 ] && grep -q "^end = $records$" "$TEST_TMP/cell.tools" \
    && pass "end line counts the records of every process" || fail "end line ($records records)"
before="$(md5sum "$TEST_TMP/cell.tools")"
expect_rc 1 "negative radius refused" --data "$data" tools set T5 radius=-1
text_check "key, value and range named" "key 'radius' = '-1': out of range (allowed 0 .. 999.99999 mm)"
expect_rc 1 "unknown key refused" --json --data "$data" tools set T5 colour=red
json_check "TOOL_VALUE" 'd["status"] == "error" and d["diagnostics"][0]["code"] == "TOOL_VALUE"'
expect_rc 1 "nan refused" --data "$data" tools set T5 l3=nan
[ "$(md5sum "$TEST_TMP/cell.tools")" = "$before" ] && pass "refusals changed nothing" || fail "file changed"
expect_rc 2 "bad tool word" --data "$data" tools set X5 radius=1
expect_rc 2 "edge out of range" --data "$data" tools set T5 E10 radius=1
expect_rc 1 "delete unknown tool" --data "$data" tools set T99 delete
text_check "TOOL_UNKNOWN" "TOOL_UNKNOWN"
expect_rc 0 "new tool T30" --data "$data" tools set T30 radius=2 l3=100 name=probe
expect_rc 0 "delete edge E2 of T5" --json --data "$data" tools set T5 E2 delete
json_check "T5 back to one edge" 'len(d["tools"][0]["edges"]) == 1'
expect_rc 2 "md options refused" --data "$data" tools get --as nc
expect_rc 2 "no action" tools

# Zero offsets.
expect_rc 0 "offsets get" --json --data "$data" offsets get
json_check "G54 of the demo mill" 'd["offsets"]["G54"] == {"X": -150, "Y": -80, "Z": -120}'
expect_rc 0 "offsets get lathe G55" --json --process 1 --data "$data" offsets get G55
json_check "lathe columns: its axis definitions" 'set(d["offsets"]["G55"]) == {"X", "Y", "Z", "C", "W"} and d["offsets"]["G55"]["X"] == 255.5'
expect_rc 0 "offsets set G54 X" --data "$data" offsets set G54 X=-140.5
expect_rc 1 "offset out of range" --data "$data" offsets set G54 Z=1e9
text_check "OFFSET_VALUE with range" "out of range (allowed -99999.9999 .. 99999.9999"
expect_rc 1 "not a definition" --data "$data" offsets set G54 Q=1
expect_rc 2 "G53 is no settable offset" --data "$data" offsets set G53 X=1

# run and restart use the files beside --data.
prog="$TEST_TMP/offsets.nc"
printf 'N0001 G54 G0 X10 Y0 Z0\nN0002 T30\nN0003 M30\n' > "$prog"
expect_rc 0 "run with the data file" --json --data "$data" run "$prog"
json_check "G54 X from the offsets file" 'd["motion"][0]["end"]["X"] == -130.5'
expect_rc 1 "run without --data: configuration's tools (no T30)" --json run "$prog"
json_check "TOOL_UNKNOWN without the file" 'any(x["code"] == "TOOL_UNKNOWN" for x in d["diagnostics"])'

# A file cut off (no end line) is refused everywhere and not overwritten.
head -n 5 "$TEST_TMP/cell.tools" > "$TEST_TMP/cut.tools"
cp "$TEST_TMP/cut.tools" "$TEST_TMP/cell.tools"
expect_rc 2 "cut-off tools file: get refused" tools get --data "$data"
text_check "file and reason named" "cell.tools:5: no 'end = N' line"
expect_rc 2 "cut-off tools file: set refused" --data "$data" tools set T1 radius=1
cmp -s "$TEST_TMP/cut.tools" "$TEST_TMP/cell.tools" && pass "not overwritten" || fail "overwritten"
expect_rc 2 "cut-off tools file: run refused" --json --data "$data" run "$prog"
json_check "TOOL_FILE" 'd["diagnostics"][0]["code"] == "TOOL_FILE"'

finish
