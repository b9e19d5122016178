; Radius compensation G41 around an island 40 x 20 (outer corners): the
; control inserts an arc of the tool radius around every corner.
; Tool T1: radius 3.5 (demo cell). G54: X-150 Y-80 Z-120.
; Hand-computed tool centre (program coordinates):
;   start-up N0004 to (-3.5, 0), perpendicular to N0005's start
;   N0005 (-3.5,0)-(-3.5,20), arc around (0,20) to (0,23.5)
;   N0006 to (40,23.5), arc around (40,20) to (43.5,20)
;   N0007 to (43.5,0), arc around (40,0) to (40,-3.5)
;   N0008 to (0,-3.5), arc around (0,0) to (-3.5,0)
;   N0009 to (-3.5,5) (perpendicular: the cancel follows), N0010 to (-20,5).
; process: 0
N0001 T1 G17 G90 G54 G0 X-20 Y-10 Z5
N0002 S3000 M3
N0003 G1 Z-5 F500
N0004 G41 X0 Y0
N0005 Y20
N0006 X40
N0007 Y0
N0008 X0
N0009 Y5
N0010 G40 G0 X-20
N0011 Z5
N0012 M30
