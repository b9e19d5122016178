#!/usr/bin/env bash
# Smaller defects of issue 22 §6 as a user meets them on the command line:
# a byte-identical copy of a demo program under another file name restarts
# like the original; `check` refuses a macro that names a later macro as
# `compile` does, naming the macros; a lexical error of a source block is
# named by compile, not only "Compiled block too long".
source "$(dirname "$0")/common.bash"

# Restart of a copy: the program is the number of its %NPG header.
cp "$MTC_SOURCE_DIR/resources/programs/N1010001.DAT" "$TEST_TMP/copy of the demo.DAT"
expect_rc 0 "restart of a renamed copy" --json restart "$TEST_TMP/copy of the demo.DAT" --target N0033
json_check "the copy restarts at its target" 'd["status"] == "ok" and d["target"]["block"] == "N0033"'
cli --json restart 1 --target N0033
original="$OUT"
cli --json restart "$TEST_TMP/copy of the demo.DAT" --target N0033
[ "$(printf '%s' "$OUT" | grep -v '"file"')" = "$(printf '%s' "$original" | grep -v '"file"')" ] \
  && pass "the copy gives the original's restart" || fail "the copy's restart differs from the original's"

# A macro naming a macro defined after it: check and compile agree.
printf '%s\n' '%NPG 1 M 7 "MACRO ORDER"' 'N0000 DEFINE FIRST AS G1 SECOND' 'N0001 DEFINE SECOND AS X10 F100' \
  'N0002 G0 X0 Y0' 'N0003 FIRST' 'N0004 M30' 'N0005 PROGRAMMENDE' >"$TEST_TMP/N1010007.DAT"
expect_rc 1 "check refuses a macro naming a later one" check "$TEST_TMP/N1010007.DAT"
text_check "check names both macros" "FIRST uses SECOND"
expect_rc 1 "compile refuses it the same way" compile "$TEST_TMP/N1010007.DAT"
text_check "compile names both macros" "FIRST uses SECOND"
if grep -q "'MAC'" "$TEST_TMP/N1010007.ERR" 2>/dev/null; then fail "the error file names a word not in the source"; else pass "no word that is not in the source"; fi

# A NUL byte in a block: the lexical error is named.
printf 'N0000 G1 X1 F100\nN0001 G1 X\0002\nN0002 M30\n' >"$TEST_TMP/N1010008.DAT"
cli compile "$TEST_TMP/N1010008.DAT"
[ "$RC" = 1 ] && pass "compile of a NUL byte fails (exit 1)" || fail "compile of a NUL byte: exit $RC"
if printf '%s\n%s' "$OUT" "$ERR" | grep -v "too long" | grep -qi "line 2"; then
  pass "the NUL byte's line is named by an error other than the length"
else fail "only 'Compiled block too long'"; fi

finish
