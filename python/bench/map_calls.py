"""map_calls.py RAWLOG MODE REPEATS: the Python half of scripts/bench-python.sh.

The same loops as map_calls.cpp through the whiskermap module, and the same line format:
- insertion: every sweep of the rawlog into a fresh map (shipped config, keep_history off),
  REPEATS times; best and median microseconds per sweep of process CPU time, best wall time;
- likelihood: against the last map, each sweep at 64 poses around its own, one call per pose
  (Map.likelihood) and one call per sweep (Map.likelihoods), microseconds per pose;
- what a call through the bindings costs by itself (Map.is_empty).
"""
import sys
import time

import numpy as np

import whiskermap as wm


def main(path, mode, repeats):
    rawlog = wm.read_rawlog(path)
    items = [(tuple(pose), sweep) for pose, sweep in rawlog]
    cpu, wall = [], []
    for _ in range(repeats):
        m = wm.Map(mode=mode)
        m.keep_history = False
        t0, c0 = time.perf_counter(), time.process_time()
        for pose, sweep in items:
            m.insert(sweep, pose)
        cpu.append((time.process_time() - c0) * 1e6 / len(items))
        wall.append((time.perf_counter() - t0) * 1e6 / len(items))
    cpu.sort()
    print(f"Python {mode:<8} {len(items)} sweeps x {len(cpu)}: cpu best {cpu[0]:.1f} "
          f"median {cpu[len(cpu) // 2]:.1f} us/sweep; wall best {min(wall):.1f} us/sweep")

    j = np.arange(64)
    offsets = np.c_[0.01 * (j % 8), 0.01 * (j // 8), np.zeros(64)]
    particles = [(sweep, [tuple(p) for p in pose + offsets], pose + offsets) for pose, sweep in rawlog]
    c0 = time.process_time()
    total = sum(m.likelihood(sweep, p) for sweep, poses, _ in particles for p in poses)
    per_call = (time.process_time() - c0) * 1e6 / (64 * len(items))
    c0 = time.process_time()
    batch = sum(m.likelihoods(sweep, array).sum() for sweep, _, array in particles)
    per_pose = (time.process_time() - c0) * 1e6 / (64 * len(items))
    print(f"Python {mode:<8} likelihood: {per_call:.2f} us/call (sum {total:.6g}); "
          f"likelihoods: {per_pose:.2f} us/pose (sum {batch:.6g})")

    n = 100000
    t0 = time.perf_counter()
    for _ in range(n):
        m.is_empty()
    print(f"Python call overhead: {(time.perf_counter() - t0) * 1e6 / n:.2f} us per call (Map.is_empty)")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]))
