# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""The Python examples of the README and of the manual page run as written (on a mesh with the
field they name), and the type stubs agree with the module (mypy's stubtest) and type-check the
README's example (mypy)."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import prstar

ROOT = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent


def readme_example() -> str:
    text = (ROOT / "README.md").read_text()
    section = text[text.index("## Using it from Python"):]
    return re.search(r"```python\n(.*?)```", section, re.S).group(1)


def manual_example() -> str:
    text = (ROOT / "doc" / "PR_star_octree" / "Python.txt").read_text()
    return re.search(r"\\code\{\.py\}\n(.*?)\\endcode", text, re.S).group(1)


@pytest.fixture()
def part_vtu(tmp_path, data_dir):
    """part.vtu in the working folder: a real-looking part, two labels and a 'temperature' field."""
    mesh = prstar.read(data_dir / "torus.mesh")
    p = mesh.points
    temperature = np.sin(3 * p[:, 0]) * np.cos(2 * p[:, 1]) + p[:, 2]
    centroid_x = p[mesh.tetrahedra.astype(np.int64)].mean(axis=1)[:, 0]
    labels = np.where(centroid_x < 0, 1, 2).astype(np.int32)
    prstar.write(tmp_path / "part.vtu", mesh, labels=labels, point_data={"temperature": temperature})
    return tmp_path


@pytest.mark.parametrize("example", [readme_example, manual_example])
def test_examples_run(example, part_vtu, monkeypatch):
    code = example()
    assert "prstar.read(\"part.vtu\")" in code
    monkeypatch.chdir(part_vtu)
    namespace: dict = {}
    exec(compile(code, f"<{example.__name__}>", "exec"), namespace)
    # what the examples made: a smaller valid mesh, written, and results of the right sizes
    small = prstar.read(part_vtu / "small.vtu")
    mesh = prstar.read(part_vtu / "part.vtu")
    assert 0 < small.number_of_tetrahedra < mesh.number_of_tetrahedra
    assert prstar.validate(small).valid
    assert namespace["b"].vertex_types.shape == (mesh.number_of_vertices,)
    assert namespace["c"].distortion.shape == (mesh.number_of_vertices,)


def mypy_available() -> bool:
    return subprocess.run([sys.executable, "-c", "import mypy"], capture_output=True).returncode == 0


@pytest.mark.skipif(not mypy_available(), reason="mypy is not installed (Debian: mypy)")
def test_stubs_match_the_module():
    modules = ["prstar._prstar", "prstar._files", "prstar._simplification", "prstar._topology"]
    p = subprocess.run([sys.executable, "-m", "mypy.stubtest", "--allowlist", str(HERE / "stubtest_allowlist.txt"),
                        *modules], capture_output=True, text=True, env=os.environ, cwd="/")
    assert p.returncode == 0, p.stdout + p.stderr


@pytest.mark.skipif(not mypy_available(), reason="mypy is not installed (Debian: mypy)")
def test_readme_example_type_checks(tmp_path):
    script = tmp_path / "example.py"
    script.write_text("import prstar\n" + readme_example() + """
reveal_type(b.triangles)
reveal_type(small.statistics)
n: int = tree.number_of_vertices
wrong: str = tree.number_of_vertices
""")
    # MYPYPATH: mypy does not look at PYTHONPATH; with it, the package itself is checked too
    env = dict(os.environ, MYPYPATH=os.environ.get("PYTHONPATH", ""))
    p = subprocess.run([sys.executable, "-m", "mypy", "--no-error-summary", "--cache-dir", str(tmp_path / "cache"),
                        str(script)], capture_output=True, text=True, env=env, cwd=tmp_path)
    lines = [l for l in p.stdout.splitlines() if "error" in l or "note: Revealed" in l]
    # the one deliberate error, and the types the stubs give
    errors = [l for l in lines if ": error:" in l]
    assert len(errors) == 1 and "Incompatible types in assignment" in errors[0], p.stdout
    assert any("Revealed type" in l and "ndarray" in l for l in lines), p.stdout
    assert any("Revealed type" in l and "dict" in l.lower() for l in lines), p.stdout
