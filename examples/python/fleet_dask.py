#!/usr/bin/env python3
"""A fleet under Dask: every log of a folder replayed through one circuit on a LocalCluster
with dask.bag; prints the summary lines of `hstmon replay --circuit FILE FOLDER` (JSON, in
the order of the sorted paths) and the machines whose last log names a fault.

    python3 examples/python/fleet_dask.py FOLDER [--circuit paper] [--workers 2]

For a cluster beyond one machine, give the scheduler's address (--scheduler tcp://host:8786):
the circuit and the logs must be readable at the same paths on every worker.
"""
import argparse
import json

import dask.bag as db
from distributed import Client, LocalCluster

import hstmon

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("folder")
parser.add_argument("--circuit", default="thesis", help="circuit file or shipped rig")
parser.add_argument("--workers", type=int, default=2)
parser.add_argument("--scheduler", default=None, help="an existing Dask scheduler's address")
args = parser.parse_args()

circuit = hstmon.Circuit.rig(args.circuit) if args.circuit in hstmon.RIGS else hstmon.Circuit.load(args.circuit)
logs = hstmon.fleet_logs(args.folder)
cluster = None if args.scheduler else LocalCluster(n_workers=args.workers, threads_per_worker=1,
                                                   dashboard_address=None)
with Client(args.scheduler or cluster):
    lines = db.from_sequence(logs, npartitions=max(1, min(len(logs), 4 * args.workers))) \
        .map(hstmon.summary, circuit=circuit).compute()
for line in lines:
    print(json.dumps(line, sort_keys=True, separators=(",", ":"), ensure_ascii=False))
last = {}
for line in lines:
    if line["status"] == "ok":
        last[line["machine"]] = line
for machine, line in sorted(last.items()):
    if line["first_diagnosis"]:
        print(f"# {machine}: {line['first_diagnosis']['fault']} in {line['log']}")
if cluster is not None:
    cluster.close()
