#!/usr/bin/env python3
"""Replay speed of the Python module from a DataFrame in memory against the CLI from disk
(issue 32): a one-hour 1 kHz thesis-rig log (3.6 M rows) written by hstmon-sim, replayed
through the thesis circuit by
  - the CLI:    hstmon replay --circuit examples/circuits/thesis.json --json --no-progress LOG
  - the module: hstmon.replay(df), df = pd.read_csv(LOG, float_precision="round_trip")
                (the read is not timed: the frame is already in memory)
Best wall time of RUNS each, rows/s, the ratio (target >= 0.5), and the two replays'
events compared (they must be equal). Release build.

    /usr/bin/python3 bench/python_replay_speed.py [BUILD_DIR] [RUNS] [MINUTES]
        (default build/host-release, 3, 60)
"""
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

root = Path(__file__).resolve().parents[1]
build = Path(sys.argv[1] if len(sys.argv) > 1 else root / "build/host-release").resolve()
runs = int(sys.argv[2]) if len(sys.argv) > 2 else 3
minutes = int(sys.argv[3]) if len(sys.argv) > 3 else 60
if not (build / "python/hstmon").is_dir() or not (build / "bin/hstmon").is_file():
    subprocess.run(["cmake", "--build", str(build), "-j2", "--target", "hstmon", "hstmon-sim", "hstmon_python"],
                   check=True, stdout=subprocess.DEVNULL)
sys.path.insert(0, str(build / "python"))
import pandas as pd  # noqa: E402

import hstmon  # noqa: E402

circuit = root / "examples/circuits/thesis.json"
with tempfile.TemporaryDirectory() as tmp:
    log = Path(tmp) / f"rig_{minutes}min.csv"
    subprocess.run([str(build / "bin/hstmon-sim"), "--scenario", "rig", "--load", "steps", "--duration",
                    str(minutes * 60), "--rate", "1000", "--seed", "1", "--out", str(log)], check=True)
    cli = [str(build / "bin/hstmon"), "replay", "--circuit", str(circuit), "--json", "--no-progress", str(log)]
    best_cli, cli_out = float("inf"), ""
    for _ in range(runs):
        t0 = time.perf_counter()
        cli_out = subprocess.run(cli, check=True, capture_output=True, text=True).stdout
        best_cli = min(best_cli, time.perf_counter() - t0)
    t0 = time.perf_counter()
    df = pd.read_csv(log, float_precision="round_trip")
    read_s = time.perf_counter() - t0
    c = hstmon.Circuit.load(circuit)
    best_py, result = float("inf"), None
    for _ in range(runs):
        t0 = time.perf_counter()
        result = hstmon.replay(df, c)
        best_py = min(best_py, time.perf_counter() - t0)
    rows = len(df)
    cli_events = [j for j in map(json.loads, cli_out.splitlines()) if j["type"] == "event"]
    same = [(e["t"], e["event"], [x["fault"] for x in e["candidates"]]) for e in cli_events] == \
        [(e["t"], e["event"], [x["fault"] for x in e["candidates"]]) for e in result.raw["events"]]
    print(f"log: {minutes} min at 1 kHz, {rows} rows, {log.stat().st_size / 1e6:.0f} MB; best of {runs}")
    print(f"CLI from disk:          {best_cli:6.2f} s  {rows / best_cli / 1e6:.2f} M rows/s")
    print(f"module from DataFrame:  {best_py:6.2f} s  {rows / best_py / 1e6:.2f} M rows/s "
          f"(pd.read_csv, not timed: {read_s:.1f} s)")
    print(f"ratio module/CLI: {best_cli / best_py:.2f} (target >= 0.5); events equal: {same}")
    sys.exit(0 if same else 1)
