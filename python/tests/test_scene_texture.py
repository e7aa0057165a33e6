"""Scenes as dicts and back; normal maps and cones equal to the CLI's."""

import json
import warnings

import numpy as np
import pytest

import asperity
from conftest import SCENES, cli_error, run_cli


def test_scene_round_trips_through_a_dict(minimal_scene):
    scene = asperity.load_scene(str(SCENES / "stacking.json"))
    again = asperity.load_scene(scene.to_dict(), base_dir=str(SCENES))
    assert again.to_dict() == scene.to_dict()
    assert again.body_names == scene.body_names
    a, b = asperity.World(scene), asperity.World(again)
    a.step(10)
    b.step(10)
    assert a.state_hash() == b.state_hash()
    assert asperity.load_scene(minimal_scene).body_names == ["ground", "box"]


def test_bad_scenes_raise_the_loader_messages(tmp_path):
    with pytest.raises(FileNotFoundError):
        asperity.load_scene(str(tmp_path / "missing.json"))
    (tmp_path / "syntax.json").write_text("{\"bodies\": [}")
    with pytest.raises(ValueError) as e:
        asperity.load_scene(str(tmp_path / "syntax.json"))
    assert str(e.value) == cli_error("run", tmp_path / "syntax.json")
    with pytest.raises(TypeError):
        asperity.load_scene(3.5)
    with pytest.raises(TypeError):
        asperity.load_scene({"bodies": [float]})


def test_deprecated_keys_give_a_warning(minimal_scene):
    old = dict(minimal_scene, settings={"sampler": "constant", "mu0": 0.5, "dt": 0.005})
    message = r'<dict>: /settings/sampler: deprecated, use "friction_provider"'
    # A world built from the dict warns, and keeps the warning.
    with pytest.warns(UserWarning, match=message):
        world = asperity.World(old)
    assert world.warnings == ['<dict>: /settings/sampler: deprecated, use "friction_provider"']
    # load_scene warns once; worlds built from its Scene do not repeat it.
    with pytest.warns(UserWarning, match=message):
        scene = asperity.load_scene(old)
    assert scene.friction_provider == scene.sampler == "constant"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert asperity.World(scene).warnings == []
        asperity.load_scene(minimal_scene)
    # Saved back, only the new key is written.
    assert "sampler" not in scene.to_dict()["settings"]
    # The old and the new key together are an error naming the pointer.
    both = dict(minimal_scene, settings={"sampler": "cpu", "friction_provider": "cpu"})
    with pytest.raises(ValueError, match=r"<dict>: /settings/sampler: deprecated name of"):
        asperity.load_scene(both)


def test_named_materials_round_trip(tmp_path):
    scene = asperity.load_scene(str(SCENES / "stacking.json"))
    saved = scene.to_dict()
    assert sorted(saved["materials"]) == ["acrylic", "cut_pvc", "oak"]
    assert saved["bodies"][1]["shapes"][0]["surface"] == "acrylic"
    bad = dict(saved)
    bad["bodies"] = [dict(saved["bodies"][1], shapes=[dict(saved["bodies"][1]["shapes"][0],
                                                           surface="teak")])]
    with pytest.raises(ValueError, match=r'/bodies/0/shapes/0/surface: unknown material "teak"'):
        asperity.load_scene(bad)


def test_generated_texture_equals_the_cli_png(tmp_path):
    png = tmp_path / "g.png"
    code, _, err = run_cli("texture", "gaussian", "--sx", 0.5, "--size", 32, "--seed", 3,
                           "--bits", 16, "--out", png)
    assert code == 0, err
    generated = asperity.generate_texture("gaussian", size=32, seed=3, sx=0.5)
    loaded = asperity.load_normal_map(str(png))
    assert generated.shape == (32, 32, 3) and generated.dtype == np.float32
    # 16-bit quantisation: within 2 / 65535 per component.
    np.testing.assert_allclose(loaded, generated, atol=4e-5)
    np.testing.assert_allclose(np.linalg.norm(generated, axis=2), 1.0, atol=1e-5)


def test_cone_equals_the_cli(tmp_path):
    code, _, err = run_cli("texture", "sawtooth", "--size", 64, "--out", tmp_path / "s.png")
    assert code == 0, err
    code, out, err = run_cli("cone", tmp_path / "s.png", "--json", "--directions", 8)
    assert code == 0, err
    cli = json.loads(out)
    cone = asperity.cone(str(tmp_path / "s.png"), directions=8)
    np.testing.assert_allclose(cone["mu"], [d["mu"] for d in cli["directions"]], rtol=1e-6)
    np.testing.assert_allclose(cone["angles_deg"], [d["angle_deg"] for d in cli["directions"]])
    assert cone["box"] == pytest.approx(cli["box"], rel=1e-6)
    # The same from the array; a flat map has no ploughing (mu = mu0).
    again = asperity.cone(asperity.load_normal_map(str(tmp_path / "s.png")), directions=8)
    np.testing.assert_allclose(again["mu"], cone["mu"], rtol=1e-6)
    flat = np.zeros((4, 4, 3), np.float32)
    flat[..., 2] = 1
    np.testing.assert_allclose(asperity.cone(flat, mu0=0.3)["mu"], 0.3, rtol=1e-6)


def test_bad_texture_arguments_raise():
    with pytest.raises(ValueError, match="unknown"):
        asperity.generate_texture("plaid")
    with pytest.raises(ValueError, match="sx"):
        asperity.generate_texture("gaussian", sx=-5)
    with pytest.raises(ValueError, match="size"):
        asperity.generate_texture("gaussian", size=0)
    with pytest.raises(FileNotFoundError):
        asperity.load_normal_map("missing.png")
    with pytest.raises(TypeError):
        asperity.cone(np.zeros((4, 4)))
    with pytest.raises(ValueError, match="directions"):
        asperity.cone(np.dstack([np.zeros((4, 4)), np.zeros((4, 4)), np.ones((4, 4))]),
                      directions=2)
    with pytest.raises(ValueError, match="z >= 0"):
        asperity.cone(np.full((2, 2, 3), np.nan))


def test_a_friction_setting_out_of_range_gets_the_words_of_every_front_end(minimal_scene):
    # The same words as a scene's, the CLI's and ContactFriction's (one range per field).
    words = r"patch_resolution must be an integer in \[1, 256\], got 512"
    with pytest.raises(ValueError, match=words):
        asperity.World(minimal_scene, patch_resolution=512)
    scene = dict(minimal_scene, settings={"patch_resolution": 512})
    with pytest.raises(ValueError, match="/settings/patch_resolution: " + words[len("patch_resolution "):]):
        asperity.World(scene)
    with pytest.raises(ValueError, match=r"directions must be an integer in \[4, 64\], got 2"):
        asperity.World(minimal_scene, directions=2)
