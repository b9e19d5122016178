#!/usr/bin/env bash
# Writes a mill program (process 0 of the demo cell) for the restart verifier
# benchmark: BLOCKS blocks in sections of about 200, each with a tool change
# through the demo library's .M6 (program 99), spindle, gear, coolant and a
# primary block, then G1/G2/G3 laps of a 30 x 30 mm pocket at the plate's G54.
# Every block is reached once, so every block is one restart target.
# Usage: scripts/gen-restart-program.sh BLOCKS OUT
set -euo pipefail
blocks="${1:?number of blocks}"
out="${2:?output file}"
awk -v blocks="$blocks" 'BEGIN {
  lap[0] = "G1 X40 Y20 F900"
  lap[1] = "G3 X50 Y30 I40 J30 F1100"
  lap[2] = "G1 X50 Y40 F900"
  lap[3] = "G2 X40 Y50 I40 J40 F1100"
  lap[4] = "G1 X30 Y50 F900"
  lap[5] = "G1 X30 Y20 F700"
  n = 0
  emit("(GENERATED RESTART BENCH)")
  emit("G0 G17 G40 G54 G90 G94 X-20 Y-20 Z50")
  section = 0
  while (n < blocks - 2) {
    tool = section % 24 + 1
    emit(": T" tool " BSR .M6")
    emit("G0 G54 G90 X30 Y20 Z5 S" (1500 + 50 * (section % 20)) " M" (41 + section % 2) " M3")
    emit("M108")
    emit("G1 Z-" (1 + section % 4) " F300")
    for (i = 0; i < 190 && n < blocks - 3; i++) emit(lap[i % 6])
    emit("G0 Z5 M109")
    section++
  }
  emit("G0 Z50 M5")
  emit("M30")
}
function emit(text) { printf "N%04d %s\n", n % 10000, text; n++ }' > "$out"
