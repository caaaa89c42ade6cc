"""hstmon.Circuit: a circuit file with its values; the shipped rigs by name."""
from __future__ import annotations

import os
from pathlib import Path
from typing import Dict, List, Optional, Union

from . import _core

PathLike = Union[str, "os.PathLike[str]"]

#: The rigs shipped in examples/circuits (installed: <prefix>/share/hstmon/examples/circuits).
RIGS = ("thesis", "paper", "closed_loop_hst", "test_stand")


def rig_dirs() -> List[Path]:
    """Where the shipped rigs are looked for, in order: $HSTMON_RIGS, the source tree of a
    build (the build's package), the share directory of the prefix the package is installed
    under, and /usr/share/hstmon."""
    here = Path(__file__).resolve().parent
    dirs: List[Path] = []
    if os.environ.get("HSTMON_RIGS"):
        dirs.append(Path(os.environ["HSTMON_RIGS"]))
    marker = here / "_build_tree.txt"
    if marker.is_file():
        dirs.append(Path(marker.read_text(encoding="utf-8").strip()))
    # <prefix>/lib/python3.X/dist-packages/hstmon → <prefix>/share/hstmon/examples/circuits
    if len(here.parents) > 3:
        dirs.append(here.parents[3] / "share" / "hstmon" / "examples" / "circuits")
    dirs.append(Path("/usr/share/hstmon/examples/circuits"))
    return dirs


class Circuit:
    """A circuit file and the values bound to it, as ``hstmon replay --circuit FILE
    [--params FILE]`` loads it. Values are SI throughout (Pa, rad/s, m³/s, s).

    A Circuit pickles as its file names (a Dask worker loads it again), so the files must
    be readable where it is unpickled.
    """

    def __init__(self, core: "_core.Circuit") -> None:
        self._core = core

    @staticmethod
    def load(path: PathLike, params: Optional[PathLike] = None) -> "Circuit":
        """Loads a circuit file. ``params``: its parameter file; None = ``<stem>.params.json``
        beside it if there is one, else the circuit file's own values.

        Raises hstmon.SourceError (file, line, column) for a bad file."""
        return Circuit(_core.Circuit(os.fspath(path), "" if params is None else os.fspath(params)))

    @staticmethod
    def rig(name: str) -> "Circuit":
        """A shipped rig by name: ``thesis`` (the default of hstmon.replay), ``paper``,
        ``closed_loop_hst``, ``test_stand``; each with its ``<name>.params.json``."""
        if name not in RIGS:
            raise ValueError(f"no shipped rig '{name}': the rigs are {', '.join(RIGS)}")
        for d in rig_dirs():
            f = d / f"{name}.json"
            if f.is_file():
                return Circuit.load(f)
        raise FileNotFoundError(f"rig '{name}' not found in " + ", ".join(str(d) for d in rig_dirs()) +
                                " (set HSTMON_RIGS to the folder of the circuit files)")

    @property
    def name(self) -> str:
        """The circuit's name (its file's "circuit")."""
        return self._core.name

    @property
    def path(self) -> str:
        """The circuit file as given."""
        return self._core.path

    @property
    def params_path(self) -> str:
        """The parameter file used ("" = the circuit file's own values)."""
        return self._core.params_path

    @property
    def inputs(self) -> List[Dict[str, object]]:
        """Inputs: name, log column, unit (the column's default), quantity, nominal value [SI]."""
        return self._core.inputs

    @property
    def sensors(self) -> List[Dict[str, object]]:
        """Sensors (the monitor's channels): name, log column, unit, SI unit, quantity,
        noise σ [SI], transmitter range lo/hi [SI]."""
        return self._core.sensors

    @property
    def parameters(self) -> List[str]:
        """The parameters' names."""
        return self._core.parameters

    def fault_hypotheses(self) -> List[str]:
        """The fault matcher's hypotheses (``kp-``, ``sensor_p_pp``, …), its table built on first use."""
        return self._core.fault_table_rows()

    def __reduce__(self):
        return (_load_again, (self._core.path, self._core.params_given))

    def __repr__(self) -> str:
        params = f", params={self.params_path!r}" if self.params_path else ""
        return f"hstmon.Circuit({self.name!r} from {self.path!r}{params})"


_loaded: Dict[tuple, Circuit] = {}


def _load_again(path: str, params: str) -> Circuit:
    """An unpickled Circuit: loaded once per process while its files are unchanged, so a
    Dask worker builds its fault table once, not per task."""
    def stamp(p: str) -> float:
        try:
            return os.stat(p).st_mtime_ns if p else 0
        except OSError:
            return -1
    implied = params or os.path.splitext(path)[0] + ".params.json"  # <stem>.params.json beside it
    key = (path, params, stamp(path), stamp(implied))
    if key not in _loaded:
        _loaded[key] = Circuit(_core.Circuit(path, params))
    return _loaded[key]


_default: Optional[Circuit] = None


def resolve(circuit: Union[None, str, PathLike, Circuit], params: Optional[PathLike] = None) -> Circuit:
    """A Circuit from what a function was given: None = the thesis rig (as the CLI with no
    --circuit), a Circuit, a rig's name or a circuit file's path."""
    global _default
    if isinstance(circuit, Circuit):
        if params is not None:
            return Circuit.load(circuit.path, params)
        return circuit
    if circuit is None:
        if params is not None:
            return Circuit.load(Circuit.rig("thesis").path, params)
        if _default is None:
            _default = Circuit.rig("thesis")
        return _default
    text = os.fspath(circuit)
    if text in RIGS and not os.path.exists(text):
        return Circuit.rig(text) if params is None else Circuit.load(Circuit.rig(text).path, params)
    return Circuit.load(text, params)
