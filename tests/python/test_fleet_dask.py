"""A fleet under Dask: hstmon.summary mapped over a folder of logs with dask.bag on a
LocalCluster gives the lines of `hstmon replay --circuit FILE FOLDER` (the CLI's fleet,
which tests/fleet shows equal to the GNU parallel and Slurm recipes)."""
import shutil

import pytest

import hstmon
from conftest import run_json_lines


@pytest.fixture(scope="module")
def fleet(tmp_path_factory, root):
    """Two machines of the paper rig: c01 four nominal days; c02 two nominal, two with the
    Dm fault; and a log with a bad number."""
    logs = tmp_path_factory.mktemp("fleet") / "clogs"
    (logs / "c01").mkdir(parents=True)
    (logs / "c02").mkdir()
    src = root / "examples/circuits"
    for day in range(1, 5):
        shutil.copy(src / "paper.csv", logs / f"c01/2026-11-0{day}.csv")
    for day, name in ((1, "paper"), (2, "paper"), (3, "paper_dm_fault"), (4, "paper_dm_fault")):
        shutil.copy(src / f"{name}.csv", logs / f"c02/2026-11-0{day}.csv")
    (logs / "c02/2026-11-05.csv").write_text("t[s],p_mi[bar]\n0,1\n0.005,x\n")
    return logs


def test_dask_bag_equals_cli_fleet(fleet, root, cli):
    dask = pytest.importorskip("dask.bag")
    distributed = pytest.importorskip("distributed")
    circuit = root / "examples/circuits/paper.json"
    want = run_json_lines([cli, "replay", "--circuit", str(circuit), str(fleet), "--jobs", "2"], root)
    assert len(want) == 9
    paths = hstmon.fleet_logs(fleet)
    assert paths == [line["log"] for line in want]
    c = hstmon.Circuit.load(circuit)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as lc, \
            distributed.Client(lc):
        got = dask.from_sequence(paths, npartitions=4).map(hstmon.summary, circuit=c).compute()
    assert got == want
    assert sum(line["status"] == "error" for line in got) == 1
    assert any((line.get("first_diagnosis") or {}).get("fault") == "Dm-" for line in got)


def test_summary_machine_rules():
    assert hstmon.machine_of("logs/m01/2026-11-01.csv") == "m01"
    assert hstmon.machine_of("one.csv") == "one"
    assert hstmon.machine_of("logs/m07_x.csv", "regex:(m[0-9]+)_") == "m07"
    assert hstmon.machine_of("logs/m01.csv", "stem") == "m01"
    with pytest.raises(ValueError):
        hstmon.machine_of("a.csv", "regex:m01")
