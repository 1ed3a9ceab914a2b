# SPDX-License-Identifier: Apache-2.0
"""flarekit.synth.dask.generate on a real cluster: a scheduler and two workers, each its own
process on 127.0.0.1, make a set identical to a one-process run; a worker killed in the middle
of a second run loses nothing."""
import filecmp
import os
import signal
import socket
import subprocess
import sys
import threading
import time

import pytest

distributed = pytest.importorskip("distributed", reason="python3-distributed")

import flarekit.synth as synth  # noqa: E402
import flarekit.synth.dask as synth_dask  # noqa: E402

ARGS = dict(count=200, seed=17, size=(64, 48))


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def files(root):
    return sorted(os.path.relpath(os.path.join(d, f), root)
                  for d, _, fs in os.walk(root) for f in fs)


def same_set(a, b):
    names = files(a)
    assert names == files(b)
    _, mismatch, errors = filecmp.cmpfiles(a, b, names, shallow=False)
    assert not mismatch and not errors


@pytest.fixture()
def cluster(tmp_path):
    port = free_port()
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path), DASK_DISTRIBUTED__WORKER__DAEMON="False")
    address = f"tcp://127.0.0.1:{port}"
    logs = open(tmp_path / "cluster.log", "w")
    scheduler = subprocess.Popen(
        [sys.executable, "-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1", "--port",
         str(port), "--dashboard-address", ":0", "--no-show"], stdout=logs, stderr=logs, env=env)
    workers = [
        subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_worker", address,
                          "--nthreads", "1", "--host", "127.0.0.1", "--dashboard-address", ":0",
                          "--name", f"w{i}", "--local-directory", str(tmp_path / f"w{i}")],
                         stdout=logs, stderr=logs, env=env)
        for i in range(2)]
    client = distributed.Client(address, timeout=60)
    client.wait_for_workers(2, timeout=60)
    yield client, workers
    client.close()
    for process in workers + [scheduler]:
        if process.poll() is None:
            process.terminate()
    for process in workers + [scheduler]:
        try:
            process.wait(timeout=20)
        except subprocess.TimeoutExpired:
            process.kill()
    logs.close()


def test_cluster_set_equals_one_process_and_survives_a_lost_worker(cluster, tmp_path):
    client, workers = cluster
    local = tmp_path / "local"
    synth.generate(local, ARGS["count"], ARGS["seed"], size=ARGS["size"])
    assert (local / "labels.jsonl").exists()

    done = synth_dask.generate(client, ARGS["count"], tmp_path / "cluster", ARGS["seed"],
                               size=ARGS["size"], shards=8)
    assert done["complete"] and done["written"] == ARGS["count"]
    assert len(client.nthreads()) == 2
    same_set(local, tmp_path / "cluster")

    # A second run; one worker is killed once a few samples are written.
    out = tmp_path / "again"
    result = {}

    def run():
        result["done"] = synth_dask.generate(client, ARGS["count"], out, ARGS["seed"],
                                             size=ARGS["size"], shards=8)

    runner = threading.Thread(target=run)
    runner.start()
    labels = out / "labels"
    deadline = time.time() + 120
    while time.time() < deadline and (not labels.exists() or len(os.listdir(labels)) < 20):
        time.sleep(0.01)
    workers[0].send_signal(signal.SIGKILL)
    runner.join(timeout=300)
    assert not runner.is_alive()
    assert workers[0].wait(timeout=10) == -signal.SIGKILL
    assert result["done"]["complete"]
    same_set(local, out)


def test_the_example_script_runs_on_the_cluster(cluster, tmp_path):
    client, _ = cluster
    script = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "dask",
                          "synth_cluster.py")
    done = subprocess.run(
        [sys.executable, script, "--scheduler", client.scheduler.address, "--count", "12",
         "--size", "32x32", "--seed", "4", "--out", str(tmp_path / "ex"), "--format", "pairs"],
        capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))
    assert done.returncode == 0, done.stderr
    assert "complete: True" in done.stdout
    assert len(os.listdir(tmp_path / "ex" / "input")) == 12
