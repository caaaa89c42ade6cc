"""simulate, identify and gap: the circuit tools of hstmon-sim, identify and gap."""
import json

import numpy as np
import pytest

import hstmon
from conftest import run_json_lines


def test_simulate_then_replay_is_nominal():
    c = hstmon.Circuit.rig("paper")
    df = hstmon.simulate(c, duration=4.0, rate=200.0, seed=3)
    assert df.columns[0] == "t[s]" and len(df) == 800
    r = hstmon.replay(df, c)
    assert r.status == "nominal"
    assert (r.stats.loc[r.stats["measured"], "mean"].abs() < 5 * r.stats.loc[r.stats["measured"], "noise"]).all()


def test_simulate_from_input_frame_matches_cli(tmp_path, sim, root):
    c = hstmon.Circuit.rig("paper")
    inputs = hstmon.simulate(c, duration=2.0, rate=100.0, noise=False)
    inputs = inputs[[col for col in inputs.columns if col == "t[s]" or col.split("[")[0] in
                     [i["column"] for i in c.inputs]]]
    path = tmp_path / "inputs.csv"
    inputs.to_csv(path, index=False, float_format="%.17g")
    out = tmp_path / "sim.csv"
    import subprocess
    subprocess.run([sim, "--circuit", c.path, "--inputs", str(path), "--seed", "5", "--out", str(out)], check=True)
    want = hstmon.read_log(str(out), c)
    got = hstmon.simulate(c, inputs, seed=5)
    assert list(got.columns) == list(want.columns)
    # the CLI's file holds 9 significant digits
    assert np.allclose(got.to_numpy(), want.to_numpy(), rtol=1e-8, atol=1e-6)


def test_simulate_rejects_bad_steps():
    with pytest.raises(ValueError):
        hstmon.simulate("paper", steps=["nosuchinput=1@1"])


def test_gap_equals_cli(root, cli, tmp_path):
    data = root / "tests/data/validation_paper"
    c = hstmon.Circuit.load(data / "paper.json")
    fit, check = data / "logs/gap_leak_pmi_fit.csv.gz", data / "logs/gap_leak_pmi_check.csv.gz"
    want = run_json_lines([cli, "gap", "--circuit", c.path, "--fit", str(fit), "--check", str(check), "--json"], root)
    g = hstmon.gap(str(fit), str(check), c)
    assert g.verdict == want[0]["verdict"] == "leak(Pmi)"
    assert list(g.ranked["effect"]) == [e["effect"] for e in want[0]["ranked"]]
    assert list(g.ranked["magnitude"]) == [e["magnitude"] for e in want[0]["ranked"]]
    assert dict(g.where["mean_fit"]) == want[0]["mean_residual_fit"]
    assert "leak(Pmi)" in g.report(tmp_path / "gap").read_text()


def test_gap_and_identify_reports_are_the_clis(root, cli, tmp_path):
    """The report folder from Python is the one the CLI writes, byte for byte."""
    import subprocess
    data = root / "tests/data/validation_paper"
    c = hstmon.Circuit.load(data / "paper.json")
    fit, check = str(data / "logs/gap_leak_pmi_fit.csv.gz"), str(data / "logs/gap_leak_pmi_check.csv.gz")
    subprocess.run([cli, "gap", "--circuit", c.path, "--fit", fit, "--check", check, "--report", str(tmp_path / "cli_gap")],
                   check=True, capture_output=True)
    g = hstmon.gap(fit, check, c)
    assert g.text.startswith(f"hstmon gap --circuit {c.path}: fit {fit}")
    g.report(tmp_path / "py_gap")
    log = str(root / "examples/circuits/paper.csv")
    subprocess.run([cli, "identify", "--circuit", c.path, "--fit", "Dm", log, "--report", str(tmp_path / "cli_id")],
                   check=True, capture_output=True)
    hstmon.identify(log, "Dm", c).report(tmp_path / "py_id")
    for name in ("gap", "id"):
        for f in ("report.md", "report.html"):
            assert (tmp_path / f"py_{name}" / f).read_bytes() == (tmp_path / f"cli_{name}" / f).read_bytes(), (name, f)


def test_identify_equals_cli(root, cli, tmp_path):
    c = hstmon.Circuit.rig("paper")
    log = root / "examples/circuits/paper.csv"
    want = run_json_lines([cli, "identify", "--circuit", c.path, "--fit", "Dm", "--json", str(log)], root)
    r = hstmon.identify(str(log), "Dm", c)
    assert [p["value"] for p in want[0]["parameters"]] == list(r.parameters["value"])
    assert r.rms_after == want[0]["rms_after"]
    assert json.loads(r.values_json)
