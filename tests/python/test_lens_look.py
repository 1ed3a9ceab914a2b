# SPDX-License-Identifier: Apache-2.0
"""Lens flares visible at their defaults: on the shipped HDR sun, every shipped lens's ghosts
show at least as clearly as the ghosts of the sprite preset `subtle`, the floor of visibility
the defaults are calibrated against (the brightest ghost at 2% of the light's measured energy).
Visibility: the most an 8-bit view (the filmic curve that `--tonemap auto` writes HDR through)
moves away from the sun's own glare."""
import numpy as np

import flarekit
from conftest import SOURCE


def filmic(x):
    """John Hable's filmic curve (GDC 2010), as flarekit applies it (checked below)."""
    a, b, c, d, e, f, white = 0.15, 0.50, 0.10, 0.20, 0.02, 0.30, 11.2

    def hable(v):
        return (v * (a * v + c * b) + d * e) / (v * (a * v + b) + d * f) - e / f

    return hable(2.0 * np.maximum(x, 0.0)) / hable(white)


def view8(linear):
    return np.round(np.clip(flarekit.linear_to_srgb(np.clip(filmic(linear), 0, 1)), 0, 1) * 255)


def test_every_lens_shows_its_ghosts_at_least_as_clearly_as_the_subtle_preset():
    image, _ = flarekit.read_image(str(SOURCE / "samples" / "sunset-hdr.exr"))
    small = np.ascontiguousarray(image[::4, ::4, :3])  # 320x180: every lens in seconds
    # The view's curve is the library's.
    shown = flarekit.apply(small, "subtle", intensity=0, tonemap="filmic")[..., :3]
    np.testing.assert_allclose(shown, np.clip(filmic(small), 0, 1), atol=1e-6)
    luminance = small.sum(axis=-1)
    sun_y, sun_x = np.unravel_index(luminance.argmax(), luminance.shape)
    y, x = np.mgrid[0:small.shape[0], 0:small.shape[1]]
    away = np.hypot(x - sun_x, y - sun_y) > 0.08 * small.shape[0]  # past the sun's own glare
    base = view8(small)

    def lift(ghosts):
        return (view8(small + ghosts) - base).max(axis=-1)[away].max()

    _, passes = flarekit.apply(small, "subtle", layers=True)
    floor = lift(passes["ghosts"])
    assert 4 <= floor <= 20  # subtle: faint, but there
    lifts = {}
    for lens in flarekit.lenses():
        name = lens if isinstance(lens, str) else lens["name"]
        _, layers = flarekit.lens_render(small, name, layers=True)
        lifts[name] = lift(layers["ghosts"])
    assert len(lifts) >= 8
    assert min(lifts.values()) >= floor, lifts
    # ...and each lens its own strength: the uncoated Petzval's few ghosts are the faintest,
    # the multi-coated zooms' dozens the strongest.
    assert lifts["kodak-petzval"] == min(lifts.values())
    assert max(lifts.values()) >= 4 * floor
