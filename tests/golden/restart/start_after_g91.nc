; The primary start block lies after G91: the NC warns (seed 000, 5.1),
; in the CLI as on the screen.
N0001 G0 G54 X10 Y10 Z5
N0002 G91 X1
N0003 : X1 ;start block, G91 still active before it
N0004 G90 X20 ;target
N0005 M30
