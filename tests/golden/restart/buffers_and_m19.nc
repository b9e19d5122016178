; 45 passes of an M of group 16 and a Q: the page 61 buffers keep the
; last 40. M19 and M119 / M219 / M319 are never stored.
N0001 @1=0
N0002 .LOOP @1=@1+1
N0003 M=500+@1 Q=200+@1 M119
N0004 M19 M219 M319
N0005 @2=@1-45 BMI .LOOP
N0006 @3=1 ;target
N0007 M30
