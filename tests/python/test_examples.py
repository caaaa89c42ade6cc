"""The examples of examples/python run and say what they should."""
import os
import subprocess
import sys

import hstmon


def run(script, *args, cwd):
    package = os.path.dirname(os.path.dirname(hstmon.__file__))  # the hstmon under test
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=package)
    return subprocess.run([sys.executable, str(script), *map(str, args)], cwd=cwd, env=env, check=True,
                          capture_output=True, text=True).stdout


def test_replay_demo(root, tmp_path):
    out = run(root / "examples/python/replay_demo.py", "--out", tmp_path / "r.png", cwd=tmp_path)
    assert "80.180 s  isolated: kp-" in out
    assert (tmp_path / "r.png").stat().st_size > 10000


def test_gap_ranking(root, tmp_path):
    data = root / "tests/data/validation_paper"
    out = run(root / "examples/python/gap_ranking.py", data / "logs/gap_leak_pmi_fit.csv.gz",
              data / "logs/gap_leak_pmi_check.csv.gz", "--circuit", data / "paper.json", "--report", tmp_path / "g",
              cwd=tmp_path)
    assert out.startswith("verdict: leak(Pmi)")
    assert (tmp_path / "g/report.md").is_file()


def test_replay_report(root, tmp_path):
    path = hstmon.replay(str(root / "examples/prv_blockage.csv")).report(tmp_path / "rep")
    text = path.read_text()
    assert "isolated" in text and (tmp_path / "rep/residuals.png").is_file()
