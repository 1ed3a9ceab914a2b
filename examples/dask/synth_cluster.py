#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""A flare-data set generated on a Dask cluster (flarekit.synth.dask): one task per shard, each
writing its samples atomically into OUT, which every worker must see (a shared file system).
A worker lost mid-run has its shard re-run by Dask; the samples it finished are skipped.

    dask-scheduler --host 10.0.0.1 &            # on the scheduler
    dask-worker tcp://10.0.0.1:8786 &           # on each worker machine
    ./synth_cluster.py --scheduler tcp://10.0.0.1:8786 --count 2400000 --size 512x512 \\
        --seed 1 --out /shared/flares --format flare7kpp
"""
import argparse
import json
import sys
import time

import distributed

import flarekit.synth.dask as synth_dask


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scheduler", required=True, help="the scheduler's address")
    parser.add_argument("--count", type=int, required=True)
    parser.add_argument("--size", default="512x512", help="WxH")
    parser.add_argument("--seed", type=int, required=True)
    parser.add_argument("--out", required=True, help="a folder every worker sees")
    parser.add_argument("--config", help="synth.json")
    parser.add_argument("--format", default="exr", choices=["flare7kpp", "pairs", "exr"])
    parser.add_argument("--shards", type=int, help="default: 4 per worker thread")
    args = parser.parse_args()
    try:
        width, height = (int(v) for v in args.size.lower().split("x"))
    except ValueError:
        sys.exit(f"synth_cluster: --size: expected WxH, got '{args.size}'")
    config = None
    if args.config:
        with open(args.config, encoding="utf-8") as f:
            config = json.load(f)
    client = distributed.Client(args.scheduler)
    start = time.perf_counter()
    try:
        done = synth_dask.generate(client, args.count, args.out, args.seed, size=(width, height),
                                   config=config, format=args.format, shards=args.shards)
    except ValueError as error:
        print(f"synth_cluster: {error}", file=sys.stderr)
        sys.exit(2)
    seconds = time.perf_counter() - start
    print(f"{done['written']} samples in {done['shards']} shards on "
          f"{len(client.nthreads())} workers, {seconds:.1f} s "
          f"({done['written'] / seconds:.1f} samples/s); complete: {done['complete']}")


if __name__ == "__main__":
    main()
