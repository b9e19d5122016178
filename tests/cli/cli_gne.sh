#!/usr/bin/env bash
# The GNE demo (CONT contour + CYCLE_11/CYCLE_10) compiles into NC blocks
# with enhanced block numbers, and the object program runs on the lathe.
# A GNE error is reported at its block and line.
source "$(dirname "$0")/common.bash"
cp "$MTC_SOURCE_DIR/resources/programs/N1011002.DAT" "$TEST_TMP/"

expect_rc 0 "GNE demo compiles" compile "$TEST_TMP/N1011002.DAT"
nco="$TEST_TMP/N1011002.NCO"
if [ -f "$nco" ] && grep -q '^N0018:0001 G90 G18 G40 G15' "$nco" &&
   grep -q '^N0019:[0-9]\{4\} G2 X.* I.* K' "$nco" && grep -q '^N0005:0000 ;START Z0 X0' "$nco"; then
  pass "cycles expanded into intermediate blocks, geometry kept as comments"
else
  fail "object program of the GNE demo"
fi
expect_rc 0 "compiled GNE demo runs on the lathe" --process 1 run "$nco"
text_check "run ended" "run: ended after"

sed 's/^N0012 LINE A180 L6$/N0012 LINE A180/' "$TEST_TMP/N1011002.DAT" >"$TEST_TMP/N1011003.DAT"
sed -i 's/N1011002/N1011003/; s/:002$/:003/' "$TEST_TMP/N1011003.DAT"
cli compile "$TEST_TMP/N1011003.DAT"
if [ "$RC" != 0 ] && printf '%s\n%s' "$OUT" "$ERR" | grep "GNE_UNDERDETERMINED" >/dev/null; then
  pass "under-determined element refused (exit $RC)"
else
  fail "under-determined element not reported"
fi
text_check "error names the block" "N0012"
finish
