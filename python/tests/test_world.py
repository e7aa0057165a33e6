"""asperity.World: hashes equal to the CLI's, state arrays, contacts, loads, bad inputs."""

import threading

import numpy as np
import pytest

import asperity
from conftest import SCENES, run_cli

EXPERIMENT_SCENES = sorted(p.name for p in SCENES.glob("*.json"))


@pytest.mark.parametrize("name", EXPERIMENT_SCENES)
def test_hash_equals_the_cli_for_every_experiment_scene(name):
    world = asperity.World(str(SCENES / name))
    world.step(15)
    code, out, err = run_cli("run", SCENES / name, "--steps", 15, "--hash")
    assert code == 0, err
    assert world.state_hash() == out.strip()
    assert len(world.state_hash()) == 16


def test_threads_do_not_change_the_bits():
    hashes = set()
    for threads in (1, 2, 4):
        world = asperity.World(str(SCENES / "stacking.json"), sampler="cpu", threads=threads)
        world.step(30)
        hashes.add(world.state_hash())
    assert len(hashes) == 1
    with pytest.raises(ValueError, match="threads"):
        asperity.World(str(SCENES / "stacking.json"), threads=-1)


def test_prepare_builds_collision_once_and_changes_no_bits():
    prepared = asperity.World(str(SCENES / "nut_bolt.json"))
    plain = asperity.World(str(SCENES / "nut_bolt.json"))
    assert prepared.prepare() > 0.0  # the nut's signed distance field
    assert prepared.prepare() == 0.0
    prepared.step(20)
    plain.step(20)
    assert prepared.state_hash() == plain.state_hash()


def test_state_arrays_have_the_documented_shapes_and_dtypes():
    world = asperity.World(str(SCENES / "stacking.json"))
    b = len(world.body_names)
    for name, cols in [("positions", 3), ("orientations", 4), ("linear_velocities", 3),
                       ("angular_velocities", 3)]:
        a = getattr(world, name)
        assert a.shape == (b, cols) and a.dtype == np.float64, name
    np.testing.assert_allclose(np.linalg.norm(world.orientations, axis=1), 1.0, atol=1e-12)


def test_state_matches_the_cli_csv(tmp_path):
    world = asperity.World(str(SCENES / "sawtooth_plane.json"))
    world.step(30)
    code, _, err = run_cli("run", SCENES / "sawtooth_plane.json", "--steps", 30, "--every", 30,
                           "--out", tmp_path / "t.csv")
    assert code == 0, err
    rows = [line.split(",") for line in (tmp_path / "t.csv").read_text().splitlines()[1:]]
    last = [r for r in rows if r[0] == "30"]
    assert [r[2] for r in last] == world.body_names
    csv = np.array([[float(x) for x in r[3:]] for r in last])
    state = np.hstack([world.positions, world.orientations, world.linear_velocities,
                       world.angular_velocities])
    np.testing.assert_array_equal(state, csv)


def test_setting_the_state_restarts_from_it(minimal_scene):
    a = asperity.World(minimal_scene)
    a.step(20)
    saved = [a.positions, a.orientations, a.linear_velocities, a.angular_velocities]
    a.step(20)
    b = asperity.World(minimal_scene)
    b.positions, b.orientations, b.linear_velocities, b.angular_velocities = saved
    b.step(20)
    # The restart forgets a's contact history (warm starts, contact points), so b follows a
    # closely rather than bit for bit.
    np.testing.assert_allclose(b.positions, a.positions, atol=1e-6)
    np.testing.assert_allclose(b.linear_velocities, a.linear_velocities, atol=1e-5)


def test_worlds_restarted_from_one_state_evolve_bit_for_bit_alike():
    # Four boxes sliding on textured friction: a new world and one that ran on its own first,
    # both set to the state of a third, then stepped alike.
    scene = asperity.load_scene(str(SCENES / "boxes_on_materials.json"))
    source = asperity.World(scene)
    source.step(60)
    saved = [source.positions, source.orientations, source.linear_velocities,
             source.angular_velocities]
    fresh, used = asperity.World(scene), asperity.World(scene)
    used.step(23)
    for w in (fresh, used):
        w.positions, w.orientations, w.linear_velocities, w.angular_velocities = saved
        w.step(100)
    assert fresh.state_hash() == used.state_hash()
    np.testing.assert_array_equal(fresh.positions, used.positions)


def test_sliding_box_stops_at_the_coulomb_distance(minimal_scene):
    world = asperity.World(minimal_scene)
    world.step(200)
    # d = v^2 / (2 mu g) with v = 1 m/s, mu = 0.5.
    assert world.positions[1, 0] == pytest.approx(1.0 / (2 * 0.5 * 9.81), rel=0.03)
    assert world.time == pytest.approx(1.0)


def test_contacts_of_the_last_step_as_arrays():
    world = asperity.World(str(SCENES / "boxes_on_materials.json"))
    world.step(5)
    c = world.contacts()
    n = len(c["phi"])
    assert n > 0
    assert c["body_a"].shape == (n,) and c["body_a"].dtype == np.int32
    assert c["points"].shape == (n, 3) and c["normals"].shape == (n, 3)
    assert c["frames"].shape == (n, 3, 3) and c["impulses"].shape == (n, 3)
    assert c["mu"].dtype == np.float32 and c["mu"].shape[0] == n
    assert c["fallback"].dtype == np.bool_ and c["patch_pixels"].dtype == np.int32
    # Frames are right-handed with b = n x t; normals are the frames' third rows.
    f = c["frames"]
    np.testing.assert_allclose(np.cross(f[:, 2], f[:, 0]), f[:, 1], atol=1e-9)
    np.testing.assert_array_equal(f[:, 2], c["normals"])
    # Boxes resting: the normal impulses carry their weight, m g dt in all.
    assert np.all(c["impulses"][:, 2] >= 0)


def test_force_torque_and_impulse_on_a_named_body(minimal_scene):
    minimal_scene["bodies"][1]["linear_velocity"] = [0, 0, 0]
    minimal_scene["bodies"][1]["position"] = [0, 0, 5]
    world = asperity.World(minimal_scene)
    mass = 8.0 * 0.001 * 1000.0  # 0.2 m cube of the default density
    world.apply_impulse("box", [mass * 2.0, 0, 0])
    world.step()
    assert world.linear_velocities[1, 0] == pytest.approx(2.0)
    # A force of m g up for one step cancels gravity.
    world.apply_force("box", [0, 0, mass * 9.81])
    vz = world.linear_velocities[1, 2]
    world.step()
    assert world.linear_velocities[1, 2] == pytest.approx(vz, abs=1e-9)
    world.apply_torque("box", [0, 0, 1.0], duration=0.1)
    world.step(10)
    assert world.angular_velocities[1, 2] > 0


def test_step_releases_the_gil(minimal_scene):
    world = asperity.World(str(SCENES / "stacking.json"))
    ticks = []
    t = threading.Thread(target=lambda: [ticks.append(1) for _ in range(2000)])
    t.start()
    world.step(50)
    t.join()
    assert len(ticks) == 2000


def test_bad_inputs_raise_with_the_cli_messages(minimal_scene, tmp_path):
    with pytest.raises(FileNotFoundError, match="nope.json: cannot open file"):
        asperity.World("nope.json")
    with pytest.raises(TypeError):
        asperity.World(42)
    bad = dict(minimal_scene)
    bad["bodies"] = [dict(b) for b in minimal_scene["bodies"]]
    bad["bodies"][1]["shapes"] = [{"type": "box", "half_extents": [-0.1, 0.1, 0.1]}]
    with pytest.raises(ValueError, match="/bodies/1/shapes/0/half_extents/0"):
        asperity.World(bad)
    path = tmp_path / "bad.json"
    path.write_text(__import__("json").dumps(bad))
    code, _, err = run_cli("run", path, "--steps", 1)
    with pytest.raises(ValueError) as e:
        asperity.load_scene(str(path))
    assert code == 1 and str(e.value) in err
    with pytest.raises(ValueError, match="unknown friction sampler"):
        asperity.World(minimal_scene, sampler="magic")
    with pytest.raises(ValueError, match="friction: unknown value 'sticky'"):
        asperity.World(minimal_scene, friction="sticky")
    with pytest.raises(ValueError, match="directions"):
        asperity.World(minimal_scene, directions=3)
    world = asperity.World(minimal_scene)
    with pytest.raises(ValueError, match="shape \\(2, 3\\)"):
        world.positions = np.zeros((3, 3))
    with pytest.raises(ValueError, match="finite"):
        world.linear_velocities = np.full((2, 3), np.nan)
    with pytest.raises(TypeError):
        world.positions = "here"
    with pytest.raises(ValueError, match="row 1 is zero"):
        world.orientations = np.array([[1, 0, 0, 0], [0, 0, 0, 0]])
    with pytest.raises(ValueError, match="no body named 'ghost'"):
        world.apply_force("ghost", [1, 0, 0])
    with pytest.raises(TypeError):
        world.apply_force("box", [1, 0])
    with pytest.raises(ValueError, match="finite"):
        world.apply_impulse("box", [np.inf, 0, 0])
    with pytest.raises(ValueError, match="n must be in 0..1000000000, got -1"):
        world.step(-1)
    with pytest.raises(ValueError, match="n must be in 0..1000000000, got 4611686018427387904"):
        world.step(2**62)
    with pytest.raises(TypeError):
        world.step("ten")


def test_render_gives_an_image_or_a_runtime_error(minimal_scene):
    world = asperity.World(minimal_scene)
    try:
        image = world.render(64, 48)
    except RuntimeError as e:
        assert "render" in str(e)
        return
    assert image.shape == (48, 64, 3) and image.dtype == np.uint8
    assert image.std() > 0  # not a blank frame
    with pytest.raises(ValueError, match="16..8192"):
        world.render(8, 8)
    with pytest.raises(TypeError):
        world.render(64, 48, camera=(1, 2, 3))
