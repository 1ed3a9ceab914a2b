# SPDX-License-Identifier: Apache-2.0
"""The Blender add-on in Blender 3.4 itself (`blender -b`, Cycles on the CPU): the example
examples/blender/lamps-and-sun.py builds a sun, two point lamps (a wall hides one), a lamp
outside the frame and a ground, enables the add-on installed by copying it into an add-ons
folder, and renders two frames. The
flare pass must hold every visible light at the position Blender's own projection gives (within
1 px), not the hidden one, and equal what flarekit's module draws for those lights."""
import json
import math
import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

import flarekit

SOURCE = pathlib.Path(__file__).resolve().parents[2]
ADDON = SOURCE / "integrations" / "blender" / "flarekit_blender"
REFERENCE_IRRADIANCE = 3.0  # the add-on's documented scale: 3 W/m^2 draws the preset's look


def render(tmp_path, occlusion, mode="SPRITE"):
    scripts = tmp_path / "scripts" / "addons"
    scripts.mkdir(parents=True)
    shutil.copytree(ADDON, scripts / "flarekit_blender")  # "installable by copying"
    env = dict(os.environ, BLENDER_USER_SCRIPTS=str(tmp_path / "scripts"))
    done = subprocess.run(["blender", "-b", "--factory-startup", "--python-use-system-env",
                           "--python", str(SOURCE / "examples" / "blender" / "lamps-and-sun.py"),
                           "--", str(tmp_path), occlusion, mode],
                          capture_output=True, text=True, env=env, timeout=600)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    assert "flarekit: frame" not in done.stderr, done.stderr[-3000:]
    return json.loads((tmp_path / "truth.json").read_text())


def expected_flare(image, lights, visible):
    """The flare flarekit's module draws for the lights the test knows to be visible, from
    Blender's projections and the lights' power: irradiance at the lens over 3 W/m^2."""
    total = np.zeros(image.shape[:2] + (3,), np.float32)
    for name in visible:
        light = lights[name]
        irradiance = light["energy"] if light["kind"] == 'SUN' else \
            light["energy"] / (4 * math.pi * light["distance"] ** 2)
        one = flarekit.apply(image, "tanczos-classic", light=(light["x"], light["y"]),
                             flare_only=True, flux_mode="fixed",
                             intensity=irradiance / REFERENCE_IRRADIANCE)
        total += one[..., :3] * np.asarray(light["color"], np.float32)
    return total


@pytest.mark.parametrize("occlusion", ["DEPTH", "RAYCAST"])
def test_two_frames_flare_the_visible_lights_where_blender_projects_them(tmp_path, occlusion):
    truth = render(tmp_path, occlusion)
    for frame in (1, 2):
        record = json.loads((tmp_path / "flares" / f"lights_{frame:04d}.json").read_text())
        lights = truth[str(frame)]
        by_name = {light["name"]: light for light in record["lights"]}
        assert set(by_name) == set(lights)
        for name, light in lights.items():
            if not light["front"]:
                continue
            mine = by_name[name]
            assert abs(mine["x"] - light["x"]) <= 1 and abs(mine["y"] - light["y"]) <= 1, name
        # The sun and the lamp are seen whole, the hidden lamp not at all; the lamp beyond the
        # frame's right edge keeps its ghosts (it is in front, nothing in the render hides it).
        assert by_name["sun"]["coverage"] == pytest.approx(1.0)
        assert by_name["lamp"]["coverage"] == pytest.approx(1.0)
        assert by_name["hidden lamp"]["coverage"] == 0.0
        assert lights["rim"]["x"] > 320 and by_name["rim"]["coverage"] == pytest.approx(1.0)

        image = flarekit.read_image(str(tmp_path / f"render_{frame:04d}.exr"))[0]
        flare = flarekit.read_image(str(tmp_path / "flares" / f"flare_{frame:04d}.exr"))[0]
        want = expected_flare(image, lights, ["sun", "lamp", "rim"])
        assert np.abs(want).max() > 0.05
        assert np.allclose(flare[..., :3], want, rtol=1e-3, atol=1e-4)
        # The hidden lamp would show: its flare alone is far larger than the tolerance.
        hidden = expected_flare(image, lights, ["hidden lamp"])
        assert np.abs(hidden).max() > 0.01


def test_the_post_process_mode_is_the_chain_on_the_render(tmp_path):
    render(tmp_path, "DEPTH", "POSTFX")
    for frame in (1, 2):
        image = flarekit.read_image(str(tmp_path / f"render_{frame:04d}.exr"))[0]
        flare = flarekit.read_image(str(tmp_path / "flares" / f"flare_{frame:04d}.exr"))[0]
        want = np.maximum(flarekit.postfx(image, "photo")[..., :3] - image[..., :3], 0)
        assert np.abs(want).max() > 0.01
        assert np.allclose(flare[..., :3], want, rtol=1e-4, atol=1e-5)


def test_the_installed_add_on_linked_into_blender_finds_the_installed_module(tmp_path):
    # `cmake --install` to a prefix, then the docs' link into Blender's add-ons folder; no
    # PYTHONPATH: the add-on finds the module installed beside it.
    prefix = tmp_path / "prefix"
    subprocess.run([os.environ["FLAREKIT_CMAKE"], "--install", os.environ["FLAREKIT_BUILD_DIR"],
                    "--prefix", str(prefix)], check=True, capture_output=True)
    addons = tmp_path / "scripts" / "addons"
    addons.mkdir(parents=True)
    (addons / "flarekit_blender").symlink_to(
        prefix / "share" / "blender" / "scripts" / "addons" / "flarekit_blender")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["BLENDER_USER_SCRIPTS"] = str(tmp_path / "scripts")
    script = ("import addon_utils, bpy, flarekit\n"
              "addon_utils.enable('flarekit_blender', default_set=True, handle_error=None)\n"
              "print('MODULE', flarekit.__file__)\n"
              "print('PANEL', hasattr(bpy.types, 'FLAREKIT_PT_render'))\n"
              "print('DEFAULT', bpy.context.scene.flarekit.preset)\n")
    done = subprocess.run(["blender", "-b", "--factory-startup", "--python-expr",
                           "import addon_utils; addon_utils.enable('flarekit_blender'); " +
                           "exec(" + repr(script) + ")"],
                          capture_output=True, text=True, env=env, timeout=300)
    assert f"MODULE {prefix}" in done.stdout, done.stdout[-2000:] + done.stderr[-2000:]
    assert "PANEL True" in done.stdout and "DEFAULT tanczos-classic" in done.stdout


def test_the_lens_mode_picks_the_lens_nearest_the_cameras_angle_of_view(tmp_path):
    render(tmp_path, "DEPTH", "LENS")
    record = json.loads((tmp_path / "flares" / "lights_0001.json").read_text())
    # Blender's default camera, 50 mm on a 36 mm sensor: 39.6 degrees across, the angle of the
    # Takumar 50 (its prescription: f = 100 mm on 72 mm); the camera's 0 blades: a round iris.
    assert record["lens"] == "asahi-takumar-50-0-blades.json"
    flare = flarekit.read_image(str(tmp_path / "flares" / "flare_0001.exr"))[0][..., :3]
    assert flare.max() > 0.1 and np.isfinite(flare).all()
