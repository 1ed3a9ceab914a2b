# SPDX-License-Identifier: Apache-2.0
"""flarekit: lens flares on numpy arrays and image files.

Every function wraps the C++ library's jobs (the same code the ``flarekit`` CLI runs): arrays
are linear float32 ``H x W x 3`` or ``H x W x 4``; bad input raises ``ValueError`` with the
CLI's one-line message (options spelt as keywords), internal failures ``RuntimeError``.
The GIL is released while the library works.
"""
from ._flarekit import (  # noqa: F401
    apply,
    apply_file,
    blend8,
    convert,
    elements,
    lens_ghosts,
    lens_info,
    lens_render,
    lens_render_file,
    lenses,
    load_preset,
    max_memory,
    postfx,
    postfx_file,
    presets,
    read_image,
    set_max_memory,
    TemporalFilter,
    validate_preset,
    visibility,
    write_image,
)

__all__ = [
    "apply", "apply_file", "blend8", "convert", "elements", "lens_ghosts", "lens_info", "lens_render",
    "lens_render_file", "lenses", "load_preset", "max_memory", "postfx", "postfx_file",
    "presets", "read_image", "set_max_memory", "TemporalFilter", "validate_preset", "visibility",
    "write_image",
]


def srgb_to_linear(encoded):
    """sRGB-encoded values (uint8 0-255, uint16 0-65535, or floats 0-1) as linear float32, by
    the sRGB curve (IEC 61966-2-1) the CLI's 8/16-bit readers apply."""
    import numpy as np

    a = np.asarray(encoded)
    if a.dtype == np.uint8:
        x = a.astype(np.float32) / np.float32(255)
    elif a.dtype == np.uint16:
        x = a.astype(np.float32) / np.float32(65535)
    else:
        x = a.astype(np.float32)
    return np.where(x <= 0.04045, x / np.float32(12.92),
                    ((x + np.float32(0.055)) / np.float32(1.055)) ** np.float32(2.4)
                    ).astype(np.float32)


def linear_to_srgb(linear):
    """Linear values as sRGB-encoded floats in [0, 1] (clipped), the inverse of srgb_to_linear."""
    import numpy as np

    x = np.clip(np.asarray(linear, dtype=np.float32), 0, 1)
    return np.where(x <= 0.0031308, x * np.float32(12.92),
                    np.float32(1.055) * x ** np.float32(1 / 2.4) - np.float32(0.055)
                    ).astype(np.float32)


__all__ += ["srgb_to_linear", "linear_to_srgb"]

from . import synth  # noqa: E402,F401  (flarekit.synth.sample; flarekit.torch is imported by
#                     whoever needs PyTorch, so `import flarekit` does not load it)
