#!/usr/bin/env bash
# --machine and --process: a bad machine file or a missing process is a file
# error (exit 2); process 1 runs the lathe demo.
source "$(dirname "$0")/common.bash"
cell="$MTC_SOURCE_DIR/resources/machines/demo-cell.cfg"

printf '[cell]\nname = broken\n[process 0 axis X]\nkind = banana\n' >"$TEST_TMP/bad.cfg"
expect_rc 2 "invalid machine file" --machine "$TEST_TMP/bad.cfg" run 1
text_check "invalid machine named" "CLI_MACHINE_INVALID"
expect_rc 2 "invalid machine file with --json" --json --machine "$TEST_TMP/bad.cfg" check 1
json_check "machine diagnostics" 'd["status"] == "error" and d["diagnostics"][0]["code"] == "CLI_MACHINE_INVALID" and len(d["diagnostics"]) >= 2'
expect_rc 2 "missing machine file" --machine "$TEST_TMP/none.cfg" run 1
expect_rc 2 "process that the cell does not have" --process 5 run 1
text_check "missing process named" "process 5 does not exist"

expect_rc 0 "demo cell given as a file" --machine "$cell" run --no-motion 1
expect_rc 0 "lathe: --process 1" --json --process 1 run 1
json_check "lathe final position has lathe axes" '"Z2" in d["final"]["position"] and "X" in d["final"]["position"]'
json_check "lathe spindles" 'all(k.startswith("S") for k in d["final"]["s"])'
finish
