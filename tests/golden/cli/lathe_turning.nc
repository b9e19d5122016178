; Lathe (process 1): G18 turning with a fillet, I = X centre, K = Z centre.
N0000 G0 G18 G54 G90 X30 Z2 S1 1500 M3
N0001 G1 Z-20 F200
N0002 G2 X35 Z-25 I35 K-20
N0003 G1 X40
N0004 G0 Z2 M5
