"""A module result in the shapes of `hstmon replay --circuit --json`, to compare line by line."""
from __future__ import annotations

import math
from typing import Any, Dict, List


def _num(v: float) -> Any:
    return v if math.isfinite(v) else None


def event_line(e: Dict[str, Any]) -> Dict[str, Any]:
    cands = []
    for c in e["candidates"]:
        j: Dict[str, Any] = {"fault": c["fault"], "score": c["score"]}
        if math.isfinite(c["size"]):
            j.update(size=c["size"], size_lo=_num(c["size_lo"]), size_hi=_num(c["size_hi"]), size_text=c["size_text"])
        cands.append(j)
    j = {"type": "event", "t": e["t"], "event": e["event"], "consistent": e["consistent"], "candidates": cands}
    if e["why"]:
        j["why"] = e["why"]
    return j


def json_lines(result) -> List[Dict[str, Any]]:
    """What the CLI prints for the same replay, less the file names in its first line."""
    raw = result.raw
    head = {"type": "replay", "circuit": result.circuit.name, "rows": raw["rows"], "t_first": raw["t_first"],
            "t_last": raw["t_last"], "tick_s": raw["tick"], "ticks": raw["ticks"], "start": raw["start"],
            "startup_hold_s": raw["startup_hold"], "fault_table_rows": raw["table_rows"],
            "undetectable": raw["undetectable"], "states": raw["states"], "stiff_nodes": raw["stiff_nodes"],
            "health": raw["health"], "unhealthy_rows": raw["unhealthy_rows"], "max_substeps": raw["max_substeps"],
            "implicit_ticks": raw["implicit_ticks"],
            "notes": raw["notes"]}
    lines = [head]
    for ch in raw["channels"]:
        j = {"type": "residual", "channel": ch["channel"], "unit": ch["unit"], "measured": ch["measured"],
             "sensor_noise": ch["sensor_noise"], "clipped_rows": ch["clipped_rows"], "n": ch["n"]}
        if ch["n"] > 0:
            j.update({k: _num(ch[k]) for k in ("mean", "rms", "max_abs", "max")})
            j["t_max"] = ch["t_max"]
            j["noise"] = _num(ch["noise"])
        lines.append(j)
    lines.append({"type": "bound", "at": "last row",
                  "channels": [{"channel": b["channel"], "bound": b["bound"], "lead": b["lead"], "share": b["share"]}
                               for b in raw["bound"]]})
    env = raw["envelope"]
    lines.append({"type": "envelope", "checked": env["checked"], "out": env["out"], "unverified": env["unverified"],
                  "text": env["text"]})
    lines += [event_line(e) for e in raw["events"]]
    diagnosis = {"type": "diagnosis", "status": raw["status"], "events": len(raw["events"])}
    if raw.get("verdict") is not None:
        diagnosis.update({"class": raw["class"], "split_by": raw["split_by"], "verdict": raw["verdict"]})
    lines.append(diagnosis)
    return lines


def without_files(lines: List[Dict[str, Any]]) -> List[Dict[str, Any]]:
    out = []
    for j in lines:
        j = dict(j)
        for k in ("log", "circuit_file", "params_file"):
            j.pop(k, None)
        out.append(j)
    return out
