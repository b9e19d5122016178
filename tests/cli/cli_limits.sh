#!/usr/bin/env bash
# Programmed numbers never drive a loop, a buffer or a simulated duration
# (issue 15 §1): huge CF/RD values are refused at once by compile and check,
# a roughing that would need millions of passes is refused, extreme values
# elsewhere end quickly. Every call is bounded by the 60 s of `cli`; each
# takes milliseconds now (the CF 1e23 compile never ended before).
source "$(dirname "$0")/common.bash"

for value in 100000000000000000000000 1E40 1e308 '=1e23'; do
  for kind in CF RD; do
    printf 'N0001 G1 G17 G90 X0 Y0 F1000\nN0002 X10 %s%s\nN0003 Y10\nN0004 M30\n' "$kind" "$value" >"$TEST_TMP/huge.nc"
    expect_rc 1 "compile $kind$value ends and refuses" --json compile "$TEST_TMP/huge.nc"
    json_check "$kind$value: COMPILER_CFRD_VALUE at N0002 line 2" 'd["diagnostics"][0]["code"] == "COMPILER_CFRD_VALUE" and d["diagnostics"][0]["block"] == "N0002" and d["diagnostics"][0]["line"] == 2'
    expect_rc 1 "check $kind$value ends and refuses" check "$TEST_TMP/huge.nc"
  done
done

# the largest value the NC writes is reduced as any other (a warning)
printf 'N0001 G1 G17 G90 X0 Y0 F1000\nN0002 X10 RD99999.9999\nN0003 Y10\nN0004 M30\n' >"$TEST_TMP/max.nc"
expect_rc 0 "RD99999.9999 is reduced" compile "$TEST_TMP/max.nc"
text_check "reduced with a warning" "COMPILER_CFRD_REDUCED"

# GNE roughing: 1e6 mm of blank at a depth of 0.01 mm
printf 'N0001 WINDOW_01 (-48, 2, 1000000)\nN0002 CONT (2)\nN0003 START Z0 X0\nN0004 LINE Z0 X12\nN0005 LINE Z-48 X12\nN0006 END_CONT\nN0007 CYCLE_11 (2, 1, 0.3, , , 0, , , 1, 0.01, 0.5, 0.2)\nN0008 M30\n' >"$TEST_TMP/rough.nc"
expect_rc 1 "roughing with 1e8 passes is refused" check "$TEST_TMP/rough.nc"
text_check "the cycle says why" "more than 2000 passes"

# contour values beyond the GNE's range
printf 'N0001 WINDOW_01 (-48, 2, 40)\nN0002 CONT (2)\nN0003 START Z0 X0\nN0004 LINE Z-1000000000000000000000000000000000000 X12\nN0005 END_CONT\nN0006 M30\n' >"$TEST_TMP/far.nc"
expect_rc 1 "a GNE value of 1e36 is refused" check "$TEST_TMP/far.nc"
text_check "at its line" "GNE_BAD_NUMBER"

# interpreter: dwell, arcs, variables and counters at the extremes end quickly
printf 'N0001 G4 F1e308\nN0002 @1=1e308*10\nN0003 @2=1e-300/1e300\nN0004 G1 X@2 F1\nN0005 M30\n' >"$TEST_TMP/interp.nc"
cli --json run "$TEST_TMP/interp.nc" --no-motion
if [ "$RC" = 0 ] || [ "$RC" = 1 ]; then pass "extreme interpreter values end (exit $RC)"; else fail "extreme interpreter values"; fi
printf 'N0001 @1=0\nN0002 .L @1=@1+1 BRA .L\n' >"$TEST_TMP/loop.nc"
expect_rc 1 "an endless counter loop stops at the block bound" run "$TEST_TMP/loop.nc" --no-motion --max-blocks 100000
text_check "named" "BLOCK_BUDGET"
finish
