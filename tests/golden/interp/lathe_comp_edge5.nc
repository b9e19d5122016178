; Cutting edge radius compensation on the lathe: cutting edge orientation
; 5, the tip lies at +Z of the nose centre
; (docs/decisions/compensation.md TC-010, the GNE table gne.md G-008).
; G18: Z is the 1st, X the 2nd plane axis, X as radius; G56 has no offset,
; so the axis positions in the transcript are the programmed coordinates.
; Tool: nose radius r = 0.8. The programmed point is the theoretical tip,
; the nose centre C runs on the contour offset by r, the axes follow
; A = C + r * v with the edge vector v (Z, X) of the orientation.
; Under G40 the tip follows the programmed points (A = programmed).
;
; Outer contour under G42 (nose on the +X side, towards the chuck): 45 degree
; chamfer (0,6)-(-4,10), cylinder X10, concave fillet R5 (centre (-10,15)),
; shoulder Z-15, convex edge radius R2 (centre (-17,18)), cylinder X20.
; Bore under G41 (nose on the -X side, towards the chuck): 45 degree chamfer
; (0,14)-(-3,11), bore X11, inside corner to the face Z-10, convex edge
; radius R2 (centre (-12,8)), bore X6. r/sqrt2 = 0.565685.
; Nose centre C (Z, X), the same for every orientation:
; process: 1
; tool: 1 radius 0.8 length 60 edge 5
;
; T1 edge 5: v = (1, 0), A = C + (0.8, 0)
;   N0004 start-up end, r*(1,1)/sqrt2 right of the chamfer   C=(0.565685, 6.565685)  A=(1.365685, 6.565685)
;   N0005 chamfer end                                        C=(-3.434315, 10.565685)  A=(-2.634315, 10.565685)
;   N0005 inserted ccw arc around (-4,10)                    C=(-4, 10.8)  A=(-3.2, 10.8)
;   N0006 cylinder X10+r                                     C=(-10, 10.8)  A=(-9.2, 10.8)
;   N0007 fillet, radius 5-r around (-10,15)                 C=(-14.2, 15)  A=(-13.4, 15)
;   N0008 shoulder Z-15+r                                    C=(-14.2, 18)  A=(-13.4, 18)
;   N0009 edge radius, 2+r around (-17,18)                   C=(-17, 20.8)  A=(-16.2, 20.8)
;   N0010 cylinder X20+r                                     C=(-25, 20.8)  A=(-24.2, 20.8)
;   N0011 cancel: C leaves from (-25, 20.8); A ends at the programmed (-25, 24)
;   N0014 start-up end, r*(1,-1)/sqrt2 left of the chamfer   C=(0.565685, 13.434315)  A=(1.365685, 13.434315)
;   N0015 chamfer end                                        C=(-2.434315, 10.434315)  A=(-1.634315, 10.434315)
;   N0015 inserted cw arc around (-3,11)                     C=(-3, 10.2)  A=(-2.2, 10.2)
;   N0016 bore X11-r up to the face Z-10+r (inside corner)   C=(-9.2, 10.2)  A=(-8.4, 10.2)
;   N0017 face Z-10+r                                        C=(-9.2, 8)  A=(-8.4, 8)
;   N0018 edge radius, 2+r around (-12,8)                    C=(-12, 5.2)  A=(-11.2, 5.2)
;   N0019 bore X6-r                                          C=(-20, 5.2)  A=(-19.2, 5.2)
;   N0020 cancel: C leaves from (-20, 5.2); A ends at the programmed (-20, 3)
N0001 T1 G18 G90 G56 G0 X30 Z5
N0002 S1000 M3
N0003 G0 X6 Z3
N0004 G42 G1 Z0 F120
N0005 X10 Z-4
N0006 Z-10
N0007 G2 X15 Z-15 I15 K-10
N0008 G1 X18
N0009 G3 X20 Z-17 I18 K-17
N0010 G1 Z-25
N0011 G40 G0 X24
N0012 Z5
N0013 X13 Z3
N0014 G41 G1 X14 Z0
N0015 X11 Z-3
N0016 Z-10
N0017 X8
N0018 G2 X6 Z-12 I8 K-12
N0019 G1 Z-20
N0020 G40 G0 X3
N0021 Z5
N0022 M30
