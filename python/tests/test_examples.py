"""examples/python run end to end (small sizes): a plot, a fitted gain, a rendered PNG, a
learnt pusher with its learning curves."""

import os
import re
import subprocess
import sys

import pytest

import asperity
from conftest import ROOT

EXAMPLES = ROOT / "examples" / "python"
# The examples import the very package under test, whatever the working directory.
ENV = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(asperity.__file__)))


def run_example(name, *args, cwd):
    r = subprocess.run([sys.executable, str(EXAMPLES / name), *map(str, args)], cwd=cwd,
                       capture_output=True, text=True, env=ENV, check=False)
    assert r.returncode == 0, r.stderr
    return r.stdout


def test_slide_vs_ra_writes_a_plot_and_rougher_slides_less(tmp_path):
    out = run_example("slide_vs_ra.py", "--samples", 3, "--seconds", 1, "--out", "p.png",
                      cwd=tmp_path)
    slides = [float(x) for x in re.findall(r"slide ([0-9.]+) m", out)]
    assert len(slides) == 3 and slides[0] > slides[1] > slides[2]
    assert (tmp_path / "p.png").stat().st_size > 1000


def test_fit_gain_recovers_the_scenes_gain(tmp_path):
    out = run_example("fit_gain.py", "--rounds", 2, cwd=tmp_path)
    k = float(re.search(r"fitted k = ([0-9.]+)", out).group(1))
    assert k == pytest.approx(2.0, rel=0.1)


def test_render_png_writes_a_frame_or_says_why(tmp_path):
    r = subprocess.run([sys.executable, str(EXAMPLES / "render_png.py"), "--size", "64x48",
                        "--at", "0.1", "--out", "f.png"], cwd=tmp_path, capture_output=True,
                       text=True, env=ENV, check=False)
    if r.returncode != 0:
        # No OpenGL context here: the RuntimeError's one line, not a traceback.
        assert r.stderr.startswith("render: ") and "Traceback" not in r.stderr, r.stderr
        return
    assert (tmp_path / "f.png").stat().st_size > 100


def test_learn_push_runs_the_learner_and_plots_its_curves(tmp_path):
    out = run_example("learn_push.py", "--iterations", 2, "--population", 6, "--elites", 2,
                      "--episodes", 1, "--validation", 2, "--held-out", 3, "--threads", 2,
                      "--out", "curves.png", cwd=tmp_path)
    assert len(re.findall(r"sawtooth iteration +\d+: validation success", out)) == 2
    assert len(re.findall(r"constant iteration +\d+", out)) == 2
    rows = re.findall(r"(sawtooth|constant) goals (ahead|behind) *: success +(\d+) %", out)
    assert len(rows) == 4
    # The steep faces hold the box whatever the policy.
    assert dict(((t, d), int(s)) for t, d, s in rows)[("sawtooth", "behind")] == 0
    assert (tmp_path / "curves.png").stat().st_size > 1000
