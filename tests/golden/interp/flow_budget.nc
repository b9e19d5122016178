; An endless loop ends in a diagnostic when the block budget is used up.
; process: 0
; budget: 1000
; expect-error: BLOCK_BUDGET
N0001 @1=0
N0002 .LOOP @1=@1+1
N0003 BRA .LOOP
