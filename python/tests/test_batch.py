"""asperity.Batch: world i is the sweep's sample i and a World of its values, on any thread
count; state views without copies; actions; resets as new worlds; bad input named."""

import copy
import threading

import numpy as np
import pytest

import asperity
from conftest import SCENES

VARY = {"/bodies/1/linear_velocity/0": "uniform(0.5,2)", "/settings/mu0": "choice(0.3,0.5)"}


@pytest.fixture
def pushed_scene(minimal_scene):
    """The minimal scene with a kinematic finger and a second box tied to the first."""
    scene = copy.deepcopy(minimal_scene)
    scene["bodies"] += [
        {"name": "tail", "position": [-0.4, 0, 0.1],
         "shapes": [{"type": "box", "half_extents": [0.1, 0.1, 0.1]}]},
        {"name": "finger", "type": "kinematic", "position": [0, -0.3, 0.05],
         "shapes": [{"type": "sphere", "radius": 0.03}]}]
    scene["joints"] = [{"name": "tie", "type": "distance", "body_a": "box", "body_b": "tail"}]
    return scene


def with_values(scene, values, i):
    """The scene dict with world i's values written at their (plain) JSON pointers."""
    scene = copy.deepcopy(scene)
    for path, column in values.items():
        *parents, last = path.strip("/").split("/")
        node = scene
        for key in parents:
            node = node[int(key)] if isinstance(node, list) else node[key]
        node[int(last) if isinstance(node, list) else last] = float(column[i])
    return scene


def forces(n, s):
    return np.array([[np.sin(i + 0.1 * s), 0.5 * i, 0.0] for i in range(n)])


def test_world_i_is_the_world_of_sample_i_on_any_thread_count(pushed_scene):
    hashes = []
    for threads in (1, 2, 0):
        batch = asperity.Batch(pushed_scene, 4, threads=threads, vary=VARY, seed=3)
        for s in range(30):
            batch.set_force("box", forces(4, s))
            batch.set_torque("tail", np.tile([0.0, 0.0, 0.2], (4, 1)))
            batch.step()
        hashes.append(batch.state_hashes())
    np.testing.assert_array_equal(hashes[0], hashes[1])
    np.testing.assert_array_equal(hashes[0], hashes[2])
    assert len(set(hashes[0])) == 4
    # The same worlds as asperity.World, from the scene with the values written in.
    for i in range(4):
        world = asperity.World(with_values(pushed_scene, batch.values, i), threads=2)
        for s in range(30):
            world.apply_force("box", forces(4, s)[i])
            world.apply_torque("tail", [0.0, 0.0, 0.2])
            world.step()
        assert world.state_hash() == hashes[0][i]
        np.testing.assert_array_equal(world.positions, batch.positions[i])
        np.testing.assert_array_equal(world.orientations, batch.orientations[i])
        np.testing.assert_array_equal(world.linear_velocities, batch.linear_velocities[i])


def test_values_and_hashes_are_the_sweeps(minimal_scene):
    batch = asperity.Batch(minimal_scene, 5, vary=VARY, seed=9)
    batch.step(40)
    r = asperity.sweep(minimal_scene, vary=VARY, samples=5, seconds=40 * 0.005, seed=9)
    assert list(batch.values) == list(VARY)
    for path in VARY:
        assert batch.values[path].shape == (5,)
        np.testing.assert_array_equal(batch.values[path], r[path])
    np.testing.assert_array_equal(batch.state_hashes(), r["state_hash"])
    np.testing.assert_array_equal(batch.positions[:, 1, 0], r["box.x"])
    np.testing.assert_array_equal(batch.samples, np.arange(5))
    np.testing.assert_allclose(batch.times, 0.2)
    assert len(batch) == batch.n == 5 and batch.body_names == ["ground", "box"]


def test_state_arrays_are_read_only_views_that_steps_refresh(pushed_scene):
    batch = asperity.Batch(pushed_scene, 3)
    views = [batch.positions, batch.orientations, batch.linear_velocities,
             batch.angular_velocities]
    assert [v.shape for v in views] == [(3, 4, 3), (3, 4, 4), (3, 4, 3), (3, 4, 3)]
    assert all(v.dtype == np.float64 and not v.flags.writeable for v in views)
    # No copies: two reads share the batch's buffer, and a step shows through an older view.
    assert np.shares_memory(batch.positions, views[0])
    before = views[0].copy()
    batch.step(10)
    assert views[0][0, 1, 0] > before[0, 1, 0]
    np.testing.assert_array_equal(views[0], batch.positions)
    with pytest.raises(ValueError):
        views[0][0, 0, 0] = 1.0
    # A view keeps the batch alive.
    del batch
    assert views[0].sum() != 0.0


def test_velocity_and_joint_targets(pushed_scene):
    batch = asperity.Batch(pushed_scene, 2)
    batch.set_velocity("finger", [[0.5, 0, 0], [0, 0.25, 0]])
    batch.set_joint_target("tie", [0.3, 0.6])
    batch.step(20)
    np.testing.assert_allclose(batch.positions[:, 3], [[0.05, -0.3, 0.05], [0, -0.275, 0.05]])
    batch.set_angular_velocity("finger", np.zeros((2, 3)))
    batch.step(100)
    gap = np.linalg.norm(batch.positions[:, 1] - batch.positions[:, 2], axis=1)
    np.testing.assert_allclose(gap, [0.3, 0.6], atol=2e-3)


def test_a_reset_world_evolves_as_a_new_one(pushed_scene):
    used = asperity.Batch(pushed_scene, 3, vary=VARY, seed=1)
    used.set_force("box", forces(3, 0))
    used.step(25)
    moved = used.state_hashes()
    used.reset([True, False, True])
    fresh = asperity.Batch(pushed_scene, 3, vary=VARY, seed=1)
    assert used.state_hashes()[0] == fresh.state_hashes()[0]
    assert used.state_hashes()[1] == moved[1]
    used.step(15)
    fresh.step(15)
    np.testing.assert_array_equal(used.state_hashes()[[0, 2]], fresh.state_hashes()[[0, 2]])
    np.testing.assert_allclose(used.times, [0.075, 0.2, 0.075])


def test_a_reset_to_a_given_state_or_sample(pushed_scene):
    batch = asperity.Batch(pushed_scene, 2, vary=VARY, seed=4)
    start = batch.positions.copy()
    batch.step(10)
    # World 1 from a state of its own: only positions given, the rest the scene's.
    positions = start.copy()
    positions[1, 1] = [0.5, 0.2, 0.1]
    batch.reset([False, True], state={"positions": positions})
    np.testing.assert_array_equal(batch.positions[1], positions[1])
    world = asperity.World(with_values(pushed_scene, batch.values, 1))
    world.positions = positions[1]
    np.testing.assert_array_equal(batch.linear_velocities[1], world.linear_velocities)
    batch.step(20)
    world.step(20)
    assert batch.state_hashes()[1] == world.state_hash()
    # World 0 becomes sample 6: its values are sample 6's.
    batch.reset([True, False], samples=[6, 0])
    other = asperity.Batch(pushed_scene, 7, vary=VARY, seed=4)
    assert batch.samples.tolist() == [6, 1]
    for path in VARY:
        assert batch.values[path][0] == other.values[path][6]


def test_step_releases_the_gil(minimal_scene):
    batch = asperity.Batch(minimal_scene, 8, threads=1)
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(1)

    t = threading.Thread(target=count)
    t.start()
    try:
        batch.step(3000)
    finally:
        stop.set()
        t.join()
    assert len(ticks) > 100


def test_bad_input_raises_naming_it(pushed_scene):
    batch = asperity.Batch(pushed_scene, 2)
    with pytest.raises(ValueError, match=r"set_force\('box'\): force must have shape \(2, 3\), "
                                         r"got \(3, 3\)"):
        batch.set_force("box", np.zeros((3, 3)))
    with pytest.raises(ValueError, match="no body named 'ghost' \\(bodies: ground, box, tail, "
                                         "finger\\)"):
        batch.set_force("ghost", np.zeros((2, 3)))
    with pytest.raises(ValueError, match="force on 'box': the value of world 1 is not finite"):
        batch.set_force("box", [[0, 0, 0], [np.nan, 0, 0]])
    with pytest.raises(ValueError, match="the body is kinematic"):
        batch.set_force("finger", np.zeros((2, 3)))
    with pytest.raises(ValueError, match="velocity on 'ground': the body is static"):
        batch.set_velocity("ground", np.zeros((2, 3)))
    with pytest.raises(ValueError, match="no joint named 'rope'"):
        batch.set_joint_target("rope", [1, 1])
    with pytest.raises(ValueError, match=r"lengths must have shape \(2,\), got \(2, 1\)"):
        batch.set_joint_target("tie", [[1], [1]])
    with pytest.raises(TypeError, match="force must be an array of numbers"):
        batch.set_force("box", "strong")
    with pytest.raises(ValueError, match=r"reset: mask must have shape \(2,\)"):
        batch.reset([True])
    with pytest.raises(ValueError, match="reset: state has no part 'pose'"):
        batch.reset(state={"pose": np.zeros((2, 4, 3))})
    with pytest.raises(ValueError, match=r"reset: state\['orientations'\] must have shape "
                                         r"\(2, 4, 4\)"):
        batch.reset(state={"orientations": np.zeros((2, 4, 3))})
    with pytest.raises(ValueError, match="reset: positions of world 0 is not finite"):
        batch.reset(state={"positions": np.full((2, 4, 3), np.inf)})
    with pytest.raises(ValueError, match="samples\\[1\\] must be >= 0"):
        batch.reset(samples=[0, -1])
    with pytest.raises(ValueError, match="step count must be >= 0"):
        batch.step(-2)
    with pytest.raises(ValueError, match="k must be in 0..1000000000, got 4611686018427387904"):
        batch.step(2**62)
    with pytest.raises(ValueError, match="batch: n must be in 1..1000000, got 0"):
        asperity.Batch(pushed_scene, 0)
    with pytest.raises(TypeError):
        asperity.Batch(pushed_scene, 2.5)
    with pytest.raises(ValueError, match="/settings/nope is not in the scene"):
        asperity.Batch(pushed_scene, 2, vary={"/settings/nope": "uniform(0,1)"})
    with pytest.raises(FileNotFoundError):
        asperity.Batch(str(SCENES / "missing.json"), 2)
