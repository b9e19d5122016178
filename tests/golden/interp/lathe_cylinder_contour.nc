; Lateral cylinder surface machining G32 with RI 36.5 on the demo lathe: a
; contour of lines and circles on the developed surface (Z1 along the axis,
; Y1 around it), centres I (Z1) and J (Y1) as absolute coordinates, one arc
; whose end point is 1 mm off its circle (rejected), then the corrected arc.
; The C axis receives angle = Y1 / RI * 180 / pi degrees.
; process: 1
; options: continue-after-error
; expect-error: ARC_RADIUS_MISMATCH
N0001 T9 S3 2000 M303
N0002 G0 X60 Z80 C0
N0003 G20 Z0 C0 X0
N0004 G32 RI 36.5
N0005 @100=G(17) @101=G(4) @102=G(7) @103=G(1)
N0006 G0 G56 Z1 30 Y1 0
N0007 X38
N0008 G1 X36 F150
N0009 Y1 20 F300
N0010 G2 Y1 26 Z1 36 I36 J20
N0011 G1 Z1 46
N0012 G3 Y1 36 Z1 56 I46 J36
N0013 G1 Y1 50
N0014 G2 Y1 54.9497 Z1 68.9497 I64 J50
N0015 G2 Y1 55.6569 Z1 69.6569 I64 J50
N0016 G1 Y1 -10
N0017 G0 X38
N0018 G30
N0019 @104=G(4) @105=G(17)
N0020 G18
N0021 M30
