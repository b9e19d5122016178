; MTD reads and writes through the machine data of the cell: the user page
; 180 of the lathe (ranges honoured), pages 60 and 61, and pages or
; elements that do not exist (page 99).
; process: 1
; options: continue-after-error
; expect-error: MTD_OUT_OF_RANGE
; expect-error: MTD_UNKNOWN_PAGE
; expect-error: MTD_UNKNOWN_ELEMENT
; expect-error: MTD_UNKNOWN_PROCESS
N0001 MTD(180,,,1)=2
N0002 MTD(180,,,2)=350.5 BEQ .NEVER
N0003 @1=MTD(180,,,1) @2=MTD(180,1,0,2) @3=MTD(60,,,4) @4=MTD(61,,1,1)
N0004 MTD(180,,,1)=3
N0005 @5=MTD(99,,,1)
N0006 @6=MTD(180,,,9)
N0007 @7=MTD(180,4,0,1)
N0008 MTD(180,,,2)=0 BEQ .ZERO
N0009 @8=1
N0010 .ZERO @9=MTD(180,,2)
N0011 M30
N0012 .NEVER M30
