# SPDX-License-Identifier: Apache-2.0
"""The frei0r filter in its real hosts: ffmpeg (-vf frei0r) and melt (-filter frei0r.flarekit),
each loading this build's flarekit.so through FREI0R_PATH, on a clip of a sun moving over dusk
hills that the test draws. Reference: the CLI of the same build on the same PNG frames."""
import os
import pathlib
import shutil

import numpy as np
import pytest

from conftest import read_frames, run_host, write_frames

# 16 frames: more than the tracker's look-back (12 at 24 fps), so frames fall out of it.
WIDTH, HEIGHT, FRAMES = 320, 180, 16
PLUGIN_DIR = os.environ.get("FLAREKIT_FREI0R_DIR", "")
METADATA = os.environ.get("FLAREKIT_MLT_METADATA", "")


def sun_at(i):
    """The sun's centre in frame i (0-based), in pixels from the top-left (pixel centres +0.5)."""
    return 60.0 + 13.1 * i + 0.5, 55.0 + 1.7 * i + 0.5


def draw_clip(with_sun):
    """Dusk sky over dark hills (sRGB codes); the sun a clipped disc of 12 px radius with a
    glow that falls off over 24 px, as a low sun with a little haze films."""
    y, x = np.mgrid[0:HEIGHT, 0:WIDTH].astype(np.float64)
    sky = np.stack([40 + 30 * (1 - y / HEIGHT), 50 + 40 * (1 - y / HEIGHT),
                    80 + 60 * (1 - y / HEIGHT)], -1)
    hills = y > 130 + 15 * np.sin(x / 37.0)
    frames = []
    for i in range(FRAMES):
        image = np.where(hills[..., None], np.array([25.0, 30.0, 20.0]), sky)
        if with_sun:
            cx, cy = sun_at(i)
            r = np.hypot(x + 0.5 - cx, y + 0.5 - cy)
            glow = 255 * np.exp(-np.maximum(r - 12, 0) / 24.0)
            image = np.maximum(image, glow[..., None] * np.array([1.0, 0.95, 0.85]))
            image[r <= 12] = 255
        frames.append(np.clip(np.rint(image), 0, 255).astype(np.uint8))
    return frames


@pytest.fixture(scope="module")
def clip(tmp_path_factory):
    folder = tmp_path_factory.mktemp("clip")
    frames = draw_clip(True)
    write_frames(frames, folder / "sun.%03d.png")
    write_frames(frames, folder / "sun.mov")
    dark = draw_clip(False)
    write_frames(dark, folder / "dusk.%03d.png")
    return folder, np.stack(frames), np.stack(dark)


def host_env():
    assert PLUGIN_DIR and (pathlib.Path(PLUGIN_DIR) / "flarekit.so").exists(), \
        "FLAREKIT_FREI0R_DIR names the folder of this build's flarekit.so"
    env = dict(os.environ)
    env["FREI0R_PATH"] = PLUGIN_DIR
    env["MLT_FREI0R_PLUGIN_PATH"] = PLUGIN_DIR
    return env


def ffmpeg(src, out, params, frames=None):
    limit = ["-frames:v", str(frames)] if frames else []
    return run_host("ffmpeg", "-v", "error", "-y", "-i", src, "-vf",
                    "frei0r=filter_name=flarekit:filter_params=" + "|".join(map(str, params)),
                    *limit, "-start_number", "1", out, env=host_env())


def melt(src, out, tmp_path, properties):
    profile = tmp_path / "profile"
    # melt 7.12 crashes on a profile without a description.
    profile.write_text(f"description=flarekit test\nwidth={WIDTH}\nheight={HEIGHT}\nprogressive=1\nframe_rate_num=24\n"
                       "frame_rate_den=1\nsample_aspect_num=1\nsample_aspect_den=1\n"
                       "display_aspect_num=16\ndisplay_aspect_den=9\ncolorspace=709\n")
    return run_host("melt", "-silent", "-profile", profile, src, "-filter", "frei0r.flarekit",
                    *[f"{k}={v}" for k, v in properties.items()], "-consumer",
                    f"avformat:{out}", "vcodec=png", "start_number=1", env=host_env())


def worst(a, b):
    return [int(np.abs(a[i].astype(int) - b[i].astype(int)).max()) for i in range(len(a))]


def test_ffmpeg_and_melt_flare_the_followed_sun_as_the_cli_does(cli, clip, tmp_path):
    folder, frames, _ = clip
    # The CLI: the sun followed through the sequence, its flare 8x the energy model's.
    (tmp_path / "cli").mkdir()
    cli("apply", folder / "sun.%03d.png", "-o", tmp_path / "cli" / "f.%03d.png", "--intensity", 8,
        "--write-track", tmp_path / "track.csv")
    track = np.loadtxt(tmp_path / "track.csv", delimiter=",", skiprows=1)
    assert len(track) == FRAMES
    for row in track:
        x, y = sun_at(int(row[0]) - 1)
        assert abs(row[1] - x) <= 1 and abs(row[2] - y) <= 1, row
    reference = read_frames(tmp_path / "cli" / "f.%03d.png", WIDTH, HEIGHT)

    (tmp_path / "ff").mkdir()
    ffmpeg(folder / "sun.%03d.png", tmp_path / "ff" / "f.%03d.png",
           ["sprite", "tanczos-classic", "track", 0.5, 0.5, 8])
    by_ffmpeg = read_frames(tmp_path / "ff" / "f.%03d.png", WIDTH, HEIGHT)
    (tmp_path / "melt").mkdir()
    melt(folder / "sun.mov", tmp_path / "melt" / "f.%03d.png", tmp_path,
         {"mode": "sprite", "light": "track", "intensity": 8})
    by_melt = read_frames(tmp_path / "melt" / "f.%03d.png", WIDTH, HEIGHT)

    assert len(by_ffmpeg) == len(by_melt) == FRAMES
    # Every frame flared (its ghosts move tens of levels) ...
    assert min(worst(by_ffmpeg, frames)) > 20
    # ... where the CLI's tracked light puts it: within a level of the CLI, and the hosts
    # within 2 of each other.
    assert max(worst(by_ffmpeg, reference)) <= 1
    assert max(worst(by_melt, by_ffmpeg)) <= 2

    # The comparison sees a 1 px error: the CLI's flare from the track moved 1 px right
    # differs from the hosts' by more than 2 levels in every frame.
    shifted = tmp_path / "shifted.csv"
    shifted.write_text("frame,x,y,intensity\n" + "".join(
        f"{int(r[0])},{r[1] + 1},{r[2]},{r[3] * 8}\n" for r in track))
    (tmp_path / "moved").mkdir()
    cli("apply", folder / "sun.%03d.png", "-o", tmp_path / "moved" / "f.%03d.png",
        "--light-track", shifted)
    moved = read_frames(tmp_path / "moved" / "f.%03d.png", WIDTH, HEIGHT)
    assert min(worst(moved, by_ffmpeg)) > 2


def test_a_clip_without_a_light_passes_through_unchanged(clip, tmp_path):
    folder, _, dark = clip
    ffmpeg(folder / "dusk.%03d.png", tmp_path / "f.%03d.png", ["sprite", "", "track"])
    assert np.array_equal(read_frames(tmp_path / "f.%03d.png", WIDTH, HEIGHT), dark)
    # Found in each frame on its own: nothing there either.
    ffmpeg(folder / "dusk.%03d.png", tmp_path / "g.%03d.png", ["sprite", "", "auto"])
    assert np.array_equal(read_frames(tmp_path / "g.%03d.png", WIDTH, HEIGHT), dark)


def test_postfx_and_lens_modes_equal_the_cli(cli, clip, tmp_path):
    folder, frames, _ = clip
    (tmp_path / "cli").mkdir()
    cli("postfx", folder / "sun.%03d.png", "-o", tmp_path / "cli" / "p.%03d.png", "--preset",
        "modern", "--frames", "1-2", "--expand-highlights")
    ffmpeg(folder / "sun.%03d.png", tmp_path / "p.%03d.png", ["postfx", "modern"], frames=2)
    reference = read_frames(tmp_path / "cli" / "p.%03d.png", WIDTH, HEIGHT)
    by_ffmpeg = read_frames(tmp_path / "p.%03d.png", WIDTH, HEIGHT)
    assert min(worst(by_ffmpeg, frames[:2])) > 5
    assert max(worst(by_ffmpeg, reference)) <= 1

    # A lens at the sun placed by the host's parameters (fractions of the frame).
    x, y = sun_at(0)
    cli("lens", "render", "asahi-takumar-50", folder / "sun.001.png", "-o",
        tmp_path / "cli" / "l.png", "--light", f"{x},{y}")
    ffmpeg(folder / "sun.%03d.png", tmp_path / "l.%03d.png",
           ["lens", "asahi-takumar-50", "position", x / WIDTH, y / HEIGHT], frames=1)
    reference = read_frames(tmp_path / "cli" / "l.png", WIDTH, HEIGHT)
    by_ffmpeg = read_frames(tmp_path / "l.%03d.png", WIDTH, HEIGHT)
    assert worst(by_ffmpeg, frames[:1])[0] > 5
    assert max(worst(by_ffmpeg, reference)) <= 1


def test_a_keyframed_position_in_melt_places_the_light_each_frame(cli, clip, tmp_path):
    folder, frames, _ = clip
    # x and y keyframed from the first frame's sun to the last's: melt interpolates linearly.
    (x0, y0), (x1, y1) = sun_at(0), sun_at(FRAMES - 1)
    last = FRAMES - 1
    melt(folder / "sun.mov", tmp_path / "k.%03d.png", tmp_path,
         {"light": "position", "x": f"0={x0 / WIDTH};{last}={x1 / WIDTH}",
          "y": f"0={y0 / HEIGHT};{last}={y1 / HEIGHT}", "intensity": 8})
    by_melt = read_frames(tmp_path / "k.%03d.png", WIDTH, HEIGHT)
    for i in (0, 5, last):
        t = i / last
        x, y = x0 + t * (x1 - x0), y0 + t * (y1 - y0)
        out = tmp_path / f"cli.{i}.png"
        cli("apply", folder / f"sun.{i + 1:03d}.png", "-o", out, "--light", f"{x},{y}",
            "--intensity", 8)
        reference = read_frames(out, WIDTH, HEIGHT)[0]
        assert worst([by_melt[i]], [reference])[0] <= 2, i
        assert worst([by_melt[i]], [frames[i]])[0] > 20, i


def test_bad_parameters_never_stop_the_host(clip, tmp_path):
    folder, frames, _ = clip
    # An unknown mode keeps the current one (sprite), with one line on stderr.
    done = ffmpeg(folder / "sun.%03d.png", tmp_path / "a.%03d.png", ["bogus"], frames=2)
    assert done.stderr.count("mode: expected one of sprite, postfx, lens, got 'bogus'") == 1
    ffmpeg(folder / "sun.%03d.png", tmp_path / "b.%03d.png", ["sprite"], frames=2)
    assert np.array_equal(read_frames(tmp_path / "a.%03d.png", WIDTH, HEIGHT),
                          read_frames(tmp_path / "b.%03d.png", WIDTH, HEIGHT))
    # melt sets every parameter again for each frame: still said once.
    done = melt(folder / "sun.mov", tmp_path / "m.%03d.png", tmp_path, {"mode": "bogus"})
    assert done.stderr.count("got 'bogus'") == 1, done.stderr
    # A preset that is not there: every frame unchanged, the reason said once.
    done = ffmpeg(folder / "sun.%03d.png", tmp_path / "c.%03d.png", ["sprite", "no-such-preset"],
                  frames=3)
    assert done.stderr.count("no-such-preset") == 1, done.stderr
    assert "frame left unchanged" in done.stderr
    assert np.array_equal(read_frames(tmp_path / "c.%03d.png", WIDTH, HEIGHT), frames[:3])
    # A negative intensity is clamped to the table's minimum, 0: no flare.
    ffmpeg(folder / "sun.%03d.png", tmp_path / "d.%03d.png", ["sprite", "", "track", 0.5, 0.5, -5],
           frames=2)
    assert np.array_equal(read_frames(tmp_path / "d.%03d.png", WIDTH, HEIGHT), frames[:2])


def test_mlt_lists_the_filter_with_its_named_ranged_parameters(tmp_path):
    assert METADATA and pathlib.Path(METADATA).exists(), "FLAREKIT_MLT_METADATA names the YAML"
    # MLT reads a frei0r filter's metadata from MLT_DATA/frei0r/filter_frei0r.NAME.yml: a copy of
    # the system's data folder with ours added, as the docs' install step leaves it.
    data = tmp_path / "mlt-data"
    shutil.copytree("/usr/share/mlt-7", data)
    shutil.copy(METADATA, data / "frei0r")
    env = host_env()
    env["MLT_DATA"] = str(data)
    done = run_host("melt", "-query", "filter=frei0r.flarekit", env=env)
    text = done.stdout
    assert "title: flarekit Lens Flare" in text
    for name in ("mode", "preset", "light", "x", "y", "intensity", "threshold", "fps"):
        assert f"identifier: {name}\n" in text, name
    intensity = text[text.index("identifier: intensity"):]
    assert "maximum: 1000" in intensity.split("identifier:")[1]


def test_the_installed_plugin_linked_into_a_users_folder_finds_its_presets(clip, tmp_path):
    # `cmake --install` to a prefix, then the docs' one command: a link in ~/.frei0r-1/lib, the
    # folder ffmpeg and melt search in every user's home.
    prefix, home = tmp_path / "prefix", tmp_path / "home"
    run_host(os.environ["FLAREKIT_CMAKE"], "--install", os.environ["FLAREKIT_BUILD_DIR"],
             "--prefix", prefix)
    plugin = prefix / "lib" / "frei0r-1" / "flarekit.so"
    assert plugin.exists()
    assert (prefix / "share" / "mlt-7" / "frei0r" / "filter_frei0r.flarekit.yml").exists()
    (home / ".frei0r-1" / "lib").mkdir(parents=True)
    (home / ".frei0r-1" / "lib" / "flarekit.so").symlink_to(plugin)
    env = {k: v for k, v in os.environ.items()
           if k not in ("FREI0R_PATH", "MLT_FREI0R_PLUGIN_PATH", "FLAREKIT_DATA_DIR",
                        "FLAREKIT_PRESET_PATH")}
    env["HOME"] = str(home)
    folder, frames, _ = clip
    done = run_host("ffmpeg", "-v", "error", "-y", "-i", folder / "sun.%03d.png", "-vf",
                    "frei0r=flarekit:lens|asahi-takumar-50|auto", "-frames:v", "1",
                    "-start_number", "1", tmp_path / "f.%03d.png", env=env)
    assert "flarekit" not in done.stderr, done.stderr
    flared = read_frames(tmp_path / "f.%03d.png", WIDTH, HEIGHT)
    assert worst(flared, frames[:1])[0] > 5


def test_the_docs_table_is_the_plugins_own():
    build = pathlib.Path(os.environ["FLAREKIT_BUILD_DIR"])
    done = run_host(build / "flarekit-frei0r-metadata", "--markdown")
    page = (pathlib.Path(os.environ["FLAREKIT_SOURCE_DIR"]) / "docs" / "hosts.md").read_text()
    start = page.index("<!-- generated by: flarekit-frei0r-metadata --markdown -->\n")
    table = page[page.index("\n", start) + 1:page.index("<!-- end generated -->", start)]
    assert table == done.stdout, "docs/hosts.md is out of date: scripts/update-docs.sh"
