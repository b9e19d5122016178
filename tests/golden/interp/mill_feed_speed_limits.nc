; The path feed never exceeds what the axes allow (issue 22 §6, MOT-003):
; TIME shows F60000 on the 30000 mm/min X axis taking 0.6 s for 300 mm, and
; a full circle at F40000 taking the time of the axes' 30000 mm/min where
; the circle runs along them. A feed below 0.001 mm/min and a spindle speed
; above max_speed (8000 rpm) are refused; G96 S is a cutting speed.
; process: 0
; options: continue-after-error
; expect-error: FEED_TOO_SMALL
; expect-error: SPEED_ABOVE_MAXIMUM
N0001 G0 X0 Y0 Z0
N0002 @1=TIME
N0003 G1 X300 F60000
N0004 @2=TIME-@1
N0005 G1 X0 F0.0000000001
N0006 S9999999999 M3
N0007 S8000 M3
N0008 G1 F40000 X0
N0009 @3=TIME
N0010 G2 X0 Y0 I-50 J0
N0011 @4=TIME-@3
N0012 G96 S9000
N0013 M30
