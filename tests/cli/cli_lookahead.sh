#!/usr/bin/env bash
# `mtc200-cli compile` with the enhanced look-ahead (seed 001 ch. 6): sub-blocks
# with enhanced block numbers in the .NCO (demo cell limits), errors in the .ERR.
source "$(dirname "$0")/common.bash"

cat >"$TEST_TMP/N0010071.DAT" <<'NC'
N0000 G0 G17 G90 X0 Y0 Z0
N0001 METB=5 VFBT=2
N0002 LA_ON
N0003 G1 X300 F24000
N0004 Y2
N0005 LA_OFF
N0006 G0 X0 Y0
NC
expect_rc 0 "look-ahead program compiles" compile "$TEST_TMP/N0010071.DAT" -o "$TEST_TMP/ok.NCO"
OUT="$(cat "$TEST_TMP/ok.NCO" 2>/dev/null)"
text_check "first sub-block of the long block" "^N0003:0001 G1 X"
text_check "programmed end point kept" "^N0003:0[0-9]* G1 X300 F"
text_check "source F restored at LA_OFF" "^N0005:0000 G1 F24000"
text_check "no look-ahead keyword left" "^N0002:0000$"
# F never above the programmed 24000 and never above X's 30000 of the demo cell.
if printf '%s\n' "$OUT" | grep -o 'F[0-9.]*' | tr -d F | awk '$1 > 24000 { bad = 1 } END { exit bad }'; then
  pass "F within the programmed feed"
else
  fail "F above the programmed feed"
fi

cat >"$TEST_TMP/N0010072.DAT" <<'NC'
N0000 G0 X0 Y0
N0001 LA_ON
N0002 G1 X10 F1000 M8
N0003 G1 X@4
NC
expect_rc 1 "look-ahead errors" compile "$TEST_TMP/N0010072.DAT" -o "$TEST_TMP/bad.NCO"
OUT="$(cat "$TEST_TMP/bad.ERR" 2>/dev/null)"
text_check ".ERR names the forbidden word" "M8 not allowed in LA segment"
text_check ".ERR block of the variable end point" "^N0003:"
text_check ".ERR missing LA_OFF" "LA_ON without LA_OFF"
finish
