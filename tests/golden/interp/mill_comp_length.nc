; Tool length compensation G48 / G47 along the tool axis of the plane (Z
; under G17, X under G19): the length of the tool in working position is
; added to the axis when a block programs it; a tool change moves nothing by
; itself. T1 length 82.5, T4 length 90 (changed with MTP + TCH into tool
; spindle 1). G54: X-150 Y-80 Z-120.
; Hand-computed axis positions:
;   N0003 Z5 + 82.5 - 120 = -32.5; N0004 (X, Y only) Z stays -32.5;
;   N0006 Z5 with T4: -25; N0007 G47 Z5: -115;
;   N0009 G19 G48 X10: X 10 - 150 + 90 = -50 (X is the tool axis of G19);
;   N0011 G41 with G48 under G19 (plane Y Z, radius 8 of T4): start-up to
;   (Y2, Z0), N0012 to (2,20), inserted arc around (10,20) to (10,28),
;   N0013 to (20,28), cancel N0014 to (30,30);
;   N0015 G17 X0: X, no tool axis now, loses its offset: -150;
;   N0016 Z10 + 90 - 120 = -20: the final axis position of Z differs from
;   the programmed one by the length in effect ("state axes").
; process: 0
N0001 T1 G17 G90 G54 G0 X0 Y0 Z50
N0002 G48
N0003 Z5
N0004 X10 Y10
N0005 T4 MTP TCH
N0006 Z5
N0007 G47 Z5
N0008 G48 X10
N0009 G19 X10
N0010 Y0 Z0
N0011 G41 G1 Y10 Z0 F400
N0012 Z20
N0013 Y20
N0014 G40 Y30 Z30
N0015 G17 X0
N0016 Z10
N0017 M30
