; Radius compensation with circles (tool T1, radius 3.5): a full circle
; around a boss (outside, G2 with G41); with G42 an S of two tangent
; quarter circles (G3 outside, G2 inside), a circle meeting a line at an
; inside corner (intersection of line and circle), a line meeting a circle
; at an outside corner and a circle meeting a circle at an outside corner
; (inserted arcs). G54: X-150 Y-80 Z-120.
; Hand-computed tool centre (program coordinates):
;   N0004 start-up to (-13.5,0); N0005 full circle R13.5 around (0,0);
;   N0006 cancel to (-30,0).
;   N0009 start-up from (0,-30) to (0,-23.5), perpendicular to N0010's start;
;   N0010 G3 R13.5 around (0,-10) to (13.5,-10);
;   N0011 G2 R6.5 around (20,-10) to (20,-3.5) (tangent);
;   N0012 line to (40,-3.5); N0013 G2 R6.5 around (40,-10) to
;   (45.4772256,-6.5): 40 + sqrt(6.5^2 - 3.5^2), on the next line y -6.5;
;   N0014 line to (30,-6.5); inserted G3 around (30,-10) to (26.5,-10);
;   N0015 G2 R6.5 around (20,-10) to (20,-16.5); inserted G3 around
;   (20,-20) to (16.5,-20); N0016 G3 R13.5 around (30,-20) to (30,-33.5)
;   (perpendicular), cancel N0017 to (30,-45).
; process: 0
N0001 T1 G17 G90 G54 G0 X-30 Y0 Z2
N0002 S3000 M3
N0003 G1 Z-3 F300
N0004 G41 X-10
N0005 G2 X-10 Y0 I0 J0
N0006 G40 G1 X-30
N0007 G0 X0 Y-30
N0008 G1 Z-3
N0009 G42 Y-20
N0010 G3 X10 Y-10 I0 J-10
N0011 G2 X20 Y0 I20 J-10
N0012 G1 X40
N0013 G2 X50 Y-10 I40 J-10
N0014 G1 X30
N0015 G2 X20 Y-20 I20 J-10
N0016 G3 X30 Y-30 I30 J-20
N0017 G40 G1 Y-45
N0018 G0 Z5
N0019 M30
