; Cutting edge radius compensation on the lathe (G18: Z 1st, X 2nd axis,
; X as radius): T1 nose radius 0.4, cutting edge orientation 3 (the
; theoretical tip is at -Z -X of the nose centre). Face, 45 degree chamfer,
; cylinder, concave R5 fillet, shoulder, cylinder; G42 keeps the nose on
; the material side (+X, +Z). Tool reference = nose centre + (-0.4, -0.4).
; Hand-computed nose centre (Z, X):
;   start-up N0004 from (3.4, 0.4) to (0.4, 0)
;   N0005 face (0.4,0)-(0.4,8); inserted arc around (0,8) to (0.28284,8.28284)
;   N0006 chamfer to (-1.71716,10.28284); inserted arc around (-2,10) to (-2,10.4)
;   N0007 cylinder to (-20,10.4); N0008 fillet R4.6 around (-20,15) to (-24.6,15)
;   N0009 shoulder to (-24.6,20); inserted arc around (-25,20) to (-25,20.4)
;   N0010 cylinder to (-40,20.4); cancel N0011 to (-39.6,25.4): tip at (-40, 25).
; G54: Z +255.5.
; process: 1
N0001 T1 G18 G90 G54 G0 X30 Z20
N0002 S1200 M3
N0003 X0 Z3
N0004 G42 G1 Z0 F150
N0005 X8
N0006 X10 Z-2
N0007 Z-20
N0008 G2 X15 Z-25 I15 K-20
N0009 G1 X20
N0010 Z-40
N0011 G40 G0 X25
N0012 Z20
N0013 M30
