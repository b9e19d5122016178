; The target lies in .TAP of program 99, reached through the second call.
N0001 @10=1 BSR .TAP
N0002 @10=2 BSR .TAP
N0003 @10=3
N0004 M30
