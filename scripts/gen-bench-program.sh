#!/usr/bin/env bash
# Writes the benchmark program: N blocks of G1/G2/G3 moves with block numbers
# and feeds, as a plain file of blocks, in MTC200 syntax (circle centres I/J
# absolute) or ISO/RS274 syntax (centres relative to the start point).
# Usage: scripts/gen-bench-program.sh mtc|iso BLOCKS OUT
# The path is a closed lap of six blocks in the XY plane (30 x 30 mm with two
# R10 arcs) repeated; block numbers run N0000..N9999 and wrap.
set -euo pipefail
syntax="${1:?mtc|iso}"
blocks="${2:?number of blocks}"
out="${3:?output file}"
awk -v syntax="$syntax" -v blocks="$blocks" 'BEGIN {
  if (syntax == "mtc") {
    lap[0] = "G1 X10 Y0 F1000"
    lap[1] = "G3 X20 Y10 I10 J10 F1200"
    lap[2] = "G1 X20 Y20 F1000"
    lap[3] = "G2 X10 Y30 I20 J30 F1200"
    lap[4] = "G1 X0 Y30 F1000"
    lap[5] = "G1 X0 Y0 F800"
  } else {
    lap[0] = "G1 X10 Y0 F1000"
    lap[1] = "G3 X20 Y10 I0 J10 F1200"
    lap[2] = "G1 X20 Y20 F1000"
    lap[3] = "G2 X10 Y30 I0 J10 F1200"
    lap[4] = "G1 X0 Y30 F1000"
    lap[5] = "G1 X0 Y0 F800"
  }
  for (i = 0; i < blocks; i++) printf "N%04d %s\n", i % 10000, lap[i % 6]
  if (syntax == "iso") print "M2"
}' > "$out"
