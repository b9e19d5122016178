; Radius compensation on the developed lateral cylinder surface (G32 RI 40,
; seed 003, 2.5 and 6.4): a slot 12 mm wide with round ends, 40 mm long
; around the circumference, milled with the driven tool T9 (radius 4.85,
; length 73.5 along the infeed axis X under G48) on its walls with G41.
; Plane Z1 (1st) Y1 (2nd), mm on the surface; C = Y1 / 40 * 180 / pi deg.
; G55: Z +255.5 (column X after G20). Slot walls Z1 -36 and -24.
; Hand-computed tool centre (Z1, Y1):
;   start-up N0009 from the slot centre (-30,20) to (-28.85,20)
;   N0010 (-28.85,20)-(-28.85,40): the wall -24 = -28.85 + 4.85
;   N0011 end R1.15 around (-30,40) to (-31.15,40)
;   N0012 (-31.15,40)-(-31.15,0): the wall -36 = -31.15 - 4.85
;   N0013 end R1.15 around (-30,0) to (-28.85,0)
;   N0014 (-28.85,0)-(-28.85,24) (perpendicular: cancel after the stops)
; Then the seed's pattern: retract with G41 still on, G30, G32 again, and
; the cancel move G40 from where the tool stands.
; process: 1
N0001 T9 G18 G90 G54 G0 X60 Z80 C0
N0002 S3 2500 M303
N0003 G20 Z0 C0 X0
N0004 G32 RI40
N0005 G0 G55 G48 Z1-30 Y1 20
N0006 X44
N0007 G1 X38 F150
N0008 F300
N0009 G41 Z1-24
N0010 Y1 40
N0011 G3 Z1-36 Y1 40 I-30 J40
N0012 G1 Y1 0
N0013 G3 Z1-24 Y1 0 I-30 J0
N0014 G1 Y1 24
N0015 G0 X44
N0016 G30
N0017 G32 RI40
N0018 G0 G40 G55 Z1-30 Y1 24
N0019 G47 X60
N0020 G30
N0021 G18
N0022 M30
