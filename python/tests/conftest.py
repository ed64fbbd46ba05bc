"""Shared fixtures: paths that ctest passes in the environment (python/CMakeLists.txt)."""
import os
import subprocess
from pathlib import Path

import pytest


def _env(name):
    value = os.environ.get(name)
    if not value:
        pytest.exit(f"{name} is not set: run these tests through ctest (ctest -R python)", returncode=2)
    return value


@pytest.fixture(scope="session")
def src():
    return Path(_env("WHISKERMAP_SOURCE_DIR"))


@pytest.fixture(scope="session")
def dataset(src):
    """The shipped paper-arena rawlog with default noise."""
    return src / "datasets" / "paper_arena" / "default.rawlog"


@pytest.fixture(scope="session")
def app():
    """app("map", args...) runs whisker-map (or sim, eval) and returns the CompletedProcess."""
    def run(name, *args):
        exe = _env(f"WHISKERMAP_{name.upper()}_APP")
        return subprocess.run([exe, *map(str, args)], capture_output=True, text=True, check=False)
    return run
