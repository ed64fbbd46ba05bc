"""doc/python.md's example, run as written: it simulates, maps, scores and draws a PNG."""
import os
import re
import subprocess
import sys

import matplotlib.image


def test_the_documented_example_runs(src, tmp_path):
    doc = (src / "doc" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", doc, flags=re.S)
    assert blocks, "doc/python.md has no python block"
    script = tmp_path / "example.py"
    script.write_text(blocks[0])
    r = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True, text=True,
                       env=dict(os.environ, MPLBACKEND="Agg"), timeout=300, check=False)
    assert r.returncode == 0, r.stderr
    assert "F1" in r.stdout and "CHierarchicalObjectMap (lasting): 400 sweeps inserted" in r.stdout
    image = matplotlib.image.imread(tmp_path / "paper_arena_map.png")
    assert image.shape[0] >= 400 and image.shape[1] >= 400
    assert image[..., :3].std() > 0.05  # something was drawn
