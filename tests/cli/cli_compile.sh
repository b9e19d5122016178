#!/usr/bin/env bash
# `mtc200-cli compile` (CLI-CONTRACT.md): .NCO written for good programs,
# .ERR (and no .NCO) for programs with errors, -o, --json, exit codes, the
# golden object/error files byte for byte with a fixed stamp, user
# compilers, and `check` compiling programs with compiler keywords.
source "$(dirname "$0")/common.bash"
golden="$MTC_GOLDEN/compiler"
export SOURCE_DATE_EPOCH=1700000000   # 14.11.2023 22:13:20 UTC in the identification

cp "$golden/N0010001.DAT" "$TEST_TMP/"
expect_rc 0 "compile a program with chamfers and roundings" compile "$TEST_TMP/N0010001.DAT"
text_check "text summary" "compile: ok, 19 blocks (6 inserted)"
if [ -f "$TEST_TMP/N0010001.NCO" ] && [ ! -f "$TEST_TMP/N0010001.ERR" ]; then
  pass "object file next to the source, no error file"
else fail "object file next to the source"; fi
if tail -n +2 "$TEST_TMP/N0010001.NCO" | cmp -s - <(tail -n +2 "$golden/N0010001.NCO"); then
  pass "object file equals the golden file below the identification"
else fail "object file differs from $golden/N0010001.NCO"; fi
ident="$(head -1 "$TEST_TMP/N0010001.NCO")"
size="$(stat -c %s "$TEST_TMP/N0010001.NCO")"
if [ "$ident" = "iMTc/000101/01.00/$(printf '%010d' "$size")/14.11.2023/22:13:20/N0010001.NCO/1" ]; then
  pass "identification updated (size, stamp, name)"
else fail "identification: $ident (size $size)"; fi

cli --json compile "$TEST_TMP/N0010001.DAT" -o "$TEST_TMP/renamed.NCO"
json_check "compile JSON" 'd["status"] == "ok" and d["compile_status"] == "C" and d["object_file"].endswith("renamed.NCO") and d["blocks"] == 19 and d["intermediate_blocks"] == 6 and d["error_file"] == ""'
[ -f "$TEST_TMP/renamed.NCO" ] && pass "renamed object written" || fail "renamed object written"

# the interpreter accepts every inserted arc (radius check 0.002 mm) and line
cp "$golden/N0010002.DAT" "$golden/N0010006.DAT" "$TEST_TMP/"
for p in N0010001 N0010002 N0010006; do
  [ -f "$TEST_TMP/$p.NCO" ] || cli compile "$TEST_TMP/$p.DAT"
  expect_rc 0 "compiled $p runs in the simulator" --json run "$TEST_TMP/$p.NCO" --no-motion
  json_check "compiled $p runs without diagnostics" 'd["status"] == "ok" and d["diagnostics"] == []'
done

cp "$golden/N0010005.DAT" "$TEST_TMP/"
: >"$TEST_TMP/N0010005.NCO"   # a stale object file must go
expect_rc 1 "program with compiler errors" --json compile "$TEST_TMP/N0010005.DAT"
json_check "errors as diagnostics" 'd["status"] == "error" and d["compile_status"] == "E" and d["object_file"] == "" and d["error_file"].endswith("N0010005.ERR")'
json_check "block, line and code of the first error" 'd["diagnostics"][0]["block"] == "N0001" and d["diagnostics"][0]["line"] == 7 and d["diagnostics"][0]["code"] == "COMPILER_CFRD_VALUE"'
json_check "diagnostic keys" 'all(all(k in x for k in ("severity","code","program","block","line","message","details")) for x in d["diagnostics"])'
[ ! -f "$TEST_TMP/N0010005.NCO" ] && pass "no object file after errors" || fail "stale object file removed"
if tail -n +2 "$TEST_TMP/N0010005.ERR" | cmp -s - <(tail -n +2 "$golden/N0010005.ERR"); then
  pass "error file equals the golden file"
else fail "error file differs from $golden/N0010005.ERR"; fi
head -1 "$TEST_TMP/N0010005.ERR" | grep '/N0010005.ERR/1$' >/dev/null && pass "error file identification" || fail "error file identification"

cp "$golden/N0010006.DAT" "$TEST_TMP/"
expect_rc 0 "warnings only: compiled" compile "$TEST_TMP/N0010006.DAT"
text_check "warning listed" "COMPILER_CFRD_REDUCED"
[ -f "$TEST_TMP/N0010006.NCO" ] && [ ! -f "$TEST_TMP/N0010006.ERR" ] && pass "object file, no error file for warnings (C-014)" || fail "object file, no error file for warnings"

# user compiler 1 rewrites a keyword of its own before the INDRAMAT compiler
printf 'N0001 G1 X0 Y0 F100\nN0002 X10 CORNER\nN0003 Y10\n' >"$TEST_TMP/user.nc"
expect_rc 0 "user compiler before the INDRAMAT compiler" compile "$TEST_TMP/user.nc" \
  --user-compiler "1=sh -c 'sed s/CORNER/RD1/ \"\$0\" > \"\$1\"'"
grep -q "^N0002:0001 G3 X10 Y1 I9 J1$" "$TEST_TMP/user.NCO" && pass "user compiler output compiled" || fail "user compiler output compiled"
expect_rc 1 "failing user compiler" --json compile "$TEST_TMP/N0010001.DAT" -o "$TEST_TMP/after.NCO" --user-compiler "3=false"
json_check "user compiler failure" 'd["diagnostics"][0]["code"] == "USER_COMPILER_FAILED" and d["diagnostics"][0]["block"] == "A0001"'

expect_rc 2 "no program" compile
expect_rc 2 "two programs" compile "$TEST_TMP/user.nc" "$TEST_TMP/user.nc"
expect_rc 2 "missing file" compile "$TEST_TMP/none.DAT"
expect_rc 2 "-o only for compile" check 1 -o x.NCO
expect_rc 2 "bad user compiler slot" compile "$TEST_TMP/user.nc" --user-compiler "5=true"

# check compiles programs with compiler keywords
expect_rc 1 "check reports compiler errors" --json check "$TEST_TMP/N0010005.DAT"
json_check "check has COMPILER_ codes" 'any(x["code"] == "COMPILER_CFRD_NO_TARGET" and x["block"] == "N0020" for x in d["diagnostics"])'
expect_rc 0 "check of a compilable program" check "$TEST_TMP/N0010001.DAT"

# global macros of the NC options: GLOBAL_MACROS.MAC of --programs (GM-005)
mkdir -p "$TEST_TMP/gm"
printf 'N0000 G0 G17 G90 X0 Y0\nN0001 G1 F500 X10\nN0002 SLOTFEED Y20\nN0003 M30\n' >"$TEST_TMP/gm/N0010007.DAT"
printf 'N0000 G0 X0\nN0001 NOSUCHMAC Y20\nN0002 M30\n' >"$TEST_TMP/gm/N0010008.DAT"
printf '; NC options\nDEFINE SLOTFEED AS F250 G1\nDEFINE 1BAD AS X1\n' >"$TEST_TMP/gm/GLOBAL_MACROS.MAC"
expect_rc 0 "compile with a global macro" compile --programs "$TEST_TMP/gm" 7
grep -q "^N0002:0000 F250 G1 Y20$" "$TEST_TMP/gm/N0010007.NCO" && pass "global macro expanded in the object" || fail "global macro expanded in the object"
text_check "refused macro line named" "GLOBAL_MACRO_REFUSED"
expect_rc 0 "check accepts a global macro name" check --programs "$TEST_TMP/gm" 7
expect_rc 1 "check still refuses an unknown word" check --programs "$TEST_TMP/gm" 8
text_check "unknown word named" "NOSUCHMAC"
expect_rc 1 "run of a source with a global macro asks for the compiler" run --programs "$TEST_TMP/gm" 7 --no-motion
text_check "global macro use is a compiler function at run time" "NEEDS_COMPILER"
text_check "the message names the macro, not the rest of its block" "'SLOTFEED' needs the NC compiler"
if printf '%s\n%s' "$OUT" "$ERR" | grep -q "SLOTFEED Y20"; then fail "block text left out of the message"
else pass "block text left out of the message"; fi
cli --json run --programs "$TEST_TMP/gm" 7 --no-motion
json_check "one line, no detail lines (it is the panel's alarm)" '[(x["details"], x["message"].split(chr(39))[1]) for x in d["diagnostics"] if x["code"] == "NEEDS_COMPILER"] == [([], "SLOTFEED")]'

# one rule (C-015): check fails where compile fails, GNE and look-ahead included
printf 'N0001 WINDOW_01 (-40, 2, 30)\nN0002 CYCLE_10 (7, 1, 0.2)\nN0003 M30\n' >"$TEST_TMP/gne_bad.nc"
expect_rc 1 "compile of a GNE program with an error" compile "$TEST_TMP/gne_bad.nc"
expect_rc 1 "check of the same program fails too" --json check "$TEST_TMP/gne_bad.nc"
json_check "check names the GNE error" 'any(x["code"] == "GNE_NO_GEOMETRY" and x["block"] == "N0002" for x in d["diagnostics"])'
printf 'N0001 G0 G17 G90 X0 Y0\nN0002 LA_ON\nN0003 G1 X10 F1000\nN0004 G0 X20\nN0005 LA_OFF\nN0006 M30\n' >"$TEST_TMP/la_bad.nc"
expect_rc 1 "compile of a look-ahead program with an error" compile "$TEST_TMP/la_bad.nc"
expect_rc 1 "check of the same program fails too" check "$TEST_TMP/la_bad.nc"
text_check "check names the look-ahead error" "LA_COMMAND_NOT_ALLOWED"
# lines over 71 characters: compile refuses what check refuses (seed 001 ch. 10)
{ head -5 "$golden/N0010001.DAT"; printf 'N0001 G1 G17 G90 X0 Y0 F1000\nN0002 X10 CF1 ;%s\nN0003 Y10\nN0004 M30\nN0005 PROGRAMMENDE\n' "$(printf 'a%.0s' $(seq 60))"; } >"$TEST_TMP/N0010009.DAT"
expect_rc 1 "check refuses a line of 76 characters" check "$TEST_TMP/N0010009.DAT"
expect_rc 1 "compile refuses it too" --json compile "$TEST_TMP/N0010009.DAT"
json_check "at its block and line" 'd["diagnostics"][0]["code"] == "FILE_LINE_TOO_LONG" and d["diagnostics"][0]["block"] == "N0002" and d["diagnostics"][0]["line"] == 7'

# compiler off (run takes the source): a keyword refuses the program before
# any block moves, at its block (seed 001 ch. 7, C-016)
printf 'N0001 G1 G17 G90 X0 Y0 F1000\nN0002 X10\nN0003 Y10 RD2\nN0004 X0\nN0005 M30\n' >"$TEST_TMP/late_rd.nc"
expect_rc 1 "run of a source with a late RD" --json run "$TEST_TMP/late_rd.nc"
json_check "refused at N0003 before any motion" 'd["diagnostics"][0]["code"] == "NEEDS_COMPILER" and d["diagnostics"][0]["block"] == "N0003" and d["motion_count"] == 0'

# hostile input: never a crash or a hang
head -c 20000 /dev/urandom >"$TEST_TMP/garbage.DAT"
cli compile "$TEST_TMP/garbage.DAT"
if [ "$RC" = 1 ] || [ "$RC" = 0 ]; then pass "binary garbage (exit $RC)"; else fail "binary garbage"; fi

finish
