; The run stops at the first rejected block; the state is as before it.
N0000 G0 X10 Y5
N0001 T7
N0002 T31 ;the mill has tools T1..T24 only
N0003 G0 X50
