#!/usr/bin/env python3
"""Runs the gap tool on two logs of one circuit (fit on the first, judged on the withheld
second) and prints the ranking, as `hstmon gap --circuit FILE --fit A --check B`.

    python3 examples/python/gap_ranking.py [FIT CHECK] [--circuit paper] [--report DIR]
"""
import argparse
from pathlib import Path

import hstmon

circuits = Path(__file__).resolve().parent.parent / "circuits"
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("fit", nargs="?", default=str(circuits / "paper.csv"))
parser.add_argument("check", nargs="?", default=str(circuits / "paper_dm_fault.csv"))
parser.add_argument("--circuit", default="paper", help="circuit file or shipped rig")
parser.add_argument("--report", default=None, help="write report.md and the tables to this folder")
args = parser.parse_args()

g = hstmon.gap(args.fit, args.check, args.circuit)
print(f"verdict: {g.verdict}")
print("\nwhere the gap lies (model − reading over the fit log's points, in sensor σ):")
print(g.where["mean_fit"].to_string(float_format=lambda v: f"{v:+.3g}"))
print("\ncandidates, best check RMS first:")
print(g.ranked.to_string(index=False, float_format=lambda v: f"{v:.4g}"))
if args.report:
    print(f"\nreport: {g.report(args.report)}")
