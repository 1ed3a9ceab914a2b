# SPDX-License-Identifier: Apache-2.0
"""The seeded flare-data generator (the library's, as `flarekit synth` runs it).

``sample(index, seed, width, height, config)`` makes one sample in memory: a dict of float32
``H x W x 3`` linear, unclamped layers (``background``, ``light_source``, ``flare``, the flare's
components, ``gt``, ``composite``) and ``"label"``, equal to the sample's line of
``labels.jsonl``. Sample ``index`` of ``seed`` is the same whatever else is made, in any order,
on any machine. ``generate`` writes a shard of a set to a folder, as the CLI does.
"""
from .. import _flarekit

__all__ = ["sample", "generate"]


def sample(index, seed, width, height, config=None):
    """Sample ``index`` of ``seed`` at ``width`` x ``height`` (config: synth.json's keys)."""
    return _flarekit._synth_sample(index, seed, width, height, config)


def generate(out, count, seed, size=(512, 512), config=None, format="exr", shard=(0, 1),
             depth=8, resume=False):
    """``flarekit synth``: shard ``shard = (I, K)`` of a set of ``count`` samples into ``out``
    (layout ``format``: flare7kpp, pairs or exr). Each sample's files are written atomically and
    its label last; with ``resume`` the complete ones are skipped. Returns written, skipped and
    complete (every sample of the set is there and labels.jsonl is written)."""
    width, height = size
    index, shards = shard
    return _flarekit._synth_run(count, str(out), seed, width, height, config, format, index,
                                shards, depth, resume)
