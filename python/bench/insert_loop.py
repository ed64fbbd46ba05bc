"""insert_loop.py RAWLOG MODE REPEATS: the Python half of scripts/bench-python.sh.

The same loop as insert_loop.cpp through the whiskermap module: every sweep of the rawlog
inserted into a fresh map (shipped config, keep_history off), REPEATS times; prints the best
and median microseconds per sweep.
"""
import sys
import time

import whiskermap as wm


def main(path, mode, repeats):
    rawlog = wm.read_rawlog(path)
    items = [(tuple(pose), sweep) for pose, sweep in rawlog]
    us = []
    for _ in range(repeats):
        m = wm.Map(mode=mode)
        m.keep_history = False
        t0 = time.perf_counter()
        for pose, sweep in items:
            m.insert(sweep, pose)
        us.append((time.perf_counter() - t0) * 1e6 / len(items))
    us.sort()
    print(f"Python {mode:<8} {len(items)} sweeps x {len(us)}: best {us[0]:.1f} us/sweep, "
          f"median {us[len(us) // 2]:.1f} us/sweep")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]))
