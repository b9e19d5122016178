; Lines and circles in G17, G18 and G19 with the centre as absolute
; coordinates (I for X, J for Y, K for Z), a full circle, a helix and the
; same arc written incrementally.
; process: 0
N0001 G0 X0 Y0 Z0
N0002 G1 X10 F1000
N0003 G17 G3 X0 Y10 I0 J0
N0004 G2 X10 Y0 I0 J0
N0005 G2 X10 Y0 I5 J0
N0006 G3 X-10 Y0 Z-5 I0 J0
N0007 G18 G1 X0 Y0 Z0
N0008 G2 Z10 X10 K0 I10
N0009 G19 G1 Y0 Z0
N0010 G3 Y10 Z10 J10 K0
N0011 G17 G91 G1 X10 Y0
N0012 G3 X10 Y10 I10 J0
N0013 G90 G0 X0 Y0 Z0
N0014 M30
