"""Fixtures of the Python module's tests: the source tree and the CLI they compare with.

Run by CTest (python.pytest) with PYTHONPATH at the build's package and HSTMON_CLI /
HSTMON_SIM naming the build's programs; by hand:
    PYTHONPATH=build/X/python HSTMON_CLI=build/X/bin/hstmon python3 -m pytest tests/python
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path
from typing import Dict, List

import pytest

ROOT = Path(__file__).resolve().parents[2]


def _program(env: str, name: str) -> str:
    path = os.environ.get(env) or shutil.which(name)
    if not path:
        pytest.skip(f"{env} not set and no {name} on PATH")
    return path


@pytest.fixture(scope="session")
def root() -> Path:
    return ROOT


@pytest.fixture(scope="session")
def cli() -> str:
    return _program("HSTMON_CLI", "hstmon")


@pytest.fixture(scope="session")
def sim() -> str:
    return _program("HSTMON_SIM", "hstmon-sim")


def run_json_lines(args: List[str], cwd: Path) -> List[Dict]:
    """A command's JSON lines (its exit code ignored: a fleet with a bad log exits 2)."""
    out = subprocess.run(args, cwd=cwd, capture_output=True, text=True, check=False).stdout
    return [json.loads(line) for line in out.splitlines() if line.strip()]
