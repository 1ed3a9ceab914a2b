# SPDX-License-Identifier: Apache-2.0
"""Presets, lenses, scenes, images and blends through the module agree with the CLI; bad input
is a ValueError with the CLI's message; the GIL is released while the library works."""
import json
import os
import re

import numpy as np
import pytest

import flarekit
from conftest import SOURCE, read, small_hdr

SCENE = SOURCE / "samples" / "scenes" / "sun-behind-trees.json"


def test_presets_and_lenses_are_the_clis(cli):
    listed = cli("presets").stdout
    for name in flarekit.presets():
        assert name in listed
    assert "photo" in flarekit.presets("postfx")
    lenses = cli("lens", "list").stdout
    assert flarekit.lenses() and all(name in lenses for name in flarekit.lenses())
    assert flarekit.presets("lens") == flarekit.lenses()


def test_load_and_validate_presets(cli, tmp_path):
    preset = flarekit.load_preset("tanczos-classic")
    assert preset["elements"]
    flarekit.validate_preset(preset)
    preset["elements"][0]["size"] = -3
    with pytest.raises(ValueError) as error:
        flarekit.validate_preset(preset)
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(preset))
    cli_error = cli("presets", "--check", bad, ok=False)
    assert cli_error.returncode == 2
    # The same one-line message as the CLI's, but for the file's name.
    theirs = cli_error.stderr.strip().splitlines()[-1]
    assert str(error.value).split(": ", 1)[1] in theirs
    with pytest.raises(ValueError, match="killzone2"):
        flarekit.load_preset("no-such-preset", kind="postfx")
    assert flarekit.load_preset("killzone2", kind="postfx")
    assert flarekit.load_preset(flarekit.lenses()[0], kind="lens")["surfaces"]


def test_visibility_equals_cli(cli):
    ours = flarekit.visibility(str(SCENE))
    theirs = json.loads(cli("visibility", SCENE, "--json").stdout)
    assert ours["method"] == theirs["method"] == "raycast"
    assert ours["samples"] == theirs["samples"]
    assert abs(ours["coverage"] - theirs["coverage"]) <= 5e-7
    as_dict = flarekit.visibility(json.loads(SCENE.read_text()), samples=32)
    assert 0 <= as_dict["coverage"] <= 1 and as_dict["samples"] > 0
    with pytest.raises(ValueError, match="samples: expected an integer"):
        flarekit.visibility(str(SCENE), samples=0)
    with pytest.raises(ValueError, match="method: expected one of raycast"):
        flarekit.visibility(str(SCENE), method="guess")


def test_gpu_visibility_on_mesa(cli):
    ours = flarekit.visibility(str(SCENE), method="query")
    theirs = json.loads(cli("visibility", SCENE, "--method", "query", "--json").stdout)
    assert abs(ours["coverage"] - theirs["coverage"]) <= 5e-7


def test_blend8_equals_cli(cli, tmp_path):
    rng = np.random.default_rng(7)
    src = rng.integers(0, 256, (17, 23, 4), dtype=np.uint8)
    dst = rng.integers(0, 256, (17, 23, 3), dtype=np.uint8)
    # Colour sRGB-decoded, alpha linear: as the PNG reader gives them back.
    src_linear = flarekit.srgb_to_linear(src)
    src_linear[..., 3] = src[..., 3] / np.float32(255)
    flarekit.write_image(str(tmp_path / "src.png"), src_linear, depth="8")
    flarekit.write_image(str(tmp_path / "dst.png"), flarekit.srgb_to_linear(dst), depth="8")
    for mode in ("alpha", "alpha-shift", "premultiplied", "add"):
        cli("blend", "--mode", mode, "--src", tmp_path / "src.png", "--dst", tmp_path / "dst.png",
            "-o", tmp_path / f"{mode}.png")
        theirs = np.rint(flarekit.linear_to_srgb(read(tmp_path / f"{mode}.png")) * 255)
        ours = flarekit.blend8(mode, src, dst)
        assert ours.dtype == np.uint8 and np.array_equal(ours, theirs.astype(np.uint8)), mode
    # The 1999 article's alpha blend, by hand for one pixel.
    s, d = src[0, 0].astype(int), dst[0, 0].astype(int)
    assert list(flarekit.blend8("alpha", src, dst)[0, 0]) == [
        (s[c] * s[3] + d[c] * (255 - s[3])) // 255 for c in range(3)]


def test_images_round_trip(tmp_path):
    _, image = small_hdr(tmp_path)
    flarekit.write_image(str(tmp_path / "a.exr"), image, depth="float")
    back, info = flarekit.read_image(str(tmp_path / "a.exr"))
    assert np.array_equal(back, image) and not info["display_referred"]
    flarekit.write_image(str(tmp_path / "a.png"), np.clip(image, 0, 1), depth="16")
    png, info = flarekit.read_image(str(tmp_path / "a.png"))
    assert info["display_referred"] and np.abs(png - np.clip(image, 0, 1)).max() < 1e-3
    with pytest.raises(ValueError, match="holds"):
        flarekit.write_image(str(tmp_path / "a.jpg"), image, depth="16")
    assert not (tmp_path / "a.jpg").exists()


def test_bad_arrays_are_value_errors(tmp_path):
    _, image = small_hdr(tmp_path)
    cases = [
        (image.astype(np.float64), "float32"),
        (image[..., 0], "H x W x 3 or H x W x 4"),
        (np.zeros((4, 4, 5), np.float32), "got 4 x 4 x 5"),
        (np.zeros((0, 4, 3), np.float32), "without pixels"),
        ([[1.0, 2.0]], "numpy array"),
    ]
    for bad, message in cases:
        for call in (flarekit.apply, flarekit.postfx):
            with pytest.raises(ValueError, match=re.escape(message)):
                call(bad)
    with pytest.raises(ValueError, match="unknown keyword 'intensty'"):
        flarekit.apply(image, intensty=2)
    with pytest.raises(ValueError, match=r"intensity: expected a number in \[0, 1000\], got -1"):
        flarekit.apply(image, intensity=-1)
    with pytest.raises(ValueError, match="flux_mode: expected"):
        flarekit.apply(image, flux_mode="loud")
    with pytest.raises(ValueError, match="light 2e"):
        flarekit.apply(image, light=(2e9, 0))


def test_strided_and_read_only_inputs(tmp_path):
    _, image = small_hdr(tmp_path)
    wide = np.zeros((image.shape[0] * 2, image.shape[1], 4), np.float32)
    wide[::2, :, :3] = image
    view = wide[::2, :, :3]  # not contiguous: every other row, 3 of 4 channels
    assert not view.flags["C_CONTIGUOUS"]
    before = view.copy()
    view.flags.writeable = False
    assert np.array_equal(flarekit.apply(view, light=(31.5, 21.5)),
                          flarekit.apply(np.ascontiguousarray(before), light=(31.5, 21.5)))
    assert np.array_equal(view, before)


def test_memory_budget_refuses_huge_arrays():
    budget = flarekit.max_memory()
    try:
        flarekit.set_max_memory(64 << 20)
        huge = np.broadcast_to(np.float32(0.1), (4096, 4096, 3))  # 192 MiB as RGBA floats
        with pytest.raises(ValueError, match="memory budget of 64 MiB.*set_max_memory"):
            flarekit.postfx(huge)
    finally:
        flarekit.set_max_memory(budget)


def test_docstrings_list_the_parameter_tables(cli):
    doc = flarekit.apply.__doc__
    help_text = cli("apply", "--help").stdout
    for key in ("intensity", "exposure", "flux_mode", "light_threshold", "max_lights"):
        assert f"    {key}: " in doc
        assert "--" + key.replace("_", "-") in help_text
    assert "[0, 1000], default 1" in doc
    assert "ghost_gain" in flarekit.lens_render.__doc__
    stubs = (SOURCE / "build").parent  # the stubs sit beside the built module
    assert stubs.exists()
    pyi = os.path.join(os.path.dirname(flarekit.__file__), "_flarekit.pyi")
    text = open(pyi, encoding="utf-8").read()
    assert "def apply(image: numpy.ndarray" in text and "light_threshold" in text


def test_temporal_filter_releases_with_its_time_constant_and_checks_its_keywords():
    f = flarekit.TemporalFilter(release=0.5, attack=0.0)
    first = f.update(1.0, (50, 50), True, 100, 100, 0.0)
    assert first["coverage"] == 1.0 and first["edge_fade"] == 1.0
    # Hidden: the coverage falls by exp(-dt / release) a frame (the library's closed form).
    hidden = f.update(0.0, (50, 50), True, 100, 100, 1 / 24)
    assert hidden["coverage"] == pytest.approx(np.exp(-1 / 24 / 0.5), rel=1e-12)
    # Attack 0: back at once. On the frame's edge the flare weight is 0, the coverage is not.
    edge = f.update(1.0, (0, 50), True, 100, 100, 1 / 24)
    assert edge["coverage"] == 1.0 and edge["edge_fade"] == 0.0 and edge["flare_weight"] == 0.0
    with pytest.raises(ValueError, match="release"):
        flarekit.TemporalFilter(release=-1)
    with pytest.raises(ValueError, match="coverage"):
        f.update(1.5, (0, 0), True, 10, 10, 0.1)


def test_lens_info_gives_the_paraxial_focal_length_and_the_angle_of_view():
    info = flarekit.lens_info("asahi-takumar-50")
    # The prescription is the patent's, scaled to f = 100 mm on a 72 x 48 mm sensor: the angle
    # of view of a 50 mm lens on 36 x 24 mm.
    assert info["focal_length_mm"] == pytest.approx(100.0, abs=0.05)
    assert info["sensor_mm"] == (72.0, 48.0)
    assert info["horizontal_fov_deg"] == pytest.approx(
        np.degrees(2 * np.arctan(36.0 / info["focal_length_mm"])), rel=1e-12)
    assert info["horizontal_fov_deg"] == pytest.approx(39.6, abs=0.1)
    assert info["blades"] == 6
    with pytest.raises(ValueError, match="no-such-lens"):
        flarekit.lens_info("no-such-lens")
