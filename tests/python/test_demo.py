"""The demo through Python: the thesis rig is the default, and its events are the CLI's."""
import hstmon


def test_demo_detects_and_isolates_kp_minus(root):
    r = hstmon.replay(str(root / "examples/prv_blockage.csv"))
    ev = r.events
    detected = ev[ev["event"] == "detected"].iloc[0]
    isolated = ev[ev["event"] == "isolated"].iloc[0]
    assert round(detected["t"], 3) == 80.030
    assert round(isolated["t"], 3) == 80.180
    assert isolated["faults"][0] == "kp-"
    assert isolated["faults"] == ["kp-"]
    assert r.status == "isolated"
    assert r.circuit.name == "thesis"
    assert list(ev.columns[:4]) == ["t", "event", "faults", "scores"]


def test_rigs_by_name():
    for name in hstmon.RIGS:
        c = hstmon.Circuit.rig(name)
        assert c.name and c.sensors
    assert hstmon.Circuit.rig("paper").name == "paper"


def test_stats_are_per_channel_in_si(root):
    r = hstmon.replay(str(root / "examples/prv_blockage.csv"))
    s = r.stats
    assert list(s.index) == [x["name"] for x in r.circuit.sensors]
    assert set(s["unit"]) <= {"Pa", "rad/s", "m^3/s", "m3/s"}
    assert (s.loc[s["measured"], "n"] > 0).all()


def test_threads_give_the_same_answer(root):
    # The GIL is released while a log is read and replayed: threads replay side by side.
    from concurrent.futures import ThreadPoolExecutor
    log = str(root / "examples/prv_blockage.csv")
    with ThreadPoolExecutor(2) as pool:
        a, b = pool.map(lambda _: hstmon.replay(log), range(2))
    assert a.events.equals(b.events) and a.stats.equals(b.stats)
