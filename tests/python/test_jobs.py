# SPDX-License-Identifier: Apache-2.0
"""apply, postfx and lens_render on arrays give what the CLI writes to a float EXR, bit for bit,
and the file jobs (images and sequences) are the CLI's."""
import numpy as np
import pytest

import flarekit
from conftest import read, small_hdr


def test_apply_equals_cli_bit_for_bit(cli, tmp_path, sunset):
    src = tmp_path / "in.exr"
    flarekit.write_image(str(src), sunset, depth="float")
    cli("apply", src, "-o", tmp_path / "cli.exr", "--depth", "float")
    ours = flarekit.apply(sunset)
    assert ours.shape == sunset.shape and ours.dtype == np.float32
    theirs = read(tmp_path / "cli.exr")
    assert np.array_equal(ours, theirs)
    assert np.abs(ours - sunset).max() > 0.01  # a flare was drawn


def test_apply_placed_light_and_layers(cli, tmp_path):
    path, image = small_hdr(tmp_path)
    cli("apply", path, "-o", tmp_path / "cli.exr", "--depth", "float", "--light", "31.5,21.5",
        "--preset", "hexagon-ghosts", "--layers", tmp_path / "layers")
    out, layers = flarekit.apply(image, "hexagon-ghosts", light=(31.5, 21.5), layers=True)
    assert np.array_equal(out, read(tmp_path / "cli.exr"))
    assert "flare" in layers
    for name, layer in layers.items():
        assert np.array_equal(layer, read(tmp_path / "layers" / f"{name}.exr")), name
    # The output is exactly the input plus the whole flare.
    assert np.allclose(out, image + layers["flare"], atol=0, rtol=0)


def test_postfx_equals_cli_bit_for_bit(cli, tmp_path, sunset):
    src = tmp_path / "in.exr"
    flarekit.write_image(str(src), sunset, depth="float")
    for preset in ("photo", "killzone2"):
        cli("postfx", src, "-o", tmp_path / f"{preset}.exr", "--preset", preset)
        ours = flarekit.postfx(sunset, preset)
        assert np.array_equal(ours, read(tmp_path / f"{preset}.exr")), preset


def test_lens_render_equals_cli(cli, tmp_path):
    path, image = small_hdr(tmp_path)
    # A float EXR input gives a float EXR output (the input's pixel type).
    cli("lens", "render", "angenieux-double-gauss", path, "-o", tmp_path / "cli.exr",
        "--ghosts", "8")
    ours, layers = flarekit.lens_render(image, "angenieux-double-gauss", ghosts=8, layers=True)
    assert np.array_equal(ours, read(tmp_path / "cli.exr"))
    assert set(layers) == {"ghosts", "starburst", "glare", "flare"}
    assert layers["ghosts"].max() > 0


def test_four_channels_keep_alpha(tmp_path):
    _, image = small_hdr(tmp_path)
    rgba = np.concatenate([image, np.full(image.shape[:2] + (1,), 0.25, np.float32)], axis=-1)
    out = flarekit.apply(rgba, light=(31.5, 21.5))
    assert out.shape == rgba.shape
    assert np.all(out[..., 3] == 0.25)
    assert np.array_equal(out[..., :3], flarekit.apply(image, light=(31.5, 21.5)))


def test_file_job_on_a_sequence_writes_the_track(cli, tmp_path):
    _, image = small_hdr(tmp_path)
    for frame in (1, 2, 3):
        shifted = np.roll(image, 4 * frame, axis=1)
        flarekit.write_image(str(tmp_path / f"in.{frame:04d}.exr"), shifted, depth="float")
    report = flarekit.apply_file(str(tmp_path / "in.####.exr"), str(tmp_path / "py.####.exr"),
                                 write_track=str(tmp_path / "py.csv"))
    assert report["sequence"] and report["frames"] == 3
    cli("apply", tmp_path / "in.####.exr", "-o", tmp_path / "cli.####.exr",
        "--write-track", tmp_path / "cli.csv")
    assert (tmp_path / "py.csv").read_text() == (tmp_path / "cli.csv").read_text()
    for frame in (1, 2, 3):
        assert np.array_equal(read(tmp_path / f"py.{frame:04d}.exr"),
                              read(tmp_path / f"cli.{frame:04d}.exr"))


def test_postfx_file_and_lens_file(cli, tmp_path):
    path, _ = small_hdr(tmp_path)
    flarekit.postfx_file(str(path), str(tmp_path / "py.exr"), "modern")
    cli("postfx", path, "-o", tmp_path / "cli.exr", "--preset", "modern")
    assert np.array_equal(read(tmp_path / "py.exr"), read(tmp_path / "cli.exr"))
    flarekit.postfx_file(str(path), str(tmp_path / "py2.exr"), "modern", exposure=0.5,
                         threshold=2.0, knee=0.25)
    cli("postfx", path, "-o", tmp_path / "cli2.exr", "--preset", "modern", "--exposure", "0.5",
        "--threshold", "2", "--knee", "0.25")
    assert np.array_equal(read(tmp_path / "py2.exr"), read(tmp_path / "cli2.exr"))
    assert not np.array_equal(read(tmp_path / "py2.exr"), read(tmp_path / "py.exr"))
    flarekit.lens_render_file(str(path), str(tmp_path / "lpy.exr"), "angenieux-double-gauss",
                              ghosts=4)
    cli("lens", "render", "angenieux-double-gauss", path, "-o", tmp_path / "lcli.exr",
        "--ghosts", "4")
    assert np.array_equal(read(tmp_path / "lpy.exr"), read(tmp_path / "lcli.exr"))


def test_display_referred_expands_clipped_lights():
    # An 8-bit photograph's lamp: a glow around a core clipped at white.
    y, x = np.mgrid[0:96, 0:128].astype(np.float32)
    glow = 4.0 / (1.0 + ((x - 64) ** 2 + (y - 40) ** 2) / 9.0)
    photo = np.repeat(np.clip(0.1 + glow, 0, 1)[..., None], 3, axis=-1).astype(np.float32)
    plain = flarekit.postfx(photo, "modern")
    expanded = flarekit.postfx(photo, "modern", expand_highlights=8, display_referred=True)
    assert expanded[..., :3].sum() > plain[..., :3].sum() * 1.01
    with pytest.warns(UserWarning, match="expand_highlights is for 8/16-bit input"):
        hdr = flarekit.postfx(photo, "modern", expand_highlights=8)
    assert np.array_equal(hdr, plain)
