G21 (Units in millimeters) 
G90 (Absolute programming) 
G17 (XY plane) 
F900

G3 X0 Y0 I20 J0
G3 X0 Y0 z 20 I20 J0
G3 X0 Y0 I20 J0

G1 Z0
G2 X0 Y0 I-20 J0
G2 X0 Y0 z -20 I-20 J0
G2 X0 Y0 I-20 J0
G1 Z0

