# SPDX-License-Identifier: Apache-2.0
"""flarekit convert from the CLI and from Python: the same files, the same warnings, exit 2 and
one line for bad input with nothing written, and an imported flare used by the apply job."""
import json
import os
import pathlib
import shutil
import subprocess

import pytest

import flarekit

SOURCE = pathlib.Path(__file__).resolve().parents[2]
INTEROP = SOURCE / "examples" / "interop"


def cli(*args):
    return subprocess.run([os.environ["FLAREKIT_CLI"], *map(str, args)], capture_output=True,
                          text=True)


@pytest.mark.parametrize("fixture,to", [
    ("babylon/sun-flares.json", "babylon"),
    ("three/lensflare.json", "three"),
    ("playcanvas/look.json", "playcanvas"),
    ("unity/Assets/Flares/SunFlare.asset", "unity"),
    ("unreal/lensflare.ini", "unreal"),
    ("godot/lens_flare.tscn", "godot"),
])
def test_cli_and_python_write_the_same_files(tmp_path, fixture, to):
    name = pathlib.Path(fixture).name
    done = cli("convert", INTEROP / fixture, "-o", tmp_path / "cli" / "flare.json", "--to",
               "flarekit")
    assert done.returncode == 0, done.stderr
    warnings = flarekit.convert(str(INTEROP / fixture), str(tmp_path / "py" / "flare.json"),
                                to="flarekit")
    # The CLI prints each warning as "flarekit: warning: ..."; Python returns them.
    assert done.stderr.splitlines() == ["flarekit: warning: " + w for w in warnings]
    for f in (tmp_path / "cli").iterdir():
        assert f.read_bytes() == (tmp_path / "py" / f.name).read_bytes(), f.name
    back = cli("convert", tmp_path / "cli" / "flare.json", "-o", tmp_path / "back" / name,
               "--to", to)
    assert back.returncode == 0, back.stderr


def test_an_imported_flare_is_a_preset_the_apply_job_uses(tmp_path):
    flarekit.convert(str(INTEROP / "three" / "lensflare.json"), str(tmp_path / "three.json"),
                     to="flarekit")
    preset = flarekit.load_preset(str(tmp_path / "three.json"))
    assert [e["type"] for e in preset["elements"]] == ["image"] * 5
    done = cli("apply", SOURCE / "samples" / "sunset-hdr.exr", "-o", tmp_path / "out.png",
               "--preset", tmp_path / "three.json")
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "out.png").stat().st_size > 0


def test_bad_input_is_exit_2_one_line_and_nothing_written(tmp_path):
    bad = tmp_path / "b.json"
    bad.write_text('{"flares":[{"size":0.1,"position":"far","textureName":"x.png"}]}')
    done = cli("convert", bad, "-o", tmp_path / "out" / "x.json", "--to", "flarekit")
    assert done.returncode == 2
    assert done.stderr == (f"flarekit: {bad}: flares[0].position: expected a number in "
                           "[-8, 8], got \"far\"\n")
    assert not (tmp_path / "out").exists()
    with pytest.raises(ValueError, match=r"flares\[0\]\.position: expected a number"):
        flarekit.convert(str(bad), str(tmp_path / "out" / "x.json"), to="flarekit")
    # A .json output without --to: the format cannot be told.
    done = cli("convert", INTEROP / "babylon" / "sun-flares.json", "-o", tmp_path / "x.json")
    assert done.returncode == 2 and "--to: expected the output format" in done.stderr
    # An unknown Unity blend mode names the field and both orders' meaning.
    asset = tmp_path / "u.asset"
    asset.write_text((INTEROP / "unity" / "Assets" / "Flares" / "SunFlare.asset").read_text()
                     .replace("blendMode: 1", "blendMode: 9"))
    done = cli("convert", asset, "-o", tmp_path / "u.json", "--to", "flarekit", "--unity-assets",
               INTEROP / "unity" / "Assets")
    assert done.returncode == 2
    assert "elements[2].blendMode: expected 0 to 3" in done.stderr
    assert not (tmp_path / "u.json").exists()


def test_the_input_is_never_replaced(tmp_path):
    copy = tmp_path / "look.json"
    shutil.copy(INTEROP / "playcanvas" / "look.json", copy)
    shutil.copy(INTEROP / "playcanvas" / "streak.png", tmp_path / "streak.png")
    before = copy.read_bytes()
    done = cli("convert", copy, "-o", copy, "--to", "playcanvas")
    assert done.returncode == 2 and "would replace the input" in done.stderr
    assert copy.read_bytes() == before
