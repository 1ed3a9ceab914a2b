# SPDX-License-Identifier: Apache-2.0
"""The flare-data generator: samples are the same whatever the shard, thread count or order;
the physics the template banks lack (ghosts on the line through the optical centre, lights off
the frame, occluders dimming the whole flare); the layouts; bad input; --resume."""
import filecmp
import json
import os
import signal
import subprocess
import time

import numpy as np
import pytest

import flarekit
from flarekit import synth

ONE_LIGHT = {"lights_min": 1, "lights_max": 1, "off_frame": 0, "occluded": 0}


def light_of(sample):
    (light,) = sample["label"]["lights"]
    return np.array([light["x"], light["y"]])


def distance_to_centre_line(point, light, width, height):
    centre = np.array([width / 2, height / 2])
    d = light - centre
    v = point - centre
    return abs(d[0] * v[1] - d[1] * v[0]) / np.hypot(*d)


def symmetric_centroid(layer, light, width, height):
    """The energy centroid over the pixels whose mirror image across the line through the light
    and the centre is also in the frame: a pattern symmetric about that line has its centroid
    on it there, however the frame's edges cut it."""
    centre = np.array([width / 2, height / 2])
    u = (light - centre) / np.hypot(*(light - centre))
    ys, xs = np.mgrid[0:height, 0:width]
    p = np.stack([xs + 0.5, ys + 0.5], axis=-1) - centre
    mirrored = 2 * (p @ u)[..., None] * u - p + centre
    inside = ((mirrored[..., 0] >= 0) & (mirrored[..., 0] < width) &
              (mirrored[..., 1] >= 0) & (mirrored[..., 1] < height))
    energy = layer.sum(axis=-1) * inside
    total = energy.sum()
    return np.array([((xs + 0.5) * energy).sum() / total, ((ys + 0.5) * energy).sum() / total])


@pytest.mark.parametrize("kind", ["sprite", "postfx", "lens"])
def test_ghosts_lie_on_the_line_through_the_optical_centre(kind):
    config = dict(ONE_LIGHT, sprite=0, postfx=0, lens=0)
    config[kind] = 1
    checked = 0
    for index in range(12):
        s = synth.sample(index, 5, 256, 256, config)
        light = light_of(s)
        assert s["label"]["flare"]["kind"] == kind and "ghosts" in s
        if np.hypot(*(light - 128)) < 10 or s["ghosts"].sum() <= 0:
            continue
        centroid = symmetric_centroid(s["ghosts"], light, 256, 256)
        assert distance_to_centre_line(centroid, light, 256, 256) < 1.0, index
        checked += 1
        if checked == 4:
            break
    assert checked == 4


def test_lights_outside_the_frame_still_flare_into_it():
    config = dict(ONE_LIGHT, off_frame=1, off_frame_margin=0.3, sprite=1, postfx=0, lens=0)
    flared = 0
    for index in range(6):
        s = synth.sample(index, 9, 256, 256, config)
        (light,) = s["label"]["lights"]
        assert not light["in_frame"]
        assert not (0 <= light["x"] < 256 and 0 <= light["y"] < 256)
        assert s["light_source"].max() < light["radiance"] * 0.5  # its disc is not in the frame
        flared += s["flare"].sum() > 0
    assert flared >= 4


def test_point_lights_dim_with_depth_and_occluders_dim_the_whole_flare():
    # Large near lights, so that occluders often cut their discs.
    config = dict(ONE_LIGHT, sprite=1, postfx=0, lens=0, point_lights=1, occluded=1,
                  radius_min=0.04, radius_max=0.06, depth_max=1.2)
    open_config = dict(config, occluded=0)
    checked = 0
    for index in range(60):
        hidden = synth.sample(index, 3, 256, 256, config)
        (light,) = hidden["label"]["lights"]
        assert light["kind"] == "point" and light["depth"] >= 1
        if not 0.05 < light["coverage"] < 0.95:
            continue
        visible = synth.sample(index, 3, 256, 256, open_config)
        assert visible["label"]["lights"][0]["coverage"] == 1
        ratio = hidden["flare"].sum() / visible["flare"].sum()
        assert ratio == pytest.approx(light["coverage"], rel=1e-3)
        checked += 1
        if checked == 2:
            break
    assert checked >= 1


def test_sample_layers_and_label():
    s = synth.sample(2, 11, 200, 120)
    for name in ("background", "light_source", "flare", "gt", "composite"):
        assert s[name].shape == (120, 200, 3) and s[name].dtype == np.float32
    label = s["label"]
    assert label["index"] == 2 and label["seed"] == 11 and 1 <= len(label["lights"]) <= 4
    for component in label["flare"]["components"]:
        assert s[component].shape == (120, 200, 3)
    # No camera model: the composite is the linear sum of its parts.
    assert np.allclose(s["composite"], s["gt"] + s["flare"], rtol=1e-6, atol=1e-6)
    assert np.allclose(s["gt"], s["background"] + s["light_source"], rtol=1e-6, atol=1e-6)
    again = synth.sample(2, 11, 200, 120)
    assert all(np.array_equal(s[k], again[k]) for k in s if k != "label")
    assert synth.sample(3, 11, 200, 120)["label"] != label


def test_camera_model():
    config = {"camera": True, "gamma_min": 2.0, "gamma_max": 2.0, "bits": 8}
    s = synth.sample(4, 1, 128, 96, config)
    camera = s["label"]["camera"]
    assert camera["gamma"] == 2.0 and s["label"]["gamma"] == 2.0
    codes = s["composite"] * 255
    assert np.all(np.abs(codes - np.rint(codes)) < 1e-3) and s["composite"].max() <= 1
    # JPEG at quality 30: the same 8-bit image, blocky; still 8-bit codes.
    jpeg = synth.sample(4, 1, 128, 96, dict(config, jpeg_quality=30))
    assert jpeg["label"]["camera"]["jpeg_quality"] == 30
    difference = np.abs(jpeg["composite"] - s["composite"])
    assert 0.002 < difference.mean() < 0.1
    codes = jpeg["composite"] * 255
    assert np.all(np.abs(codes - np.rint(codes)) < 1e-3)
    assert np.array_equal(jpeg["background"], s["background"])  # linear layers untouched
    with pytest.raises(ValueError, match="jpeg_quality: JPEG holds 8-bit samples"):
        synth.sample(4, 1, 128, 96, dict(config, bits=16, jpeg_quality=30))


def run_cli(cli, *args, ok=True):
    return cli("synth", *args, ok=ok)


def same_tree(a, b):
    left = sorted(os.path.relpath(os.path.join(d, f), a) for d, _, fs in os.walk(a) for f in fs)
    right = sorted(os.path.relpath(os.path.join(d, f), b) for d, _, fs in os.walk(b) for f in fs)
    assert left == right
    match, mismatch, errors = filecmp.cmpfiles(a, b, left, shallow=False)
    assert not mismatch and not errors, mismatch
    return len(match)


def test_shards_threads_and_order_give_the_same_files(cli, tmp_path):
    args = ["--count", 9, "--size", "96x64", "--seed", 21]
    run_cli(cli, *args, "--out", tmp_path / "one")
    env = dict(os.environ)
    for shard in ("2/3", "0/3", "1/3"):  # another order, one core each
        done = subprocess.run(["taskset", "-c", "0", os.environ["FLAREKIT_CLI"], "synth", *map(str, args),
                               "--out", str(tmp_path / "sharded"), "--shard", shard],
                              capture_output=True, text=True, env=env)
        assert done.returncode == 0, done.stderr
    assert same_tree(tmp_path / "one", tmp_path / "sharded") == 9 + 9 + 2
    # The in-memory sample is the file's, bit for bit.
    s = synth.sample(4, 21, 96, 64)
    assert np.array_equal(flarekit.read_image(str(tmp_path / "one" / "000004.exr"))[0],
                          s["composite"])
    lines = (tmp_path / "one" / "labels.jsonl").read_text().splitlines()
    assert json.loads(lines[4]) == s["label"]


def test_layouts(cli, tmp_path):
    run_cli(cli, "--count", 3, "--size", "64x64", "--seed", 2, "--out", tmp_path / "f7",
            "--format", "flare7kpp")
    compound = sorted(os.listdir(tmp_path / "f7" / "Scattering_Flare" / "Compound_Flare"))
    assert compound == sorted(os.listdir(tmp_path / "f7" / "Scattering_Flare" / "Light_Source"))
    assert compound == sorted(os.listdir(tmp_path / "f7" / "Reflective_Flare")) == [
        "000000.png", "000001.png", "000002.png"]
    source, info = flarekit.read_image(str(tmp_path / "f7/Scattering_Flare/Light_Source/000001.png"))
    assert info["display_referred"]
    y, x = np.unravel_index(np.argmax(source.sum(axis=-1)), source.shape[:2])
    assert abs(x - 32) <= 1 and abs(y - 32) <= 1  # the light at the centre
    run_cli(cli, "--count", 2, "--size", "80x48", "--seed", 2, "--out", tmp_path / "pairs",
            "--format", "pairs", "--depth", "16")
    for folder in ("input", "gt", "flare", "mask"):
        assert sorted(os.listdir(tmp_path / "pairs" / folder)) == ["000000.png", "000001.png"]
    mask = flarekit.read_image(str(tmp_path / "pairs" / "mask" / "000000.png"))[0]
    assert set(np.unique(mask)) <= {0.0, 1.0}
    with pytest.raises(ValueError, match="square"):
        synth.generate(tmp_path / "x", 2, 1, size=(64, 32), format="flare7kpp")


@pytest.mark.parametrize("args, message", [
    (["--count", 0], "--count: expected"),
    (["--size", "0x64"], "--size: expected WxH"),
    (["--size", "16385x64"], "--size: expected WxH"),
    (["--shard", "3/2"], "--shard: expected I/K"),
    (["--config", "{bad}"], "lights_max: expected at least lights_min"),
    (["--config", "{key}"], "unknown key"),
    (["--backgrounds", "{empty}"], "no image in the folder"),
])
def test_bad_input_is_one_line_and_exit_2(cli, tmp_path, args, message):
    (tmp_path / "bad.json").write_text('{"lights_min": 3, "lights_max": 2}')
    (tmp_path / "key.json").write_text('{"lights": 3}')
    (tmp_path / "empty").mkdir()
    args = [str(a).format(bad=tmp_path / "bad.json", key=tmp_path / "key.json",
                          empty=tmp_path / "empty") for a in args]
    base = {"--count": "4", "--size": "32x32", "--seed": "1", "--out": str(tmp_path / "out")}
    for flag, value in zip(args[::2], args[1::2]):
        base[flag] = value
    done = run_cli(cli, *[x for kv in base.items() for x in kv], ok=False)
    assert done.returncode == 2
    assert message in done.stderr and len(done.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "out" / "000000.exr").exists()


def test_a_folder_of_another_seed_is_refused(cli, tmp_path):
    run_cli(cli, "--count", 2, "--size", "32x32", "--seed", 1, "--out", tmp_path / "set")
    done = run_cli(cli, "--count", 2, "--size", "32x32", "--seed", 2, "--out", tmp_path / "set",
                   ok=False)
    assert done.returncode == 2 and "holds the samples of seed 1" in done.stderr
    with pytest.raises(ValueError, match="config: lights_max: expected"):
        synth.sample(0, 1, 32, 32, {"lights_max": 100})
    with pytest.raises(ValueError, match="index: expected a whole number"):
        synth.sample(-1, 1, 32, 32)


def test_interrupted_run_resumes_to_the_same_set(cli, tmp_path):
    args = ["--count", 40, "--size", "256x256", "--seed", 8]
    run_cli(cli, *args, "--out", tmp_path / "whole")
    process = subprocess.Popen([os.environ["FLAREKIT_CLI"], "synth", *map(str, args), "--out",
                                str(tmp_path / "cut")], stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, text=True)
    labels = tmp_path / "cut" / "labels"
    deadline = time.time() + 60
    # Complete labels only: a label being written is a hidden temporary file until its rename.
    def complete():
        return [f for f in os.listdir(labels) if not f.startswith(".")] if labels.exists() else []

    while time.time() < deadline and len(complete()) < 3:
        time.sleep(0.01)
    process.send_signal(signal.SIGTERM)
    _, err = process.communicate(timeout=60)
    finished = sorted(os.listdir(labels))
    assert 3 <= len(finished) < 40, err
    assert not [f for f in finished if f.startswith(".")]
    assert process.returncode != 0 and "interrupted" in err
    # Every sample with a label is complete; no temporary file is left.
    for name in finished:
        exr = tmp_path / "cut" / name.replace(".json", ".exr")
        assert filecmp.cmp(exr, tmp_path / "whole" / exr.name, shallow=False)
    assert not [f for f in os.listdir(tmp_path / "cut") if f.startswith(".")]
    # What a writer killed outright (SIGKILL, a lost cluster worker) leaves: its temporary file.
    orphan = labels / ".flarekit-tmp-999999-0-000039.json"
    orphan.write_text("{")
    done = run_cli(cli, *args, "--out", tmp_path / "cut", "--resume")
    assert not orphan.exists()
    assert f"{len(finished)} already complete" in done.stderr
    same_tree(tmp_path / "whole", tmp_path / "cut")
