#!/usr/bin/env bash
# `mtc200-cli verify-restart` (CLI-CONTRACT.md "Extensions", restart.md
# R-028): every demo program of both machines passes with --adjust (the GNE
# program compiled first); the JSON shape of the contract; a program
# directory with an ADJUST that leaves G0 active fails with every target
# listed; usage errors.
source "$(dirname "$0")/common.bash"
demo="$MTC_SOURCE_DIR/resources/programs"

# Every demo program, the label libraries too, with --adjust.
for args in "1" "2" "99" "--process 1 1" "--process 1 99"; do
  # shellcheck disable=SC2086
  expect_rc 0 "verify-restart $args --adjust" verify-restart $args --adjust
  text_check "coverage line ($args)" "^verify-restart: .* of .* targets re-established$"
done
# The lathe's GNE program runs only compiled: its object program (NC blocks
# only) stands in a program directory under the program's name.
mkdir -p "$TEST_TMP/gne" "$TEST_TMP/lathe"
cp "$demo"/N1011002.DAT "$TEST_TMP/gne/"
expect_rc 0 "compile the GNE demo" --process 1 compile "$TEST_TMP/gne/N1011002.DAT"
cp "$demo"/N1011001.DAT "$demo"/N1011099.DAT "$TEST_TMP/lathe/"
cp "$TEST_TMP/gne/N1011002.NCO" "$TEST_TMP/lathe/N1011002.DAT"
expect_rc 0 "verify-restart of the compiled GNE demo" --json --programs "$TEST_TMP/lathe" \
  --process 1 verify-restart 2 --adjust
json_check "every target of the GNE demo" 'd["complete"] and d["targets"] == d["reestablished"] and d["targets"] > 100'
expect_rc 1 "the GNE source itself needs the compiler" --process 1 verify-restart 2 --adjust
text_check "the run stops at the compiler function" "NEEDS_COMPILER"

# JSON shape of the contract.
expect_rc 0 "JSON of the mill demo" --json verify-restart 1 --adjust
json_check "contract keys" 'all(k in d for k in ("status","targets","reestablished","differences","diagnostics"))'
json_check "every target re-established" 'd["status"] == "ok" and d["targets"] == d["reestablished"] and d["targets"] > 100 and d["differences"] == []'
json_check "coverage and completeness" 'd["complete"] is True and d["coverage"].startswith("%d of %d" % (d["reestablished"], d["targets"]))'

# An ADJUST that leaves G0 active after a tool change at clearance height.
mkdir -p "$TEST_TMP/bad"
cat >"$TEST_TMP/bad/N1010099.DAT" <<'EOF'
N0000 M30
N0001 .ADJUST @150=M(2) @151=G(4)
N0002 G53 G0 Z90
N0003 G=@151
N0004 .REPOS G77 S0 M=@150
N0005 G77 X0 Y0 F2000
N0006 G77 Z0 F1000 RTS
EOF
cat >"$TEST_TMP/bad/N1010001.DAT" <<'EOF'
N0001 G0 G54 X10 Y10 Z5 S2000 M3
N0002 G1 Z-2 F300
N0003 X50
N0004 Y40
N0005 G0 Z5
N0006 M30
EOF
expect_rc 1 "an ADJUST that leaves G0" --programs "$TEST_TMP/bad" verify-restart 1 --adjust
text_check "coverage names the targets" "verify-restart: 3 of 6 targets re-established; 3 leave G0 active: N0003, N0004, N0005"
text_check "each difference with its target" "P1 N0004 pass 1 after REPOS: G group 1 (interpolation) expected 1, got 0"
expect_rc 1 "the same as JSON" --json --programs "$TEST_TMP/bad" verify-restart 1 --adjust
json_check "differences of the contract" 'd["status"] == "error" and d["targets"] == 6 and d["reestablished"] == 3 and [(x["target"], x["pass"], x["what"], x["expected"], x["actual"]) for x in d["differences"]] == [("N0003", 1, "g1", 1, 0), ("N0004", 1, "g1", 1, 0), ("N0005", 1, "g1", 1, 0)]'
expect_rc 0 "without --adjust the computing process is right" --programs "$TEST_TMP/bad" verify-restart 1

# Passes: a loop of three passes, only the first two verified.
cat >"$TEST_TMP/loop.nc" <<'EOF'
N0001 @1=3
N0002 .L G1 X=@1 F100
N0003 @1=@1-1 BNE .L
N0004 M30
EOF
expect_rc 0 "--max-passes 2" --json verify-restart "$TEST_TMP/loop.nc" --max-passes 2
json_check "two passes of three" 'd["targets"] == 6 and d["beyond_passes"] == 2 and d["arrivals"] == 8'

# Usage errors.
expect_rc 2 "--max-passes 0" verify-restart 1 --max-passes 0
expect_rc 2 "--max-passes 65537" verify-restart 1 --max-passes 65537
expect_rc 2 "--max-passes belongs to verify-restart" run 1 --max-passes 2
expect_rc 2 "--target belongs to restart" verify-restart 1 --target N0001
expect_rc 2 "no program" verify-restart
expect_rc 2 "two programs" verify-restart 1 2
finish
