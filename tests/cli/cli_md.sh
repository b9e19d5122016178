#!/usr/bin/env bash
# md get / md set (CLI-CONTRACT.md, docs/CLI.md): tables and JSON of pages 30,
# 60, 61 and the lathe's user page 180; writes as NC, SPS and operator with
# write protection, password, ranges and data types; exit 1 when the machine
# data refuses, 2 for usage and text in a number; the data file keeps values,
# a damaged file is kept aside with a warning.
source "$(dirname "$0")/common.bash"
export XDG_STATE_HOME="$TEST_TMP/state"
data="$TEST_TMP/cell.mdt"

expect_rc 0 "md get lists the pages" --data "$data" md get
text_check "page list" "30  Adaptive feed control"
expect_rc 0 "md get 30" --data "$data" md get 30
text_check "page 30 table header" "Nr.  Title"
text_check "element 004 default 200 ms" "004  Measuring period idling torque *200 ms"
expect_rc 0 "md get 30 --json" --json --data "$data" md get 30
json_check "page 30 has elements 1..14" '[e["number"] for e in d["subs"][0]["elements"]] == list(range(1, 15))'
json_check "element 1 is protected for everybody" 'd["subs"][0]["elements"][0]["write_protected"] == {"nc": True, "sps": True, "gui": True}'
json_check "element 3 default 0.1 1/s AMPL" 'd["subs"][0]["elements"][2]["value"] == 0.1 and d["subs"][0]["elements"][2]["unit"] == "1/s" and d["subs"][0]["elements"][2]["type"] == "AMPL"'
json_check "every page 30 element has a password" 'all(e["password"] for e in d["subs"][0]["elements"])'

# Writes and their refusals.
expect_rc 1 "operator without password" --data "$data" md set 30 10 55
text_check "password required named" "MTD_PASSWORD_REQUIRED"
expect_rc 1 "wrong password" --data "$data" md set 30 10 55 --password nope
text_check "wrong password named" "MTD_WRONG_PASSWORD"
expect_rc 0 "operator with password" --data "$data" md set 30 10 55.55 --password MTC200
text_check "old and new value, rounded to PERC" "0.0 -> 55.6 %"
expect_rc 1 "status element refused for NC" --data "$data" md set 30 7 12 --as nc
text_check "write protection named" "MTD_WRITE_PROTECTED"
expect_rc 1 "status element refused for SPS" --json --data "$data" md set 30 11 12 --as sps
json_check "refusal JSON" 'd["status"] == "error" and d["diagnostics"][0]["code"] == "MTD_WRITE_PROTECTED"'
expect_rc 1 "out of range" --data "$data" md set 30 13 100.5 --as sps
text_check "range and old value told" "0.0..100.0 %; the value stays 0.0"
expect_rc 1 "whole number expected" --data "$data" md set 30 2 1.5 --as nc
text_check "type named" "MTD_WRONG_TYPE"
expect_rc 2 "text in a numeric field" --data "$data" md set 30 2 ten --as nc
text_check "text named" "VALUE 'ten' is not a number"
expect_rc 2 "text as element" --data "$data" md set 30 x 1
expect_rc 1 "unknown page" --data "$data" md set 31 1 1
text_check "unknown page named" "MTD_UNKNOWN_PAGE"
expect_rc 1 "unknown element" --data "$data" md set 30 15 1 --as nc
text_check "unknown element named" "MTD_UNKNOWN_ELEMENT"
expect_rc 1 "unknown page for get" --data "$data" md get 180
expect_rc 2 "bad writer" --data "$data" md set 30 2 1 --as robot
expect_rc 2 "md options outside md" --data "$data" check 1
expect_rc 2 "md without action" md
expect_rc 2 "set without value" --data "$data" md set 30 2

# Page 61 needs its sub; page 60 and the lathe's page 180.
expect_rc 2 "page 61 without --sub" --data "$data" md set 61 1 68 --as nc
expect_rc 0 "page 61 sub 2" --data "$data" md set 61 40 9501 --sub 2 --as nc
expect_rc 0 "page 60 T number without password" --data "$data" md set 60 5 12
expect_rc 1 "page 60 transformation 33" --data "$data" md set 60 4 33 --as nc
expect_rc 0 "lathe page 180" --process 1 --data "$data" md set 180 2 612.25 --as sps

# Everything that was accepted is kept in the data file, per process.
expect_rc 0 "values kept" --json --data "$data" md get 30
json_check "element 10 kept, element 13 unchanged" 'd["subs"][0]["elements"][9]["value"] == 55.6 and d["subs"][0]["elements"][12]["value"] == 0'
expect_rc 0 "page 61 kept" --json --data "$data" md get 61
json_check "Q buffer element 40" 'd["subs"][1]["elements"][39]["value"] == 9501 and d["subs"][1]["title"] == "Q functions"'
expect_rc 0 "md get 61 --sub 2 shows only the Q buffer" --json --data "$data" md get 61 --sub 2
json_check "one sub, the Q buffer" '[s["sub"] for s in d["subs"]] == [2] and d["subs"][0]["elements"][39]["value"] == 9501'
expect_rc 0 "md get 61 --sub 1 as text" --data "$data" md get 61 --sub 1
text_check "sub 1 title" "sub 1: "
if printf '%s' "$OUT" | grep "sub 2: " >/dev/null; then fail "text shows sub 2 too"; else pass "text shows sub 1 only"; fi
expect_rc 2 "md get 61 --sub 3 does not exist" --data "$data" md get 61 --sub 3
text_check "sub range told" "has no sub 3 (1..2)"
expect_rc 2 "md get 30 has no sub-pages" --data "$data" md get 30 --sub 1
expect_rc 2 "--sub without PAGE" --data "$data" md get --sub 1
expect_rc 2 "--as still belongs to md set" --data "$data" md get 61 --as nc
expect_rc 0 "lathe value kept" --json --process 1 --data "$data" md get 180
json_check "page 180 element 2" 'd["subs"][0]["elements"][1]["value"] == 612.25'
expect_rc 0 "other process untouched" --json --process 1 --data "$data" md get 30
json_check "process 1 element 10 default" 'd["subs"][0]["elements"][9]["value"] == 0'

# A damaged file: kept aside, defaults, the user told; the next set saves anew.
head -c 300 "$data" >"$TEST_TMP/cut" && cp "$TEST_TMP/cut" "$data"
expect_rc 0 "truncated file still answers" --json --data "$data" md get 30
json_check "damage reported" 'd["diagnostics"][0]["code"] == "MD_FILE_DAMAGED" and d["diagnostics"][0]["severity"] == "warning"'
json_check "defaults loaded" 'd["subs"][0]["elements"][9]["value"] == 0'
if ls "$data".damaged-* >/dev/null 2>&1 && cmp -s "$TEST_TMP/cut" "$(ls "$data".damaged-* | head -1)"; then
  pass "damaged file kept aside unchanged"
else
  fail "damaged file kept aside unchanged"
fi
expect_rc 0 "set after damage" --data "$data" md set 30 2 10 --as nc
expect_rc 0 "no warning any more" --json --data "$data" md get 30
json_check "new file sound" 'd["diagnostics"] == [] and d["subs"][0]["elements"][1]["value"] == 10'
printf 'garbage\n' >"$data"
expect_rc 0 "garbage file" --data "$data" md get 60
text_check "garbage told on stderr" "is damaged"

# Default location and no file at all.
expect_rc 0 "default data file in XDG_STATE_HOME" md set 60 6 77
expect_rc 0 "default file read back" --json md get 60
json_check "default location used" 'd["data_file"].startswith("'"$TEST_TMP"'/state/mtc200/machine-data/") and d["subs"][0]["elements"][5]["value"] == 77'
expect_rc 0 "--data - keeps nothing" --json --data - md set 60 6 5
json_check "not saved" 'd["saved"] == False and d["data_file"] is None'
expect_rc 2 "data file in a missing directory" --data "$TEST_TMP/none/x/../y.mdt" md set 60 6 5
text_check "not saved told" "NOT saved"
finish
