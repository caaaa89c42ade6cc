"""hstmon.replay: a log through its circuit's monitor, as ``hstmon replay --circuit``."""
from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any, Dict, List, Optional, Union

import numpy as np
import pandas as pd

from . import _core, _logs
from ._circuit import Circuit, PathLike, resolve

#: The replay options, with the CLI's meaning: tick [s] (--tick; 0 = the log's median
#: period, at most 10 ms), init ("auto" | "rest" | "steady": --init), diagnosis (False =
#: --no-diagnosis), matcher_only (True = --matcher-only: the firmware's verdict, no fit),
#: residuals (keep the per-row trace: .residuals, .plot()).
REPLAY_OPTIONS = ("tick", "init", "diagnosis", "matcher_only", "residuals")


def replay(log: Union[PathLike, pd.DataFrame], circuit: Union[None, str, PathLike, Circuit] = None,
           params: Optional[PathLike] = None, name: Optional[str] = None, **options: Any) -> "ReplayResult":
    """Replays a log through the circuit's monitor: observer, sensor checks, residual
    evaluator and fault matcher on the circuit's table, then the fit of the steady windows
    (as ``hstmon replay --circuit FILE [--params FILE] LOG``).

    log: a path (CSV/TSV, plain or .gz) or a pandas DataFrame with the columns a CSV log
        has (``t[s]``, ``p_mi[bar]``, …; a bare name is in the unit the circuit file gives
        the column).
    circuit: a Circuit, a shipped rig's name, a circuit file, or None for the thesis rig.
    params: the circuit's parameter file (None: ``<stem>.params.json`` beside it).
    name: the DataFrame's name in messages (default "DataFrame").
    options: the CLI's options: the log options ``separator``, ``lenient``, ``rate`` [Hz],
        ``encoding``, ``map``; and ``tick`` [s], ``init``, ``diagnosis``, ``matcher_only``,
        ``residuals`` (see REPLAY_OPTIONS, hstmon.READ_OPTIONS).

    Raises hstmon.SourceError (file, line, column) for a bad circuit, parameter file or log;
    with ``lenient=True`` the rows before a bad one are replayed and ``.read_error`` says why.
    The GIL is released while the log is read and replayed.
    """
    c = resolve(circuit, params)
    read_options, rest = _logs.split_read_options(options)
    unknown = sorted(set(rest) - set(REPLAY_OPTIONS))
    if unknown:
        raise TypeError(f"replay() got unknown options {unknown}; the options are "
                        f"{sorted(REPLAY_OPTIONS + _logs.READ_OPTIONS)}")
    data = _logs.read(c, log, name, **read_options)
    run = dict(tick=float(rest.get("tick", 0.0) or 0.0), init=str(rest.get("init", "auto")),
               diagnose=bool(rest.get("diagnosis", True)), fit=not bool(rest.get("matcher_only", False)))
    raw = _core.replay(data, keep_trace=bool(rest.get("residuals", False)), **run)
    label = os.fspath(log) if not isinstance(log, pd.DataFrame) else (name or "DataFrame")
    return ReplayResult(c, data, raw, run, label)


class ReplayResult:
    """The result of hstmon.replay. Every value is SI (Pa, rad/s, m³/s; times in s)."""

    def __init__(self, circuit: Circuit, log: "_core.Log", raw: Dict[str, Any], run: Dict[str, Any], label: str) -> None:
        self.circuit = circuit
        self.log = label
        self.raw = raw  #: the replay as a dict, as `hstmon replay --circuit --json` prints it
        self._data = log
        self._run = run

    # What the CLI prints -------------------------------------------------------------
    @property
    def status(self) -> str:
        """The diagnosis at the end of the log: ``nominal``, ``detected``, ``isolated``,
        ``ambiguous``, ``unexplained``, ``out_of_envelope``, ``unverified``, or ``not_run`` (no fault table
        or ``diagnosis=False``)."""
        return self.raw["status"]

    @property
    def verdict(self) -> Optional[str]:
        """The final verdict in words: the status, what the final candidates share and what
        would tell them apart, e.g. ``ambiguous: a leak between line A and line B: R_ip-, R_im-
        (a flow meter on leak_pump would tell them apart)``; None when the monitor ended on no
        candidates. ``raw["class"]`` and ``raw["split_by"]`` hold its two parts."""
        return self.raw.get("verdict")

    @property
    def events(self) -> pd.DataFrame:
        """The monitor's events in time order: ``t`` [s], ``event`` (detected, isolated,
        ambiguous, unexplained, cleared, out_of_envelope, unverified), ``faults`` (names, best first),
        ``scores`` (the matcher's score per fault, 0…1), ``consistent`` (hypotheses still
        consistent), ``sizes`` (the fit's size per fault in words, "" without one), ``why``."""
        rows = [{"t": e["t"], "event": e["event"],
                 "faults": [c["fault"] for c in e["candidates"]],
                 "scores": [c["score"] for c in e["candidates"]],
                 "consistent": e["consistent"],
                 "sizes": [c["size_text"] for c in e["candidates"]],
                 "why": e["why"]} for e in self.raw["events"]]
        return pd.DataFrame(rows, columns=["t", "event", "faults", "scores", "consistent", "sizes", "why"])

    @property
    def stats(self) -> pd.DataFrame:
        """Per channel (index: the circuit's sensor names), residual = measured − model:
        ``unit`` (SI), ``measured`` (in the log), ``n``, ``mean``, ``rms``, ``noise``
        (scatter from successive samples), ``max_abs``, ``max`` (signed), ``t_max`` [s],
        ``sensor_noise`` (the sensor's σ), ``clipped_rows`` (readings at a range end, not compared)."""
        cols = ["unit", "measured", "n", "mean", "rms", "noise", "max_abs", "max", "t_max", "sensor_noise",
                "clipped_rows"]
        rows = [{k: ch.get(k, math.nan) for k in cols} for ch in self.raw["channels"]]
        return pd.DataFrame(rows, columns=cols, index=pd.Index([ch["channel"] for ch in self.raw["channels"]],
                                                               name="channel"))

    @property
    def envelope(self) -> Dict[str, Any]:
        """Does the model describe this machine at its first steady stretch? checked, out,
        t0/t1 [s] of the window judged, text."""
        return self.raw["envelope"]

    @property
    def bound(self) -> "pd.DataFrame":
        """Per channel, the model bound at the last row's inputs [SI] and the parameter whose
        uncertainty leads it (``lead``, ``share`` of the bound): what ``identify`` would pin
        down to make smaller faults visible there."""
        cols = ["bound", "lead", "share"]
        rows = [{k: b[k] for k in cols} for b in self.raw["bound"]]
        return pd.DataFrame(rows, columns=cols, index=pd.Index([b["channel"] for b in self.raw["bound"]],
                                                               name="channel"))

    @property
    def notes(self) -> List[str]:
        """The reader's notes (file:line:column) and the replay's."""
        return list(self._data.notes) + list(self.raw["notes"])

    @property
    def read_error(self) -> Optional[str]:
        """With lenient=True: the reader's error after the rows replayed, else None."""
        e = self._data.error
        return None if e is None else str(_errors_of(e))

    @property
    def residuals(self) -> pd.DataFrame:
        """Per log row: ``t`` [s], then per channel ``<ch>`` (measured), ``<ch>_hat``
        (model), ``r_<ch>`` (measured − model) and ``b_<ch>`` (the matcher's bound on |r|),
        SI, NaN where absent; ``health`` (observer HealthFlag bits). Needs
        ``replay(..., residuals=True)`` (as the CLI's --residuals)."""
        trace = self.raw.get("trace")
        if trace is None:
            raise ValueError("no residuals kept: replay(..., residuals=True)")
        data: Dict[str, np.ndarray] = {"t": trace["t"]}
        for k, ch in enumerate(self.raw["channels"]):
            name = ch["channel"]
            data[name] = trace["y"][:, k]
            data[f"{name}_hat"] = trace["y_hat"][:, k]
            data[f"r_{name}"] = trace["r"][:, k]
            data[f"b_{name}"] = trace["bound"][:, k]
        data["health"] = trace["health"]
        return pd.DataFrame(data)

    def with_residuals(self) -> "ReplayResult":
        """This replay again with the per-row trace kept (for .residuals and .plot())."""
        if "trace" in self.raw:
            return self
        raw = _core.replay(self._data, keep_trace=True, **self._run)
        return ReplayResult(self.circuit, self._data, raw, self._run, self.log)

    def plot(self, channels: Optional[List[str]] = None):
        """A matplotlib figure: per measured channel, measured and model over time, and the
        residual with the matcher's bound; the events as vertical lines."""
        from ._plot import replay_figure
        return replay_figure(self.with_residuals(), channels)

    def summary(self, machine_from: str = "parent") -> Dict[str, Any]:
        """The log's summary line as ``hstmon replay --circuit FILE FOLDER`` writes it (a dict;
        docs/fleet.md): the same keys and values."""
        from ._fleet import summary_of
        return summary_of(self, machine_from)

    def report(self, folder: PathLike) -> Path:
        """Writes report.md (verdict, events, residual statistics) and residuals.png to
        folder; returns the report's path."""
        from ._report import replay_report
        return replay_report(self, Path(folder))

    def __repr__(self) -> str:
        return (f"<hstmon.ReplayResult {self.log}: {self.raw['rows']} rows, status {self.status}, "
                f"{len(self.raw['events'])} events>")


def _errors_of(e: Any) -> Any:
    from ._errors import SourceError
    return SourceError(*e)
