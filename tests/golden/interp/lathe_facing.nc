; Facing G31 (polar coordinate transformation) on the demo lathe: after
; G20 X0 C0 Z0 the end face is programmed in X1 / Y1; the machine receives
; the radius in X and the angle in C (the nearest turn, the angle kept at
; the rotation centre).
; process: 1
N0001 G0 X40 Z10 C0
N0002 G20 X0 C0 Z0
N0003 G31
N0004 G1 X1 20 Y1 20 F200
N0005 Y1 -20
N0006 X1 -20
N0007 X1 0 Y1 0
N0008 G2 X1 10 Y1 0 I5 J0
N0009 G3 X1 0 Y1 10 I0 J0
N0010 G30
N0011 M30
