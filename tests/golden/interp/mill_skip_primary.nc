; Skip blocks '/' with the skip switch on are passed over; primary blocks
; ':' run like any other block.
; process: 0
; options: skip-blocks
N0001 @1=1
/N0002 @2=1
N0003 : @3=1
/ N0004 @4=1
: N0005 @5=1
N0006 M30
