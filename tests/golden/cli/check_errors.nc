; check: every problem with its block, line and column.
N0000 G1 X10 F100
N0001 BSR .MISSING
N0002 JSR 42
N0003 G1 X20 #
N0004 M30
