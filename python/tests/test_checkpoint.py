"""Checkpoints from Python: World.save_state, World.load_state and World(scene, state=path)
continue a run bit for bit, interchangeably with `asperity run --save-state/--load-state`, and
refuse files that do not fit with the messages of the CLI."""
import pathlib

import pytest

import asperity
from conftest import SCENES, run_cli


@pytest.mark.parametrize("name,sampler", [("stacking.json", "cpu"),
                                          ("sawtooth_plane.json", "constant"),
                                          ("chain_bolas_rough.json", "cpu")])
def test_a_saved_world_continues_bit_for_bit(tmp_path, name, sampler):
    scene = str(SCENES / name)
    whole = asperity.World(scene, sampler=sampler)
    whole.step(60)
    saver = asperity.World(scene, sampler=sampler)
    saver.step(25)
    path = tmp_path / "w.state"
    saver.save_state(path)
    loaded = asperity.World(scene, sampler=sampler, threads=2, state=path)
    assert loaded.step_count == 25
    assert loaded.time == saver.time
    loaded.step(35)
    assert loaded.state_hash() == whole.state_hash()
    # load_state into a world that ran on replaces its state the same way.
    used = asperity.World(scene, sampler=sampler)
    used.step(50)
    used.load_state(str(path))
    used.step(35)
    assert used.state_hash() == whole.state_hash()


def test_python_and_cli_checkpoints_are_interchangeable(tmp_path):
    scene = SCENES / "stacking.json"
    from_cli = tmp_path / "cli.state"
    code, _, err = run_cli("run", scene, "--steps", 20, "--save-state", from_cli)
    assert code == 0, err
    world = asperity.World(str(scene), state=from_cli)
    world.step(20)
    code, out, err = run_cli("run", scene, "--steps", 40, "--hash")
    assert code == 0, err
    assert world.state_hash() == out.strip()
    from_python = tmp_path / "py.state"
    world.save_state(from_python)
    code, out, err = run_cli("run", scene, "--steps", 10, "--load-state", from_python, "--hash")
    assert code == 0, err
    world.step(10)
    assert world.state_hash() == out.strip()


def test_files_that_do_not_fit_raise(tmp_path):
    path = tmp_path / "s.state"
    world = asperity.World(str(SCENES / "stacking.json"))
    world.step(5)
    world.save_state(path)
    with pytest.raises(ValueError, match="saved from another scene"):
        asperity.World(str(SCENES / "sawtooth_plane.json"), state=path)
    with pytest.raises(ValueError, match="saved with friction provider"):
        asperity.World(str(SCENES / "stacking.json"), sampler="constant", state=path)
    cut = tmp_path / "cut.state"
    cut.write_bytes(path.read_bytes()[:1000])
    with pytest.raises(ValueError, match="cut.state: truncated"):
        asperity.World(str(SCENES / "stacking.json"), state=cut)
    with pytest.raises(FileNotFoundError):
        asperity.World(str(SCENES / "stacking.json"), state=tmp_path / "missing.state")
    with pytest.raises(ValueError, match="/dev/zero: not a regular file"):
        world.load_state("/dev/zero")
    with pytest.raises(ValueError, match="write failed"):
        world.save_state("/dev/full")
    assert not pathlib.Path(str(path) + ".tmp").exists()
