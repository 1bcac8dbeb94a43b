# Copyright (c) 2026 The PR-star octree project.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Shared fixtures of the Python module's tests.

The tests compare the module with the ``prstar`` tool (``PRSTAR_CLI``) on the meshes the build
generates (``PRSTAR_TEST_DATA``: cube.mesh, sphere.mesh, torus.mesh, cube_tetgen.vtu, ...) and, when
it exists, on the real meshes of ``PRSTAR_SHARED_DATA`` (../shared/data).  ctest sets the three
variables; run by hand as

    PYTHONPATH=BUILD/python PRSTAR_CLI=BUILD/tools/prstar/prstar \
    PRSTAR_TEST_DATA=BUILD/test/PR_star_octree/data /usr/bin/python3 -m pytest python/tests
"""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path
from typing import List, Optional

import pytest


def _env_path(name: str) -> Optional[Path]:
    v = os.environ.get(name)
    return Path(v) if v else None


class Cli:
    """The prstar tool: ``run(...)`` returns the CompletedProcess, ``json(...)`` the parsed --json."""

    def __init__(self, path: Path) -> None:
        self.path = path

    def run(self, *args: str, check: bool = False) -> subprocess.CompletedProcess:
        p = subprocess.run([str(self.path), *map(str, args)], capture_output=True, text=True, timeout=600)
        if check and p.returncode != 0:
            raise AssertionError(f"prstar {' '.join(map(str, args))} exited {p.returncode}: {p.stderr}")
        return p

    def json(self, *args: str, statuses: List[int] = [0]) -> dict:
        p = self.run(*args, "--json")
        assert p.returncode in statuses, f"prstar {' '.join(map(str, args))} exited {p.returncode}: {p.stderr}"
        return json.loads(p.stdout)


@pytest.fixture(scope="session")
def cli() -> Cli:
    path = _env_path("PRSTAR_CLI")
    if path is None or not path.exists():
        pytest.skip("PRSTAR_CLI (the prstar tool) not set")
    return Cli(path)


@pytest.fixture(scope="session")
def data_dir() -> Path:
    d = _env_path("PRSTAR_TEST_DATA")
    if d is None or not d.is_dir():
        pytest.skip("PRSTAR_TEST_DATA (the generated test meshes) not set")
    return d


@pytest.fixture(scope="session")
def shared_data() -> Path:
    d = _env_path("PRSTAR_SHARED_DATA")
    if d is None or not d.is_dir():
        pytest.skip("../shared/data is absent")
    return d


#: the generated meshes every application is compared on
TEST_MESHES = ["cube.mesh", "sphere.mesh", "torus.mesh", "sphere_tetgen.mesh", "cube_tetgen.vtu"]
