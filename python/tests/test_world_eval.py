"""The simulator and the evaluation from Python: the same bytes and figures as the apps."""
import json

import numpy as np
import pytest

import whiskermap as wm


@pytest.fixture(scope="module")
def arena(src):
    return wm.World.load(src / "config" / "worlds" / "paper_arena.ini")


def test_world_tables(arena):
    t = arena.tables
    assert t.dtype.names == ("x", "y", "yaw", "length", "width", "leg_width", "texture")
    assert len(t) == 6 and np.all(t["length"] == 1.0)
    assert (arena.x_min, arena.y_min) == (0.0, 0.0) and arena.x_max > 0 and arena.y_max > 0
    assert len(arena.tiled(2, 3).tables) == 36
    assert wm.config_path("worlds/paper_arena.ini").endswith("config/worlds/paper_arena.ini")


def test_simulation_reproduces_the_shipped_dataset(arena, src, tmp_path):
    """whisker-sim --seed 2011 --noise default, step by step from Python: the same bytes."""
    sim = wm.Simulator(arena, wm.Robot.load("scratchbot"), wm.Noise.load("default"), seed=2011)
    out = tmp_path / "default.rawlog"
    written = 0
    with wm.RawlogWriter(str(out)) as writer:
        for pose in wm.paper_grid(arena):
            if sim.pose_is_free(pose):
                writer.write(pose, sim.sense(pose, timestamp=1300000000.0 + written))
                written += 1
    data = src / "datasets" / "paper_arena"
    assert written == 400
    assert out.read_bytes() == (data / "default.rawlog").read_bytes()
    assert (tmp_path / "default_ground_truth_robot_path.txt").read_bytes() == \
        (data / "default_ground_truth_robot_path.txt").read_bytes()


def test_truth_of_each_whisker(arena):
    sim = wm.Simulator(arena, wm.Robot.load("scratchbot"), wm.Noise(), seed=1)
    tables = walls = 0
    for pose in wm.paper_grid(arena):
        sweep, truth = sim.sense_with_truth(pose)
        assert truth.dtype.names == ("table", "leg", "wall") and len(truth) == len(sweep)
        touched = sweep.whiskers["touched"]
        assert np.all(touched[truth["table"] >= 0]) and np.all(touched[truth["wall"]])
        assert np.all((truth["table"] >= 0) == (truth["leg"] >= 0))
        tables += np.count_nonzero(truth["table"] >= 0)
        walls += np.count_nonzero(truth["wall"])
    assert tables > 50 and walls > 50
    assert not sim.pose_is_free((-1.0, -1.0, 0.0))


def test_paths(arena, tmp_path):
    grid = wm.paper_grid(arena)
    assert grid.shape == (400, 3)
    assert np.allclose(np.degrees(grid[:4, 2]) % 360, [0, 90, 180, 270])
    assert wm.paper_grid(arena, 3, 2).shape == (24, 3)
    wm.write_path_file(tmp_path / "p.txt", grid[:10], comment="ten poses")
    back = wm.read_path_file(tmp_path / "p.txt")
    assert np.allclose(back, grid[:10], atol=1e-9)


@pytest.fixture(scope="module")
def mapped(app, dataset, tmp_path_factory):
    out = tmp_path_factory.mktemp("per_pose")
    r = app("map", "-q", "-i", dataset, "-o", out, "--mode", "per_pose")
    assert r.returncode == 0, r.stderr
    return out


def test_evaluation_is_whisker_eval(app, arena, src, dataset, mapped):
    world_ini = src / "config" / "worlds" / "paper_arena.ini"
    rawlog = wm.read_rawlog(str(dataset))
    per_pose = wm.read_per_pose_csv(str(mapped / "per_pose_tables.csv"), len(rawlog))
    report = wm.evaluate(arena, wm.read_map_csv(str(mapped / "map_tables.csv")),
                         per_pose=per_pose, rawlog=rawlog)
    r = app("eval", "--json", "-w", world_ini, "-m", mapped / "map_tables.csv",
            "--per-pose", mapped / "per_pose_tables.csv", "--rawlog", dataset)
    assert r.returncode == 0, r.stderr
    assert report.to_json() == r.stdout
    figures = report.to_dict()
    assert figures == json.loads(r.stdout)
    assert figures["f1"] == pytest.approx(report.map.figures.f1, abs=1e-6)
    assert report.per_pose.poses == 400 and report.per_pose.local is not None
    assert report.objects_on_walls == 0
    assert report.identifiability.recall(report.map) == pytest.approx(1.0)
    r = app("eval", "-w", world_ini, "-m", mapped / "map_tables.csv")
    assert wm.evaluate(arena, wm.read_map_csv(str(mapped / "map_tables.csv"))).to_text() == r.stdout


def test_map_evaluation_pieces(arena):
    truth = arena.tables
    e = wm.MapEvaluation.compute(truth, truth)
    assert (e.estimated, e.truth, e.matched) == (6, 6, 6)
    assert e.truth_match == list(range(6))
    assert (e.figures.precision, e.figures.recall, e.figures.f1, e.figures.ospa) == (1, 1, 1, 0)
    moved = truth.copy()
    moved["x"][0] += 0.5  # beyond the 0.25 m gate
    e = wm.MapEvaluation.compute(truth, moved, wm.EvalOptions(gate_distance=0.25))
    assert e.matched == 5 and e.truth_match[0] == -1
    e = wm.MapEvaluation.compute(truth, moved, wm.EvalOptions(gate_distance=0.6))
    assert e.matched == 6 and e.figures.rmse_m == pytest.approx(0.5 / np.sqrt(6))
    shifted = truth.copy()
    shifted["x"] += 0.03  # the whole map moved: its shape is exact
    e = wm.MapEvaluation.compute(truth, shifted)
    assert e.figures.rmse_m == pytest.approx(0.03) and e.figures.rmse_aligned_m == pytest.approx(0, abs=1e-9)
    empty = wm.MapEvaluation.compute(truth, truth[:0])
    assert np.isnan(empty.figures.rmse_m) and np.isnan(empty.figures.rmse_aligned_m) and empty.figures.recall == 0
    pp = wm.PerPoseEvaluation.compute(truth, [truth, truth[:3]])
    assert pp.poses == 2 and pp.all.recall == pytest.approx(0.75) and pp.local is None
    with pytest.raises(wm.WhiskermapError, match="ospa_p"):
        wm.EvalOptions(ospa_p=0.5).validate()
