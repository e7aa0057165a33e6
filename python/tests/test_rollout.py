"""asperity.rollout: open-loop trajectories of a batch, equal to stepping the Batch by hand,
on any thread count and on a Dask cluster."""

import numpy as np
import pytest

import asperity

VARY = {"/bodies/1/linear_velocity/0": "uniform(0.5,2)", "/settings/mu0": "choice(0.3,0.5)"}


def pushes(n, steps):
    """A force on the box per world and control step."""
    t = np.arange(steps)[None, :, None]
    i = np.arange(n)[:, None, None]
    return np.concatenate([np.sin(0.3 * t + i), 0.2 * i + 0 * t, 0 * (t + i)], axis=2)


def test_a_rollout_is_the_batch_stepped_by_hand(minimal_scene):
    n, steps = 5, 12
    forces = pushes(n, steps)
    r = asperity.rollout(minimal_scene, n, steps, actions={"force": {"box": forces}},
                         vary=VARY, seed=4, frame_skip=3, threads=2)
    batch = asperity.Batch(minimal_scene, n, vary=VARY, seed=4)
    assert r["positions"].shape == (n, steps + 1, 2, 3)
    assert r["orientations"].shape == (n, steps + 1, 2, 4)
    np.testing.assert_array_equal(r["positions"][:, 0], batch.positions)
    for t in range(steps):
        batch.set_force("box", forces[:, t])
        batch.step(3)
        np.testing.assert_array_equal(r["positions"][:, t + 1], batch.positions)
        np.testing.assert_array_equal(r["angular_velocities"][:, t + 1],
                                      batch.angular_velocities)
    np.testing.assert_array_equal(r["state_hash"], batch.state_hashes())
    for path in VARY:
        np.testing.assert_array_equal(r["values"][path], batch.values[path])
    assert r["body_names"] == ["ground", "box"]
    one = asperity.rollout(minimal_scene, n, steps, actions={"force": {"box": forces}},
                           vary=VARY, seed=4, frame_skip=3, threads=1)
    np.testing.assert_array_equal(one["state_hash"], r["state_hash"])


def test_a_rollout_on_dask_equals_the_threaded_one(minimal_scene):
    import distributed  # Debian python3-distributed, installed by scripts/install-deps.sh

    n, steps = 10, 8
    kwargs = dict(actions={"force": {"box": pushes(n, steps)}}, vary=VARY, seed=2,
                  frame_skip=2)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        on_cluster = asperity.rollout(minimal_scene, n, steps, client=client, **kwargs)
    local = asperity.rollout(minimal_scene, n, steps, threads=2, **kwargs)
    for key in ("positions", "orientations", "linear_velocities", "angular_velocities",
                "state_hash"):
        np.testing.assert_array_equal(on_cluster[key], local[key])
    for path in VARY:
        np.testing.assert_array_equal(on_cluster["values"][path], local["values"][path])


def test_bad_rollouts_are_rejected(minimal_scene):
    with pytest.raises(ValueError, match=r"actions\['force'\]\['box'\] must have shape "
                                         r"\(2, 3, 3\), got \(2, 3\)"):
        asperity.rollout(minimal_scene, 2, 3, actions={"force": {"box": np.zeros((2, 3))}})
    with pytest.raises(ValueError, match="unknown kind 'push'"):
        asperity.rollout(minimal_scene, 2, 3, actions={"push": {"box": np.zeros((2, 3, 3))}})
    with pytest.raises(ValueError, match="no body named 'ghost'"):
        asperity.rollout(minimal_scene, 2, 3, actions={"force": {"ghost": np.zeros((2, 3, 3))}})
    with pytest.raises(ValueError, match="steps must be >= 0"):
        asperity.rollout(minimal_scene, 2, -1)
    with pytest.raises(TypeError):
        asperity.rollout(minimal_scene, 2, 3, actions=[1, 2])
