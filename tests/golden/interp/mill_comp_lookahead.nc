; The look-ahead of radius compensation (tool T1, radius 3.5, G42): blocks
; without motion in the plane between two contour elements wait behind the
; held move and take place where the corner leaves the tool; more than 10
; such blocks, or a programmed stop, end the held move at its perpendicular
; (an outside corner after it gets its arc, an inside corner is an error:
; the tool has already cut into it). G54: X-150 Y-80 Z-120.
; Hand-computed tool centre (program coordinates):
;   N0004 start-up to (0,-3.5); N0005 to (20,-3.5), inserted arc to (23.5,0);
;   then N0006 Z-4, M108 and the dwell of N0009 at (23.5,0);
;   N0010 to (23.5,16.5) (inside corner with N0011), N0011 to (40,16.5)
;   where eleven blocks without plane motion end it at its perpendicular;
;   N0023 after an inserted arc around (40,20) from (40,16.5) to (43.5,20),
;   to (43.5,40) where M00 ends it; N0025 turns right: an inside corner
;   after the stop, COMP_CORNER_INTERRUPTED.
; process: 0
; expect-error: COMP_CORNER_INTERRUPTED
N0001 T1 G17 G90 G54 G0 X-20 Y0 Z2
N0002 S3000 M3
N0003 G1 Z-3 F300
N0004 G42 X0 Y0
N0005 X20
N0006 Z-4
N0007 M108
N0008 @100=1
N0009 G4 F0.5
N0010 Y20
N0011 X40
N0012 @101=1
N0013 @102=2
N0014 @103=3
N0015 @104=4
N0016 @105=5
N0017 @106=6
N0018 @107=7
N0019 @108=8
N0020 @109=9
N0021 @110=10
N0022 @111=11
N0023 Y40
N0024 M0
N0025 X60
N0026 G40 Y60
N0027 M30
