"""Logs in and out: a path or a pandas DataFrame read through the CLI's reader; a log as a DataFrame."""
from __future__ import annotations

import os
from typing import Any, Dict, Mapping, Optional, Tuple, Union

import numpy as np
import pandas as pd

from . import _core
from ._circuit import Circuit
from ._errors import SourceError

#: The log options of every command, with the CLI's meaning: separator (",", ";", "tab"),
#: lenient (--lenient), rate [Hz] (--rate), encoding (--encoding), map (--map: a dict
#: {column: signal} or a list of "COLUMN=SIGNAL" / "#N=SIGNAL").
READ_OPTIONS = ("separator", "lenient", "rate", "encoding", "map")


def split_read_options(options: Mapping[str, Any]) -> Tuple[Dict[str, Any], Dict[str, Any]]:
    """The log options (as _core's keywords) and the rest."""
    read: Dict[str, Any] = {}
    rest: Dict[str, Any] = {}
    for k, v in options.items():
        if k in READ_OPTIONS:
            read["maps" if k == "map" else k] = v
        else:
            rest[k] = v
    if "rate" in read and read["rate"] is None:
        read["rate"] = 0.0
    return read, rest


def read(circuit: Circuit, log: Any, name: Optional[str] = None, **read_options: Any) -> "_core.Log":
    """A log of `circuit` from a file path or a DataFrame (columns as a CSV log's header:
    ``t[s]``, ``p_mi[bar]``, ``q`` …; a bare name is in the unit the circuit file gives
    the column, else SI). Raises SourceError as the CLI reports the same log."""
    if isinstance(log, pd.DataFrame):
        return from_frame(circuit, log, name or "DataFrame", **read_options)
    if isinstance(log, _core.Log):
        return log
    return _core.read_log(circuit._core, os.fspath(log), **read_options)


def from_frame(circuit: Circuit, df: pd.DataFrame, source: str, **read_options: Any) -> "_core.Log":
    """A DataFrame's columns through the reader's header rules (names, units, maps, notes,
    checks), without a CSV round trip. A time index (named ``t`` or ``t[s]``) counts as a column."""
    if df.index.name is not None and str(df.index.name).split("[")[0].strip().lower() in ("t", "time"):
        df = df.reset_index()
    names = [str(c) for c in df.columns]
    used = _core.columns_used(circuit._core, names, source, **read_options)
    columns = []
    for k, (col, use) in enumerate(zip(df.columns, used)):
        if not use:
            columns.append(None)
            continue
        try:
            columns.append(df[col].to_numpy(dtype=np.float64, copy=False))
        except (TypeError, ValueError):
            raise SourceError(source, 1, k + 1, f"column '{names[k]}' is not numeric ({df[col].dtype})") from None
    return _core.log_from_columns(circuit._core, names, columns, len(df), source, **read_options)


def to_frame(circuit: Circuit, log: "_core.Log") -> pd.DataFrame:
    """A log as a DataFrame in SI units, its columns named as a CSV log's header with the
    unit written out (``t[s]``, ``p_mi[Pa]``, ``w_m[rad/s]``), so that the frame reads back
    (hstmon.replay, hstmon.simulate's inputs) with the same values."""
    data: Dict[str, np.ndarray] = {"t[s]": log.t}
    for items, values in ((circuit.inputs, log.inputs), (circuit.sensors, log.sensors)):
        for item in items:
            if item["name"] in values:
                data[f"{item['column']}[{item['si_unit']}]"] = values[item["name"]]
    return pd.DataFrame(data)


LogLike = Union[str, "os.PathLike[str]", pd.DataFrame]
