; Restart from the last primary block: inside the subroutine.
N0001 @1=1
N0002 : G0 G54 X10 Y10 Z5
N0003 BSR .PART
N0004 M30
N0005 .PART @5=1
N0006 : G1 X20 F500 @6=1
N0007 Y20 ;target
N0008 RTS
