#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes presets/lenses/canon-zoom-70-210{,-tele}.json from US 4,380,377 (Canon, 1983), Example 1.

The patent prints radii, thicknesses, n_d and v_d and the three variable gaps, but neither the
clear apertures, the stop's place nor the back focus, so this script derives them (run it from
the repository root; it only writes the two files):
- the back focus is the paraxial one of each zoom position (focus at infinity);
- the stop sits in the gap before group IV, 1 mm ahead of its first surface, so it does not move
  while the groups in front zoom (where a constant-aperture zoom of this type keeps it);
- the stop's radius gives the patent's F/4 at each position (the paraxial marginal ray);
- every other clear radius passes the whole axial F/4 beam and the chief ray of the full 36x24 mm
  field (at most 50% vignetting in the corners, as photographic lenses are designed): the larger
  paraxial height of the two, the largest over the wide, middle and tele positions (a real barrel
  is the same at every position), rounded up to 0.1 mm. The front element comes out 51.4 mm
  across, as the product's 52 mm filter thread implies; the unvignetted |marginal| + |chief|
  would make its second surface cross the third. Where two neighbouring surfaces would come
  closer than EDGE_MM at that height (the air space inside group II, at tele), both are cut back
  to the height where they do: the real barrel's spacer sits there.
"""
import json
import math

# Canon's Super Spectra Coating was multi-layer, its colour varying surface by surface: broadband
# quarter-half-quarter stacks at 530, 500 and 550 nm and single MgF2 layers at 470 nm, in turn
# over the glass-air surfaces (the same cycle as the other multi-coated lenses, from its third).
COATINGS = [{"design": "broadband", "design_nm": 530}, {"design": "mgf2", "design_nm": 470},
            {"design": "broadband", "design_nm": 500}, {"design": "broadband", "design_nm": 550}]
COATING_START = 2

# Example 1: radius, thickness to the next surface, n_d and v_d of the medium after it (None =
# air). "d5", "d10" and "d13" are the variable gaps.
TABLE = [
    (144.296, 2.8, 1.80518, 25.4), (67.895, 6.6, 1.61272, 58.7), (-4571.825, 0.2, None, None),
    (94.482, 4.7, 1.61272, 58.7), (26667.449, "d5", None, None),
    (464.312, 1.5, 1.713, 53.9), (40.285, 4.2, None, None), (-45.202, 1.5, 1.713, 53.9),
    (44.784, 3.4, 1.84666, 23.0), (-3270.421, "d10", None, None),
    (108.4, 5.8, 1.51633, 64.1), (-32.441, 1.5, 1.7552, 27.5), (-56.830, "d13", None, None),
    (36.187, 4.5, 1.61272, 58.7), (797.679, 1.95, None, None), (-213.357, 2.0, 1.80518, 25.4),
    (570.712, 47.33, None, None), (-19.993, 2.0, 1.8061, 40.9), (-42.359, 0.3, None, None),
    (172.917, 3.5, 1.59551, 39.2), (-61.717, "bf", None, None),
]
POSITIONS = {  # the patent's stated focal length and variable gaps per position
    "wide": (70.55, {"d5": 0.50, "d10": 34.12, "d13": 18.62}),
    "middle": (137.04, {"d5": 32.54, "d10": 17.63, "d13": 3.07}),
    "tele": (205.31, {"d5": 43.86, "d10": 0.68, "d13": 8.70}),
}
F_NUMBER = 4.0
STOP_BEFORE_GROUP_IV = 1.0  # mm
HALF_DIAGONAL = math.hypot(36.0, 24.0) / 2.0
EDGE_MM = 0.2  # the thinnest edge or air space at the rim a lens shop would make
STOP_AFTER = 12  # the stop goes into the gap after surface 12 (the patent's r13)


def surfaces(gaps):
    """The prescription with the stop inserted: (radius, thickness, n_after, v_d, is_stop)."""
    out = []
    for i, (r, t, n, v) in enumerate(TABLE):
        t = gaps.get(t, t)
        if i == STOP_AFTER:
            out.append((r, t - STOP_BEFORE_GROUP_IV, n, v, False))
            out.append((0.0, STOP_BEFORE_GROUP_IV, None, None, True))
        else:
            out.append((r, t, n, v, False))
    return out


def trace(surfs, y, u):
    """Paraxial y-u trace; heights at each surface and the final (y, u) after the last."""
    heights, n = [], 1.0
    for r, t, n_after, _, _ in surfs:
        heights.append(y)
        n2 = n_after or 1.0
        c = 0.0 if r == 0 else 1.0 / r
        u = (n * u - y * c * (n2 - n)) / n2
        n = n2
        if t != "bf":
            y = y + t * u
    return heights, y, u


def position(name):
    f_stated, gaps = POSITIONS[name]
    surfs = surfaces(gaps)
    _, y1, u1 = trace(surfs, 1.0, 0.0)
    f = -1.0 / u1
    bf = -y1 / u1
    stop = next(i for i, s in enumerate(surfs) if s[4])
    a, _, _ = trace(surfs, 1.0, 0.0)
    b, _, _ = trace(surfs, 0.0, 1.0)
    marginal = [h * f / (2.0 * F_NUMBER) for h in a]
    tan_field = HALF_DIAGONAL / f
    y0 = -tan_field * b[stop] / a[stop]
    chief = [y0 * ha + tan_field * hb for ha, hb in zip(a, b)]
    return surfs, f, f_stated, bf, stop, marginal, chief


def sag(r, h):
    return 0.0 if r == 0 else r - math.copysign(math.sqrt(r * r - h * h), r)


def edge_limit(surfs, i):
    """The largest height at which surface i and the next stay EDGE_MM apart."""
    (r1, t, _, _, _), (r2, _, _, _, _) = surfs[i], surfs[i + 1]
    lo, hi = 0.0, 0.999 * min(abs(r) for r in (r1, r2, 1e9) if r != 0)
    if t - sag(r1, hi) + sag(r2, hi) >= EDGE_MM:
        return hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if t - sag(r1, mid) + sag(r2, mid) >= EDGE_MM else (lo, mid)
    return lo


def main():
    data = {p: position(p) for p in POSITIONS}
    count = len(data["wide"][0])
    clear = [max(max(abs(data[p][5][i]), abs(data[p][6][i])) for p in POSITIONS) for i in range(count)]
    clear = [math.ceil(c * 10.0) / 10.0 for c in clear]
    for p in POSITIONS:  # the tightest gap over the positions (only fixed gaps are that tight)
        surfs = data[p][0]
        for i in range(count - 1):
            if surfs[i][4] or surfs[i + 1][4]:
                continue
            limit = math.floor(edge_limit(surfs, i) * 10.0) / 10.0
            clear[i], clear[i + 1] = min(clear[i], limit), min(clear[i + 1], limit)
    for p, suffix in (("wide", ""), ("tele", "-tele")):
        surfs, f, f_stated, bf, stop, marginal, _ = data[p]
        track = sum(s[1] for s in surfs[:-1]) + bf
        print(f"{p}: f {f:.3f} (stated {f_stated}), back focus {bf:.3f}, track {track:.2f}, "
              f"track/f {track / f:.3f}, stop radius {abs(marginal[stop]):.3f}")
        rows = []
        coated = 0
        for i, (r, t, n, v, is_stop) in enumerate(surfs):
            t = round(bf, 3) if t == "bf" else round(t, 3)
            if is_stop:
                rows.append({"stop": True, "thickness": t,
                             "semi_aperture": round(abs(marginal[stop]), 3)})
                continue
            row = {"radius": r, "thickness": t}
            if n:
                row.update({"n_d": n, "v_d": v})
            row["semi_aperture"] = clear[i]
            before = surfs[i - 1][2] if i else None
            if not (n and before):  # a glass-air surface carries the coating, a cemented one not
                row["coating"] = COATINGS[(coated + COATING_START) % len(COATINGS)]
                coated += 1
            rows.append(row)
        lens = {
            "name": "canon-zoom-70-210" + suffix,
            "source": f"US 4,380,377 (Canon, 1983), Example 1, the {p} position (f = {f_stated}); "
                      "the New FD 70-210 mm F/4 design. The patent does not print the clear "
                      "apertures, the stop's place or the back focus: they are derived by "
                      "scripts/lens-canon-zoom-70-210.py (the axial F/4 beam and the full 36x24 field's chief ray pass; "
                      "the stop 1 mm before group IV; paraxial back focus)",
            "f_number": F_NUMBER,
            "patent_focal_length_mm": f_stated,
            "coating": COATINGS[0],
            "surfaces": rows,
            "aperture": {"blades": 8, "rotation_deg": 0, "roundness": 0.0},
            "sensor": {"width": 36, "height": 24},
        }
        with open(f"presets/lenses/canon-zoom-70-210{suffix}.json", "w") as out:
            out.write("{\n")
            items = list(lens.items())
            for k, (key, value) in enumerate(items):
                comma = "," if k + 1 < len(items) else ""
                if key == "surfaces":
                    out.write(' "surfaces": [\n')
                    out.write(",\n".join("  " + json.dumps(s) for s in value))
                    out.write(f"]{comma}\n")
                else:
                    out.write(f" {json.dumps(key)}: {json.dumps(value)}{comma}\n")
            out.write("}\n")


if __name__ == "__main__":
    main()
