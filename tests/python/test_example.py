# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""The documented example runs and draws its picture (when Matplotlib is installed)."""

import os
import subprocess
import sys

import pytest


def test_grazing_scene_example_draws_its_picture(tmp_path):
    pytest.importorskip("matplotlib")
    source = os.environ.get("GRAZELAB_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))
    script = os.path.join(source, "examples", "python", "grazing_scene.py")
    picture = tmp_path / "scene.png"
    done = subprocess.run([sys.executable, script, "--out", str(picture)], capture_output=True,
                          text=True, timeout=120, env=dict(os.environ, MPLBACKEND="Agg"))
    assert done.returncode == 0, done.stderr
    assert "60 contacts (60 impacts), trust ok" in done.stdout
    assert picture.stat().st_size > 20000
    with open(picture, "rb") as handle:
        assert handle.read(8) == b"\x89PNG\r\n\x1a\n"
