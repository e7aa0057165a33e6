"""Assets from other tools drive friction as our own scenes do.

One sawtooth slab three ways: a native JSON box with a PNG normal map, an OBJ + MTL whose
map_Bump is that PNG, and a .glb that a third-party converter (obj2gltf, from the npm registry,
installed by scripts/install-node-tools.sh) made from the OBJ. All three must give the same
per-direction friction where their contacts coincide, and the same box slides along +u and -u.
And a normal-mapped glTF plate written out as FBX and COLLADA by the assimp command (Debian's
assimp-utils) gives the same contacts and friction as the glTF itself.
"""

import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

import asperity
from conftest import ROOT, run_cli

OBJ2GLTF = pathlib.Path(os.environ.get(
    "ASPERITY_OBJ2GLTF", ROOT / "build" / "node-tools" / "node_modules" / ".bin" / "obj2gltf"))

REPEAT = 0.25           # metres per texture repeat (the box's texture_size, the OBJ's UV scale)
HALF = (0.5, 0.5, 0.05)  # the slab
# A sawtooth of period 8 texels in a 256 map: 7.8 mm. The patch spans exactly five periods at
# 40 x 40 pixels, so its mean hardly depends on where along the teeth a contact falls.
PERIOD_M = REPEAT * 8 / 256
SETTINGS = {"friction_provider": "cpu", "mu0": 0.1, "dt": 0.005, "frame_mode": "world",
            "patch_width": 5 * PERIOD_M, "patch_resolution": 40}


def write_slab_obj(folder):
    """A closed slab as exporters write one: each face its own UV island; the top face's UVs
    are (x, y) / REPEAT, the mapping of a box's +z face."""
    hx, hy, hz = HALF
    corners = [(-hx, -hy, -hz), (hx, -hy, -hz), (hx, hy, -hz), (-hx, hy, -hz),
               (-hx, -hy, hz), (hx, -hy, hz), (hx, hy, hz), (-hx, hy, hz)]
    lines = ["mtllib slab.mtl", "o slab"] + ["v %g %g %g" % c for c in corners]
    lines += ["vt %g %g" % (corners[i][0] / REPEAT, corners[i][1] / REPEAT) for i in (4, 5, 6, 7)]
    lines += ["vt 0 0", "vt 1 0", "vt 1 1", "vt 0 1", "usemtl sawtooth", "f 5/1 6/2 7/3 8/4"]
    for face in [(4, 3, 2, 1), (1, 2, 6, 5), (2, 3, 7, 6), (3, 4, 8, 7), (4, 1, 5, 8)]:
        lines.append("f " + " ".join("%d/%d" % (v, 5 + k) for k, v in enumerate(face)))
    (folder / "slab.obj").write_text("\n".join(lines) + "\n")
    (folder / "slab.mtl").write_text("newmtl sawtooth\nKd 0.6 0.6 0.6\nmap_Bump sawtooth.png\n")


@pytest.fixture(scope="module")
def slabs(tmp_path_factory):
    """The slab's shape three ways: native JSON, OBJ + MTL, and the converter's .glb."""
    if not OBJ2GLTF.exists():
        if os.environ.get("ASPERITY_REQUIRE_NODE_TOOLS"):
            pytest.fail(f"obj2gltf is missing at {OBJ2GLTF} (scripts/install-node-tools.sh)")
        pytest.skip("obj2gltf is not installed (make node-tools)")
    folder = tmp_path_factory.mktemp("slabs")
    code, _, err = run_cli("texture", "sawtooth", "--size", 256, "--period", 8,
                           "--out", folder / "sawtooth.png")
    assert code == 0, err
    write_slab_obj(folder)
    subprocess.run([str(OBJ2GLTF), "-i", str(folder / "slab.obj"), "-o", str(folder / "slab.glb")],
                   check=True, capture_output=True)
    return {
        "json": {"type": "box", "half_extents": list(HALF),
                 "surface": {"normal_map": str(folder / "sawtooth.png"), "texture_size": REPEAT}},
        "obj": {"type": "mesh", "file": str(folder / "slab.obj")},
        "glb": {"type": "mesh", "file": str(folder / "slab.glb")},
    }


def world(slab, velocity_x, position=(0.0, 0.0)):
    """A 0.1 m box on the slab, sent along x (the texture's u)."""
    return asperity.World(asperity.load_scene({
        "settings": SETTINGS,
        "bodies": [{"name": "slab", "type": "static", "shapes": [slab]},
                   {"name": "box", "position": [position[0], position[1], HALF[2] + 0.05],
                    "linear_velocity": [velocity_x, 0, 0],
                    "shapes": [{"type": "box", "half_extents": [0.05, 0.05, 0.05]}]}]}))


def mu_by_point(w):
    """Per-direction mu (t, b, -t, -b with t = world x, n up) of each contact, by its point."""
    c = w.contacts()
    mu = c["mu"].copy()
    down = c["normals"][:, 2] < 0  # the slab is body A there: b = n x t flips
    mu[down] = mu[down][:, [0, 3, 2, 1]]
    return {tuple(np.round(p[:2], 4)): m for p, m in zip(c["points"], mu)}


def test_per_direction_mu_agrees_where_contacts_coincide(slabs):
    measured = {}
    for name, slab in slabs.items():
        w = world(slab, 0.0, position=(0.013, 0.021))
        w.step(1)
        measured[name] = mu_by_point(w)
    reference = measured["json"]
    # The teeth run along u: t (= u) grips far more than b, along which the slab is flat. The
    # .glb agreeing below shows that the converter carried map_Bump into normalTexture.
    for m in reference.values():
        assert m[0] > 3 * m[1]
    for name in ("obj", "glb"):
        shared = set(measured[name]) & set(reference)
        assert len(shared) >= 2, (name, sorted(measured[name]), sorted(reference))
        for point in shared:
            np.testing.assert_allclose(measured[name][point], reference[point], rtol=0.02,
                                       err_msg=f"{name} at {point}")


def test_the_box_slides_the_same_along_plus_and_minus_u(slabs):
    slides = {}
    for name, slab in slabs.items():
        slides[name] = []
        for vx in (1.0, -1.0):
            w = world(slab, vx)
            w.step(400)
            slides[name].append(abs(w.positions[1][0]))
    json_plus, json_minus = slides["json"]
    # The sawtooth is one-sided: one way glides, the other stops short.
    assert json_plus > 3 * json_minus
    for name in ("obj", "glb"):
        plus, minus = slides[name]
        # Box-on-box and box-on-mesh contacts differ in number and place: a few per cent.
        assert plus == pytest.approx(json_plus, rel=0.05), (name, slides)
        assert minus == pytest.approx(json_minus, rel=0.05), (name, slides)


@pytest.mark.parametrize("extension,format_id", [("dae", "collada"), ("fbx", "fbxa")])
def test_fbx_and_collada_written_by_assimp_give_the_gltfs_friction(tmp_path, extension, format_id):
    if shutil.which("assimp") is None:
        pytest.skip("the assimp command is not installed (Debian assimp-utils)")
    fixtures = ROOT / "tests" / "fixtures" / "assets"
    for name in ("plate.gltf", "tilt_normal.png"):
        shutil.copy(fixtures / name, tmp_path / name)
    # (Binary FBX as assimp 5.2.5 writes it does not read back; its ASCII FBX does.)
    subprocess.run(["assimp", "export", str(tmp_path / "plate.gltf"),
                    str(tmp_path / f"plate.{extension}"), f"-f{format_id}"],
                   check=True, capture_output=True)

    def contacts(asset):
        w = asperity.World(asperity.load_scene({
            "settings": {"friction_provider": "cpu", "frame_mode": "world"},
            "bodies": [{"name": "plate", "type": "static",
                        "shapes": [{"type": "mesh", "file": str(tmp_path / asset)}]},
                       {"name": "box", "position": [0, 0, 0.0199],
                        "shapes": [{"type": "box", "half_extents": [0.02, 0.02, 0.02]}]}]}))
        w.step(1)
        return mu_by_point(w)

    reference, converted = contacts("plate.gltf"), contacts(f"plate.{extension}")
    assert sorted(converted) == sorted(reference)
    for point, mu in reference.items():
        # The tilted texels push one way along t: the map arrived, with the glTF's frame.
        assert mu[0] > 2 * mu[2]
        np.testing.assert_allclose(converted[point], mu, rtol=1e-5, err_msg=str(point))
