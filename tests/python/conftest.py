# SPDX-License-Identifier: Apache-2.0
"""The Python module's tests: `import flarekit` from the build tree (PYTHONPATH, set by ctest)
and the CLI of the same build (FLAREKIT_CLI) as the reference its results must equal."""
import os
import pathlib
import subprocess

import numpy as np
import pytest

import flarekit

SOURCE = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("FLAREKIT_CLI")
    assert path and os.access(path, os.X_OK), "FLAREKIT_CLI names the flarekit CLI to compare with"

    def run(*args, ok=True):
        done = subprocess.run([path, *map(str, args)], capture_output=True, text=True)
        if ok:
            assert done.returncode == 0, done.stderr
        return done

    return run


@pytest.fixture(scope="session")
def sunset():
    """The shipped HDR sample (a sun over water), linear float32 H x W x 3."""
    image, info = flarekit.read_image(str(SOURCE / "samples" / "sunset-hdr.exr"))
    assert not info["display_referred"]
    return image


def read(path):
    return flarekit.read_image(str(path))[0]


def small_hdr(tmp_path, width=96, height=64):
    """A dim gradient with one bright 3x3 light, written as a float EXR: its values are exactly
    what the module gets as an array."""
    y, x = np.mgrid[0:height, 0:width].astype(np.float32)
    image = np.stack([x / width * 0.2, y / height * 0.2, np.full_like(x, 0.05)], axis=-1)
    image[20:23, 30:33] = 400.0
    path = tmp_path / "small.exr"
    flarekit.write_image(str(path), image.astype(np.float32), depth="float")
    return path, image.astype(np.float32)
