# SPDX-License-Identifier: Apache-2.0
"""The GIMP plug-in in GIMP 2.10 itself (`gimp -i -b`, batch mode, Script-Fu), loaded from a
private GIMP folder (GIMP2_DIRECTORY) that links this build's flarekit-gimp: a real photograph
(8-bit) and a real HDR sky (16-bit half float), against the CLI of the same build."""
import os
import pathlib
import re
import subprocess

import numpy as np
import pytest

from conftest import read_frames, run_host

SOURCE = pathlib.Path(__file__).resolve().parents[2]
PHOTO = SOURCE / "docs" / "images" / "gallery" / "sunrise-input.jpg"  # a photograph, 640x360
HDR = SOURCE / "tests" / "golden" / "input" / "sunrise-blender-320x180.exr"  # CC0 HDRI, half


@pytest.fixture(scope="module")
def gimp(tmp_path_factory):
    """Runs Script-Fu in GIMP with this build's plug-in; returns (stdout + stderr, status)."""
    plugin = pathlib.Path(os.environ.get("FLAREKIT_GIMP_PLUGIN", ""))
    assert plugin.is_file(), "FLAREKIT_GIMP_PLUGIN names this build's flarekit-gimp"
    home = tmp_path_factory.mktemp("gimp")
    (home / "plug-ins").mkdir()
    for data in ("gradients", "brushes", "patterns", "palettes"):
        (home / data).mkdir()
    # A link, as the docs install it: the plug-in finds its presets through it.
    (home / "plug-ins" / "flarekit-gimp").symlink_to(plugin)

    def run(script, cwd):
        env = dict(os.environ, GIMP2_DIRECTORY=str(home))
        env.pop("DISPLAY", None)
        done = subprocess.run(["gimp", "-i", "-d", "-f", "-b", script, "-b", "(gimp-quit 0)"],
                              capture_output=True, text=True, env=env, cwd=cwd, timeout=300)
        return done.stdout + done.stderr, done.returncode

    return run


def flare_script(source, out, args, save, precision=True):
    """Load SOURCE, run the procedure with ARGS (Script-Fu), report the precision before and
    after, merge the layers and save OUT with SAVE (a Script-Fu export procedure)."""
    return f"""
(let* ((image (car (gimp-file-load RUN-NONINTERACTIVE "{source}" "{source}")))
       (drawable (car (gimp-image-get-active-drawable image))))
  (gimp-message (string-append "precision-before "
                               (number->string (car (gimp-image-get-precision image)))))
  (plug-in-flarekit-lens-flare RUN-NONINTERACTIVE image drawable {args})
  (gimp-message (string-append "precision-after "
                               (number->string (car (gimp-image-get-precision image)))))
  (gimp-message (string-append "layers " (number->string (car (gimp-image-get-layers image)))))
  (gimp-image-merge-visible-layers image CLIP-TO-IMAGE)
  ({save} RUN-NONINTERACTIVE image (car (gimp-image-get-active-drawable image)) "{out}" "{out}"))
"""


def reported(log, what):
    found = re.findall(what + r" (\d+)", log)
    assert found, log
    return int(found[-1])


def test_a_photograph_flared_as_a_new_layer_equals_the_cli_within_a_level(gimp, cli, tmp_path):
    # The photograph as PNG, so both read exactly the same 8-bit pixels.
    run_host("oiiotool", PHOTO, "-o", tmp_path / "photo.png")
    log, status = gimp(flare_script("photo.png", "gimp.png",
                                    '"sprite" "" TRUE 0 0 1.0 0 TRUE', "file-png-save-defaults"),
                       tmp_path)
    assert status == 0 and "batch command executed successfully" in log, log
    assert reported(log, "precision-before") == reported(log, "precision-after") == 150  # u8
    assert reported(log, "layers") == 2  # the photograph and the flare's Addition layer
    cli("apply", tmp_path / "photo.png", "-o", tmp_path / "cli.png")
    photo = read_frames(tmp_path / "photo.png", 640, 360)[0].astype(int)
    by_gimp = read_frames(tmp_path / "gimp.png", 640, 360)[0].astype(int)
    by_cli = read_frames(tmp_path / "cli.png", 640, 360)[0].astype(int)
    assert np.abs(by_cli - photo).max() > 40  # the sun found and flared
    assert np.abs(by_gimp - by_cli).max() <= 1


def test_a_half_float_hdr_stays_float_and_equals_the_cli(gimp, cli, tmp_path):
    import flarekit  # this build's module (PYTHONPATH), to read the EXRs
    log, status = gimp(flare_script(HDR, "gimp.exr", '"sprite" "" TRUE 0 0 1.0 0 FALSE',
                                    "file-exr-save"), tmp_path)
    assert status == 0 and "batch command executed successfully" in log, log
    # GIMP's half-float linear precision (500) kept: no 8-bit round trip.
    assert reported(log, "precision-before") == reported(log, "precision-after") == 500
    assert reported(log, "layers") == 1  # drawn onto the layer
    cli("apply", HDR, "-o", tmp_path / "cli.exr", "--exr-compression", "zip")
    by_gimp = flarekit.read_image(str(tmp_path / "gimp.exr"))[0][..., :3]
    by_cli = flarekit.read_image(str(tmp_path / "cli.exr"))[0][..., :3]
    plate = flarekit.read_image(str(HDR))[0][..., :3]
    assert np.abs(by_cli - plate).max() > 1  # flared
    # Both halves of the same floats: within half precision's rounding (2^-11 relative).
    assert np.all(np.abs(by_gimp - by_cli) <= 1e-3 * np.abs(by_cli) + 1e-4)


def test_bad_arguments_are_gimp_errors_and_leave_the_image(gimp, tmp_path):
    run_host("oiiotool", PHOTO, "-o", tmp_path / "photo.png")
    log, _ = gimp(flare_script("photo.png", "bogus.png", '"bogus" "" TRUE 0 0 1.0 0 FALSE',
                               "file-png-save-defaults"), tmp_path)
    assert "mode: expected sprite, postfx or lens, got 'bogus'" in log, log
    assert not (tmp_path / "bogus.png").exists()
    log, _ = gimp(flare_script("photo.png", "x.png", '"sprite" "no-such-preset" TRUE 0 0 1.0 0 '
                               "FALSE", "file-png-save-defaults"), tmp_path)
    assert "preset 'no-such-preset'" in log, log
    log, _ = gimp(flare_script("photo.png", "y.png", '"lens" "" FALSE 1e30 0 1.0 0 FALSE',
                               "file-png-save-defaults"), tmp_path)
    assert "light-x, light-y" in log, log
    log, _ = gimp(flare_script("photo.png", "z.png", '"sprite" "" TRUE 0 0 -3 0 FALSE',
                               "file-png-save-defaults"), tmp_path)
    assert "intensity: expected a number in [0, 1000]" in log, log


def test_the_docs_table_is_the_procedures_own():
    done = run_host(os.environ["FLAREKIT_GIMP_PLUGIN"], "--markdown")
    page = (SOURCE / "docs" / "hosts.md").read_text()
    start = page.index("<!-- generated by: flarekit-gimp --markdown -->\n")
    table = page[page.index("\n", start) + 1:page.index("<!-- end generated -->", start)]
    assert table == done.stdout, "docs/hosts.md is out of date: scripts/update-docs.sh"


def test_a_16_bit_image_stays_16_bit(gimp, cli, tmp_path):
    run_host("oiiotool", PHOTO, "-d", "uint16", "-o", tmp_path / "photo16.png")
    log, status = gimp(flare_script("photo16.png", "gimp16.png",
                                    '"sprite" "" TRUE 0 0 1.0 0 FALSE', "file-png-save-defaults"),
                       tmp_path)
    assert status == 0 and "batch command executed successfully" in log, log
    # GIMP's 16-bit perceptual precision (250) kept.
    assert reported(log, "precision-before") == reported(log, "precision-after") == 250
    cli("apply", tmp_path / "photo16.png", "-o", tmp_path / "cli16.png", "--depth", 16)
    by_gimp, by_cli = read16(tmp_path / "gimp16.png"), read16(tmp_path / "cli16.png")
    # Within a 16-bit code of the CLI's 16-bit output (GIMP's own conversion, babl's, rounds
    # the same floats).
    assert np.abs(by_gimp - by_cli).max() <= 1


def read16(path):
    done = subprocess.run(["ffmpeg", "-v", "error", "-i", str(path), "-f", "rawvideo", "-pix_fmt",
                           "rgb48le", "-"], capture_output=True, check=True)
    return np.frombuffer(done.stdout, np.uint16).reshape(360, 640, 3).astype(int)
