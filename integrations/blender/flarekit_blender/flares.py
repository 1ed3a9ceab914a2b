# SPDX-License-Identifier: Apache-2.0
"""The flare of a rendered frame through flarekit's jobs: each light's sprite flare at its
projected position (scaled by the light it sends into the lens, its colour and its coverage),
the post-process chain on the whole render, or a lens prescription matched to the camera."""
import functools
import json
import math
import os
import tempfile

import numpy as np

import flarekit

#: The irradiance (W/m^2 at the lens) at which a light draws its preset's own look: a sun of
#: strength 3, Blender's usual daylight, gives intensity 1.
REFERENCE_IRRADIANCE = 3.0
#: flarekit's intensity range (its parameter table's maximum).
MAX_INTENSITY = 1000.0


def light_intensity(light, coverage, gain):
    """The flarekit intensity of a light's sprite flare."""
    value = gain * light.irradiance / REFERENCE_IRRADIANCE * coverage
    return float(min(max(value, 0.0), MAX_INTENSITY))


def camera_hfov(scene, camera, focal_px):
    """The render's horizontal angle of view, degrees."""
    width = scene.render.resolution_x * scene.render.resolution_percentage / 100.0
    return math.degrees(2.0 * math.atan(width / (2.0 * focal_px)))


@functools.lru_cache(maxsize=1)
def _shipped_lens_infos():
    """Every shipped lens's paraxial data, traced once (they do not change while Blender runs)."""
    return tuple(flarekit.lens_info(name) for name in flarekit.lenses())


def nearest_lens(hfov):
    """The shipped lens whose sensor and focal length make the angle of view nearest hfov."""
    return min(_shipped_lens_infos(), key=lambda i: abs(i["horizontal_fov_deg"] - hfov))["name"]


def lens_with_blades(name, blades, folder):
    """The lens as a JSON file with the camera's blade count (Blender's 0: a round iris)."""
    count = int(blades) if blades >= 3 else 0
    path = os.path.join(folder, f"{name}-{count}-blades.json")
    if os.path.exists(path):  # written for an earlier frame of this render
        return path
    data = flarekit.load_preset(name, kind="lens")
    data["aperture"] = dict(data.get("aperture", {}), blades=count)
    with open(path, "w") as out:
        json.dump(data, out)
    return path


#: The energy (pixels x linear white) a light at REFERENCE_IRRADIANCE is drawn with for the
#: lens: what the lens job gives a light it finds no pixels of (a 100-pixel source at 100 x
#: white), so a lamp that sends 3 W/m^2 into the lens flares like an unmeasured light there.
LENS_REFERENCE_ENERGY = 1.0e4


def with_lights_shown(image, lights, weights):
    """The render with each lamp the camera cannot see (Cycles and Eevee render no lamp
    itself) drawn as its disc holding the energy its irradiance at the lens gives, so that the
    lens job, which measures a light's energy from the pixels around it, finds it."""
    shown = image.copy()
    height, width = image.shape[:2]
    ys, xs = np.mgrid[0:height, 0:width].astype(np.float32) + 0.5
    for light, coverage in zip(lights, weights):
        if light.kind == 'EMISSIVE' or coverage <= 0.0 or not light.in_front:
            continue
        x, y = light.position
        r = max(light.radius_px, 1.0)
        disc = (xs - x) ** 2 + (ys - y) ** 2 <= r * r
        if not disc.any():
            continue
        energy = LENS_REFERENCE_ENERGY * light.irradiance / REFERENCE_IRRADIANCE * coverage
        value = energy / float(disc.sum()) * np.asarray(light.color, np.float32)
        shown[disc, :3] = np.maximum(shown[disc, :3], value)
    return shown


def draw(settings, image, lights, weights, lens=None, f_number=0.0):
    """The flare alone (H x W x 3 linear float32) on `image` (H x W x 4 linear, the render).
    `weights`: each light's coverage (0-1, filtered over time)."""
    height, width = image.shape[:2]
    flare = np.zeros((height, width, 3), np.float32)
    if settings.mode == 'POSTFX':
        out = flarekit.postfx(image, settings.postfx_preset)
        return np.maximum(out[..., :3] - image[..., :3], 0.0).astype(np.float32)
    for light, coverage in zip(lights, weights):
        if coverage <= 0.0 or not light.in_front:
            continue
        color = np.asarray(light.color, np.float32)
        if settings.mode == 'SPRITE':
            intensity = light_intensity(light, coverage, settings.gain)
            if intensity <= 0.0:
                continue
            one = flarekit.apply(image, settings.preset, light=light.position, flare_only=True,
                                 flux_mode="fixed", intensity=intensity)
            flare += one[..., :3] * color
        else:
            # The lens measures the light's energy from the pixels around it: the render with
            # the lamps drawn in (they are invisible to the camera), one light at a time.
            shown = with_lights_shown(image, [light], [coverage])
            out = flarekit.lens_render(shown, lens, light=light.position, f_number=f_number)
            flare += np.maximum(out[..., :3] - shown[..., :3], 0.0) * settings.gain
    return flare


def temp_folder():
    return tempfile.mkdtemp(prefix="flarekit-blender-")
