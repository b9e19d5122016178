; Dwell G4 (time in F, seconds; not a feed), commands handed to the machine
; (tool change, magazine, drive data), compiler-only keywords refused, and
; the simulated clock read with TIME.
; process: 0
; options: continue-after-error
; expect-error: DWELL_TIME_MISSING
; expect-error: DWELL_WITH_AXES
; expect-error: NEEDS_COMPILER
N0001 G1 X10 F600
N0002 G4 F2.5
N0003 @1=TIME
N0004 G4
N0005 G4 X5 F1
N0006 T7 MTP
N0007 TCH(1,1)
N0008 AXD (X:S-0-0104)=7000
N0009 LA_ON
N0010 @2=T
N0011 G0 X20 BTE .T0
N0012 T0 BTE .T0
N0013 @9=1
N0014 .T0 M30
