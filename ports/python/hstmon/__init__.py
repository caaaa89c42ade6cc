"""hstmon: monitoring of hydrostatic transmissions, from Python.

The same libraries and the same answers as the ``hstmon`` command line, on the circuit
path: a machine is a circuit file (the thesis rig's ``thesis.json`` by default), a log is
a path or a pandas DataFrame with a CSV log's columns, results are DataFrames in SI units.

    >>> import hstmon
    >>> r = hstmon.replay("examples/prv_blockage.csv")      # the thesis rig
    >>> r.events[["t", "event", "faults"]]
    >>> r.stats                                              # residual = measured − model
    >>> hstmon.gap("healthy.csv", "check.csv", circuit="paper").verdict

See docs/python.md.
"""
from __future__ import annotations

from . import _core
from ._analysis import GapResult, IdentifyResult, gap, identify, simulate
from ._circuit import RIGS, Circuit
from ._errors import SourceError
from ._fleet import fleet_logs, machine_of, summary
from ._logs import READ_OPTIONS
from ._replay import REPLAY_OPTIONS, ReplayResult, replay

__all__ = [
    "Circuit", "RIGS", "SourceError", "READ_OPTIONS", "REPLAY_OPTIONS",
    "replay", "ReplayResult", "simulate", "identify", "IdentifyResult", "gap", "GapResult",
    "summary", "fleet_logs", "machine_of", "read_log",
]


def read_log(log, circuit=None, params=None, **read_options):
    """A log as the reader sees it for a circuit: a DataFrame in SI units (``t[s]``,
    ``<column>[<SI unit>]``), through the CLI's reader (units, maps, checks). Raises
    SourceError (file, line, column) as the CLI would for the same log."""
    from . import _logs
    from ._circuit import resolve
    c = resolve(circuit, params)
    from ._analysis import _only_read_options
    return _logs.to_frame(c, _logs.read(c, log, None, **_only_read_options(read_options, "read_log")))
