#!/usr/bin/env python3
"""The limit of two softbody CSVs made with a model parameter at p and p/2, where the path converges linearly in it:
2 x HALF - FULL, column by column (centre of mass, velocity, volume, lowest point), the rest of HALF's row kept.

Usage: bench/extrapolate_csv.py FULL.csv HALF.csv OUT.csv
(bench/run_hard_contact_limit.sh: the bounce's paths as the smooth floor's time constant goes to 0, the hard contact.)
"""
import csv, sys

EXTRAPOLATED = ('com_x', 'com_y', 'com_z', 'vel_x', 'vel_y', 'vel_z', 'volume', 'min_y')
full, half = (list(csv.DictReader(open(p))) for p in sys.argv[1:3])
if [(r['frame'], r['body']) for r in full] != [(r['frame'], r['body']) for r in half]:
    sys.exit(f"{sys.argv[0]}: {sys.argv[1]} and {sys.argv[2]} do not have the same frames and bodies")
with open(sys.argv[3], 'w', newline='') as f:
    out = csv.DictWriter(f, fieldnames=list(half[0].keys()))
    out.writeheader()
    for a, b in zip(full, half):
        row = dict(b)
        for column in EXTRAPOLATED:
            row[column] = repr(2.0 * float(b[column]) - float(a[column]))
        out.writerow(row)
