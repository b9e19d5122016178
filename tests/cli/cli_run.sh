#!/usr/bin/env bash
# `mtc200-cli run`: the demo programs run clean, the JSON shape of
# CLI-CONTRACT.md, --no-motion, --max-blocks, errors at run time, streaming.
source "$(dirname "$0")/common.bash"
programs="$MTC_SOURCE_DIR/resources/programs"

# The demo programs run without any diagnostic.
expect_rc 0 "mill demo program 1" --json run 1
json_check "mill demo: status ok, no diagnostics" 'd["status"] == "ok" and d["diagnostics"] == []'
json_check "run keys" 'all(k in d for k in ("status", "diagnostics", "motion", "final"))'
json_check "state keys" 'all(k in d["final"] for k in ("g","m_groups","page61","page60","s","t","e","f","variables","position","call_stack"))'
json_check "G groups by number" 'all(k.isdigit() for k in d["final"]["g"]) and all(isinstance(v, (int, float)) for v in d["final"]["g"].values()) and d["final"]["g"]["2"] == 17'
json_check "M groups 1..15" 'sorted(int(k) for k in d["final"]["m_groups"]) == list(range(1, 16))'
json_check "page 61 buffers of 40" 'len(d["final"]["page61"]["m16"]) == 40 and len(d["final"]["page61"]["q"]) == 40'
json_check "page 60" 'len(d["final"]["page60"]["rotary_axis_mode"]) == 3 and len(d["final"]["page60"]["tool_spindle"]) == 4 and isinstance(d["final"]["page60"]["transformation"], (int, float))'
json_check "variables written by the program" 'all(k in d["final"]["variables"] for k in ("100", "101", "110", "111"))'
json_check "mill position axes" 'sorted(d["final"]["position"]) == ["X", "Y", "Z"]'
json_check "call stack empty at the end" 'd["final"]["call_stack"] == []'
json_check "numbers are numbers" 'isinstance(d["final"]["t"], (int, float)) and isinstance(d["final"]["f"], (int, float))'
json_check "motion entries" 'len(d["motion"]) > 40 and all(all(k in m for k in ("program","block","line","type","end","feed")) for m in d["motion"])'
json_check "motion types" '{m["type"] for m in d["motion"]} == {"rapid", "linear", "cw", "ccw"}'
json_check "center only on arcs" 'all(("center" in m) == (m["type"] in ("cw", "ccw")) for m in d["motion"])'
json_check "block ids N0000" 'all(len(m["block"]) == 5 and m["block"][0] == "N" and m["block"][1:].isdigit() for m in d["motion"])'
json_check "subroutine motion from program 99" 'any(m["program"] == 99 for m in d["motion"]) and any(m["program"] == 1 for m in d["motion"])'
json_check "motion count" 'd["motion_count"] == len(d["motion"])'

expect_rc 0 "lathe demo program 1" --json --process 1 run 1
json_check "lathe demo: status ok, no diagnostics" 'd["status"] == "ok" and d["diagnostics"] == []'
json_check "lathe arcs and rapid moves" '{"rapid", "linear"} <= {m["type"] for m in d["motion"]} and any(m["type"] in ("cw","ccw") for m in d["motion"])'
expect_rc 0 "lathe demo by path picks process 1 from the name" --json run "$programs/N1011001.DAT"
json_check "process from the file name" '"Z2" in d["final"]["position"]'
expect_rc 0 "program 99 started on its own ends at once" run 99

# Readable text without --json.
expect_rc 0 "text output" run 1
text_check "text motion line" "^P1 N0002 L19 rapid X="
text_check "text status" "status: ok"

# --no-motion leaves the list out but still runs and reports the final state.
expect_rc 0 "--no-motion" --json run --no-motion 1
json_check "no motion list" '"motion" not in d and "motion_count" not in d and "final" in d and d["blocks_interpreted"] > 40'

# --max-blocks: exceeding the bound is a diagnostic and exit 1.
expect_rc 1 "--max-blocks exceeded" --json run --max-blocks 10 1
json_check "block limit diagnostic" 'd["status"] == "error" and len(d["diagnostics"]) == 1 and d["diagnostics"][0]["severity"] == "error" and d["diagnostics"][0]["line"] > 0'
printf 'N0000 @1=0\nN0001 .LOOP @1=@1+1\nN0002 BRA .LOOP\n' >"$TEST_TMP/endless.nc"
SECONDS=0
expect_rc 1 "endless loop ends at the bound" --json run --max-blocks 100000 "$TEST_TMP/endless.nc"
json_check "endless loop diagnostic" 'd["status"] == "error" and d["diagnostics"][-1]["block"] in ("N0001", "N0002")'
if [ "$SECONDS" -lt 30 ]; then pass "bounded run is quick"; else fail "bounded run took ${SECONDS}s"; fi

# Errors found while running: exit 1 with block and line.
printf 'N0000 G0 X10\nN0001 T99\nN0002 G1 X20 F100\n' >"$TEST_TMP/badtool.nc"
expect_rc 1 "tool that is not in the tool list" --json run "$TEST_TMP/badtool.nc"
json_check "tool error located" 'any(x["block"] == "N0001" and x["line"] == 2 and x["severity"] == "error" for x in d["diagnostics"])'
json_check "state before the bad block kept" 'd["final"]["position"]["X"] == 10'
printf 'N0000 G1 X10 F100\nN0001 G1 X20 $$\nN0002 M30\n' >"$TEST_TMP/badword.nc"
expect_rc 1 "program with a parse error" --json run "$TEST_TMP/badword.nc"
json_check "parse error located" 'any(x["block"] == "N0001" and x["line"] == 2 for x in d["diagnostics"])'

# Streaming: the motion list of a long run is written as it comes, so peak
# memory with the list hardly differs from --no-motion.
"$MTC_SOURCE_DIR/scripts/gen-bench-program.sh" mtc 200000 "$TEST_TMP/long.nc"
if ldd "$MTC_CLI" 2>/dev/null | grep libasan >/dev/null; then
  pass "streaming memory check skipped under AddressSanitizer (its quarantine distorts RSS)"
elif [ -x /usr/bin/time ]; then
  /usr/bin/time -f %M -o "$TEST_TMP/rss1" "$MTC_CLI" --json run "$TEST_TMP/long.nc" >"$TEST_TMP/long.json"
  rc1=$?
  /usr/bin/time -f %M -o "$TEST_TMP/rss2" "$MTC_CLI" --json run --no-motion "$TEST_TMP/long.nc" >/dev/null
  rss1=$(tail -1 "$TEST_TMP/rss1"); rss2=$(tail -1 "$TEST_TMP/rss2")
  json_bytes=$(stat -c %s "$TEST_TMP/long.json")
  OUT="with list ${rss1} KiB, without ${rss2} KiB, JSON ${json_bytes} bytes"; RC=$rc1
  if [ "$rc1" = 0 ] && [ $((rss1 - rss2)) -lt $((json_bytes / 1024 / 4)) ]; then
    pass "motion list streams ($OUT)"
  else
    fail "motion list does not stream"
  fi
  OUT="$(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(len(d["motion"]), d["status"])' "$TEST_TMP/long.json")"
  if [ "$OUT" = "200000 ok" ]; then pass "200000 motions in valid JSON"; else fail "long JSON: $OUT"; fi
else
  pass "streaming check skipped: /usr/bin/time missing"
fi

# A process alone owns its axes (docs/decisions/restart.md R-022): GAX is
# granted at once, a move of an axis released with FAX is an error of its block.
printf 'N0001 FAX(Y)\nN0002 GAX(Y)\nN0003 G0 Y5\nN0004 FAX(X)\nN0005 G0 X6\nN0006 M30\n' >"$TEST_TMP/fax.nc"
expect_rc 1 "move after FAX" --json run "$TEST_TMP/fax.nc"
json_check "AXIS_NOT_HELD at N0005 line 5, Y moved after GAX" 'd["diagnostics"][0]["code"] == "AXIS_NOT_HELD" and d["diagnostics"][0]["block"] == "N0005" and d["diagnostics"][0]["line"] == 5 and d["final"]["position"]["Y"] == 5'
# run --sample-ms (docs/decisions/station.md ST-007): samples every N ms of
# simulated time from Start, the block the machine executes, the machine
# position and the actual feed; a last sample at the end.
printf 'N0001 G1 G90 X10 F600\nN0002 X20\nN0003 G4 F0.5\nN0004 M30\n' >"$TEST_TMP/samples.nc"
expect_rc 0 "run --sample-ms 250" --json run "$TEST_TMP/samples.nc" --sample-ms 250
# 20 mm at 10 mm/s with one ramp up and down at 2500 mm/s^2 (+0.004 s), 0.5 s dwell.
json_check "samples every 0.25 s up to the end, 2.504 s" '[round(s["t"], 6) for s in d["samples"]] == [0.25 * i for i in range(11)] + [2.504] and abs(d["simulated_time"] - 2.504) < 1e-9'
json_check "positions in between: X on its way at 10 mm/s" 'abs(d["samples"][4]["position"]["X"] - 9.98) < 1e-9 and abs(d["samples"][6]["position"]["X"] - 14.98) < 1e-9'
json_check "sample fields" 'all(set(s) == {"t", "program", "block", "position", "feed"} for s in d["samples"])'
json_check "samples follow the blocks" 'd["samples"][2]["block"] == "N0001" and d["samples"][6]["block"] == "N0002" and d["samples"][9]["block"] == "N0003"'
json_check "feed while moving, none while dwelling" 'd["samples"][3]["feed"] > 0 and d["samples"][9]["feed"] == 0'
json_check "last sample is the end position" 'd["samples"][-1]["position"]["X"] == 20 == d["final"]["position"]["X"]'
expect_rc 2 "run --sample-ms 0 is refused" run "$TEST_TMP/samples.nc" --sample-ms 0
expect_rc 2 "--sample-ms belongs to run" --json check "$TEST_TMP/samples.nc" --sample-ms 10
finish
