; Calls nest up to 10 program levels (main program and 9 calls); the call
; that would open the 11th level is rejected (the block changes nothing).
; process: 0
; expect-error: CALL_DEPTH
N0001 @1=0
N0002 BSR .DEEP
N0003 M30
N0004 .DEEP @1=@1+1 BSR .DEEP
N0005 RTS
