"""hstmon.simulate, hstmon.identify and hstmon.gap: the circuit tools of hstmon-sim
--circuit, ``hstmon identify --circuit`` and ``hstmon gap --circuit``."""
from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence, Union

import pandas as pd

from . import _core, _logs
from ._circuit import Circuit, PathLike, resolve

CircuitLike = Union[None, str, PathLike, Circuit]
LogLike = Union[PathLike, pd.DataFrame]


def simulate(circuit: CircuitLike = None, inputs: Optional[LogLike] = None, *, duration: Optional[float] = None,
             rate: Optional[float] = None, seed: int = 1, start: str = "steady", noise: bool = True,
             steps: Sequence[str] = (), faults: Sequence[str] = (), params: Optional[PathLike] = None,
             hold: str = "linear") -> pd.DataFrame:
    """Simulates a circuit as ``hstmon-sim --circuit`` does: the full equations (stiff
    Rosenbrock-4), the outputs through the sensor chain (noise and range from the circuit's
    sensors section).

    inputs: a DataFrame (or log path) of input columns over time (``t[s]`` and any of the
        circuit's input columns, with units as in a log) driving the run on its own clock:
        from its first row's time to its last, rows at its own row times.
    hold: how the inputs go between rows: "linear" (the line between them) or "step"
        (each row held until the next, zero-order hold).
    duration [s], rate [Hz]: the run (default 10 s at 100 Hz, or the inputs' span and rows;
        a rate then writes rows t0 + k/rate).
    seed: the noise seed; start: "steady" (the steady state of the first inputs) or "rest";
    noise: False = no sensor noise (clipping kept).
    steps: input steps "INPUT=VALUE@T" ("n_e=1800 rpm@2.5"); faults: "PARAM=FACTOR@T" ("kp=0.5@80").

    Returns a DataFrame in SI units with header-style names (``t[s]``, ``p_mi[Pa]``, …),
    which hstmon.replay reads back as it is. The GIL is released while it runs.
    """
    c = resolve(circuit, params)
    data = None
    if inputs is not None:
        data = _logs.read(c, inputs, "inputs")
    log = _core.simulate(c._core, data, duration=float(duration or 0.0), rate=float(rate or 0.0), seed=int(seed),
                         start=start, noise=bool(noise), steps=list(steps), faults=list(faults), hold=hold)
    return _logs.to_frame(c, log)


def _only_read_options(options: Dict[str, Any], function: str) -> Dict[str, Any]:
    read_kw, rest = _logs.split_read_options(options)
    if rest:
        raise TypeError(f"{function}() got unknown options {sorted(rest)}; the log options are {list(_logs.READ_OPTIONS)}")
    return read_kw


class _ToolResult:
    """What the results of identify and gap share: the circuit, the C++ outcome (whose text
    and report are the CLI's) and its dict ``raw``."""

    def __init__(self, circuit: Circuit, outcome: Any) -> None:
        self.circuit = circuit
        self._outcome = outcome
        self.raw = outcome.as_dict()

    @property
    def text(self) -> str:
        """What ``hstmon identify --circuit`` or ``hstmon gap --circuit`` prints for the same run."""
        return self._outcome.text


class IdentifyResult(_ToolResult):
    """The result of hstmon.identify: fitted values [SI] and residuals in sensor σ."""

    @property
    def parameters(self) -> pd.DataFrame:
        """Per fitted parameter: ``name``, ``start`` and ``value`` [SI], ``change`` [-]
        (value/start − 1), ``rel_se`` (standard error relative to the value [-]), ``unit``."""
        df = pd.DataFrame(self.raw["parameters"], columns=["name", "start", "value", "rel_se", "unit"])
        df.insert(3, "change", df["value"] / df["start"] - 1.0)
        return df

    @property
    def points(self) -> pd.DataFrame:
        """The operating points: ``log`` (index in the logs given), ``t0``/``t1`` [s],
        ``rows``, and per channel the residual (mean reading − model, in σ) before and after."""
        rows = []
        names = [s["name"] for s in self.circuit.sensors]
        for p in self.raw["points"]:
            row = {"log": p["log"], "t0": p["t0"], "t1": p["t1"], "rows": p["rows"]}
            for k, n in enumerate(names):
                row[f"before_{n}"] = p["before"][k] if k < len(p["before"]) else float("nan")
                row[f"after_{n}"] = p["after"][k] if k < len(p["after"]) else float("nan")
            rows.append(row)
        return pd.DataFrame(rows)

    @property
    def verdict(self) -> str:
        """The solver's stop reason."""
        return self.raw["status"]

    status = verdict
    rms_before = property(lambda self: self.raw["rms_before"], doc="residual RMS before the fit [σ]")
    rms_after = property(lambda self: self.raw["rms_after"], doc="residual RMS after the fit [σ]")
    notes = property(lambda self: list(self.raw["notes"]), doc="what the operating-point search noted")
    values_json = property(lambda self: self.raw["values_json"],
                           doc="the parameter file with the fitted values (identify --out)")

    def values(self) -> Dict[str, float]:
        """The fitted values by name [SI]."""
        return {p["name"]: p["value"] for p in self.raw["parameters"]}

    def write_params(self, path: PathLike) -> None:
        """Writes the fitted parameter file (as ``identify --out``)."""
        Path(path).write_text(self.values_json, encoding="utf-8")

    def report(self, folder: PathLike) -> Path:
        """Writes the report folder ``hstmon identify --circuit --report`` writes (report.md,
        report.html, the figure with figure.dat and plots.gp), plus parameters.csv,
        points.csv and fitted.params.json; returns the path of report.md."""
        from ._report import identify_report
        return identify_report(self, Path(folder))


def identify(logs: Union[LogLike, Sequence[LogLike]], fit: Union[str, Sequence[str], None] = None,
             circuit: CircuitLike = None, params: Optional[PathLike] = None, min_duration: float = 0.2,
             **read_options: Any) -> IdentifyResult:
    """Fits parameters of the circuit to the steady operating points of its logs, as
    ``hstmon identify --circuit FILE --fit P1,P2 LOG...``.

    logs: one log or several (paths or DataFrames); fit: parameter names ("Dm,Rmlkg" or a
    list; None: the circuit's losses and openings, those the points cannot determine held);
    params: the starting values' parameter file; min_duration: the shortest steady
    stretch after the settle time [s]; read_options: the log options (separator, lenient,
    rate, encoding, map). Raises SourceError for a bad file, ValueError when nothing can be fitted.
    """
    c = resolve(circuit, params)
    if isinstance(logs, (str, os.PathLike, pd.DataFrame)):
        logs = [logs]
    names = [] if fit is None else [n.strip() for n in fit.split(",")] if isinstance(fit, str) else list(fit)
    read_kw = _only_read_options(read_options, "identify")
    data = [_logs.read(c, log, f"DataFrame {k}", **read_kw) for k, log in enumerate(logs)]
    labels = [os.fspath(x) if not isinstance(x, pd.DataFrame) else f"DataFrame {k}" for k, x in enumerate(logs)]
    return IdentifyResult(c, _core.identify(c._core, data, names, float(min_duration), labels))


class GapResult(_ToolResult):
    """The result of hstmon.gap: the verdict, where the gap lies, and the candidates ranked."""

    def __init__(self, circuit: Circuit, outcome: Any, fit_log: str, check_log: str) -> None:
        super().__init__(circuit, outcome)
        self.fit_log = fit_log
        self.check_log = check_log

    @property
    def verdict_text(self) -> str:
        """The verdict in one sentence, as the CLI says it."""
        return self._outcome.verdict_text

    @property
    def verdict(self) -> str:
        """The named effect ("leak(Pmi)", "friction(motor)", "offset(p_mi)", "parameter(Dm)"),
        "none", "insufficient_data", "ambiguous: A or B" or "unexplained"."""
        return self.raw["verdict"]

    @property
    def ranked(self) -> pd.DataFrame:
        """Every candidate, best check RMS first: ``effect``, fitted ``magnitude`` in ``unit``
        (SI), ``rms_fit``/``rms_check`` [σ], ``shrink`` (of the check log's RMS [-]),
        ``z_check`` (what remains beyond noise and uncertainty [σ])."""
        df = pd.DataFrame(self.raw["ranked"], columns=["effect", "magnitude", "unit", "rms_fit", "rms_check", "z_check"])
        df.insert(5, "shrink", 1.0 - df["rms_check"] / self.raw["rms_check"])
        return df

    @property
    def where(self) -> pd.DataFrame:
        """Per channel: the mean residual over the fit log's points (measured − model, in σ;
        where the gap lies), and the σ each log is weighed in [SI]."""
        return pd.DataFrame({"mean_fit": self.raw["mean_fit"], "noise_fit": self.raw["noise_fit"],
                             "noise_check": self.raw["noise_check"]},
                            index=pd.Index(self.raw["channels"], name="channel"))

    notes = property(lambda self: list(self.raw["notes"]), doc="what the gap tool noted")
    evidence_missing = property(lambda self: self.raw["evidence_missing"],
                                doc="what the logs lack (verdict insufficient_data)")

    def to_json(self) -> str:
        """The result as ``hstmon gap --circuit --json`` keys (a JSON object)."""
        return json.dumps(self.raw, allow_nan=False, default=str)

    def report(self, folder: PathLike) -> Path:
        """Writes the report folder ``hstmon gap --circuit --report`` writes (report.md,
        report.html, the figure with figure.dat and plots.gp), plus ranked.csv and
        where.csv; returns the path of report.md."""
        from ._report import gap_report
        return gap_report(self, Path(folder))


def gap(fit: LogLike, check: LogLike, circuit: CircuitLike = None, params: Optional[PathLike] = None,
        **read_options: Any) -> GapResult:
    """Where the circuit's model and its machine disagree, which unmodelled effect explains
    it, and how far the gap shrinks with it, judged on the withheld log: ``hstmon gap
    --circuit FILE --fit LOG --check LOG``. fit, check: paths or DataFrames; read_options:
    the log options. The GIL is released while the candidates are fitted."""
    c = resolve(circuit, params)
    read_kw = _only_read_options(read_options, "gap")
    logs = [_logs.read(c, log, name, **read_kw) for log, name in ((fit, "fit DataFrame"), (check, "check DataFrame"))]
    label = [os.fspath(x) if not isinstance(x, pd.DataFrame) else n
             for x, n in ((fit, "fit DataFrame"), (check, "check DataFrame"))]
    return GapResult(c, _core.gap(c._core, logs[0], logs[1], label[0], label[1]), label[0], label[1])
