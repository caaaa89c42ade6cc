"""Reports in a folder. identify and gap write the CLI's own report (the C++ core's writer)
plus CSV tables of their results; replay writes report.md, CSV tables and a figure."""
from __future__ import annotations

from pathlib import Path
from typing import Any

import pandas as pd


def _table(df: pd.DataFrame) -> str:
    """A DataFrame as a Markdown table (no optional dependency: pandas' to_markdown needs tabulate)."""
    cols = [str(c) for c in df.columns]
    lines = ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
    for _, row in df.iterrows():
        lines.append("| " + " | ".join(_cell(v) for v in row) + " |")
    return "\n".join(lines)


def _cell(v: Any) -> str:
    if isinstance(v, float):
        return f"{v:.4g}"
    if isinstance(v, (list, tuple)):
        return ", ".join(_cell(x) for x in v)
    return str(v)


def _write(folder: Path, text: list, notes: list) -> Path:
    """report.md: the text, then the notes."""
    if notes:
        text += ["## Notes", ""] + [f"- {n}" for n in notes] + [""]
    path = folder / "report.md"
    path.write_text("\n".join(text), encoding="utf-8")
    return path


def replay_report(result: Any, folder: Path) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    fig = result.plot()
    fig.savefig(folder / "residuals.png", dpi=110)
    import matplotlib.pyplot as plt
    plt.close(fig)
    result.events.to_csv(folder / "events.csv", index=False)
    result.stats.to_csv(folder / "stats.csv")
    text = [f"# hstmon replay: {result.log}", "",
            f"Circuit **{result.circuit.name}** ({result.circuit.path}); {result.raw['rows']} rows, "
            f"t = {result.raw['t_first']:g} … {result.raw['t_last']:g} s.", "",
            f"**Status at the end of the log: {result.status}**", "",
            f"Envelope: {result.envelope['text']}", "", "## Events", "",
            _table(result.events) if len(result.events) else "No fault detected.", "",
            "## Residuals (measured − model, SI)", "", _table(result.stats.reset_index()), "",
            "![residuals](residuals.png)", ""]
    return _write(folder, text, result.notes)


def _cli_report(outcome: Any, folder: Path) -> Path:
    """The CLI's own report folder (report.md, report.html, figure), written by the C++ core."""
    folder.mkdir(parents=True, exist_ok=True)
    missing = outcome.report(str(folder))
    if missing:
        import warnings
        warnings.warn(f"{folder}: no figure: {missing}", stacklevel=3)
    return folder / "report.md"


def gap_report(result: Any, folder: Path) -> Path:
    path = _cli_report(result._outcome, folder)
    result.ranked.to_csv(folder / "ranked.csv", index=False)
    result.where.to_csv(folder / "where.csv")
    return path


def identify_report(result: Any, folder: Path) -> Path:
    path = _cli_report(result._outcome, folder)
    result.parameters.to_csv(folder / "parameters.csv", index=False)
    result.points.to_csv(folder / "points.csv", index=False)
    (folder / "fitted.params.json").write_text(result.values_json, encoding="utf-8")
    return path
