; "from last primary block" without a primary block before the target:
; one warning, the computing process starts at N0000.
N0001 G0 G54 X10 Y10 Z5
N0002 G1 Z-2 F300
N0003 X40 ;target
N0004 M30
