"""A fleet of logs: the summary line of ``hstmon replay --circuit FILE FOLDER`` per log, for
Dask, multiprocessing or a plain loop (docs/fleet.md)."""
from __future__ import annotations

import math
import os
import re
from pathlib import PurePath
from typing import Any, Dict, List, Optional, Union

from ._circuit import Circuit, PathLike, resolve
from ._errors import SourceError

MAX_NOTES = 30  # notes per line, as the CLI (cli_log_options.hpp kMaxNotes)
MAX_CHARS = 400  # bytes per message, as the CLI's capped()


def fleet_logs(*names: PathLike) -> List[str]:
    """The logs ``hstmon replay`` takes from files and folders: folders searched
    recursively for *.csv, *.tsv and *.txt; sorted by path (byte order), duplicates removed."""
    out = set()
    for name in map(os.fspath, names):
        if not os.path.isdir(name):
            out.add(name)
            continue
        for folder, _, files in os.walk(name):
            for f in files:
                if os.path.splitext(f)[1] in (".csv", ".tsv", ".txt"):
                    out.add(os.path.join(folder, f))
    return sorted(out, key=lambda p: p.encode("utf-8", "surrogateescape"))


def machine_of(path: str, rule: str = "parent") -> str:
    """The machine of a log (--machine-from): ``parent`` (its folder; the stem for a log
    given without one), ``stem``, or ``regex:PATTERN`` (the first capture group, "" when
    the pattern does not match)."""
    p = PurePath(path)
    if rule == "parent":
        parent = os.path.dirname(path)
        if parent and os.path.basename(parent) not in (".", ".."):
            return os.path.basename(parent)
        return p.stem
    if rule == "stem":
        return p.stem
    if rule.startswith("regex:"):
        pattern = re.compile(rule[len("regex:"):])
        if pattern.groups < 1:
            raise ValueError(f"'{rule}' needs a capture group, e.g. regex:(m[0-9]+)_")
        m = pattern.search(path)
        return (m.group(1) or "") if m else ""
    raise ValueError(f"'{rule}' is not parent, stem or regex:PATTERN")


def capped(message: str, max_chars: int = MAX_CHARS) -> str:
    """A message cut to max_chars bytes on a UTF-8 boundary, "… (N bytes in all)" appended."""
    b = message.encode("utf-8")
    if len(b) <= max_chars:
        return message
    cut = max_chars
    while cut > 0 and (b[cut] & 0xC0) == 0x80:
        cut -= 1
    return b[:cut].decode("utf-8") + f"… ({len(b)} bytes in all)"


def _number(v: Optional[float]) -> Optional[float]:
    return v if v is not None and math.isfinite(v) else None


def summary_of(result: Any, machine_from: str = "parent") -> Dict[str, Any]:
    """A replay's summary line (see summary())."""
    raw = result.raw
    line: Dict[str, Any] = {"type": "log", "log": result.log, "machine": machine_of(result.log, machine_from),
                            "circuit": result.circuit.name, "status": "ok"}
    if result.read_error is not None:
        line["error"] = capped(result.read_error)
    line["rows"] = raw["rows"]
    line["t_first"] = raw["t_first"]
    line["t_last"] = raw["t_last"]
    line["final_status"] = raw["status"]
    line["events"] = len(raw["events"])
    first = None  # the first isolation, ambiguity or unexplained episode: when and what
    for e in raw["events"]:
        if e["event"] in ("isolated", "ambiguous", "unexplained"):
            first = {"t": e["t"], "event": e["event"], "fault": e["candidates"][0]["fault"] if e["candidates"] else ""}
            break
    line["first_diagnosis"] = first
    line["health"] = list(raw["health"])
    residuals: Dict[str, Any] = {}
    for ch in raw["channels"]:
        if not ch["measured"] or ch["n"] == 0:
            continue
        residuals[ch["channel"]] = {"n": ch["n"], "mean": _number(ch["mean"]), "rms": _number(ch["rms"]),
                                    "max_abs": _number(ch["max_abs"]), "max": _number(ch["max"]),
                                    "t_max": ch["t_max"], "noise": _number(ch["noise"])}
    line["residuals"] = residuals
    line["notes"] = [capped(n) for n in result.notes[:MAX_NOTES]]
    return line


def summary(log: PathLike, circuit: Union[None, str, PathLike, Circuit] = None, machine_from: str = "parent",
            **options: Any) -> Dict[str, Any]:
    """The summary line of one log, as ``hstmon replay --circuit FILE LOG --summary`` writes
    it (parsed JSON: the same keys and values). A log that cannot be read gives a line with
    ``status`` "error" and the reader's ``error`` instead of raising, as the CLI goes on
    with the other logs. Options as hstmon.replay's (residuals are not kept)."""
    from ._replay import replay
    c = resolve(circuit, options.pop("params", None))
    path = os.fspath(log)
    try:
        result = replay(path, c, **options)
    except SourceError as e:
        return {"type": "log", "log": path, "machine": machine_of(path, machine_from), "circuit": c.name,
                "status": "error", "error": capped(str(e))}
    return summary_of(result, machine_from)
