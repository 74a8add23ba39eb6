#!/usr/bin/env python3
"""Summary of bench/run_peers.sh's table out/peers/peers_LEVEL.csv as markdown.

Usage: bench/peers/peers_table.py out/peers/peers_3.csv [...]
Per scene: Jolt's cheapest setting, the cheapest run of each program within 1 % (and 10 %) of the reference's volume,
the smallest volume error each program reaches, and Jolt's error against its substep (dt / iterations).
"""
import csv, sys
from fractions import Fraction

def rows_of(path):
    rows = list(csv.DictReader(open(path)))
    for r in rows:
        r['cpu'] = float(r['cpu_per_sim_s'])
        r['vol'] = float(r['volume_error_pct'])
        r['com'] = float(r['com_error_cm'])
    return rows

def setting(r):
    if r['program'] == 'jolt':
        return f"Jolt dt {r['dt_s']} s, {r['iterations']} it."
    if r['program'] == 'xpbd':
        return f"xpbd substeps {r['substeps']}"
    if r['program'] == 'vbd':
        alone = ", no coarse level" if r['family'] == 'vbd_affine' else ""
        return f"vbd substeps {r['substeps']}, {r['iterations']} sweeps{alone}"
    if r['program'] == 'bullet':
        return f"Bullet dt {r['dt_s']} s, {r['iterations']} position it."
    if r['program'] == 'rk45':
        return f"rk45 {r['dt_s']}"
    return f"{r['program']} dt auto"

def line(label, r):
    if r is None:
        return f"| {label} | – | – | – |"
    return f"| {label} | {setting(r)} | {r['cpu']:.3g} | {r['vol']:.3g} %, {r['com']:.3g} cm |"

for path in sys.argv[1:]:
    rows = rows_of(path)
    level = rows[0]['level']
    for scene in ('breathing', 'bounce'):
        s = [r for r in rows if r['scene'] == scene]
        print(f"\n**Level {level}, {scene}** (CPU s per simulated s; worst volume error, worst centre-of-mass distance)\n")
        print("| what | setting | CPU s / sim. s | error |\n|---|---|---|---|")
        jolt = [r for r in s if r['program'] == 'jolt']
        cheapest = min(jolt, key=lambda r: r['cpu'], default=None)
        print(line("Jolt's cheapest", cheapest))
        for program in ('jolt', 'xpbd', 'vbd', 'symplectic', 'verlet', 'rk4', 'rk45'):
            p = [r for r in s if r['program'] == program]
            for limit in (10.0, 1.0):
                ok = [r for r in p if r['vol'] <= limit]
                print(line(f"{program}, cheapest within {limit:g} % volume", min(ok, key=lambda r: r['cpu'], default=None)))
            print(line(f"{program}, smallest volume error", min(p, key=lambda r: r['vol'], default=None)))
        auto = [r for r in s if r['family'] == 'xpbd_auto']
        if auto:
            print(line("xpbd auto", auto[0]))
        if jolt:
            print("\nJolt by substep length dt / iterations (runs with equal substeps give the same error):\n")
            print("| substeps per s | volume error [%] | centre of mass [cm] | CPU s / sim. s |\n|---|---|---|---|")
            by = {}
            for r in jolt:
                n = int(round(1 / float(Fraction(r['dt_s'])))) * int(r['iterations'])
                by.setdefault(n, []).append(r)
            for n in sorted(by):
                rs = by[n]
                vols = sorted({f"{r['vol']:.3g}" for r in rs}, key=float)
                coms = sorted({f"{r['com']:.3g}" for r in rs}, key=float)
                print(f"| {n} | {', '.join(vols)} | {', '.join(coms)} | {min(r['cpu'] for r in rs):.3g} |")
