; Lathe: lateral cylinder under G70. RI 0.5 inch = 12.7 mm; 0.5 inch on the
; shell is one radian of C (57.2958 degrees). The run stops with G32 still
; active, so the final position names the plane axes by designation 2
; (Z1, Y1) in inch, the motion records the machine axes (Z, C in degrees).
N0000 G0 G18 G71 X30 Z100 C0
N0001 G70 G20 Z0 C0 X0
N0002 G32 RI 0.5
N0003 G0 Y1 0.5 Z1 3.5
N0004 G1 X0.5 F4
N0005 G1 Y1 0 F10
N0006 G1 Y1 0.25
N0007 G77 X1 ;no re-entry point: the run stops here, G32 active
N0008 G30
