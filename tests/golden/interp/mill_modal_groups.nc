; Modal G groups on the mill: dimension, units, zero offsets, feed type,
; radius/diameter, tool path and length compensation, G(n) reads, G=expr.
; process: 0
; options: continue-after-error
; expect-error: G_GROUP_CONFLICT
; expect-error: UNKNOWN_G
; expect-error: G_NOT_SUPPORTED
N0001 G0 G90 X10 Y20 Z5
N0002 G54 X10 Y20
N0003 G91 X5 Y-5
N0004 G90 G55 X0 Y0
N0005 G70 G1 X1 F10
N0006 G71 X0 F500
N0007 G16 X40
N0008 G15 X40
N0009 G41 G48 G7 G9 G95 S1000 F0.2 X0
N0010 @101=G(1) @102=G(2) @103=G(3) @104=G(4) @105=G(5) @106=G(6)
N0011 @107=G(7) @108=G(8) @109=G(9) @110=G(13) @111=G(17) @112=G(10) @113=G(11)
N0012 G53 G0 G94 Z0
N0013 G=@104 G=@101 F300 X1
N0014 G0 G1 X2
N0015 G99 X3
N0016 G33 X4
N0017 G53 G40 G47 X0 Y0 Z0
N0018 M30
