; Mill: rapid, linear and both arc directions in G17 with absolute centres.
N0000 G0 G17 G90 G54 X-10 Y0 Z5 S3000 M3
N0001 G1 Z-1 F300
N0002 X20 F800
N0003 G2 X30 Y10 I20 J10 ;quarter circle clockwise
N0004 G1 Y20
N0005 G3 X20 Y30 I20 J20 ;quarter circle counter-clockwise
N0006 G1 X0
N0007 G0 Z5 M5
