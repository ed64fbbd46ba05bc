"""The map from Python: the same maps, likelihoods and bytes as the C++ side."""
import copy
import os
import subprocess
import threading

import numpy as np
import pytest

import whiskermap as wm

OBJECT_FIELDS = ("x", "y", "yaw", "length", "width", "leg_width", "texture",
                 "existence", "contacts", "legs", "sd_x", "sd_y", "sd_yaw")
MODES = ("lasting", "per_pose")
SEED = 7


@pytest.fixture(scope="module")
def rawlog(dataset):
    return wm.read_rawlog(str(dataset))


def build(rawlog, mode, seed=SEED, sweeps=slice(None)):
    m = wm.Map(mode=mode, seed=seed)
    for pose, sweep in list(rawlog)[sweeps]:
        assert m.insert(sweep, pose)
    return m


@pytest.fixture(scope="module")
def maps(rawlog):
    return {mode: build(rawlog, mode) for mode in MODES}


@pytest.fixture(scope="module")
def whisker_map(app, dataset, tmp_path_factory):
    """whisker-map's output folder per mode, same seed."""
    out = {}
    for mode in MODES:
        d = tmp_path_factory.mktemp(mode)
        r = app("map", "-q", "-i", dataset, "-o", d, "--mode", mode, "--seed", SEED)
        assert r.returncode == 0, r.stderr
        out[mode] = d
    return out


def test_defaults_come_from_the_shipped_config():
    m = wm.Map()
    assert m.config.endswith("config/whisker-map.ini")
    assert (m.mode, m.seed, m.steps, m.is_empty()) == ("lasting", 1, 0, True)
    m.mode, m.seed = "per_pose", 99
    assert (m.mode, m.seed) == ("per_pose", 99)


@pytest.mark.parametrize("mode", MODES)
def test_same_csv_bytes_as_whisker_map(maps, whisker_map, mode, tmp_path):
    m, ref = maps[mode], whisker_map[mode]
    assert m.mode == mode and m.steps == 400
    spreads = mode == "lasting"  # the lasting map reports each object's pose spread
    wm.write_objects_csv(str(tmp_path / "map_tables.csv"), m.map_objects(spreads), spreads)
    wm.write_objects_csv(str(tmp_path / "map_candidates.csv"), m.candidate_objects(spreads), spreads)
    for name in ("map_tables.csv", "map_candidates.csv"):
        assert (tmp_path / name).read_bytes() == (ref / name).read_bytes(), name
    m.save(str(tmp_path / "saved"))
    assert (tmp_path / "saved_map_tables.csv").read_bytes() == (ref / "map_tables.csv").read_bytes()
    if mode == "per_pose":
        wm.write_per_pose_csv(str(tmp_path / "per_pose_tables.csv"), m.pose_records())
        assert (tmp_path / "per_pose_tables.csv").read_bytes() == (ref / "per_pose_tables.csv").read_bytes()
        assert (tmp_path / "saved_per_pose_tables.csv").read_bytes() == (ref / "per_pose_tables.csv").read_bytes()


@pytest.mark.parametrize("mode", MODES)
def test_objects_are_structured_arrays(maps, rawlog, mode):
    m = maps[mode]
    objs = m.map_objects()
    assert objs.dtype.names == OBJECT_FIELDS
    assert 4 <= len(objs) <= 8  # the paper arena holds 6 tables
    assert np.all(objs["length"] == 1.0) and np.all(objs["width"] == 0.6)
    assert np.all((objs["legs"] >= 2) & (objs["legs"] <= 4))
    assert np.all(np.isnan(objs["sd_x"]))  # spreads only when asked for
    if mode == "lasting":  # sub-millimetre on the default readings, and the same table by table
        spread = m.map_objects(spreads=True)
        assert np.all((spread["sd_x"] > 0) & (spread["sd_x"] < 0.005) & (spread["sd_yaw"] > 0) & (spread["sd_yaw"] < 0.01))
        for f in OBJECT_FIELDS[:10]:
            assert np.array_equal(spread[f], objs[f])
    tables = m.map_tables()
    for f in wm.TABLE_DTYPE.names:
        assert np.array_equal(tables[f], objs[f])
    assert len(m.shapelets()) == sum(s.contact_count() for s in rawlog.sweeps)


def test_per_pose_records(maps, rawlog):
    records = maps["per_pose"].pose_records()
    assert len(records) == 400
    assert np.array_equal(np.array([r.pose for r in records]), rawlog.poses)
    assert sum(len(r.tables) for r in records) > 100
    assert all(0 < r.shapelets <= 7 for r in records if len(r.tables))
    assert all(r.tables.dtype == wm.TABLE_DTYPE for r in records)
    # The lasting mode records poses but no per-pose tables.
    assert all(len(r.tables) == 0 for r in maps["lasting"].pose_records())


@pytest.mark.parametrize("mode", MODES)
def test_likelihood_equals_the_cpp_value(maps, rawlog, dataset, mode):
    ref = subprocess.run([os.environ["WHISKERMAP_LIKELIHOOD_REFERENCE"], str(dataset), mode, str(SEED)],
                         capture_output=True, text=True, check=True).stdout
    expected = np.array([[float(v) for v in line.split()] for line in ref.splitlines()])
    assert expected.shape == (400, 2)
    m = maps[mode]
    moved = rawlog.poses + [0.05, -0.03, 0.1]
    got = np.array([[m.likelihood(s, p), m.likelihood(s, q)] for (p, s), q in zip(rawlog, moved)])
    assert np.array_equal(got, expected)
    assert np.mean(expected[:, 0] > expected[:, 1]) > 0.7  # the true pose is usually the likelier
    # The batch form gives the same numbers, one per pose.
    _, s = rawlog[5]
    assert np.array_equal(m.likelihoods(s, np.array([rawlog.poses[5], moved[5]])), expected[5])


@pytest.mark.parametrize("mode", MODES)
def test_serialization_round_trip(rawlog, mode):
    first = build(rawlog, mode, sweeps=slice(0, 200))
    data = first.to_bytes()
    assert isinstance(data, bytes) and len(data) > 1000
    back = wm.Map.from_bytes(data)
    assert back.to_bytes() == data
    assert (back.mode, back.seed, back.steps) == (mode, SEED, 200)
    assert back.map_objects().tobytes() == first.map_objects().tobytes()
    _, s = rawlog[300]
    assert back.likelihood(s, rawlog.poses[300]) == first.likelihood(s, rawlog.poses[300])
    # A reloaded map goes on as the original does.
    for pose, sweep in list(rawlog)[200:]:
        first.insert(sweep, pose)
        back.insert(sweep, pose)
    assert back.map_objects().tobytes() == first.map_objects().tobytes()
    assert back.to_bytes() == first.to_bytes()


def test_sweeps_annealed_in_batches(rawlog):
    """batch_sweeps: contacts wait, unexplained, for the batch; anneal_pending() finishes it."""
    m = wm.Map(mode="lasting", seed=SEED)
    m.batch_sweeps = 3
    for pose, sweep in list(rawlog)[:200]:
        m.insert(sweep, pose)
    assert m.pending_sweeps in (0, 1, 2)
    if m.pending_sweeps == 0:
        m.insert(*reversed(rawlog[200]))
    assert m.pending_sweeps > 0
    back = wm.Map.from_bytes(m.to_bytes())
    assert (back.batch_sweeps, back.pending_sweeps) == (3, m.pending_sweeps)
    for x in (m, back):
        x.anneal_pending()
        assert x.pending_sweeps == 0
    assert back.to_bytes() == m.to_bytes()
    assert len(m.map_tables()) > 0
    with pytest.raises(ValueError):
        m.batch_sweeps = 0


def test_disjoint_tables(rawlog):
    """disjoint_tables: a table overlapping one with more contacts leaves the map for the
    candidates (early in the arena, with min_existence 0, a two-legged hypothesis beside a
    true table)."""
    m = wm.Map(mode="lasting", seed=SEED)
    m.min_existence = 0
    assert not m.disjoint_tables
    left = 0
    for pose, sweep in list(rawlog)[:200]:
        m.insert(sweep, pose)
        every = len(m.map_objects())
        m.disjoint_tables = True
        kept, candidates = len(m.map_objects()), len(m.candidate_objects())
        m.disjoint_tables = False
        assert kept + candidates == every
        left = max(left, every - kept)
    assert left > 0
    m.disjoint_tables = True
    assert wm.Map.from_bytes(m.to_bytes()).disjoint_tables


def test_copies_are_deep(rawlog):
    m = build(rawlog, "lasting", sweeps=slice(0, 100))
    for c in (m.copy(), copy.copy(m), copy.deepcopy(m)):
        assert c.to_bytes() == m.to_bytes()
        c.insert(*reversed(rawlog[150]))
        assert c.steps == 101 and m.steps == 100


def test_maps_in_threads_equal_maps_in_sequence(rawlog, maps):
    """Insertions release the GIL: two maps built at once in two threads, each as built alone."""
    built = {}

    def run(mode):
        built[mode] = build(rawlog, mode)
    threads = [threading.Thread(target=run, args=(mode,)) for mode in MODES]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for mode in MODES:
        assert built[mode].to_bytes() == maps[mode].to_bytes()
