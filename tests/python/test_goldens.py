"""Module == CLI on every golden log: the circuit goldens (tests/goldens/circuit_*.jsonl,
committed `hstmon replay --circuit --json`) line by line, and the thesis rig's logs against
`hstmon replay --circuit examples/circuits/thesis.json --json` of this build."""
import json

import pytest

import hstmon
from cli_shapes import json_lines, without_files
from conftest import run_json_lines

CIRCUIT_GOLDENS = ["closed_loop_hst", "paper", "test_stand"]
THESIS_LOGS = ["prv_blockage", "prv_blockage_das", "prv_staircase_das"]


def committed(root, name):
    with open(root / "tests/goldens" / f"{name}.jsonl", encoding="utf-8") as f:
        return [json.loads(line) for line in f]


@pytest.mark.parametrize("name", CIRCUIT_GOLDENS)
def test_circuit_golden(root, name):
    c = hstmon.Circuit.load(root / f"examples/circuits/{name}.json", root / f"examples/circuits/{name}.params.json")
    r = hstmon.replay(str(root / f"examples/circuits/{name}.csv"), c)
    assert without_files(json_lines(r)) == without_files(committed(root, f"circuit_{name}"))


@pytest.mark.parametrize("name", THESIS_LOGS)
def test_thesis_log_equals_cli(root, cli, name):
    want = run_json_lines([cli, "replay", "--json", "--no-progress", "--circuit", "examples/circuits/thesis.json",
                           f"examples/{name}.csv"], root)
    assert want, "the CLI printed nothing"
    r = hstmon.replay(str(root / f"examples/{name}.csv"))  # thesis.json is the default
    assert without_files(json_lines(r)) == without_files(want)


def test_options_mean_what_the_cli_means(root, cli):
    args = ["--tick", "0.005", "--init", "rest", "--matcher-only"]
    want = run_json_lines([cli, "replay", "--json", "--no-progress", "--circuit", "examples/circuits/thesis.json",
                           *args, "examples/prv_blockage.csv"], root)
    r = hstmon.replay(str(root / "examples/prv_blockage.csv"), tick=0.005, init="rest", matcher_only=True)
    assert without_files(json_lines(r)) == without_files(want)
    want = run_json_lines([cli, "replay", "--json", "--no-progress", "--circuit", "examples/circuits/thesis.json",
                           "--no-diagnosis", "examples/prv_blockage.csv"], root)
    r = hstmon.replay(str(root / "examples/prv_blockage.csv"), diagnosis=False)
    assert without_files(json_lines(r)) == without_files(want)
