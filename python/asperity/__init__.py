"""Asperity: rigid bodies whose friction comes from the normal maps of their surfaces.

The simulator is C++ (asperity._asperity); this package adds ensembles of runs
(:func:`sweep`) on a pool of threads or a Dask cluster, batches of worlds stepped together
(:class:`Batch`, and open-loop :func:`rollout` of them on threads or Dask) and environments for
learning over them (:mod:`asperity.envs`).
docs/python.md describes the API.
"""

import json
import os

import numpy as np

from ._asperity import (  # noqa: F401  (re-exported)
    Scene,
    World,
    _Batch,
    _Sweep,
    calibrate,
    cone,
    generate_texture,
    load_normal_map,
    load_scene,
    tribometer,
)

__all__ = ["Batch", "Scene", "World", "calibrate", "cone", "generate_texture", "load_normal_map",
           "load_scene", "rollout", "sweep", "tribometer"]


def _scene_source(scene):
    """The scene's JSON text and the file name relative paths resolve against."""
    if isinstance(scene, Scene):
        name = scene.source_file or os.path.join(os.getcwd(), "<dict>")
        return json.dumps(scene.to_dict()), os.path.abspath(name)
    if isinstance(scene, dict):
        return json.dumps(scene, allow_nan=False), os.path.join(os.getcwd(), "<dict>")
    if isinstance(scene, (str, os.PathLike)):
        path = os.fspath(scene)
        load_scene(path)  # the loader's FileNotFoundError / ValueError, as the CLI words them
        with open(path, encoding="utf-8") as f:
            return f.read(), os.path.abspath(path)
    raise TypeError("scene must be a path, a dict or an asperity.Scene, got "
                    + type(scene).__name__)


def _vary_pairs(vary):
    """{path: spec} as [(path, spec)]; specs are 'uniform(a,b)'-style strings or tuples."""
    if not isinstance(vary, dict):
        raise TypeError("vary must be a dict {json_path: spec}")
    pairs = []
    for path, spec in vary.items():
        if not isinstance(path, str):
            raise TypeError("vary: paths must be strings, got " + type(path).__name__)
        if isinstance(spec, (tuple, list)) and spec and isinstance(spec[0], str):
            spec = "%s(%s)" % (spec[0], ",".join(repr(float(x)) for x in spec[1:]))
        if not isinstance(spec, str):
            raise TypeError("vary: spec of %s must be a string such as 'uniform(0,1)'" % path)
        pairs.append((path, spec))
    return pairs


class Batch(_Batch):
    """n worlds of one scene stepped together, each with its own values of `vary`.

    scene: a path, a dict or an asperity.Scene. vary: {json_path: spec} as for
    :func:`sweep`; world i takes the values sample i of a sweep with the same seed takes, and is
    bit for bit a World of the scene with those values written in, given the same actions, on
    any thread count. threads: the pool the worlds step on (0 = every core; each world steps on
    one thread).

    State: positions, orientations, linear_velocities, angular_velocities, read-only views
    (n, B, 3) / (n, B, 4) of the batch's own buffers that every step and reset refresh (copy
    them to keep a snapshot). Actions for the next step(k): set_force, set_torque,
    set_velocity, set_angular_velocity (body name, (n, 3) array), set_joint_target (joint
    name, (n,) array). reset(mask, state, samples) starts worlds again as new ones. values:
    {path: (n,) array}; state_hashes(): (n,) strings as World.state_hash().
    """

    def __init__(self, scene, n, threads=0, vary=None, seed=0):
        _check_type_int(n, "n")
        threads = _check_int(threads, "threads", 0)
        seed = _check_int(seed, "seed", 0)
        text, scene_file = _scene_source(scene)
        pairs = _vary_pairs(vary or {})
        super().__init__(text, scene_file, pairs, int(n), seed, threads)

    @property
    def n(self):
        """Number of worlds."""
        return len(self)

    def __repr__(self):
        return "<asperity.Batch of %d worlds, %d bodies>" % (len(self), len(self.body_names))


def _check_type_int(value, name):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError("%s must be an integer, got %s" % (name, type(value).__name__))


def _run_chunk(args, indices):
    """Runs samples `indices` of a sweep on a Dask worker, on a pool of its machine's cores."""
    return _Sweep(*args).run(list(indices), 0)


def _check_int(value, name, low):
    _check_type_int(value, name)
    if value < low:
        raise ValueError("%s must be >= %d, got %d" % (name, low, value))
    return int(value)


def sweep(scene, vary=None, samples=1, seconds=1.0, seed=1, measure=(), threads=0,
          client=None, out=None, resume=False):
    """Runs `samples` independent worlds of `scene`, each with its own values of `vary`.

    scene: a path, a dict or an asperity.Scene. vary: {json_path: spec}, json_path a JSON
    pointer into the scene with '*' for every element of an array
    ('/bodies/*/linear_velocity/0'), spec 'uniform(a,b)', 'normal(m,s)', 'choice(a,b,...)' or
    'grid(a,b,n)'. Each sample runs `seconds` of simulated time. measure: names
    'distance:BODY', 'speed:BODY', 'angle:BODY', 'height:BODY', and/or a callable
    f(state) -> float or {name: float}, where state holds the sample's final 'positions',
    'orientations', 'linear_velocities', 'angular_velocities' ((B, 3) / (B, 4)),
    'body_names' and 'values' ({path: value}).

    threads: size of the oneTBB pool (0 = every core). client: a dask.distributed.Client; the
    samples are then spread over its workers, which need the scene's files at the same paths.
    Sample i of a seed gives the same numbers whatever the thread count or client.

    Returns a dict of NumPy arrays keyed by column: 'sample', the varied paths, each body's
    'NAME.x' ... 'NAME.qz', the measures, 'state_hash' (16 hex digits, as `asperity run
    --hash`). out: also write the table as CSV to this path; with named measures only and no
    client, each sample's row reaches the file as soon as it and every lower one are done (as
    `asperity sweep --out`), and resume=True continues a killed sweep from the rows the file
    holds, giving the bytes of an uninterrupted run.
    """
    samples = _check_int(samples, "samples", 1)
    seed = _check_int(seed, "seed", 0)
    threads = _check_int(threads, "threads", 0)
    if isinstance(seconds, bool) or not isinstance(seconds, (int, float, np.floating)):
        raise TypeError("seconds must be a number")
    names, callables = _split_measures(measure)
    text, scene_file = _scene_source(scene)
    args = (text, scene_file, _vary_pairs(vary or {}), samples, seed, float(seconds), names)
    core = _Sweep(*args)  # checks everything before any sample runs
    if resume and (out is None or callables or client is not None):
        raise ValueError("resume=True needs out= and runs named measures on threads only "
                         "(no callables, no client)")
    if out is not None and not callables and client is None:
        core.run_to_file(os.fspath(out), threads, bool(resume))
        return _read_csv(out)
    if client is None:
        columns, state = core.run([], threads)
    else:
        columns, state = _run_on_client(client, args, samples)
    _apply_callables(columns, state, callables, core.body_names, [p for p, _ in args[2]])
    if out is not None:
        write_csv(columns, out)
    return columns


def _split_measures(measure):
    """Named (C++) measures and Python callables."""
    if callable(measure) or isinstance(measure, str):
        measure = [measure]
    names, callables = [], []
    for m in measure:
        if isinstance(m, str):
            names.append(m)
        elif callable(m):
            callables.append(m)
        else:
            raise TypeError("measure must be names 'KIND:BODY' or callables")
    return names, callables


def _run_on_client(client, args, samples):
    """Spreads the samples over the cluster's workers in chunks and joins them in order."""
    chunks = _client_chunks(client, samples)
    futures = client.map(_run_chunk, [args] * len(chunks), chunks, pure=False)
    parts = client.gather(futures)
    columns = {k: np.concatenate([p[0][k] for p in parts]) for k in parts[0][0]}
    state = {k: np.concatenate([p[1][k] for p in parts]) for k in parts[0][1]}
    return columns, state


def _client_chunks(client, n):
    """Indices 0..n-1 in consecutive chunks, about four per worker of the cluster."""
    workers = max(1, len(client.scheduler_info().get("workers", {})))
    return [c.tolist() for c in np.array_split(np.arange(n), min(n, 4 * workers))]


def _apply_callables(columns, state, callables, body_names, paths):
    """Adds the columns of Python measures, called once per sample on its final state."""
    if not callables:
        return
    rows = []
    for i in range(len(columns["sample"])):
        s = {k: v[i] for k, v in state.items()}
        s["body_names"] = list(body_names)
        s["values"] = {p: float(columns[p][i]) for p in paths}
        row = {}
        for f in callables:
            value = f(s)
            if isinstance(value, dict):
                row.update({str(k): float(v) for k, v in value.items()})
            else:
                row[getattr(f, "__name__", "measure")] = float(value)
        rows.append(row)
    hashes = columns.pop("state_hash")
    for key in rows[0]:
        columns[key] = np.array([r[key] for r in rows], dtype=np.float64)
    columns["state_hash"] = hashes


def _read_csv(path):
    """A sweep's CSV as the columns sweep() returns: 'sample' int64, numbers float64,
    'state_hash' 16 hex digits."""
    with open(path, encoding="utf-8") as f:
        keys = f.readline().rstrip("\n").split(",")
        rows = [line.rstrip("\n").split(",") for line in f]
    columns = {"sample": np.array([int(r[0]) for r in rows], dtype=np.int64)}
    for j, key in enumerate(keys[1:-1], start=1):
        columns[key] = np.array([float(r[j]) for r in rows], dtype=np.float64)
    columns["state_hash"] = np.array([r[-1] for r in rows], dtype="U16")
    return columns


def write_csv(columns, path):
    """Writes a sweep's columns as CSV (numbers in shortest round-trip form, as the CLI),
    whole or not at all: into PATH.tmp, renamed into place when complete (as the CLI's
    outputs; a device such as /dev/stdout is written in place)."""
    keys = list(columns)
    lines = [",".join(keys) + "\n"]
    for i in range(len(columns["sample"])):
        cells = []
        for k in keys:
            v = columns[k][i]
            cells.append(str(v) if isinstance(v, (str, np.str_, np.integer)) else _number(v))
        lines.append(",".join(cells) + "\n")
    path = os.fspath(path)
    in_place = os.path.exists(path) and not os.path.isfile(path)
    temporary = path if in_place else path + ".tmp"
    try:
        with open(temporary, "w", encoding="utf-8") as f:
            f.write("".join(lines))
            f.flush()
            if not in_place:
                os.fsync(f.fileno())
        if not in_place:
            os.replace(temporary, path)
    finally:
        if not in_place and os.path.exists(temporary):
            os.remove(temporary)


def _number(x):
    """The shortest text that reads back to x, fixed or scientific whichever is shorter (fixed
    on a tie): the C++ std::to_chars form the CLI writes."""
    fixed = np.format_float_positional(x, unique=True, trim="-")
    sci = np.format_float_scientific(x, unique=True, trim="-", exp_digits=2)
    return fixed if len(fixed) <= len(sci) else sci


# The parts built on the names above.
from . import envs  # noqa: E402,F401  (asperity.envs after the names it imports)
from .rollout import rollout  # noqa: E402,F401
