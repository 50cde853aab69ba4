#!/usr/bin/env python3
"""The time-step study's table (scripts/timestep_study.sh): one row per run
of OUTDIR/<case>/<run>/, from its summary.json and history.csv."""
import csv
import json
import os
import sys


def impulse(history):
    """The trapezoid sum of penalty_force_x_N_per_m over the history's time, N s/m
    (aliased where the step's force alternates faster than the samples)."""
    with open(history) as f:
        rows = list(csv.DictReader(f))
    total = 0.0
    for a, b in zip(rows, rows[1:]):
        t0, t1 = float(a["time_s"]), float(b["time_s"])
        total += 0.5 * (t1 - t0) * (float(a["penalty_force_x_N_per_m"]) + float(b["penalty_force_x_N_per_m"]))
    return total


def main(out):
    print("| case | run | steps | impulse x, N s/m | com dx, mm | mass loss | fragments | broken bonds | wall, s |")
    print("|---|---|---|---|---|---|---|---|---|")
    for case in sorted(os.listdir(out)):
        folder = os.path.join(out, case)
        if not os.path.isdir(folder):
            continue
        for run in sorted(os.listdir(folder)):
            summary = os.path.join(folder, run, "summary.json")
            if not os.path.exists(summary):
                print(f"| {case} | {run} | failed | | | | | | |")
                continue
            s = json.load(open(summary))
            j = s.get("penalty_impulse_x_N_s_per_m")
            if j is None:  # a binary before the running impulse: the history's samples
                j = impulse(os.path.join(folder, run, "history.csv"))
            print(f"| {case} | {run} | {s.get('steps', '')} | {j:.5g} | {1e3 * s.get('com_dx_m', 0.0):.4g} | "
                  f"{100 * s.get('mass_loss', 0.0):.2f} % | {s.get('fragment_count', '')} | "
                  f"{100 * s.get('broken_bond_fraction', 0.0):.1f} % | {s.get('wall_s', 0.0):.1f} |")


main(sys.argv[1])
