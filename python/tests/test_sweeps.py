"""Sweeps as numpy arrays, rawlogs read and written (obs::RawlogReader, world::RawlogWriter)."""
import numpy as np
import pytest

import whiskermap as wm

WHISKER_FIELDS = ("mount_x", "mount_y", "sweep_start", "sweep_end", "length",
                  "touched", "angle", "r", "normal", "texture")


@pytest.fixture(scope="module")
def rawlog(dataset):
    return wm.read_rawlog(dataset)


def test_reads_the_shipped_dataset(rawlog):
    assert len(rawlog) == 400 and len(rawlog.sweeps) == 400
    assert rawlog.objects == 800  # odometry + sweep per pose
    assert not rawlog.action_sensory_frame
    assert rawlog.poses.shape == (400, 3)
    pose, sweep = rawlog[-1]
    assert np.array_equal(pose, rawlog.poses[399])
    assert sweep.label == "WHISKERS"
    assert sweep.timestamp == pytest.approx(1300000000.0 + 399, abs=1e-3)


def test_sweep_rows_are_whiskers(rawlog):
    touched_total = 0
    for _, sweep in rawlog:
        w = sweep.whiskers
        assert w.dtype.names == WHISKER_FIELDS
        assert w.dtype["touched"] == np.bool_
        assert len(w) == len(sweep) > 0
        assert np.all((w["r"] >= 0) & (w["r"] <= w["length"]))
        assert sweep.contact_count() == np.count_nonzero(w["touched"])
        touched_total += sweep.contact_count()
    assert touched_total > 100  # the arena's tables and walls are touched


def test_shapelets_are_the_touched_whiskers_in_the_world_frame(rawlog):
    pose, sweep = next((p, s) for p, s in rawlog if s.contact_count() >= 2)
    shapelets = sweep.shapelets(pose)
    w = sweep.whiskers
    assert list(shapelets["whisker"]) == list(np.flatnonzero(w["touched"]))
    # The same sweep from a pose moved by (1, 2) moves its contacts by (1, 2).
    moved = sweep.shapelets((pose[0] + 1, pose[1] + 2, pose[2]))
    assert np.allclose(moved["x"] - shapelets["x"], 1) and np.allclose(moved["y"] - shapelets["y"], 2)
    # Each contact lies on its whisker's shaft: a unit vector pointing from the pivot to it.
    assert np.allclose(np.hypot(shapelets["shaft_x"], shapelets["shaft_y"]), 1)
    assert np.allclose(moved["shaft_x"], shapelets["shaft_x"]) and np.allclose(moved["shaft_y"], shapelets["shaft_y"])


def test_rewriting_the_sweeps_gives_the_same_bytes(rawlog, dataset, tmp_path):
    out = tmp_path / "copy.rawlog"
    with wm.RawlogWriter(out) as writer:
        for pose, sweep in rawlog:
            writer.write(pose, sweep)
    assert out.read_bytes() == dataset.read_bytes()
    truth = "default_ground_truth_robot_path.txt"
    assert (tmp_path / "copy_ground_truth_robot_path.txt").read_text() == (dataset.parent / truth).read_text()


def test_sweeps_rebuilt_from_arrays_round_trip(rawlog, tmp_path):
    out = tmp_path / "rebuilt.rawlog"
    writer = wm.RawlogWriter(str(out), format="action-sf", ground_truth=False)
    for pose, s in rawlog:
        rebuilt = wm.Sweep(s.whiskers, noise=s.noise, sensor_pose=s.sensor_pose,
                           timestamp=s.timestamp, label=s.label)
        writer.write(pose, rebuilt)
    assert not out.exists()  # nothing appears before close()
    writer.close()
    assert not writer.is_open
    back = wm.read_rawlog(str(out))
    assert back.action_sensory_frame and len(back) == len(rawlog)
    assert np.allclose(back.poses, rawlog.poses, atol=1e-9)  # composed from increments
    for (_, a), (_, b) in zip(rawlog, back):
        assert a.whiskers.tobytes() == b.whiskers.tobytes()
        assert (a.noise.sigma_r, a.noise.sigma_phi, a.noise.sigma_tau) == \
               (b.noise.sigma_r, b.noise.sigma_phi, b.noise.sigma_tau)
        assert np.allclose(a.sensor_pose, b.sensor_pose, atol=1e-12)
        assert a.timestamp == pytest.approx(b.timestamp, abs=1e-6)
    assert not (tmp_path / "rebuilt_ground_truth_robot_path.txt").exists()


def test_packed_arrays_and_other_field_orders_are_accepted(rawlog):
    _, s = rawlog[0]
    w = s.whiskers
    packed = np.zeros(len(w), dtype=[(n, w.dtype[n]) for n in reversed(WHISKER_FIELDS)] + [("extra", "i4")])
    for n in WHISKER_FIELDS:
        packed[n] = w[n]
    assert wm.Sweep(packed).whiskers.tobytes() == w.tobytes()


def test_a_failed_write_leaves_no_file(rawlog, tmp_path):
    out = tmp_path / "failed.rawlog"
    with pytest.raises(RuntimeError, match="stop"):
        with wm.RawlogWriter(out) as writer:
            writer.write(*rawlog[0])
            raise RuntimeError("stop")
    assert list(tmp_path.iterdir()) == []
    with pytest.raises(wm.WhiskermapError, match="the rawlog writer is closed"):
        writer.write(*rawlog[0])


def test_streaming_visits_every_sweep_in_order(rawlog, dataset):
    seen = []
    count = wm.for_each_sweep(dataset, lambda pose, sweep: seen.append(pose))
    assert count == len(seen) == 400
    assert np.array_equal(np.array(seen), rawlog.poses)

    def stop(pose, sweep):
        raise KeyError("from the callback")
    with pytest.raises(KeyError, match="from the callback"):
        wm.for_each_sweep(dataset, stop)


def test_blank_sweep_of_a_robot():
    robot = wm.Robot.load("scratchbot")
    s = robot.blank_sweep(wm.Noise.load("default"), timestamp=12.5)
    assert s.contact_count() == 0 and s.timestamp == pytest.approx(12.5)
    assert np.array_equal(s.whiskers["angle"], s.whiskers["sweep_end"])
    assert np.array_equal(s.whiskers["length"], robot.whiskers["length"])
    assert s.sensor_pose == pytest.approx(robot.sensor_pose)
