"""examples/compare_two_feet.py end to end against a live cycloptd (started by in_netns.sh)."""

import os
import subprocess
import sys

import pytest


def test_example_compares_two_feet(tmp_path):
    pytest.importorskip("matplotlib")
    figure = tmp_path / "compare_two_feet.png"
    script = os.path.join(os.environ["CYCLOPT_SOURCE_DIR"], "examples", "compare_two_feet.py")
    # Two speeds and one start keep it under a minute; the defaults draw bench/results/python_compare_two_feet.png.
    out = subprocess.run([sys.executable, script, "--speeds", "1.0:0.1:1.1", "--starts", "1", "--out", str(figure)],
                         check=True, capture_output=True, text=True, timeout=110).stdout
    print(out)
    assert "f_mech" in out and "saving" in out
    assert figure.stat().st_size > 10000
    assert figure.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
