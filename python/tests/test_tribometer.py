"""asperity.tribometer: arrays equal to the CLI's JSON, a scene's bodies, NaN where a test gave
no coefficient, and the CLI's error messages."""

import json

import numpy as np
import pytest

import asperity
from conftest import SCENES, cli_error, run_cli

QUICK = dict(directions=4, tracks=1, mu0=0.2)
B, A = "gen:gaussian:1:size=64", "gen:gaussian:2:size=64"


def test_the_same_numbers_as_the_cli():
    r = asperity.tribometer(B, A, **QUICK)
    code, out, err = run_cli("tribometer", B, "--a", A, "--directions", 4, "--tracks", 1,
                             "--mu0", 0.2, "--json")
    assert code == 0, err
    rows = json.loads(out)["directions"]
    for key in ("angle_deg", "mu_s", "mu_k", "mu_model"):
        assert r[key].dtype == np.float64 and r[key].shape == (4,)
        assert r[key].tolist() == [row[key] for row in rows]
    assert r["toppled"].dtype == np.bool_ and not r["toppled"].any()


def test_two_bodies_of_a_scene_with_a_given_gain():
    r = asperity.tribometer(scene=SCENES / "boxes_on_materials.json",
                            bodies=["box_steel", "plane_steel"], directions=4, tracks=1,
                            tests=["drag"], k_b=4.0)
    assert np.isnan(r["mu_s"]).all()
    assert np.allclose(r["mu_k"], r["mu_model"], rtol=0.05)
    assert (r["mu_k"] > 0.2).all()


def test_a_toppled_block_reads_nan():
    r = asperity.tribometer(B, sampler="constant", mu0=0.8, block_height=0.3, directions=4,
                            tracks=1, tests=["tilt"])
    assert np.isnan(r["mu_s"]).all() and r["toppled"].all()
    assert np.isnan(r["mu_model"]).all()


def test_bad_input_raises_the_cli_messages():
    with pytest.raises(ValueError) as e:
        asperity.tribometer("missing.png")
    assert str(e.value) == cli_error("tribometer", "missing.png")
    with pytest.raises(ValueError) as e:
        asperity.tribometer(scene=SCENES / "boxes_on_materials.json", bodies=["box_steel", "x"])
    assert "'x'" in str(e.value)
    with pytest.raises(ValueError, match="directions"):
        asperity.tribometer(B, directions=0)
    with pytest.raises(ValueError, match="tests"):
        asperity.tribometer(B, tests=["spin"])
    with pytest.raises(TypeError):
        asperity.tribometer(3.5)


def test_calibrate_gives_the_clis_values_and_the_rows(tmp_path):
    plate, block = "gen:sawtooth:1:size=128,period=16", "gen:sawtooth:2:size=128,period=16,axis=v"
    r = asperity.tribometer(plate, block, k_a=1.5, k_b=0.8, mu0=0.3, directions=8, tracks=2,
                            tests=["drag"])
    data = tmp_path / "mu.csv"
    data.write_text("angle_deg,mu\n" + "".join(
        "%r,%r\n" % (a, m) for a, m in zip(r["angle_deg"], r["mu_model"])))
    c = asperity.calibrate(data, plate, block, tracks=2, write=tmp_path / "fitted.json")
    assert c["k_a"] == pytest.approx(1.5, rel=0.02)
    assert c["k_b"] == pytest.approx(0.8, rel=0.02)
    assert c["mu0"] == pytest.approx(0.3, rel=0.02)
    assert c["residual"].shape == (8,) and np.allclose(c["measured"] - c["model"], c["residual"])
    code, out, err = run_cli("calibrate", data, plate, "--a", block, "--tracks", 2, "--json")
    assert code == 0, err
    assert json.loads(out) == {k: c[k] for k in ("k_a", "k_b", "mu0", "rms_residual")}
    assert json.loads((tmp_path / "fitted.json").read_text())["settings"]["mu0"] == c["mu0"]
    fixed = asperity.calibrate(data, plate, block, tracks=2, k_a=1.5, mu0=0.3)
    assert set(fixed) == {"k_b", "rms_residual", "angle_deg", "measured", "model", "residual"}


def test_calibrate_raises_the_clis_messages(tmp_path):
    (tmp_path / "bad.csv").write_text("angle_deg,mu\n0,nan\n")
    with pytest.raises(ValueError) as e:
        asperity.calibrate(tmp_path / "bad.csv", "gen:sawtooth:1")
    assert str(e.value) == cli_error("calibrate", tmp_path / "bad.csv", "gen:sawtooth:1")
    with pytest.raises(ValueError, match="model"):
        asperity.calibrate(tmp_path / "bad.csv", "gen:sawtooth:1", model="spline")
