; M functions by group, group 16, Q and S/T words; no program end, so the
; groups keep their last values.
N0000 T12 S4000 M41 M3
N0001 M108 M208 M10 M917
N0002 M62 Q120 ;group 16 and a Q function
N0003 M109 M5
N0004 @200=M(2) @201=M(5) @202=M(16) @203=T @204=S
