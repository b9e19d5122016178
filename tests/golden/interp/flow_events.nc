; Event-dependent branches and calls: BES (event set), BER (event reset),
; BEV (subroutine if set), JEV (program if set); events as process:event.
; process: 0
; event: 0:15
; event: 1:7
N0001 BES .SET 0:15
N0002 @1=1
N0003 .SET BER .RES 0:16
N0004 @2=1
N0005 .RES BEV .SUB 0:15
N0006 JEV 5 0:16
N0007 JEV 5 1:7
N0008 BES .NEVER 0:16
N0009 BER .NEVER 1:7
N0010 M30
N0011 .SUB @3=1
N0012 RTS
N0013 .NEVER @9=1
N0014 M30
;== program 5 ==
N0000 @4=@4+1
N0001 RTS
