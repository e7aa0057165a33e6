"""asperity.envs.PushOnTexture: spaces and bounds, determinism for a seed, the single env as
world 0 of the vector env, termination at the goal, truncation, autoreset, textures, and bad
input."""

import numpy as np
import pytest

import asperity
from asperity.envs import GOAL_RADIUS, TEXTURES, PushOnTexture, PushOnTextureVec, mean_mu
from asperity.spaces import _Box


def push(obs):
    """A scripted pusher: full force toward the goal, the finger kept on the box-goal line."""
    box, finger, finger_v, box_v, goal = obs[:, 0:2], obs[:, 6:8], obs[:, 8:10], obs[:, 4:6], \
        obs[:, 10:12]
    u = (goal - box) / np.linalg.norm(goal - box, axis=1, keepdims=True)
    n = np.stack([-u[:, 1], u[:, 0]], axis=1)
    lateral = np.sum((finger - box) * n, 1) - 0.5 * np.sum(box_v * n, 1)
    a = u - (30 * lateral + 3 * np.sum(finger_v * n, 1))[:, None] * n
    return np.clip(a, -1, 1)


def run(env, policy, steps):
    """Steps until every episode ended once; returns (success, steps taken) per episode."""
    obs, _ = env.reset(seed=7)
    ended = np.zeros(env.num_envs, dtype=bool)
    success = np.zeros(env.num_envs, dtype=bool)
    taken = np.full(env.num_envs, steps)
    for s in range(steps):
        obs, _, terminated, truncated, info = env.step(policy(obs))
        new = (terminated | truncated) & ~ended
        success |= new & info["success"]
        taken[new] = s + 1
        ended |= new
        if ended.all():
            break
    return success, taken


def test_spaces_have_shapes_and_bounds():
    env = PushOnTexture(texture="sawtooth")
    assert env.observation_space.shape == (12,) and env.action_space.shape == (2,)
    np.testing.assert_array_equal(env.action_space.low, [-1, -1])
    np.testing.assert_array_equal(env.action_space.high, [1, 1])
    obs, info = env.reset(seed=1)
    assert obs.shape == (12,) and obs.dtype == np.float64 and env.observation_space.contains(obs)
    for _ in range(20):
        obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
        assert env.observation_space.contains(obs)
        assert isinstance(reward, float) and isinstance(terminated, bool)
    vec = PushOnTextureVec(3, texture="sawtooth")
    assert vec.observation_space.shape == (3, 12) and vec.action_space.shape == (3, 2)
    assert vec.single_observation_space == env.observation_space
    box = _Box(-1.0, 2.0, shape=(2,), seed=3)
    assert box.contains(box.sample()) and not box.contains(np.array([3.0, 0.0]))
    assert not box.contains(np.zeros(3))


def test_a_seed_gives_the_same_episode_and_the_vector_envs_world_0():
    def rollout(env, seed):
        obs, _ = env.reset(seed=seed)
        rng = np.random.default_rng(0)
        out = [obs]
        for _ in range(30):
            obs, reward, *_ = env.step(rng.uniform(-1, 1, size=2))
            out += [obs, reward]
        return np.hstack(out)

    single = PushOnTexture(texture="random")
    first, again = rollout(single, 11), rollout(single, 11)
    np.testing.assert_array_equal(first, again)
    assert not np.array_equal(first, rollout(single, 12))
    # World i of the vector env is the single env with seed + i.
    vec = PushOnTextureVec(3, texture="random", threads=2)
    obs, info = vec.reset(seed=11)
    for i in range(3):
        o, inf = single.reset(seed=11 + i)
        np.testing.assert_array_equal(obs[i], o)
        assert info["texture"][i] == inf["texture"]


def test_the_box_reaches_the_goal_and_the_episode_terminates():
    # The scripted pusher does not plan: a box that it pushes past the goal, or that turns off
    # the finger, is lost. Over 16 episodes it reaches 11 to 13 goals (seeds 1, 7, 15 and 23).
    env = PushOnTextureVec(16, texture="sawtooth", autoreset=False, threads=2)
    success, taken = run(env, push, 250)
    assert success.sum() >= 10, success
    assert np.all(taken[success] < 250)
    # The last step of a success: terminated, within the goal radius, with its bonus.
    obs, _ = env.reset(seed=7)
    for _ in range(int(taken[success][0])):
        obs, reward, terminated, truncated, info = env.step(push(obs))
    i = np.flatnonzero(success)[0]
    assert terminated[i] and not truncated[i] and info["success"][i]
    assert info["distance"][i] < GOAL_RADIUS and reward[i] > 5.0


def test_steep_faces_hold_the_box_that_constant_friction_lets_go():
    """The sawtooth's steep sense ('behind'): the same pusher fails there, not on a plate of
    the sawtooth's mean friction."""
    saw = run(PushOnTextureVec(6, texture="sawtooth", goal_directions="behind", threads=2),
              push, 250)[0]
    flat = run(PushOnTextureVec(6, texture="constant", goal_directions="behind", threads=2),
               push, 250)[0]
    assert saw.sum() == 0 and flat.sum() >= 3


def test_truncation_and_next_step_autoreset():
    env = PushOnTextureVec(2, texture="concrete", max_steps=3)
    obs, _ = env.reset(seed=2)
    for _ in range(3):
        obs, reward, terminated, truncated, info = env.step(np.zeros((2, 2)))
    assert truncated.all() and not terminated.any()
    # The next call starts new episodes, ignores the actions and pays nothing.
    obs, reward, terminated, truncated, info = env.step(np.ones((2, 2)))
    np.testing.assert_array_equal(reward, 0.0)
    np.testing.assert_array_equal(info["steps"], 0)
    assert not (terminated | truncated).any()
    assert env.batch.times.tolist() == [0.0, 0.0]


def test_textures_are_drawn_per_episode_and_constant_has_the_sawtooths_mean():
    env = PushOnTextureVec(24, texture="random")
    _, info = env.reset(seed=0)
    assert set(info["texture"]) == set(TEXTURES)
    mu = mean_mu("sawtooth")
    assert 0.5 < mu < 0.9
    flat = PushOnTextureVec(1, texture="constant")
    assert flat.constant_mu == mu and flat.batch.body_names == ["plate_constant", "box", "finger"]
    _, info = flat.reset(seed=0)
    assert info["texture"][0] == "constant"


def test_bad_input_is_rejected():
    env = PushOnTextureVec(2, texture="sawtooth")
    env.reset(seed=0)
    with pytest.raises(ValueError, match=r"actions must have shape \(2, 2\)"):
        env.step(np.zeros(2))
    with pytest.raises(ValueError, match="actions must be finite"):
        env.step(np.full((2, 2), np.nan))
    with pytest.raises(ValueError, match="texture must be"):
        PushOnTextureVec(2, texture="ice")
    with pytest.raises(ValueError, match="goal_directions must be"):
        PushOnTexture(goal_directions="up")
    with pytest.raises(ValueError, match=r"action must have shape \(2,\)"):
        PushOnTexture(texture="sawtooth").step([1.0, 0.0, 0.0])
    assert isinstance(env.batch, asperity.Batch)
