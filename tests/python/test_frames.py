"""DataFrames in and out: a frame gives what its CSV file gives; errors are located."""
import numpy as np
import pandas as pd
import pytest

import hstmon
from cli_shapes import json_lines, without_files


def demo_frame(root):
    # round_trip: the same doubles as the C++ reader's from_chars (pandas' default parser
    # may differ in the last bit)
    return pd.read_csv(root / "examples/prv_blockage.csv", float_precision="round_trip")


def test_frame_equals_path(root):
    a = hstmon.replay(str(root / "examples/prv_blockage.csv"))
    b = hstmon.replay(demo_frame(root))
    assert without_files(json_lines(a)) == without_files(json_lines(b))
    pd.testing.assert_frame_equal(a.stats, b.stats)
    pd.testing.assert_frame_equal(a.events, b.events)


def test_frame_equals_path_on_a_circuit(root):
    c = hstmon.Circuit.rig("paper")
    log = root / "examples/circuits/paper_dm_fault.csv"
    a = hstmon.replay(str(log), c)
    b = hstmon.replay(pd.read_csv(log, float_precision="round_trip", comment="#"), c)
    assert without_files(json_lines(a)) == without_files(json_lines(b))


def test_units_in_names_are_converted(root):
    df = demo_frame(root)
    si = hstmon.read_log(df)
    assert np.allclose(si["p_mi[Pa]"].to_numpy(), df["p_mi[bar]"].to_numpy() * 1e5)
    again = hstmon.replay(si)  # SI names read back to the same values
    pd.testing.assert_frame_equal(again.events, hstmon.replay(df).events)


def test_residuals_on_request(root):
    r = hstmon.replay(str(root / "examples/prv_blockage.csv"), residuals=True)
    res = r.residuals
    assert len(res) == r.raw["rows"]
    assert np.allclose(res["r_p_mi"], res["p_mi"] - res["p_mi_hat"], equal_nan=True)
    with pytest.raises(ValueError):
        hstmon.replay(str(root / "examples/prv_blockage.csv")).residuals


def test_bad_log_file_raises_with_position(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("t[s],p_mi[bar]\n0,1\n0.01,x\n")
    with pytest.raises(hstmon.SourceError) as e:
        hstmon.replay(str(bad))
    assert (e.value.file, e.value.line, e.value.column) == (str(bad), 3, 6)
    assert str(e.value).startswith(f"{bad}:3:6: error: bad number 'x' in column 'p_mi'")


def test_bad_frame_raises_with_row_and_column(root):
    df = demo_frame(root)
    df.loc[5, "p_mi[bar]"] = np.nan
    with pytest.raises(hstmon.SourceError) as e:
        hstmon.replay(df, name="rig7")
    assert (e.value.file, e.value.line, e.value.column) == ("rig7", 7, list(df.columns).index("p_mi[bar]") + 1)
    with pytest.raises(hstmon.SourceError) as e:
        hstmon.replay(df.rename(columns={"p_mi[bar]": "p_mi[furlong]"}))
    assert e.value.line == 1 and e.value.column == list(df.columns).index("p_mi[bar]") + 1
    with pytest.raises(hstmon.SourceError, match="no time column"):
        hstmon.replay(df.drop(columns=["t[s]"]))


def test_bad_circuit_raises_with_position(tmp_path):
    bad = tmp_path / "c.json"
    bad.write_text('{"circuit": "x",\n  "nodes": [1, }\n')
    with pytest.raises(hstmon.SourceError) as e:
        hstmon.Circuit.load(bad)
    assert e.value.file == str(bad) and e.value.line == 2 and e.value.column > 0


def test_missing_file_and_unknown_option(root):
    with pytest.raises(hstmon.SourceError) as e:
        hstmon.replay("/nonexistent/log.csv")
    assert e.value.line == 0
    with pytest.raises(TypeError, match="unknown options"):
        hstmon.replay(str(root / "examples/prv_blockage.csv"), tik=0.01)
    with pytest.raises(ValueError):
        hstmon.replay(str(root / "examples/prv_blockage.csv"), init="cold")
    with pytest.raises(ValueError):
        hstmon.replay(str(root / "examples/prv_blockage.csv"), separator="|")


def test_lenient_keeps_the_rows_before_a_bad_one(tmp_path, root):
    text = (root / "examples/prv_blockage.csv").read_text().splitlines()
    text[3000] = text[3000].replace(",", ",x", 1)
    bad = tmp_path / "bad.csv"
    bad.write_text("\n".join(text) + "\n")
    with pytest.raises(hstmon.SourceError):
        hstmon.replay(str(bad))
    r = hstmon.replay(str(bad), lenient=True)
    assert r.raw["rows"] == 2999 and r.read_error.startswith(f"{bad}:3001:")
