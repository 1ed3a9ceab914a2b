# SPDX-License-Identifier: Apache-2.0
"""A sample set generated on a Dask cluster: one task per shard, each writing its samples
atomically into a folder every worker sees (a shared file system), with ``resume`` so a shard
re-run after a lost worker skips what was finished and the result is identical to one
process's."""
import flarekit.synth as synth

__all__ = ["generate"]


def _shard(out, count, seed, size, config, format, index, shards, depth):
    # Imported on the worker: the task carries only plain values.
    import flarekit.synth as worker_synth

    return worker_synth.generate(out, count, seed, size=size, config=config, format=format,
                                 shard=(index, shards), depth=depth, resume=True)


def generate(client, count, out, seed, size=(512, 512), config=None, format="exr", shards=None,
             depth=8):
    """Spreads ``count`` samples of ``seed`` over ``client``'s workers in ``shards`` shards
    (default: 4 per worker thread, at most one per sample) and waits. Returns the samples
    written, and ``complete`` once labels.jsonl is written."""
    if shards is None:
        threads = sum(client.nthreads().values()) or 1
        shards = max(1, min(count, 4 * threads))
    futures = [
        client.submit(_shard, str(out), count, seed, tuple(size), config, format, i, shards,
                      depth, key=f"flarekit-synth-{seed}-{i}-of-{shards}", pure=False)
        for i in range(shards)
    ]
    results = client.gather(futures)
    written = sum(r["written"] for r in results)
    # Every shard done: one last pass skips every sample and writes labels.jsonl.
    final = client.submit(_shard, str(out), count, seed, tuple(size), config, format, 0, 1,
                          depth, pure=False).result()
    return {"written": written, "shards": shards, "complete": final["complete"]}



