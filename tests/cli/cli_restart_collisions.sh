#!/usr/bin/env bash
# mtc200-cli restart --check-collisions (issue 19 §5, CLI-CONTRACT.md
# "Extensions", D-021): the ADJUST/REPOS moves against the part cut up to the
# target. A way back straight through the part is listed with its block,
# phase and the machine position where it enters the material (JSON and
# text); the same way back after going up first is clear; a lathe case; a
# part too fine to model says the check was not done; misplaced options.
source "$(dirname "$0")/common.bash"
cd "$TEST_TMP" || exit 1

# library DIR PROCESS BLOCKS: program 99 of process PROCESS in DIR.
library() {
  local dir="$1" process="$2" body="$3" name="N101${2}099.DAT"
  mkdir -p "$dir"
  {
    printf 'iMTc/01%s099/01.00/0000000000/26.11.2026/12:00:00/%s/1\n' "$process" "$name"
    printf '%%NPG:1:01:%s:099\n!01.00\n#01Collision test library\n$\n$\n$\n$\n' "$process"
    printf '*Collision test library\n%%NPG\n%sPROGRAMMENDE\n' "$body"
  } >"$dir/$name"
}

# Mill: a slot 4 deep along Y30 from X20 to X80 (T2, R5); the target N0050
# turns it. The part is X0..100 Y0..60 Z-12..0 at G54 = X-150 Y-80 Z-120.
cat >slot.nc <<'NC'
N0010 : T2 S1500 M3
N0020 G0 G54 X20 Y30 Z2
N0030 G1 Z-4 F200
N0040 X80
N0050 X80 Y45 ;target
N0060 G0 Z10
N0070 M30
NC
library straight 0 'N0000 M30
N0001 .ADJUST G0 G54 X120 Y30 Z-2 ;beside the part, below its top
N0002 .REPOS G77 X0 Y0 F2000 ;through the part at Z-2
N0003 G77 Z0 F500 RTS
'
library upfirst 0 'N0000 M30
N0001 .ADJUST G0 G54 Z20 ;above the part first
N0002 .REPOS G77 X0 Y0 F2000
N0003 G77 Z0 F500 RTS
'

expect_rc 0 "a way back through the part --json" \
  --json restart slot.nc --programs straight --target N0050 --check-collisions
json_check "checked: 3 moves, the slot cut before the target" \
  'd["collision_check"]["checked"] and d["collision_check"]["moves"] == 3 and abs(d["collision_check"]["removed_volume"] - (600 + 3.14159 * 25) * 4) < 60'
json_check "one collision: REPOS N0002 of P99, a feed move" \
  'len(d["collisions"]) == 1 and d["collisions"][0]["block"] == "N0002" and d["collisions"][0]["program"] == 99 and d["collisions"][0]["phase"] == "repos" and d["collisions"][0]["motion"] == "feed"'
# From X120 towards X80 at Y30 the R5 cutter meets the X100 face (cells to
# 99.9) with its centre at X104.9: machine X -45.1, Y -50, Z -122.
json_check "where it enters the material (machine position)" \
  'abs(d["collisions"][0]["position"]["X"] + 45.1) < 0.2 and d["collisions"][0]["position"]["Y"] == -50 and d["collisions"][0]["position"]["Z"] == -122'
json_check "the restart stays at the target" 'd["restart_phase"] == "target_reached"'
expect_rc 0 "the same in text" restart slot.nc --programs straight --target N0050 --check-collisions
text_check "a line per collision" "^collision repos P99 N0002 L[0-9]* feed X=-45.1[0-9]* Y=-50 Z=-122$"
text_check "the summary" "collision check: 1 of 3 ADJUST/REPOS moves collide"

expect_rc 0 "up first, then over and down into the slot" \
  --json restart slot.nc --programs upfirst --target N0050 --check-collisions --resolution 0.5
json_check "no collisions, checked at 0.5 mm" \
  'd["collisions"] == [] and d["collision_check"]["checked"] and d["collision_check"]["resolution"] == 0.5'
expect_rc 0 "without --check-collisions" --json restart slot.nc --programs straight --target N0050
json_check "no collision keys" '"collisions" not in d and "collision_check" not in d'
expect_rc 0 "with --adjust the check is before Start" \
  --json restart slot.nc --programs straight --target N0050 --check-collisions --adjust
json_check "listed, and ADJUST/REPOS ran to the re-entry" \
  'len(d["collisions"]) == 1 and d["restart_phase"] == "reestablished" and len(d["repos_motion"]) == 2'

# Lathe: bar R40 from Z2 back (G54 X0 Z255.5), turned to R30 up to Z-50.
# The axes stand at machine zero; ADJUST takes them behind the turned length.
cat >shaft.nc <<'NC'
N0010 : T1 S800 M4
N0020 G0 G54 X45 Z5
N0030 G1 X30 F200
N0040 Z-50
N0050 X45 ;target
N0060 G0 Z5
N0070 M30
NC
library xfirst 1 'N0000 M30
N0001 .ADJUST G0 G54 X45 Z-100 ;above the bar, behind the turned part
N0002 .REPOS G77 X0 F1000 ;down into the bar
N0003 G77 Z0 F500 RTS
'
library zfirst 1 'N0000 M30
N0001 .ADJUST G0 G54 X45 Z-100
N0002 .REPOS G77 Z0 F1000 ;along outside the bar
N0003 G77 X0 F500 RTS
'
expect_rc 0 "lathe: X first" --json restart shaft.nc --process 1 --programs xfirst --target N0050 --check-collisions
# (N0003 then runs along Z on the insert's side, which the turned profile
# counts as reached from where the plunge stopped: D-020, D-021.)
json_check "the plunge into the bar is listed" \
  'd["collisions"][0]["block"] == "N0002" and all(c["phase"] == "repos" for c in d["collisions"])'
json_check "X enters at the bar's radius" 'abs(d["collisions"][0]["position"]["X"] - 40) < 0.6'
expect_rc 0 "lathe: Z first" --json restart shaft.nc --process 1 --programs zfirst --target N0050 --check-collisions
json_check "clear" 'd["collisions"] == [] and d["collision_check"]["checked"]'

# A resolution the stock cannot be modelled at: not checked, and said so.
expect_rc 1 "a part over the cell limit" \
  --json restart slot.nc --programs straight --target N0050 --check-collisions --resolution 0.01
json_check "REMOVAL_STOCK and REENTRY_NOT_CHECKED, no list" \
  'not d["collision_check"]["checked"] and d["collisions"] == [] and {"REMOVAL_STOCK", "REENTRY_NOT_CHECKED"} <= {x["code"] for x in d["diagnostics"]}'
# A target that is never reached: no check at all.
expect_rc 1 "target not reached" --json restart slot.nc --programs straight --target N0050 --runs 2 --check-collisions
json_check "collision_check null, empty list" 'd["collision_check"] is None and d["collisions"] == []'

expect_rc 2 "--check-collisions belongs to restart" run slot.nc --check-collisions
text_check "says where it belongs" "belongs to 'restart'"
expect_rc 2 "--resolution needs --check-collisions" restart slot.nc --target N0050 --resolution 0.5
expect_rc 2 "a bad resolution" restart slot.nc --target N0050 --check-collisions --resolution 0
expect_rc 2 "--stl stays with simulate" restart slot.nc --target N0050 --check-collisions --stl x.stl
finish
