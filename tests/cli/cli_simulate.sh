#!/usr/bin/env bash
# mtc200-cli simulate (issue 19 §5, CLI-CONTRACT.md "Extensions", D-020):
# removed volume of a pocket in JSON and text, the STL written atomically
# (binary, its triangle count), the lathe's turned part, a rapid into the
# part named with its block, the program's WINDOW_02 as the stock, a RAW
# contour as the lathe's blank, and
# refusals: bad resolutions, a grid over the cell cap, a bad window, a FIFO as
# output, program errors (no STL), misplaced options.
source "$(dirname "$0")/common.bash"
cd "$TEST_TMP" || exit 1

# A 40 x 20 x 4 pocket by its centre path with T1 (radius 3.5):
# (40 * 20 - (4 - pi) * 3.5^2) * 4 = 3157.94 mm3.
cat >pocket.nc <<'NC'
N0001 T1 G17 G90 G54 G0 X23.5 Y23.5 Z2
N0002 G1 Z-4 F200
N0003 X56.5
N0004 Y30
N0005 X23.5
N0006 Y36.5
N0007 X56.5
N0008 Y23.5
N0009 X23.5
N0010 Y36.5
N0011 G0 Z2
N0012 M30
NC

expect_rc 0 "simulate a pocket --json" --json simulate pocket.nc --stl part.stl --resolution 0.2
json_check "status ok, no diagnostics" 'd["status"] == "ok" and d["diagnostics"] == []'
json_check "removed volume within the border bound" 'abs(d["removed_volume"] - 3157.94) < 120 * 1.4143 * 0.2 * 4'
json_check "resolution and stl reported" 'd["resolution"] == 0.2 and d["stl"] == "part.stl"'
json_check "height field of 500 x 300 cells" 'd["model"] == "height_field" and d["cells"] == 150000'
json_check "counts" 'd["complete"] and d["blocks_interpreted"] == 12 and d["rapid_cuts"] == 0'
json_check "no developed surface on the mill" 'd["developed_cells"] == 0 and d["developed_volume"] == 0'
python3 - "$OUT" <<'PY' && pass "the STL is binary with the reported triangles" || fail "STL size"
import json, os, struct, sys
d = json.loads(sys.argv[1])
data = open("part.stl", "rb").read()
count = struct.unpack("<I", data[80:84])[0]
sys.exit(0 if count == d["triangles"] and len(data) == 84 + 50 * count else 1)
PY

expect_rc 0 "simulate text" simulate pocket.nc --resolution 0.5
text_check "text names the volume" "removed volume: 31[0-9][0-9]\.[0-9]* mm3"
text_check "text: no STL asked for" "stl: none written"

expect_rc 0 "simulate the demo lathe program" --json --process 1 simulate 1 --stl shaft.stl
json_check "turned profile" 'd["model"] == "turned_profile" and d["removed_volume"] > 80000'
json_check "the G32 groove is cut on the developed surface (D-027)" \
  'd["developed_volume"] > 500 and d["developed_cells"] > 0 and not any(x["code"] == "REMOVAL_NOT_SIMULATED" for x in d["diagnostics"])'
[ -s shaft.stl ] && pass "the lathe STL is written" || fail "no shaft.stl"

# A ring groove milled under G32 with T9 (radius 4.85) 2 mm into the R40
# bar: pi (40^2 - 38^2) 9.7 = 4753.8 mm3, within two slices of the ring.
cat >ring.nc <<'NC'
N0001 T9 G18 G90 G54 G0 X45 Z-30
N0002 G0 C0
N0003 G20 Z0 C0 X0
N0004 G32 RI 40
N0005 G0 G56 Y1 0 Z1 200
N0006 G1 X38 F100
N0007 G1 Y1 251.3274123 F300
N0008 G0 X45
N0009 G30
N0010 G18
N0011 M30
NC
expect_rc 0 "simulate a ring groove under G32" --json --process 1 simulate ring.nc
json_check "the ring groove's volume, all of it on the developed surface" \
  'abs(d["removed_volume"] - 4753.8) < 2 * 0.2 * 490.1 and d["developed_volume"] == d["removed_volume"] and d["cutting_moves"] == 2'
json_check "the jacket's cells: 1257 columns x 588 slices" 'd["developed_cells"] == 1257 * 588'
expect_rc 0 "a jacket over the cell cap gets fewer columns" --json --process 1 simulate ring.nc --resolution 0.1
json_check "REMOVAL_DEVELOPED_COARSER says how many, and the groove is cut" \
  'd["developed_cells"] == 1702 * 1175 and abs(d["removed_volume"] - 4753.8) < 2 * 0.1 * 490.1 and [x["block"] for x in d["diagnostics"] if x["code"] == "REMOVAL_DEVELOPED_COARSER"] == ["N0005"]'
expect_rc 0 "simulate a ring groove, text" --process 1 simulate ring.nc
text_check "text names the developed surface" "developed surface: 1257 x 588 cells, 47[0-9][0-9]\.[0-9]* mm3 of it cut under G32"

printf 'N0001 T1 G17 G90 G54 G0 X10 Y10 Z2\nN0002 Z-3\nN0003 G0 Z5\nN0004 M30\n' >rapid.nc
expect_rc 0 "a rapid into the part is a warning" --json simulate rapid.nc
json_check "REMOVAL_RAPID_CUT with program, block and line" \
  '[(x["code"], x["block"], x["line"]) for x in d["diagnostics"]] == [("REMOVAL_RAPID_CUT", "N0002", 2)]'

# The tool list beside --data is the one cut with: T1 at radius 5 widens the
# pocket to (40 + 3) x (20 + 3) with corners of radius 5.
expect_rc 0 "tools set T1 radius=5" --data "$TEST_TMP/cell.mdt" tools set T1 radius=5
expect_rc 0 "simulate with the tool file" --json --data "$TEST_TMP/cell.mdt" simulate pocket.nc
json_check "the wider cutter removes the wider pocket" \
  'abs(d["removed_volume"] - (43 * 23 - (4 - 3.14159265) * 25) * 4) < 126 * 1.4143 * 0.2 * 4'

for bad in 0 -1 nan 1e9 0.001 abc ""; do
  expect_rc 2 "--resolution '$bad' refused" simulate pocket.nc --resolution "$bad"
done
text_check "the range is named" "millimetres from 0.01 to 10"
expect_rc 2 "a grid over the cell cap" --json simulate pocket.nc --resolution 0.01
json_check "the cap and a coarser resolution are named" \
  'd["status"] == "error" and "needs 60000000 cells" in d["diagnostics"][0]["message"] and "at most 2000000" in d["diagnostics"][0]["message"] and "try 0.055 mm" in d["diagnostics"][0]["message"]'

# A process without stock, and a bar on the mill: refused with the reason.
cfg="$MTC_SOURCE_DIR/resources/machines/demo-cell.cfg"
sed 's/^stock = block .*/stock = none/' "$cfg" >nostock.cfg
expect_rc 2 "no stock in the configuration" --machine nostock.cfg simulate pocket.nc
text_check "says the stock is missing" "has no stock in its machine configuration"
sed 's/^stock = block .*/stock = cylinder Z 40 -130 -120/' "$cfg" >bar.cfg
expect_rc 2 "a cylinder stock on the mill" --json --machine bar.cfg simulate pocket.nc
json_check "REMOVAL_STOCK says why" \
  'd["diagnostics"][0]["code"] == "REMOVAL_STOCK" and "milling process" in d["diagnostics"][0]["message"]'

# The program's drawing window is the stock (TP-008): under G55 (X50 Y-80
# Z-120) the configuration's block (X-150..-50) is far away, the window's
# blank X60..120 Y-70..-30 holds the pocket.
{ echo 'N0000 G55'; echo 'N0001 ;WINDOW_02 (10, 10, 70, 50, 0, -8)'; sed 's/G54/G55/' pocket.nc; } >window.nc
expect_rc 0 "simulate a program with WINDOW_02" --json simulate window.nc
json_check "the stock is the window, in G55" \
  'd["stock"] == {"source": "window", "keyword": "WINDOW_02", "program": d["program"], "block": "N0001", "line": 2, "zero_offset": "G55"}'
json_check "the pocket is cut out of it" \
  'abs(d["stock_volume"] - 60 * 40 * 8) < 1e-6 and abs(d["removed_volume"] - 3157.94) < 120 * 1.4143 * 0.2 * 4'
expect_rc 0 "text names the window" simulate window.nc
text_check "stock line" "stock: WINDOW_02 of P[0-9]* N0001 (line 2) in G55"
expect_rc 0 "without a window" --json simulate pocket.nc
json_check "the configuration's stock" 'd["stock"] == {"source": "configuration"}'
sed 's/WINDOW_02 (10, 10, 70, 50, 0, -8)/WINDOW_02 (10, 10, 10, 50)/' window.nc >flat.nc
expect_rc 2 "a window without width" --json simulate flat.nc
json_check "REMOVAL_WINDOW at its block and line" \
  '[(x["code"], x["block"], x["line"]) for x in d["diagnostics"]][:1] == [("REMOVAL_WINDOW", "N0001", 2)] and "XMIN and XMAX are equal" in d["diagnostics"][0]["message"]'

# A RAW contour after the lathe's window is the blank (TP-021): a preform
# of radius 20 up to Z-30 on a bar of radius 30 from Z-60 to Z2; the pass
# at radius 18 over Z-20..2 takes pi * (20^2 - 18^2) * 22 from it.
cat >preform.nc <<'NC'
N0001 G18 G54 G90 G0 X50 Z5
N0002 ;WINDOW_01 (-60, 2, 30)
N0003 ;CONT (4, RAW)
;START Z2 X20
;LINE Z-30 X20
;LINE Z-30 X30
;LINE Z-60 X30
;END_CONT
N0010 G0 X18 Z5
N0011 G1 Z-20 F0.2
N0012 G0 X50
N0013 M30
NC
expect_rc 0 "simulate a preform" --json --process 1 simulate preform.nc
json_check "the RAW contour is named in the stock" \
  'd["stock"]["raw_contour"] == 4 and d["stock"]["raw_line"] == 3 and d["stock"]["keyword"] == "WINDOW_01"'
json_check "stock and removed volume are the preform's" \
  'abs(d["stock_volume"] - 3.14159265358979 * (900 * 30 + 400 * 32)) < 1e-6 and abs(d["removed_volume"] - 3.14159265358979 * 76 * 22) < 1e-6'
expect_rc 0 "simulate a preform, text" --process 1 simulate preform.nc
text_check "blank line" "blank: RAW contour 4 (line 3)"

mkfifo pipe.stl
expect_rc 2 "--stl FIFO refused" simulate pocket.nc --stl pipe.stl
[ -p pipe.stl ] && pass "the FIFO stays a FIFO" || fail "the FIFO was replaced"
echo keep >kept.stl
printf 'N0001 T1 G17 G90 G54 G0 X10 Y10 Z2\nN0002 G1 Z-2 F100\nN0003 G1 X20 Q\nN0004 M30\n' >broken.nc
expect_rc 1 "a program with errors" --json simulate broken.nc --stl kept.stl
json_check "its error with block and line, stl null" \
  'd["status"] == "error" and d["stl"] is None and any(x["severity"] == "error" and x["line"] == 3 for x in d["diagnostics"])'
[ "$(cat kept.stl)" = keep ] && pass "the old file is kept" || fail "kept.stl was overwritten"

expect_rc 2 "--stl outside simulate" run pocket.nc --stl x.stl
text_check "says where it belongs" "belong to 'simulate'"
expect_rc 2 "simulate needs a program" simulate
expect_rc 2 "simulate takes one program" simulate pocket.nc pocket.nc
finish
