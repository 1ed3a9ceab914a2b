# SPDX-License-Identifier: Apache-2.0
"""The host plug-ins' tests: each runs the real host (ffmpeg, melt) on material the test makes,
with this build's plug-in, and compares with this build's CLI (FLAREKIT_CLI)."""
import os
import subprocess

import numpy as np
import pytest


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("FLAREKIT_CLI")
    assert path and os.access(path, os.X_OK), "FLAREKIT_CLI names the flarekit CLI to compare with"

    def run(*args):
        done = subprocess.run([path, *map(str, args)], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        return done

    return run


def run_host(*args, env=None):
    """A host program; its exit status must be 0 (a plug-in never takes its host down)."""
    done = subprocess.run([*map(str, args)], capture_output=True, text=True, env=env)
    assert done.returncode == 0, f"{args[0]} exited {done.returncode}: {done.stderr[-2000:]}"
    return done


def read_frames(pattern, width, height):
    """Every frame of an image pattern or a clip as uint8 H x W x 3 (decoded by ffmpeg, exactly:
    PNG and the PNG codec are lossless)."""
    done = subprocess.run(["ffmpeg", "-v", "error", "-i", str(pattern), "-f", "rawvideo",
                           "-pix_fmt", "rgb24", "-"], capture_output=True, check=True)
    return np.frombuffer(done.stdout, np.uint8).reshape(-1, height, width, 3)


def write_frames(frames, pattern, fps=24):
    """uint8 H x W x 3 frames as a PNG sequence numbered from 1 (or a clip, by extension)."""
    height, width = frames[0].shape[:2]
    extra = ["-start_number", "1"] if "%" in str(pattern) else ["-c:v", "png"]
    subprocess.run(["ffmpeg", "-v", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s",
                    f"{width}x{height}", "-r", str(fps), "-i", "-", *extra, str(pattern)],
                   input=b"".join(f.tobytes() for f in frames), check=True)
