; Radius compensation G41 inside a pocket 40 x 30 with one rounded corner
; (R8 > tool radius 5): inside corners are trimmed to the intersection.
; Tool T2: radius 5. G54: X-150 Y-80 Z-120.
; Hand-computed tool centre (program coordinates):
;   start-up N0004 from (20,15) to (20,5)
;   N0005 (20,5)-(32,5), N0006 arc R3 around (32,8) to (35,8) (tangent)
;   N0007 (35,8)-(35,25), N0008 (35,25)-(5,25), N0009 (5,25)-(5,5)
;   N0010 (5,5)-(20,5), cancel N0011 to (20,15).
; process: 0
N0001 T2 G17 G90 G54 G0 X20 Y15 Z2
N0002 S2500 M3
N0003 G1 Z-4 F400
N0004 G41 Y0
N0005 X32
N0006 G3 X40 Y8 I32 J8
N0007 G1 Y30
N0008 X0
N0009 Y0
N0010 X20
N0011 G40 Y15
N0012 G0 Z5
N0013 M30
