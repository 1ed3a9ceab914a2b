# SPDX-License-Identifier: Apache-2.0
"""flarekit studio under a private X server (Xvfb, started and stopped here, local socket only):
scripted actions through the window's own panels and pointer, checked against the CLI, the
shipped presets and the studio's own pictures."""
import json
import os
import subprocess

import numpy as np
import pytest

import flarekit
from conftest import SOURCE, read

pytestmark = pytest.mark.skipif(
    os.environ.get("FLAREKIT_STUDIO") != "1", reason="built without the studio (FLAREKIT_STUDIO)")

SUNSET = SOURCE / "samples" / "sunset.png"          # 1280x720, 8-bit
SUNSET_HDR = SOURCE / "samples" / "sunset-hdr.exr"  # linear float


@pytest.fixture(scope="module")
def display():
    read_end, write_end = os.pipe()
    server = subprocess.Popen(
        ["Xvfb", "-displayfd", str(write_end), "-nolisten", "tcp", "-screen", "0", "1920x1080x24"],
        pass_fds=(write_end,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_end)
    number = b""
    with os.fdopen(read_end, "rb") as pipe:
        while not number.endswith(b"\n"):
            chunk = pipe.read(1)
            assert chunk, "Xvfb did not start"
            number += chunk
    yield ":" + number.decode().strip()
    server.terminate()
    server.wait(timeout=30)


@pytest.fixture
def studio(cli, display, tmp_path):
    """Runs `flarekit studio` with a script of actions; paths in the script are under tmp_path."""

    def run(actions, *args, ok=True):
        script = tmp_path / "actions.json"
        script.write_text(json.dumps({"actions": actions}))
        env = dict(os.environ, DISPLAY=display)
        done = subprocess.run([os.environ["FLAREKIT_CLI"], "studio", "--script", str(script),
                               "--stats", *map(str, args)], capture_output=True, text=True,
                              env=env, cwd=tmp_path, timeout=300)
        if ok:
            assert done.returncode == 0, done.stderr
        return done

    return run


def srgb8(image):
    return np.round(np.clip(flarekit.linear_to_srgb(image[..., :3]), 0, 1) * 255)


def levels(a, b):
    return np.abs(srgb8(a) - srgb8(b)).max()


def canonical(studio, tmp_path, preset):
    """A preset (a name, or a dict written to a file) as presetToJson writes it: loaded and saved
    untouched, so that keys equal to their type's defaults are left out as the save leaves them."""
    if isinstance(preset, dict):
        (tmp_path / "expected-in.json").write_text(json.dumps(preset))
        preset = str(tmp_path / "expected-in.json")
    studio([{"action": "load", "preset": preset},
            {"action": "save", "path": "canonical.json"}])
    return (tmp_path / "canonical.json").read_text()


def centroid_of_flare(path, source):
    """Where the flare alone (the export minus the plate) is brightest on average."""
    flare = (read(path)[..., :3] - read(source)[..., :3]).sum(axis=-1)
    weight = np.where(flare > 0.05 * flare.max(), flare, 0)
    y, x = np.mgrid[0:weight.shape[0], 0:weight.shape[1]]
    return np.array([(x * weight).sum() / weight.sum(), (y * weight).sum() / weight.sum()]) + 0.5


def test_without_a_display_it_says_how_to_run_it(cli):
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    done = subprocess.run([os.environ["FLAREKIT_CLI"], "studio", str(SUNSET)], env=env,
                          capture_output=True, text=True)
    assert done.returncode == 2
    assert len(done.stderr.strip().splitlines()) == 1
    assert "display" in done.stderr and "Xvfb" in done.stderr


def test_screenshot_of_a_file_writes_the_window_and_exits(cli, display, tmp_path):
    shot = tmp_path / "window.png"
    done = subprocess.run([os.environ["FLAREKIT_CLI"], "studio", str(SUNSET), "--screenshot",
                           str(shot), "--size", "1280x800"], env=dict(os.environ, DISPLAY=display),
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    image, info = flarekit.read_image(str(shot))
    assert image.shape == (800, 1280, 3)
    # The photograph with its flare fills the middle of the view: bright, warm, not the UI grey.
    view = srgb8(image[200:500, 500:1100])
    assert view.mean() > 80 and view[..., 0].mean() > view[..., 2].mean()


def test_the_flare_follows_the_pointer(studio, tmp_path):
    # The glow alone (solo), so that the flare's centre is the light.
    studio([{"action": "open", "path": str(SUNSET)},
            {"action": "solo", "element": 0},
            {"action": "light", "at": [400, 300]},
            {"action": "export", "path": "before.exr"},
            {"action": "drag", "from": [400, 300], "to": [820, 420], "frames": 10},
            {"action": "export", "path": "after.exr"}])
    start = centroid_of_flare(tmp_path / "before.exr", SUNSET)
    end = centroid_of_flare(tmp_path / "after.exr", SUNSET)
    assert np.abs(start - [400, 300]).max() < 0.6
    # The pointer lands on whole screen pixels: 1280 image pixels over ~830 on screen.
    assert np.abs(end - [820, 420]).max() < 2.0, end


def test_hide_undo_redo_on_screen(studio, tmp_path):
    studio([{"action": "open", "path": str(SUNSET)},
            {"action": "screenshot", "path": "shown.png"},
            {"action": "hide", "element": 2},
            {"action": "screenshot", "path": "hidden.png"},
            {"action": "undo"},
            {"action": "screenshot", "path": "undone.png"},
            {"action": "redo"},
            {"action": "screenshot", "path": "redone.png"}])
    shown, hidden = read(tmp_path / "shown.png"), read(tmp_path / "hidden.png")
    undone, redone = read(tmp_path / "undone.png"), read(tmp_path / "redone.png")
    # Undo restores every pixel of the window but the status line (which names the action).
    window = slice(0, shown.shape[0] - 80)
    assert np.array_equal(shown[window], undone[window])
    assert np.array_equal(hidden[window], redone[window])
    assert levels(shown, hidden) > 30     # the streaks went (and the list's box unticked)


def test_a_hidden_element_is_saved_and_the_cli_draws_without_it(studio, cli, tmp_path):
    studio([{"action": "open", "path": str(SUNSET)},
            {"action": "light", "at": [900.5, 250.25]},
            {"action": "hide", "element": 2},
            {"action": "save", "path": "hidden.json"},
            {"action": "export", "path": "hidden.png"}])
    saved = json.loads((tmp_path / "hidden.json").read_text())
    assert saved["elements"][2]["visible"] is False
    # Reference: the same preset with that element deleted, drawn by the CLI.
    del saved["elements"][2]
    (tmp_path / "removed.json").write_text(json.dumps(saved))
    cli("apply", SUNSET, "-o", tmp_path / "cli.png", "--preset", tmp_path / "removed.json",
        "--light", "900.5,250.25", "--flux-mode", "fixed")
    assert levels(read(tmp_path / "hidden.png"), read(tmp_path / "cli.png")) <= 1


def test_saved_preset_is_the_expected_json_and_the_cli_renders_it_alike(studio, cli, tmp_path):
    studio([{"action": "open", "path": str(SUNSET)},
            {"action": "light", "at": [700, 200]},
            {"action": "set", "element": 0, "key": "size", "value": 0.35},
            {"action": "set", "element": 4, "key": "color", "value": [0.2, 0.9, 0.4]},
            {"action": "set", "key": "intensity", "value": 1.5},
            {"action": "set", "element": 1, "key": "width", "value": 0.2},
            {"action": "undo"},
            {"action": "save", "path": "mine.json"},
            {"action": "export", "path": "mine.png"},
            {"action": "export", "path": "mine.exr"}])
    saved = (tmp_path / "mine.json").read_text()
    expected = json.loads((SOURCE / "presets" / "tanczos-classic.json").read_text())
    expected["intensity"] = 1.5
    expected["elements"][0]["size"] = 0.35
    expected["elements"][4]["color"] = [0.2, 0.9, 0.4]
    assert saved == canonical(studio, tmp_path, expected)  # byte for byte
    cli("apply", SUNSET, "-o", tmp_path / "cli.png", "--preset", tmp_path / "mine.json",
        "--light", "700,200", "--flux-mode", "fixed")
    cli("apply", SUNSET, "-o", tmp_path / "cli.exr", "--preset", tmp_path / "mine.json",
        "--light", "700,200", "--flux-mode", "fixed", "--depth", "float")
    assert levels(read(tmp_path / "mine.png"), read(tmp_path / "cli.png")) <= 1
    np.testing.assert_allclose(read(tmp_path / "mine.exr")[..., :3],
                               read(tmp_path / "cli.exr")[..., :3], rtol=1e-3, atol=1e-4)


def test_hdr_exports_match_the_cli_linear_and_through_its_curve(studio, cli, tmp_path):
    studio([{"action": "open", "path": str(SUNSET_HDR)},
            {"action": "load", "preset": "sun-wide"},
            {"action": "export", "path": "hdr.exr"},
            {"action": "export", "path": "hdr.png"}], "--stats")
    done = studio([{"action": "open", "path": str(SUNSET_HDR)}])
    light = done.stderr.split("light at ")[1].split()[0].rstrip(";")
    for out in ("cli.exr", "cli.png"):
        cli("apply", SUNSET_HDR, "-o", tmp_path / out, "--preset", "sun-wide", "--light", light,
            "--flux-mode", "fixed", *(["--depth", "float"] if out.endswith(".exr") else []))
    np.testing.assert_allclose(read(tmp_path / "hdr.exr")[..., :3],
                               read(tmp_path / "cli.exr")[..., :3], rtol=1e-3, atol=1e-4)
    assert levels(read(tmp_path / "hdr.png"), read(tmp_path / "cli.png")) <= 1


def test_choosing_a_preset_with_unsaved_edits_asks_first(studio, tmp_path):
    studio([{"action": "set", "element": 0, "key": "size", "value": 0.5},
            {"action": "choose", "preset": "anamorphic"},
            {"action": "screenshot", "path": "question.png"},
            {"action": "answer", "choice": "cancel"},
            {"action": "save", "path": "kept.json"},
            {"action": "set", "element": 0, "key": "size", "value": 0.6},
            {"action": "choose", "preset": "anamorphic"},
            {"action": "answer", "choice": "discard"},
            {"action": "save", "path": "chosen.json"}])
    kept = json.loads((tmp_path / "kept.json").read_text())
    assert kept["name"] == "tanczos-classic" and kept["elements"][0]["size"] == 0.5
    chosen = (tmp_path / "chosen.json").read_text()
    assert chosen == canonical(studio, tmp_path, "anamorphic")


def test_element_list_edits(studio, tmp_path):
    studio([{"action": "duplicate", "element": 1},   # selects the copy (2)
            {"action": "move", "element": 0, "to": 3},
            {"action": "remove", "element": 5},
            {"action": "add", "type": "polygon"},     # after the selection: at 3
            {"action": "set", "element": 3, "key": "blades", "value": 7},
            {"action": "save", "path": "edited.json"}])
    expected = json.loads((SOURCE / "presets" / "tanczos-classic.json").read_text())["elements"]
    expected.insert(2, expected[1])
    expected.insert(3, expected.pop(0))
    del expected[5]
    expected.insert(3, {"type": "polygon", "blades": 7})
    shipped = json.loads((SOURCE / "presets" / "tanczos-classic.json").read_text())
    assert (tmp_path / "edited.json").read_text() == canonical(
        studio, tmp_path, dict(shipped, elements=expected))


def test_script_errors_are_one_line_and_stop_before_any_later_action(studio, tmp_path):
    done = studio([{"action": "set", "element": 0, "key": "size", "value": 9},
                   {"action": "save", "path": "never.json"}], ok=False)
    assert done.returncode == 2
    assert done.stderr.strip().splitlines()[-1].endswith(
        "actions[0]: size: expected a number in [0, 4], got 9")
    assert not (tmp_path / "never.json").exists()
    done = studio([{"action": "jump"}], ok=False)
    assert done.returncode == 2 and "unknown action \"jump\"" in done.stderr
    done = studio([{"action": "open", "path": "missing.png"}], ok=False)
    assert done.returncode == 2 and "missing.png" in done.stderr
    # A drag's frame count that is not a count: one line, not an uncaught exception.
    done = studio([{"action": "open", "path": str(SUNSET)},
                   {"action": "drag", "from": [1, 2], "to": [3, 4], "frames": "many"}], ok=False)
    assert done.returncode == 2
    assert done.stderr.strip().splitlines()[-1].endswith(
        'actions[1]: frames: expected an integer in [1, 100000], got "many"')


def test_the_docs_list_every_script_action(cli):
    done = subprocess.run([os.environ["FLAREKIT_CLI"], "studio", "--help-script"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "| `drag` | `from`, `to`, `frames` (optional) |" in done.stdout
    assert done.stdout in (SOURCE / "docs" / "studio.md").read_text(), \
        "docs/studio.md is out of date: scripts/update-docs.sh"


def test_the_browser_shows_every_preset_on_the_image(studio, tmp_path):
    studio([{"action": "open", "path": str(SUNSET)},
            {"action": "screenshot", "path": "components.png"},
            {"action": "panel", "name": "presets"},
            {"action": "screenshot", "path": "presets.png"}], "--size", "1600x900")
    components, presets = read(tmp_path / "components.png"), read(tmp_path / "presets.png")
    strip = (slice(720, 820), slice(430, 1600))  # the bottom strip right of the preset panel
    assert levels(components[strip], presets[strip]) > 50
    # Six shipped presets, each a small copy of the sunset: warm (red over blue) in the strip.
    shown = srgb8(presets[strip])
    assert shown[..., 0].mean() > shown[..., 2].mean() + 10


def test_post_process_presets_are_edited_saved_and_rendered_as_the_cli_does(studio, cli, tmp_path):
    studio([{"action": "open", "path": str(SUNSET_HDR)},
            {"action": "mode", "kind": "postfx"},
            {"action": "load", "preset": "killzone2"},
            {"action": "set", "section": "bloom", "key": "intensity", "value": 0.3},
            {"action": "set", "ghost": 0, "key": "tint", "value": [1.0, 0.3, 0.2]},
            {"action": "add_ghost"},
            {"action": "set", "ghost": 2, "key": "scale", "value": -0.75},
            {"action": "remove_ghost", "ghost": 1},
            {"action": "set", "key": "flare_intensity", "value": 2},
            {"action": "set", "section": "halo", "key": "intensity", "value": 0.2},
            {"action": "undo"},
            {"action": "save", "path": "post.json"},
            {"action": "export", "path": "post.png"},
            {"action": "export", "path": "post.exr"}])
    saved = json.loads((tmp_path / "post.json").read_text())
    assert saved["flare_intensity"] == 2 and saved["bloom"]["intensity"] == 0.3
    assert "halo" not in saved  # undone
    assert [g["scale"] for g in saved["ghosts"]] == [2.0, -0.75]
    assert saved["ghosts"][0]["tint"] == [1.0, 0.3, 0.2]
    cli("postfx", SUNSET_HDR, "-o", tmp_path / "cli.png", "--preset", tmp_path / "post.json")
    cli("postfx", SUNSET_HDR, "-o", tmp_path / "cli.exr", "--preset", tmp_path / "post.json")
    assert levels(read(tmp_path / "post.png"), read(tmp_path / "cli.png")) <= 1
    # The CLI's EXR is half, the studio's float: equal to half precision.
    np.testing.assert_allclose(read(tmp_path / "post.exr")[..., :3],
                               read(tmp_path / "cli.exr")[..., :3], rtol=1e-3, atol=1e-3)


def test_the_gl_backend_draws_the_view_and_exports_as_the_clis_backend_gl(studio, cli, tmp_path):
    image, _ = flarekit.read_image(str(SUNSET_HDR))
    small = np.ascontiguousarray(image[::4, ::4])  # 320x180: a lens render in seconds
    flarekit.write_image(str(tmp_path / "small.exr"), small, depth="float")
    done = studio([{"action": "open", "path": "small.exr"},
                   {"action": "view", "key": "backend", "value": "gl"},
                   {"action": "mode", "kind": "postfx"},
                   {"action": "load", "preset": "modern"},
                   {"action": "export", "path": "post.exr"},
                   {"action": "export", "path": "post.png"},
                   {"action": "mode", "kind": "lens"},
                   {"action": "load", "preset": "asahi-takumar-50"},
                   {"action": "light", "at": [232.5, 62.5]},
                   {"action": "set", "section": "render", "key": "ghosts", "value": 24},
                   {"action": "drag", "from": [200, 60], "to": [232.5, 62.5], "frames": 4},
                   {"action": "light", "at": [232.5, 62.5]},
                   {"action": "export", "path": "lens.exr"}])
    # Every view update of the post-process preset and the lens was drawn by GL: all but the
    # sprite preset's views before the mode changed (the image, then the setting).
    total = int(done.stderr.split(" previews (")[0].split()[-1])
    by_gl = int(done.stderr.split(" previews (")[1].split(" by gl")[0])
    assert by_gl >= 6 and total - by_gl == 2
    cli("postfx", tmp_path / "small.exr", "-o", tmp_path / "cli.exr", "--preset", "modern",
        "--backend", "gl")
    cli("postfx", tmp_path / "small.exr", "-o", tmp_path / "cli.png", "--preset", "modern",
        "--backend", "gl")
    np.testing.assert_allclose(read(tmp_path / "post.exr")[..., :3],
                               read(tmp_path / "cli.exr")[..., :3], rtol=1e-5, atol=1e-5)
    assert levels(read(tmp_path / "post.png"), read(tmp_path / "cli.png")) <= 1
    cli("lens", "render", "asahi-takumar-50", tmp_path / "small.exr", "--light", "232.5,62.5",
        "--ghosts", 24, "--backend", "gl", "-o", tmp_path / "cli-lens.exr")
    np.testing.assert_allclose(read(tmp_path / "lens.exr")[..., :3],
                               read(tmp_path / "cli-lens.exr")[..., :3], rtol=1e-5, atol=1e-5)


def test_an_invalid_post_process_edit_is_not_saved(studio, tmp_path):
    done = studio([{"action": "mode", "kind": "postfx"},
                   {"action": "set", "ghost": 0, "key": "scale", "value": 0.01},
                   {"action": "save", "path": "bad.json"}], ok=False)
    assert done.returncode == 2
    assert "not saved: ghosts[0].scale: expected |scale| >= 0.05" in done.stderr
    assert not (tmp_path / "bad.json").exists()


def test_a_lens_is_rendered_as_the_cli_does_and_its_ghosts_are_named(studio, cli, tmp_path):
    image, _ = flarekit.read_image(str(SUNSET_HDR))
    small = np.ascontiguousarray(image[::4, ::4])  # 320x180: a lens render in seconds
    flarekit.write_image(str(tmp_path / "small.exr"), small, depth="float")
    done = studio([{"action": "open", "path": "small.exr"},
                   {"action": "mode", "kind": "lens"},
                   {"action": "load", "preset": "asahi-takumar-50"},
                   {"action": "light", "at": [232.5, 62.5]},
                   {"action": "set", "section": "render", "key": "ghosts", "value": 24},
                   {"action": "set", "section": "render", "key": "ghost_gain", "value": 3},
                   {"action": "export", "path": "lens.png"},
                   {"action": "export", "path": "lens.exr"},
                   {"action": "set", "section": "aperture", "key": "blades", "value": 5},
                   {"action": "export", "path": "blades.exr"},
                   {"action": "pick", "at": [90, 130]},
                   {"action": "save", "path": "lens.json"}])
    common = [tmp_path / "small.exr", "--light", "232.5,62.5", "--ghosts", 24, "--ghost-gain", 3]
    cli("lens", "render", "asahi-takumar-50", *common, "-o", tmp_path / "cli.png")
    cli("lens", "render", "asahi-takumar-50", *common, "-o", tmp_path / "cli.exr")
    assert levels(read(tmp_path / "lens.png"), read(tmp_path / "cli.png")) <= 1
    np.testing.assert_allclose(read(tmp_path / "lens.exr")[..., :3],
                               read(tmp_path / "cli.exr")[..., :3], rtol=1e-3, atol=1e-3)
    # Five blades instead of the lens's own iris: another starburst.
    assert np.abs(read(tmp_path / "blades.exr") - read(tmp_path / "lens.exr")).max() > 1e-3
    # The saved lens is a file the CLI reads: its iris has the five blades, and it renders as the
    # studio showed it.
    saved = json.loads((tmp_path / "lens.json").read_text())
    assert saved["aperture"]["blades"] == 5 and saved["name"] == "asahi-takumar-50"
    cli("lens", "render", tmp_path / "lens.json", *common, "-o", tmp_path / "cli-blades.exr")
    np.testing.assert_allclose(read(tmp_path / "blades.exr")[..., :3],
                               read(tmp_path / "cli-blades.exr")[..., :3], rtol=1e-3, atol=1e-3)
    picked = [line for line in done.stdout.splitlines() if line.startswith("picked ghost")]
    assert len(picked) == 1, done.stdout
    words = picked[0].split()
    first, second = int(words[4]), int(words[6])
    assert first > second >= 0


def test_a_lens_is_edited_per_surface_and_per_ghost_and_saved_for_the_cli(studio, cli, tmp_path):
    image, _ = flarekit.read_image(str(SUNSET_HDR))
    flarekit.write_image(str(tmp_path / "small.exr"), np.ascontiguousarray(image[::4, ::4]),
                         depth="float")
    start = [{"action": "open", "path": "small.exr"},
             {"action": "mode", "kind": "lens"},
             {"action": "load", "preset": "asahi-takumar-50"},
             {"action": "light", "at": [232.5, 62.5]},
             {"action": "set", "section": "render", "key": "ghosts", "value": 24},
             {"action": "set", "section": "render", "key": "starburst", "value": 0},
             {"action": "set", "section": "render", "key": "glare", "value": 0}]
    done = studio(start + [{"action": "pick", "at": [90, 130]}])
    words = [l for l in done.stdout.splitlines() if l.startswith("picked ghost")][0].split()
    pair = [int(words[4]), int(words[6])]
    studio(start + [
        {"action": "export", "path": "plain.exr"},
        # The picked ghost 4x brighter in red, 2x in green, blue as traced.
        {"action": "set", "section": "ghost_pair", "pair": pair, "key": "gain", "value": 4},
        {"action": "set", "section": "ghost_pair", "pair": pair, "key": "tint",
         "value": [1, 0.5, 0.25]},
        {"action": "export", "path": "looked.exr"},
        {"action": "set", "section": "surface", "surface": 0, "key": "radius", "value": 100},
        {"action": "set", "section": "coating", "key": "design", "value": "broadband",
         "design_nm": 500},
        {"action": "export", "path": "edited.exr"},
        {"action": "save", "path": "edited.json"}])
    plain, looked = read(tmp_path / "plain.exr")[..., :3], read(tmp_path / "looked.exr")[..., :3]
    gained = (looked - plain).reshape(-1, 3).sum(axis=0)
    assert gained[0] > 0 and gained[1] > 0
    # Red gains 3x the ghost, green 1x: their ratio is 3 x the ghost's own red/green.
    assert abs(gained[2]) <= 1e-4 * gained[0]
    saved = json.loads((tmp_path / "edited.json").read_text())
    assert saved["surfaces"][0]["radius"] == 100
    assert saved["ghost_pairs"] == [{"surfaces": pair, "gain": 4.0, "tint": [1.0, 0.5, 0.25]}]
    cli("lens", "render", tmp_path / "edited.json", tmp_path / "small.exr", "--light",
        "232.5,62.5", "--ghosts", 24, "--starburst", 0, "--glare", 0, "-o", tmp_path / "cli.exr")
    np.testing.assert_allclose(read(tmp_path / "edited.exr")[..., :3],
                               read(tmp_path / "cli.exr")[..., :3], rtol=1e-3, atol=1e-3)
    # A surface edit the lens file would refuse is not made (one line naming it, exit 2).
    done = studio(start + [{"action": "set", "section": "surface", "surface": 3,
                            "key": "thickness", "value": -30},
                           {"action": "save", "path": "never.json"}], ok=False)
    assert done.returncode == 2 and "surfaces[3].thickness" in done.stderr
    assert not (tmp_path / "never.json").exists()


def test_an_image_sequence_is_scrubbed_frame_by_frame_as_the_cli_renders_each(studio, cli,
                                                                             tmp_path):
    # Four frames of the HDR sunset, the sun 40 px further right in each.
    image, _ = flarekit.read_image(str(SUNSET_HDR))
    small = np.ascontiguousarray(image[::2, ::2])
    for k in range(4):
        flarekit.write_image(str(tmp_path / f"sh.{1001 + k:04d}.exr"),
                             np.ascontiguousarray(np.roll(small, 40 * k, axis=1)), depth="float")

    def light_of(done):
        return [float(v) for v in done.stderr.split("light at ")[1].split()[0].split(",")]

    first = light_of(studio([{"action": "open", "path": "sh.####.exr"}], "--stats"))
    done = studio([{"action": "open", "path": "sh.####.exr"},
                   {"action": "load", "preset": "sun-wide"},
                   {"action": "frame", "frame": 1003},
                   {"action": "export", "path": "f3.exr"}], "--stats")
    third = light_of(done)
    # The light followed the sun to the frame shown.
    assert abs(third[0] - first[0] - 80) <= 1 and abs(third[1] - first[1]) <= 1
    cli("apply", tmp_path / "sh.1003.exr", "-o", tmp_path / "cli3.exr", "--preset", "sun-wide",
        "--light", f"{third[0]},{third[1]}", "--flux-mode", "fixed", "--depth", "float")
    np.testing.assert_allclose(read(tmp_path / "f3.exr")[..., :3],
                               read(tmp_path / "cli3.exr")[..., :3], rtol=1e-3, atol=1e-4)
    # A light placed by hand stays where it was put on every frame.
    done = studio([{"action": "open", "path": "sh.%04d.exr"},
                   {"action": "load", "preset": "sun-wide"},
                   {"action": "light", "at": [300, 90]},
                   {"action": "frame", "frame": 1004},
                   {"action": "export", "path": "f4.exr"}], "--stats")
    assert light_of(done) == [300.0, 90.0]
    cli("apply", tmp_path / "sh.1004.exr", "-o", tmp_path / "cli4.exr", "--preset", "sun-wide",
        "--light", "300,90", "--flux-mode", "fixed", "--depth", "float")
    np.testing.assert_allclose(read(tmp_path / "f4.exr")[..., :3],
                               read(tmp_path / "cli4.exr")[..., :3], rtol=1e-3, atol=1e-4)
    # A frame that is not on disk: one line, exit 2.
    done = studio([{"action": "open", "path": "sh.####.exr"},
                   {"action": "frame", "frame": 1009}], ok=False)
    assert done.returncode == 2 and "frame 1009: not on disk (the sequence has 1001-1004)" in \
        done.stderr


@pytest.mark.parametrize("method", ["raycast", "texture-mask"])
def test_the_demo_drive_plays_with_its_coverage_as_the_cli_logs_it(studio, cli, tmp_path, method):
    done = studio([{"action": "drive", "method": method, "frames": 12},
                   {"action": "frame", "frame": 6},
                   {"action": "export", "path": "f6.png"},
                   {"action": "coverage", "path": "coverage.csv"},
                   {"action": "screenshot", "path": "drive.png"},
                   {"action": "frame", "frame": 13}], ok=False)
    # Past the drive's last frame: one line, exit 2, after everything before it was done.
    assert done.returncode == 2 and "frame: expected a frame of the drive in [1, 12]" in done.stderr
    cli("demo", "-o", tmp_path / "demo", "--frames", 12, "--size", "480x270", "--method", method,
        "--no-video")

    def columns(path):
        lines = path.read_text().splitlines()
        return [line.split(",")[:5] for line in lines]

    logged = columns(tmp_path / "demo" / "coverage.csv")
    assert logged[0] == ["frame", "time_s", "coverage_raw", "coverage_smoothed", "in_frame"]
    assert columns(tmp_path / "coverage.csv") == logged  # every frame, to the log's digits
    assert levels(read(tmp_path / "f6.png"), read(tmp_path / "demo" / "frame_0006.png")) == 0
    assert (tmp_path / "drive.png").exists()


def test_the_drives_diagnostic_views_are_the_methods_own_and_the_psp_emulators(studio, cli,
                                                                              tmp_path):
    # Frame 2 of the drive: the sun a third behind the trees (coverage about 0.36).
    studio([{"action": "drive", "method": "texture-mask", "frames": 6},
            {"action": "frame", "frame": 2},
            {"action": "diagnostics", "dir": "tm"},
            {"action": "coverage", "path": "tm.csv"},
            {"action": "drive", "method": "burnout", "frames": 6},
            {"action": "frame", "frame": 2},
            {"action": "diagnostics", "dir": "bo"},
            {"action": "coverage", "path": "bo.csv"}])

    def raw_coverage(csv):
        return float((tmp_path / csv).read_text().splitlines()[2].split(",")[2])

    def codes(path):
        return srgb8(read(tmp_path / path))

    # GPG2: the intensity map is the sum the coverage is resolved from (visible / disc), and
    # the sun map is what was summed (the 255 points of the circle variant: within a point).
    intensity = codes("tm/method-intensity-map-1x1.png")[0, 0]
    assert abs(intensity[0] / intensity[1] - raw_coverage("tm.csv")) < 1e-5
    sun_map = codes("tm/method-sun-map-18x18.png") / 255
    in_disc = sun_map[..., 1] > 0
    assert 240 <= in_disc.sum() <= 260
    assert abs(sun_map[..., 0][in_disc].mean() - raw_coverage("tm.csv")) < 2 / 255
    assert 0.2 < raw_coverage("tm.csv") < 0.6
    # Burnout: the chain's last level is the coverage (8-bit pictures: within two levels).
    last = codes("bo/method-chain-1x1.png")[0, 0]
    assert abs(last[0] / last[1] - raw_coverage("bo.csv")) < 2 / 255
    assert codes("bo/method-grid-14x14.png").shape == (14, 14, 3)
    # The PSP panel is `flarekit psp burnout` on the same moment, step for step.
    info = {key: value for key, _, value in
            (line.partition(" ") for line in (tmp_path / "bo" / "psp.txt").read_text().splitlines())}
    cli("psp", "burnout", "--occluders", tmp_path / "bo" / "psp-occluders.png", "--sun",
        info["sun"].replace(" ", ","), "-o", tmp_path / "psp.png", "--dump", tmp_path / "steps")
    steps = sorted(p.name for p in (tmp_path / "steps").iterdir())
    assert "09-clut-after.png" in steps and "02-mask.png" in steps
    for name in steps:
        assert np.array_equal(codes(f"steps/{name}"), codes(f"bo/psp-{name}")), name
    assert int(info["coverage_byte"]) > 0 and info["visible"].endswith("of 196")


def test_a_scenes_sun_follows_the_pointer_and_renders_as_the_cli_does(studio, cli, tmp_path):
    scene = SOURCE / "samples" / "scenes" / "sun-behind-trees.json"
    done = studio([{"action": "scene", "path": str(scene)},
                   {"action": "light", "at": [300, 150]},
                   {"action": "export", "path": "moved.png"},
                   {"action": "export", "path": "moved.exr"}])
    line = [l for l in done.stdout.splitlines() if l.startswith("scene: sun direction")][-1]
    words = line.split()
    direction = [float(v) for v in words[3].split(",")]
    # The sun lands under the pointer.
    assert [float(v) for v in words[5].rstrip(",").split(",")] == [300.0, 150.0]
    moved = json.loads(scene.read_text())
    moved["sun"]["direction"] = direction
    (tmp_path / "moved.json").write_text(json.dumps(moved))
    cli("render", tmp_path / "moved.json", "-o", tmp_path / "cli.png")
    cli("render", tmp_path / "moved.json", "-o", tmp_path / "cli.exr")
    assert levels(read(tmp_path / "moved.png"), read(tmp_path / "cli.png")) <= 1
    np.testing.assert_allclose(read(tmp_path / "moved.exr")[..., :3],
                               read(tmp_path / "cli.exr")[..., :3], rtol=1e-3, atol=1e-4)
    # A scene file that does not parse: one line naming it, exit 2.
    (tmp_path / "bad.json").write_text('{"camera": 1}')
    done = studio([{"action": "scene", "path": "bad.json"}], ok=False)
    assert done.returncode == 2 and "bad.json" in done.stderr
