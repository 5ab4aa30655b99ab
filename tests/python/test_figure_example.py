"""docs/examples/figure_10_2.py, the notebook-free example of docs/python.md,
runs headless and draws the seed's figure 10.2."""
import os
import subprocess
import sys

import pytest


def test_figure_10_2_example_writes_the_figure(tmp_path):
    pytest.importorskip("matplotlib")
    script = os.path.join(os.environ.get("FRICTIONREF_SOURCE_DIR", "."), "docs", "examples",
                          "figure_10_2.py")
    environment = dict(os.environ, MPLBACKEND="Agg")
    done = subprocess.run([sys.executable, script, str(tmp_path)], capture_output=True, text=True,
                          env=environment, timeout=300)
    assert done.returncode == 0, done.stderr
    figure = tmp_path / "figure_10_2.png"
    assert figure.exists() and figure.stat().st_size > 20000
    assert "verdict PASS" in done.stdout
