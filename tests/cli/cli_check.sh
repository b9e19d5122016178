#!/usr/bin/env bash
# `mtc200-cli check`: several programs, numbers and paths, exit codes 0/1/2,
# diagnostics with program, block, line and column, JSON shape.
source "$(dirname "$0")/common.bash"
programs="$MTC_SOURCE_DIR/resources/programs"

expect_rc 0 "demo programs by path" check "$programs"/N1010001.DAT "$programs"/N1010099.DAT \
  "$programs"/N1011001.DAT "$programs"/N1011099.DAT
text_check "text summary" "check: ok"
expect_rc 0 "mill programs by number" check 1 99
expect_rc 0 "lathe programs by number" --process 1 check 1 99
expect_rc 0 "demo directory given explicitly" --programs "$programs" check 1

expect_rc 0 "JSON of several programs" --json check 1 99
json_check "check JSON keys" 'd["status"] == "ok" and d["diagnostics"] == [] and len(d["programs"]) == 2'
json_check "program entries" '[p["program"] for p in d["programs"]] == [1, 99] and all(p["blocks"] > 10 and p["errors"] == 0 for p in d["programs"])'

cat >"$TEST_TMP/bad.nc" <<'NC'
N0000 G1 X10 F500
N0001 G1 X20 ?? Y5
N0002 BSR .NOWHERE
N0003 M30
NC
expect_rc 1 "program with errors" --json check "$TEST_TMP/bad.nc"
json_check "status error" 'd["status"] == "error" and len(d["diagnostics"]) >= 2'
json_check "bad word located" 'any(x["block"] == "N0001" and x["line"] == 2 and x["column"] > 0 and x["severity"] == "error" for x in d["diagnostics"])'
json_check "missing label located" 'any(x["code"] == "PROGRAM_LABEL_MISSING" and x["block"] == "N0002" and x["line"] == 3 for x in d["diagnostics"])'
json_check "diagnostic keys" 'all(all(k in x for k in ("severity","code","program","block","line","column","message","details")) for x in d["diagnostics"])'

expect_rc 1 "errors in one of several programs" check 1 "$TEST_TMP/bad.nc"
expect_rc 2 "a missing program among good ones" --json check 1 "$TEST_TMP/missing.nc" 99
json_check "the others are still checked" 'len(d["programs"]) == 3 and d["programs"][0]["found"] and not d["programs"][1]["found"] and d["programs"][2]["found"]'

# Hostile input: diagnostics, never a crash or a hang.
head -c 20000 /dev/urandom >"$TEST_TMP/garbage.nc"
cli check "$TEST_TMP/garbage.nc"
if [ "$RC" = 1 ] || [ "$RC" = 0 ]; then pass "binary garbage (exit $RC)"; else fail "binary garbage"; fi
cli --json check "$TEST_TMP/garbage.nc"
json_check "garbage gives valid JSON" 'd["status"] in ("ok", "error")'
{ printf 'iMTc/test/N1010042.DAT\n%%NPG:1:01:0:042\n!01.00\n*long line\n%%NPG\n'
  printf 'N0000 G1 X1 F100 ;%s\n' "$(printf '%054d' 0)"
  printf 'N0001 M30\nN0002 PROGRAMMENDE\n'; } >"$TEST_TMP/N1010042.DAT"
expect_rc 1 "72-character line in a .DAT file" --json check "$TEST_TMP/N1010042.DAT"
json_check "long line located" 'any(x["line"] == 6 and x["severity"] == "error" for x in d["diagnostics"])'
: >"$TEST_TMP/empty.nc"
cli check "$TEST_TMP/empty.nc"
if [ "$RC" -le 1 ]; then pass "empty file (exit $RC)"; else fail "empty file"; fi
finish
