#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The Python module's cost over the C++ call: flarekit.postfx on a 64x64 array (the same
input as bench_synth's BM_PostFxPixels64, which times the library's call alone), and
flarekit.synth.sample at 512x512 per flare kind.

    PYTHONPATH=build/python bench/python/call_overhead.py
"""
import time

import numpy as np

import flarekit
import flarekit.synth as synth


def best_of(call, repeats=5, number=200):
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        for _ in range(number):
            call()
        best = min(best, (time.perf_counter() - start) / number)
    return best


image = np.full((64, 64, 3), 0.2, np.float32)
image[30, 20] = 500
print(f"flarekit.postfx 64x64: {best_of(lambda: flarekit.postfx(image)) * 1e6:.1f} us per call")
for kind, config in [("sprite", {"postfx": 0, "lens": 0}), ("postfx", {"sprite": 0, "lens": 0})]:
    config.update(lights_min=1, lights_max=1)
    index = iter(range(10 ** 9))
    rate = 1 / best_of(lambda: synth.sample(next(index), 1, 512, 512, config), 3, 10)
    print(f"flarekit.synth.sample 512x512, {kind}, 1 light: {rate:.1f} samples/s")
