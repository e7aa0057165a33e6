"""Paths shared by the Python tests: the repository, its scenes and the built CLI."""

import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENES = ROOT / "scenes"
CLI = pathlib.Path(os.environ.get("ASPERITY_BIN", ROOT / "build" / "bin")) / "asperity"


def run_cli(*args):
    """Runs the asperity tool; returns (exit code, stdout, stderr)."""
    r = subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True, check=False)
    return r.returncode, r.stdout, r.stderr


def cli_error(*args):
    """The message of a failing CLI call, without the 'asperity: error: ' prefix."""
    code, _, err = run_cli(*args)
    assert code != 0
    return err.strip().removeprefix("asperity: error: ")


@pytest.fixture
def minimal_scene():
    return {
        "settings": {"friction_provider": "constant", "mu0": 0.5, "dt": 0.005},
        "bodies": [
            {"name": "ground", "type": "static", "shapes": [{"type": "plane"}]},
            {"name": "box", "position": [0, 0, 0.1], "linear_velocity": [1, 0, 0],
             "shapes": [{"type": "box", "half_extents": [0.1, 0.1, 0.1]}]},
        ],
    }
