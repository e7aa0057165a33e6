"""Open-loop rollouts of a batch of worlds (asperity.rollout): given actions for every world and
control step, the trajectories of every body, on a pool of threads or spread over a Dask
cluster in chunks of worlds, with the same numbers either way."""

import numpy as np

from . import _Batch, _check_int, _client_chunks, _scene_source, _vary_pairs

# Action kinds: Batch's set_<kind> method, the width of one world's value (None: a number).
ACTIONS = {"force": 3, "torque": 3, "velocity": 3, "angular_velocity": 3, "joint_target": None}
STATE = ("positions", "orientations", "linear_velocities", "angular_velocities")


def rollout(scene, n, steps, actions=None, vary=None, seed=0, frame_skip=1, threads=0,
            client=None):
    """Runs the n worlds of asperity.Batch(scene, n, vary=vary, seed=seed) for `steps` control
    steps of `frame_skip` world steps each, with the given actions.

    actions: {kind: {name: array}}, kind one of 'force', 'torque', 'velocity',
    'angular_velocity' (arrays of shape (n, steps, 3)) or 'joint_target' ((n, steps)); step t
    of world i applies actions[kind][name][i, t] for its frame_skip world steps, as
    Batch.set_<kind>(name, ...) does. threads: each pool's size (0 = every core). client: a
    dask.distributed.Client; the worlds are then spread over its workers in chunks, each
    worker building the chunk's worlds as the same samples, and the results are identical.

    Returns a dict: 'positions', 'linear_velocities', 'angular_velocities' (n, steps + 1, B, 3)
    and 'orientations' (n, steps + 1, B, 4) from the start on, 'values' ({path: (n,)}),
    'state_hash' ((n,) strings after the last step) and 'body_names'.
    """
    n = _check_int(n, "n", 1)
    steps = _check_int(steps, "steps", 0)
    frame_skip = _check_int(frame_skip, "frame_skip", 1)
    seed = _check_int(seed, "seed", 0)
    threads = _check_int(threads, "threads", 0)
    text, scene_file = _scene_source(scene)
    args = (text, scene_file, _vary_pairs(vary or {}), seed, frame_skip, steps)
    actions = _check_actions(actions or {}, n, steps)
    # The scene, variations and names checked here before any work is sent out.
    body_names = _Batch(text, scene_file, args[2], 1, seed, 1).body_names
    if client is None:
        result = _run_chunk(args, np.arange(n), actions, threads)
    else:
        result = _run_on_client(client, args, actions, n)
    result["body_names"] = list(body_names)
    return result


def _check_actions(actions, n, steps):
    """{kind: {name: array}} as {(kind, name): float64 array}, shapes checked."""
    if not isinstance(actions, dict):
        raise TypeError("actions must be a dict {kind: {name: array}}")
    checked = {}
    for kind, per_name in actions.items():
        if kind not in ACTIONS:
            raise ValueError("actions: unknown kind %r (one of %s)" % (kind, ", ".join(ACTIONS)))
        if not isinstance(per_name, dict):
            raise TypeError("actions[%r] must be a dict {name: array}" % kind)
        for name, values in per_name.items():
            a = np.ascontiguousarray(values, dtype=np.float64)
            shape = (n, steps) + ((ACTIONS[kind],) if ACTIONS[kind] else ())
            if a.shape != shape:
                raise ValueError("actions[%r][%r] must have shape %s, got %s"
                                 % (kind, name, shape, a.shape))
            checked[(kind, name)] = a
    return checked


def _run_chunk(args, worlds, actions, threads):
    """Worlds `worlds` (sample indices) of the rollout, with their rows of the actions: a batch
    of them, stepped and recorded."""
    text, scene_file, pairs, seed, frame_skip, steps = args
    worlds = np.asarray(worlds, dtype=np.int64)
    batch = _Batch(text, scene_file, pairs, len(worlds), seed, threads)
    if not np.array_equal(worlds, np.arange(len(worlds))):
        batch.reset(samples=worlds)
    # Every state array from the start on, one row per control step.
    record = {k: np.empty((len(worlds), steps + 1) + getattr(batch, k).shape[1:]) for k in STATE}
    for k in STATE:
        record[k][:, 0] = getattr(batch, k)
    for t in range(steps):
        for (kind, name), a in actions.items():
            getattr(batch, "set_" + kind)(name, a[:, t])
        batch.step(frame_skip)
        for k in STATE:
            record[k][:, t + 1] = getattr(batch, k)
    record["values"] = batch.values
    record["state_hash"] = batch.state_hashes()
    return record


def _run_on_client(client, args, actions, n):
    """Chunks of worlds on the cluster's workers (about four per worker), joined in order."""
    chunks = _client_chunks(client, n)
    futures = client.map(_run_chunk, [args] * len(chunks), chunks,
                         [{k: a[c] for k, a in actions.items()} for c in chunks],
                         [0] * len(chunks), pure=False)
    parts = client.gather(futures)
    result = {k: np.concatenate([p[k] for p in parts]) for k in STATE + ("state_hash",)}
    result["values"] = {k: np.concatenate([p["values"][k] for p in parts])
                        for k in parts[0]["values"]}
    return result
