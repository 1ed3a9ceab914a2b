# SPDX-License-Identifier: Apache-2.0
"""The GIL is released while the library works: another Python thread runs during a call, and
two threads calling the library use both cores. Timing-sensitive, so ctest runs this file
alone (PythonThreads, RUN_SERIAL)."""
import os
import threading
import time

import numpy as np

import flarekit


def test_gil_released_while_the_library_works(tmp_path):
    image = np.full((512, 512, 3), 0.2, np.float32)
    image[200:205, 300:305] = 1000
    done = threading.Event()

    def work():
        for _ in range(3):
            flarekit.postfx(image, "killzone2")
        done.set()

    worker = threading.Thread(target=work)
    counted = 0
    worker.start()
    while not done.is_set():
        counted += 1
    worker.join()
    # With the GIL held for each call this thread would only run between calls: a few
    # switch intervals (5 ms), some thousands of iterations at most.
    assert counted > 200_000


def test_two_threads_use_both_cores():
    image = np.full((256, 256, 3), 0.2, np.float32)
    image[100:104, 100:104] = 1000
    calls = 6

    def work():
        for _ in range(calls):
            flarekit.lens_ghosts("angenieux-double-gauss", angle=(4, 1), rays=48, ghost_rays=0)

    start_wall, start_cpu = time.perf_counter(), time.process_time()
    threads = [threading.Thread(target=work) for _ in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    wall, cpu = time.perf_counter() - start_wall, time.process_time() - start_cpu
    if (os.cpu_count() or 1) >= 2:
        assert cpu / wall > 1.5, f"{cpu:.2f} s CPU in {wall:.2f} s"
