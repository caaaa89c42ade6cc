"""The replay's figure: measured and model over time, the residual within its bound, the events."""
from __future__ import annotations

from typing import Any, List, Optional


def replay_figure(result: Any, channels: Optional[List[str]] = None):
    """A matplotlib figure of a replay kept with its residuals (SI units)."""
    import matplotlib
    if matplotlib.get_backend().lower() not in ("agg", "pdf", "svg", "ps", "cairo") and not _has_display():
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    res = result.residuals
    stats = result.stats
    names = channels or [ch for ch in stats.index if bool(stats.loc[ch, "measured"])]
    if not names:
        raise ValueError("no measured channel to plot")
    fig, axes = plt.subplots(len(names), 2, figsize=(11, 2.4 * len(names)), sharex=True, squeeze=False)
    for row, ch in zip(axes, names):
        unit = stats.loc[ch, "unit"]
        row[0].plot(res["t"], res[ch], lw=0.6, label="measured")
        row[0].plot(res["t"], res[f"{ch}_hat"], lw=0.9, label="model")
        row[0].set_ylabel(f"{ch} [{unit}]")
        row[1].plot(res["t"], res[f"r_{ch}"], lw=0.6, color="C2", label="residual")
        row[1].plot(res["t"], res[f"b_{ch}"], lw=0.6, color="0.5", ls="--", label="bound")
        row[1].plot(res["t"], -res[f"b_{ch}"], lw=0.6, color="0.5", ls="--")
        row[1].set_ylabel(f"r {ch} [{unit}]")
        for ax in row:
            for _, e in result.events.iterrows():
                ax.axvline(e["t"], color="C3" if e["event"] != "cleared" else "C7", lw=0.7, alpha=0.6)
    axes[0][0].legend(loc="best", fontsize="small")
    axes[0][1].legend(loc="best", fontsize="small")
    for ax in axes[-1]:
        ax.set_xlabel("t [s]")
    title = f"{result.log} on {result.circuit.name}: {result.status}"
    ev = result.events
    first = ev[ev["event"] == "isolated"]
    if len(first):
        title += f" ({', '.join(first.iloc[0]['faults'][:3])} at {first.iloc[0]['t']:.3f} s)"
    fig.suptitle(title + "   residual = measured − model")
    fig.tight_layout()
    return fig


def _has_display() -> bool:
    import os
    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))
