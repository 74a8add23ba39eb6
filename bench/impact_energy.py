#!/usr/bin/env python3
"""Where a bounce's energy goes through its first impact, from softbody's CSV columns.

Usage: bench/impact_energy.py BEFORE_S AFTER_S RUN.csv [RUN2.csv ...]
For body 0 at BEFORE_S (in flight before the impact) and AFTER_S (in flight after it): the centre of mass's energy
(1/2 m |v_com|^2 + m g y_com; m 1 kg as in scenes/bounce_smooth.json, or --mass M given first) and the CSV's
total_energy (kinetic + gravity + springs + gas); what the impact took from each; and the centre's height at the last
row. With no dashpot and no friction on the floor the only sinks are the springs' dampers and the integrator.
"""
import csv, sys

G = 9.81  # m/s^2, scenes/bounce_smooth.json's gravity
args = sys.argv[1:]
mass = 1.0
if args and args[0] == '--mass':
    mass = float(args[1])
    args = args[2:]
before, after = float(args[0]), float(args[1])


def energies(row):
    """(centre of mass's energy, total energy) [J] of one CSV row."""
    v2 = sum(float(row[c]) ** 2 for c in ('vel_x', 'vel_y', 'vel_z'))
    return 0.5 * mass * v2 + mass * G * float(row['com_y']), float(row['total_energy'])


def at(rows, t):
    return min(rows, key=lambda r: abs(float(r['time']) - t))


print(f"{'run':40s} {'E_com before':>12s} {'after':>8s} {'lost':>6s} {'E_total lost':>13s} {'y at end':>9s}")
for path in args[2:]:
    rows = [r for r in csv.DictReader(open(path)) if r['body'] == '0']
    (com0, tot0), (com1, tot1) = energies(at(rows, before)), energies(at(rows, after))
    print(f"{path:40s} {com0:12.2f} {com1:8.2f} {com0 - com1:6.2f} {tot0 - tot1:13.2f} {float(rows[-1]['com_y']):9.3f}")
