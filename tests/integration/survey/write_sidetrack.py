#!/usr/bin/env python3
"""write_sidetrack.py OUT: a sidetrack of plumb-sim's drilling-survey well as a station list, placed
by its first row: the planned path's point at MD 3.75 m (I 45 deg, azimuth 120 deg), then away from
the well (I 80 deg, azimuth 200 deg) down to MD 14 m."""
import math
import sys

kick_off, i, a = 3.75, math.radians(45), math.radians(120)
north, east, tvd = (kick_off * math.sin(i) * math.cos(a), kick_off * math.sin(i) * math.sin(a), kick_off * math.cos(i))
with open(sys.argv[1], "w") as f:
    f.write("md_m,inclination_deg,azimuth_deg,north_m,east_m,tvd_m\n")
    f.write(f"{kick_off},45,120,{north:.6f},{east:.6f},{tvd:.6f}\n")
    for md in (4.25, 5, 6, 7, 8, 9, 10, 11, 12, 14):
        f.write(f"{md},80,200,,,\n")
