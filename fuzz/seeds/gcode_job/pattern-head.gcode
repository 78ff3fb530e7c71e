; FiveBar Studio job for GRBL 1.1, host-side kinematics
; X = theta1 deg, Y = theta2 deg (continuous), F = joint rate deg/min
; profile: maker-plotter
; working mode ++, assembly +
; start pose X151.1460 Y28.8540
; estimated time 144.9 s, 709 drawing segments
; expects these GRBL settings:
; $11=0.0130 (junction deviation, deg)
; $20=0 (soft limits)
; $21=0 (hard limits)
; $22=0 (homing cycle)
; $30=1000 (max S)
; $31=0 (min S)
; $32=0 (laser mode)
; $100=35.5556 (motor 1 steps/deg)
; $101=35.5556 (motor 2 steps/deg)
; $110=9000.0 (motor 1 max rate, deg/min)
; $111=9000.0 (motor 2 max rate, deg/min)
; $120=600.0 (motor 1 acceleration, deg/s^2)
; $121=600.0 (motor 2 acceleration, deg/s^2)
; $130=315.000 (motor 1 travel, deg)
; $131=315.000 (motor 2 travel, deg)
G21 G90 G94
; stroke 0 layer 0 path 0
G1 X169.5095 Y46.6139 F12520.5
M3 S1000
G4 P0.150
G1 X168.9855 Y47.1614 F1391.3
G1 X168.8385 Y47.8957 F1374.8
G1 X169.1024 Y48.6193 F1414.0
G1 X169.7078 Y49.1420 F1468.3
G1 X170.4995 Y49.3285 F1493.2
G1 X171.2710 Y49.1300 F1462.4
G1 X171.8148 Y48.5959 F1399.3
G1 X171.9778 Y47.8645 F1375.6
G1 X171.7104 Y47.1304 F1434.3
G1 X171.0852 Y46.5942 F1512.0
G1 X170.2774 Y46.4048 F1523.2
G1 X169.5095 Y46.6139 F1461.0
M5
