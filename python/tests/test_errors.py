"""Errors raise WhiskermapError (a ValueError) with the one-line messages the apps print."""
import numpy as np
import pytest

import whiskermap as wm


def app_error(result, name):
    """The message of an app's 'NAME: error: MESSAGE' line (it must have failed)."""
    assert result.returncode == 1, result
    line = result.stderr.strip()
    prefix = f"whisker-{name}: error: "
    assert line.startswith(prefix) and "\n" not in line, line
    return line[len(prefix):]


def raised(fn, *args, **kwargs):
    with pytest.raises(wm.WhiskermapError) as e:
        fn(*args, **kwargs)
    message = str(e.value)
    assert "\n" not in message and message
    return message


def test_is_a_value_error():
    assert issubclass(wm.WhiskermapError, ValueError)


def test_rawlog_errors_match_whisker_map(app, dataset, tmp_path):
    truncated = tmp_path / "truncated.rawlog"
    truncated.write_bytes(dataset.read_bytes()[:30000])
    empty = tmp_path / "empty.rawlog"
    empty.write_bytes(b"")
    for path in (tmp_path / "missing.rawlog", truncated, empty, tmp_path):
        expected = app_error(app("map", "-q", "-i", path, "-o", tmp_path / "out"), "map")
        assert raised(wm.read_rawlog, str(path)) == expected
        assert raised(wm.for_each_sweep, str(path), lambda p, s: None) == expected
    assert "truncated or corrupt gzip data" in raised(wm.read_rawlog, str(truncated))


def test_config_errors_match_whisker_map(app, dataset, tmp_path):
    bad = tmp_path / "bad.ini"
    bad.write_text("[MetricMap]\nhierarchicalObjectMap_count=1\n"
                   "[MetricMap_hierarchicalObjectMap_00_insertOpts]\nmemory=7\n")
    none = tmp_path / "none.ini"
    none.write_text("[MetricMap]\nsimplePointsMap_count=1\n")
    for config in (bad, none, tmp_path / "missing.ini"):
        expected = app_error(app("map", "-q", "-i", dataset, "-c", config, "-o", tmp_path / "out"), "map")
        assert raised(wm.Map, config=str(config)) == expected
    assert "memory: unknown key" in raised(wm.Map, config=str(bad))


def test_world_and_noise_errors_match_whisker_sim(app, src, tmp_path):
    bad = src / "tests" / "data" / "bad_worlds"
    for world in ("overlapping.ini", "unknown_key.ini", "nan_value.ini", "nowhere.ini"):
        expected = app_error(app("sim", "-q", "-w", bad / world, "-o", tmp_path / "x.rawlog"), "sim")
        assert raised(wm.World.load, str(bad / world)) == expected
    arena = src / "config" / "worlds" / "paper_arena.ini"
    expected = app_error(app("sim", "-q", "-w", arena, "--noise", "loud", "-o", tmp_path / "x.rawlog"), "sim")
    assert raised(wm.Noise.load, "loud") == expected
    expected = app_error(app("sim", "-q", "-w", arena, "--robot", "rover", "-o", tmp_path / "x.rawlog"), "sim")
    assert raised(wm.Robot.load, "rover") == expected
    # whisker-sim commits through an output transaction (doc/reliability.md) and names the
    # folder; the writer itself names the file it cannot create.
    assert app_error(app("sim", "-q", "-w", arena, "-o", "/dev/null/x.rawlog"), "sim") == "/dev/null: not a folder"
    assert raised(wm.RawlogWriter, "/dev/null/x.rawlog").startswith("/dev/null/x.rawlog: cannot create file")


def test_bad_sweeps_name_the_whisker_and_field():
    w = wm.Robot.load("scratchbot").blank_sweep(wm.Noise()).whiskers
    w["touched"][2], w["r"][2] = True, w["length"][2] + 0.1
    assert raised(wm.Sweep, w).endswith("whisker 2: range r=0.700000 past the whisker length 0.600000")
    w["r"][2], w["texture"][2] = 0.1, np.nan
    assert raised(wm.Sweep, w).endswith("whisker 2: non-finite value (NaN or inf)")
    assert raised(wm.Sweep, w[["mount_x", "mount_y"]]) == "whiskers: no field 'sweep_start'"
    assert "structured array" in raised(wm.Sweep, np.zeros((3, 10)))
    assert "whisker" in raised(wm.Sweep, w[:0])  # no whiskers at all


def test_map_argument_errors(dataset, tmp_path):
    assert raised(wm.Map, mode="sideways") == "mode 'sideways': expected 'lasting' or 'per_pose'"
    m = wm.Map()
    with pytest.raises(wm.WhiskermapError):
        m.mode = "both"
    _, sweep = wm.read_rawlog(str(dataset))[0]
    assert "(n, 3)" in raised(m.likelihoods, sweep, np.zeros((4, 2)))
    assert "no field 'yaw'" in raised(wm.write_objects_csv, "x.csv", np.zeros(2, dtype=[("x", "f8"), ("y", "f8")]))
    # The pose spread is optional in an input array; the spread columns need it.
    plain = [f for f in wm.OBJECT_DTYPE.names if not f.startswith("sd_")]
    objs = np.zeros(1, dtype=[(f, wm.OBJECT_DTYPE[f]) for f in plain])
    objs["length"], objs["width"], objs["leg_width"] = 1.0, 0.6, 0.05
    wm.write_objects_csv(str(tmp_path / "map.csv"), objs)
    assert (tmp_path / "map.csv").read_text().startswith("id,x,y,yaw_deg,length,width,leg_width,texture,existence,contacts,legs\n0,")
    assert "has no pose spread" in raised(wm.write_objects_csv, str(tmp_path / "spread.csv"), objs, spreads=True)
    assert not (tmp_path / "spread.csv").exists()
    assert "expected 'obs' or 'action-sf'" in raised(wm.RawlogWriter, "x.rawlog", format="csv")


def test_bad_map_bytes():
    data = wm.Map().to_bytes()
    for bad in (b"", b"garbage bytes, not a map", data[: len(data) // 2]):
        raised(wm.Map.from_bytes, bad)
    assert "left after the map" in raised(wm.Map.from_bytes, data + b"xyz")


def test_bad_csv_names_file_and_line(tmp_path):
    bad = tmp_path / "map_tables.csv"
    bad.write_text("id,x,y,yaw_deg,length,width,leg_width,texture,existence,contacts,legs\n"
                   "0,abc,1,0,1,0.6,0.05,0.7,1,3,2\n")
    assert raised(wm.read_map_csv, str(bad)).startswith(str(bad) + ": line 2: column 'x'")
