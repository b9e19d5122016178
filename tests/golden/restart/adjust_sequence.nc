; A short part: ADJUST and REPOS of the test library after the restart.
N0001 : T4 S2000 M3 M108
N0002 G0 G54 X10 Y10 Z5 M62
N0003 G1 Z-2 F300
N0004 X50 ;target
N0005 M30
