#!/usr/bin/env bash
# `mtc200-cli restart` (CLI-CONTRACT.md): golden transcripts of
# tests/golden/restart (every rule of the NC program restart with programs of
# our own), the JSON shape, the text output, and the usage errors (exit 2).
# Regenerate the transcripts on purpose with scripts/update-golden.sh restart.
source "$(dirname "$0")/common.bash"
source "$(dirname "$0")/restart_golden.bash"
dir="$MTC_GOLDEN/restart"

cases=0
for args in "$dir"/*.args; do
  name="$(basename "$args" .args)"
  cases=$((cases + 1))
  if [ ! -f "$dir/$name.json" ]; then
    RC=-; OUT=""; ERR=""; fail "$name: no $name.json (run scripts/update-golden.sh restart)"; continue
  fi
  restart_transcript "$dir" "$name" >"$TEST_TMP/actual.json"
  golden_canonical "$dir/$name.json" >"$TEST_TMP/expected.json"
  if diff -u "$TEST_TMP/expected.json" "$TEST_TMP/actual.json" >"$TEST_TMP/diff"; then
    pass "golden $name"
  else
    RC=-; OUT="$(head -c 3000 "$TEST_TMP/diff")"; ERR=""; fail "golden $name differs"
  fi
done
if [ "$cases" -lt 15 ]; then RC=-; OUT=""; ERR=""; fail "too few restart golden cases in $dir"; fi

# JSON shape of the contract.
expect_rc 0 "demo mill restart" --json restart 1 --target N0033
json_check "restart keys" 'all(k in d for k in ("status","diagnostics","target","start","blocks_interpreted","state","aux_output","signals"))'
json_check "target and start" 'd["target"]["block"] == "N0033" and d["target"]["pass"] == 1 and d["start"]["block"] == "N0000" and d["start"]["primary"] is False'
json_check "state keys" 'all(k in d["state"] for k in ("g","m_groups","page61","page60","s","t","e","f","variables","position","call_stack"))'
json_check "signals numbered in order" '[s["step"] for s in d["signals"]] == list(range(1, len(d["signals"]) + 1))'
json_check "no adjust keys without --adjust" '"adjust_motion" not in d and "final" not in d'
expect_rc 0 "demo mill restart with --adjust" --json restart 1 --target N0033 --adjust
json_check "adjust keys" 'all(k in d for k in ("adjust_motion","repos_motion","final")) and d["restart_phase"] == "reestablished"'
json_check "REPOS ends on the re-entry point" 'd["final"]["position"] == d["state"]["position"]'
json_check "state re-established before CREPOS drops" '[s["name"] for s in d["signals"]][-3:] == ["P00SCREST", "P00CREPOS", "P00SREPOS"]'

# Readable text.
expect_rc 0 "text output" restart 1 --target N0012\>N0041 --runs 2
text_check "text target" "target: P1 N0041 pass 2"
text_check "text status" "status: ok"

# Usage errors: exit 2 with a diagnostic.
expect_rc 2 "runs 0" restart 1 --target N0033 --runs 0
text_check "runs message" "1..65536"
expect_rc 2 "runs 65537" restart 1 --target N0033 --runs 65537
expect_rc 2 "runs text" restart 1 --target N0033 --runs three
expect_rc 2 "runs negative" restart 1 --target N0033 --runs=-1
expect_rc 2 "no --target" restart 1
expect_rc 2 "two programs" restart 1 2 --target N0001
expect_rc 2 "--runs belongs to restart" run 1 --runs 2
expect_rc 2 "malformed path" --json restart 1 --target N0012\>\>N0041
json_check "malformed path code" 'd["diagnostics"][0]["code"] == "RESTART_PATH_SYNTAX"'
expect_rc 2 "program that does not exist" restart 7 --target N0001
cli restart 1 --target N0033 --runs 65536
[ "$RC" = 1 ] && pass "--runs 65536 accepted (target not found: exit 1)" || fail "--runs 65536 accepted"
# --data FILE as with run: loaded first, what the restart changed (page 60 at
# the target) is kept; md get reads it back; md-only options stay refused.
rdata="$TEST_TMP/restart.mdt"
expect_rc 0 "md set page 30 element 2 before" --data "$rdata" md set 30 2 10 --as nc
expect_rc 0 "restart --data" --json restart 1 --target N0033 --data "$rdata"
json_check "restart with data file ok" 'd["status"] == "ok"'
expect_rc 0 "page 60 after the restart" --json --data "$rdata" md get 60
json_check "tool spindle 1 published" 'd["subs"][0]["elements"][4]["value"] == 3'
expect_rc 0 "page 30 after the restart" --json --data "$rdata" md get 30
json_check "the loaded value was kept in the saved file" 'd["subs"][0]["elements"][1]["value"] == 10'
expect_rc 0 "restart --data - keeps nothing" restart 1 --target N0033 --data -
expect_rc 2 "restart --as refused" restart 1 --target N0033 --data "$rdata" --as nc
finish
