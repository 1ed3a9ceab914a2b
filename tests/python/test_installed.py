# SPDX-License-Identifier: Apache-2.0
"""`cmake --install` puts the module under lib/python3/dist-packages; moved elsewhere, it still
finds its own presets, lenses and image module (nothing of the build machine inside)."""
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

CHECK = r"""
import numpy as np, flarekit, sys
assert flarekit.__file__.startswith(sys.argv[1]), flarekit.__file__
assert "tanczos-classic" in flarekit.presets() and flarekit.lenses()
image = np.full((32, 48, 3), 0.25, np.float32)
flarekit.write_image(sys.argv[2], image)   # a BMP: through the OpenImageIO module
back, info = flarekit.read_image(sys.argv[2])
assert back.shape == (32, 48, 3) and info["display_referred"]
print("ok", len(flarekit.presets()), len(flarekit.lenses()))
"""


def test_installed_package_from_a_moved_prefix(tmp_path):
    build, cmake = os.environ.get("FLAREKIT_BUILD_DIR"), os.environ.get("FLAREKIT_CMAKE")
    if not build or not cmake:
        pytest.fail("FLAREKIT_BUILD_DIR and FLAREKIT_CMAKE name the build to install")
    prefix = tmp_path / "prefix"
    subprocess.run([cmake, "--install", build, "--prefix", str(prefix)], check=True,
                   capture_output=True)
    moved = tmp_path / "moved"
    shutil.move(str(prefix), str(moved))
    site = moved / "lib" / "python3" / "dist-packages"
    assert (site / "flarekit" / "_flarekit.pyi").exists()
    assert (site / "flarekit" / "py.typed").exists()
    env = {k: v for k, v in os.environ.items() if not k.startswith("FLAREKIT_")}
    env["PYTHONPATH"] = str(site)
    done = subprocess.run([sys.executable, "-c", CHECK, str(site), str(tmp_path / "a.bmp")],
                          env=env, cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("ok")
