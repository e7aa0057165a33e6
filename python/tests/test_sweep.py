"""asperity.sweep: the CLI's table, thread-count independence, Dask equal to threads."""

import numpy as np
import pytest

import asperity
from conftest import SCENES, cli_error, run_cli

VARY = {"/bodies/*/linear_velocity/0": "uniform(0.5,2)", "/settings/mu0": "choice(0.3,0.5)"}


def test_sweep_columns_physics_and_dtypes(minimal_scene):
    r = asperity.sweep(minimal_scene, vary=VARY, samples=6, seconds=0.8, seed=3,
                       measure=["distance:box", "speed:box"], threads=2)
    assert list(r)[:3] == ["sample", "/bodies/*/linear_velocity/0", "/settings/mu0"]
    assert r["sample"].dtype == np.int64 and r["box.x"].dtype == np.float64
    assert r["state_hash"].dtype.kind == "U" and len(r["state_hash"][0]) == 16
    # Every sample slides its Coulomb distance v^2 / (2 mu g).
    v, mu = r["/bodies/*/linear_velocity/0"], r["/settings/mu0"]
    np.testing.assert_allclose(r["distance:box"], v**2 / (2 * mu * 9.81), rtol=0.03)
    np.testing.assert_allclose(r["speed:box"], 0.0, atol=1e-6)


def test_sweep_equals_the_cli_and_any_thread_count(tmp_path):
    scene = SCENES / "sawtooth_plane.json"
    args = ["sweep", scene, "--vary", "/settings/mu0=normal(0.2,0.05)",
            "--samples", 4, "--seconds", 0.2, "--seed", 9, "--measure", "distance:box_along"]
    code, _, err = run_cli(*args, "--threads", 1, "--out", tmp_path / "one.csv")
    assert code == 0, err
    code, _, err = run_cli(*args, "--threads", 2, "--out", tmp_path / "two.csv")
    assert code == 0, err
    assert (tmp_path / "one.csv").read_bytes() == (tmp_path / "two.csv").read_bytes()
    r = asperity.sweep(str(scene), vary={"/settings/mu0": "normal(0.2,0.05)"},
                       samples=4, seconds=0.2, seed=9, measure="distance:box_along",
                       threads=2, out=str(tmp_path / "py.csv"))
    assert (tmp_path / "py.csv").read_bytes() == (tmp_path / "one.csv").read_bytes()
    rows = (tmp_path / "one.csv").read_text().splitlines()[1:]
    assert list(r["state_hash"]) == [row.split(",")[-1] for row in rows]


def test_callable_measures_see_the_final_state(minimal_scene):
    def slide(state):
        return state["positions"][state["body_names"].index("box"), 0]

    r = asperity.sweep(minimal_scene, vary=VARY, samples=3, seconds=0.5,
                       measure=[slide, "distance:box", lambda s: {"v": s["values"]["/settings/mu0"]}])
    np.testing.assert_allclose(r["slide"], r["box.x"])
    np.testing.assert_array_equal(r["v"], r["/settings/mu0"])
    assert list(r)[-1] == "state_hash"


def test_bad_sweeps_raise_with_the_cli_messages(minimal_scene, tmp_path):
    path = tmp_path / "s.json"
    path.write_text(__import__("json").dumps(minimal_scene))
    for vary, match in [({"/settings/nope": "uniform(0,1)"}, "/settings/nope is not in the scene"),
                        ({"/settings/mu0": "beta(1,2)"}, "unknown distribution 'beta'"),
                        ({"/settings/mu0": "uniform(2,1)"}, "a <= b")]:
        with pytest.raises(ValueError, match=match) as e:
            asperity.sweep(str(path), vary=vary, samples=2, seconds=0.1)
        # The library's words ("variation ..."); the CLI names its --vary option instead.
        path_, spec = next(iter(vary.items()))
        assert str(e.value).startswith("variation ")
        assert "--vary" + str(e.value).removeprefix("variation") == cli_error(
            "sweep", path, "--vary", path_ + "=" + spec, "--samples", 2, "--seconds", 0.1,
            "--out", tmp_path / "o.csv")
    with pytest.raises(ValueError, match="samples must be >= 1"):
        asperity.sweep(minimal_scene, samples=0)
    with pytest.raises(TypeError):
        asperity.sweep(minimal_scene, samples=2.5)
    with pytest.raises(TypeError):
        asperity.sweep(minimal_scene, vary=["/settings/mu0"])
    with pytest.raises(ValueError, match="no body named 'ghost'"):
        asperity.sweep(minimal_scene, measure="distance:ghost")
    with pytest.raises(FileNotFoundError):
        asperity.sweep(str(tmp_path / "missing.json"))
    with pytest.raises(ValueError, match="sample 0"):
        asperity.sweep(minimal_scene, samples=1,
                       vary={"/bodies/1/shapes/0/half_extents/0": "uniform(-2,-1)"})


def test_dask_sweep_equals_the_threaded_sweep(minimal_scene):
    import distributed  # Debian python3-distributed, installed by scripts/install-deps.sh

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        kwargs = dict(vary=VARY, samples=10, seconds=0.3, seed=5, measure=["distance:box"])
        on_cluster = asperity.sweep(minimal_scene, client=client, **kwargs)
    local = asperity.sweep(minimal_scene, threads=2, **kwargs)
    assert list(on_cluster) == list(local)
    for key in local:
        np.testing.assert_array_equal(on_cluster[key], local[key])


def test_a_killed_sweep_resumes_to_the_bytes_of_one_run(tmp_path):
    """A child process running sweep(out=) is killed mid-run; resume=True finishes the file."""
    import os
    import signal
    import subprocess
    import sys
    import time

    scene = str(SCENES / "examples" / "minimal.json")
    kwargs = dict(vary={"/bodies/*/linear_velocity/0": "uniform(0.5,2)"}, samples=80,
                  seconds=0.5, seed=5, measure="distance:box", threads=1)
    whole = tmp_path / "whole.csv"
    columns = asperity.sweep(scene, out=str(whole), **kwargs)
    killed = tmp_path / "killed.csv"
    code = ("import asperity, sys; asperity.sweep(sys.argv[1], out=sys.argv[2], "
            f"**{kwargs!r})")
    child = subprocess.Popen([sys.executable, "-c", code, scene, str(killed)],
                             env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline and (
            not killed.exists() or killed.read_bytes().count(b"\n") < 20):
        time.sleep(0.002)
    child.send_signal(signal.SIGKILL)
    child.wait()
    left = killed.read_bytes()
    assert left.endswith(b"\n") and whole.read_bytes().startswith(left)
    assert len(left) < len(whole.read_bytes())
    resumed = asperity.sweep(scene, out=str(killed), resume=True, **kwargs)
    assert killed.read_bytes() == whole.read_bytes()
    np.testing.assert_array_equal(resumed["state_hash"], columns["state_hash"])
    np.testing.assert_array_equal(resumed["box.x"], columns["box.x"])
    with pytest.raises(ValueError, match="resume=True needs out="):
        asperity.sweep(scene, resume=True, **kwargs)


def test_a_dask_sweep_survives_a_killed_worker(minimal_scene):
    """One worker process of a LocalCluster is killed (SIGKILL) while the sweep runs: the
    scheduler gives its chunks to the other worker (and the restarted one), and the result is
    the threaded sweep's, number for number."""
    import os
    import signal
    import threading
    import time

    import distributed

    kwargs = dict(vary=VARY, samples=64, seconds=1.5, seed=11, measure=["distance:box"])
    local = asperity.sweep(minimal_scene, threads=2, **kwargs)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        pids = client.run(os.getpid)
        result = {}
        runner = threading.Thread(
            target=lambda: result.update(columns=asperity.sweep(minimal_scene, client=client,
                                                                **kwargs)))
        runner.start()
        # Once a chunk runs on each worker, one of them is killed.
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            busy = [w for w, tasks in client.processing().items() if tasks]
            if len(busy) == 2:
                break
            time.sleep(0.005)
        victim = sorted(pids)[0]
        os.kill(pids[victim], signal.SIGKILL)
        killed_mid_run = runner.is_alive()
        runner.join(120)
        assert not runner.is_alive(), "the sweep did not finish after a worker was killed"
    assert killed_mid_run, "the sweep ended before the worker was killed"
    on_cluster = result["columns"]
    assert list(on_cluster) == list(local)
    for key in local:
        np.testing.assert_array_equal(on_cluster[key], local[key])
