#!/usr/bin/env python3
"""Worst volume error [%] and worst centre-of-mass error [cm] of CSVs against a reference CSV (softbody's columns).

Usage: bench/csv_errors.py REFERENCE.csv RUN.csv[,RUN2.csv...] [UNTIL_S]   (only rows with time <= UNTIL_S)
"""
import csv, sys, math
def load(p):
    rows = list(csv.DictReader(open(p)))
    return {(int(r['frame']), int(r['body'])): r for r in rows}
ref = load(sys.argv[1])
tmax = float(sys.argv[3]) if len(sys.argv) > 3 else 1e9
for p in sys.argv[2].split(','):
    a = load(p)
    vol = com = 0.0
    for k, r in a.items():
        if k not in ref or float(r['time']) > tmax + 1e-9: continue
        q = ref[k]
        vol = max(vol, abs(float(r['volume']) - float(q['volume'])) / float(q['volume']))
        com = max(com, math.dist([float(r[c]) for c in ('com_x','com_y','com_z')], [float(q[c]) for c in ('com_x','com_y','com_z')]))
    print(f"{p}: vol {vol*100:.3g} %  com {com*100:.3g} cm")
