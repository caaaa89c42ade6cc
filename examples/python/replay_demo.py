#!/usr/bin/env python3
"""Replays the demo log (a PRV blockage on the thesis rig), prints the diagnosis and saves
a residual plot, as `hstmon replay examples/prv_blockage.csv --plot residuals.png`.

    python3 examples/python/replay_demo.py [LOG] [--out residuals.png]
"""
import argparse
from pathlib import Path

import hstmon

here = Path(__file__).resolve().parent
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("log", nargs="?", default=str(here.parent / "prv_blockage.csv"))
parser.add_argument("--circuit", default=None, help="circuit file or shipped rig (default: thesis)")
parser.add_argument("--out", default="residuals.png", help="the residual plot (.png, .svg, .pdf)")
args = parser.parse_args()

r = hstmon.replay(args.log, args.circuit)
print(f"{r.log} on {r.circuit.name}: {r.raw['rows']} rows, status {r.status}")
print("\nresidual = measured − model [SI]")
print(r.stats[["unit", "mean", "rms", "noise"]].to_string(float_format=lambda v: f"{v:.4g}"))
print("\ndiagnosis (best first):")
for _, e in r.events.iterrows():
    faults = ", ".join(f"{f} ({s:.3f})" for f, s in zip(e["faults"][:3], e["scores"][:3]))
    print(f"  t = {e['t']:9.3f} s  {e['event']}: {faults or e['why']}")
r.plot().savefig(args.out, dpi=110)
print(f"\nresiduals plotted to {args.out}")
