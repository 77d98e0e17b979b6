#!/usr/bin/env python3
"""Alternating A/B frame-time pairs of one bench scene, each pair run only
while the host gives two cores (round 21, docs/perf-notes.md).

On the 2-vCPU hosts of 2026-11-29 two threads of pure arithmetic took by
turns as long as one (two real cores) and twice as long (one core shared),
the mode changing within minutes and reported nowhere (no steal time): a
2-thread comparison taken across a change measures the host. Before each
pair this script times one and then two processes of a fixed arithmetic
loop and skips the pair (waiting 2 s) unless the two took under 1.25x the
one.

    python3 tools/ab_pairs.py SCENE PAIRS FRAMES ENV LIBDIR_A LIBDIR_B...

ENV is `-` or `NAME=V,NAME=V` (say SOFTGL_THREADS=2); each LIBDIR is put
on LD_LIBRARY_PATH (a directory like build/lib). Prints each library's
median of the pairs' median frame times (the first frame left out), and
how many pairs the second library won. Needs build/bench/bench_scene.

Round 25: each LIBDIR is first copied into a fresh temporary directory,
and the pairs alternate which library runs first. The same library
bytes in a file left idle for about 45 minutes ran 15 % slower than a
fresh copy of it (arrays_1m with 1 thread, 26.9 against 22.9 ms, 6 of 6
pairs) until the page cache was dropped (this host's DAMON pages out idle
memory; likely, text read back in afterwards sits in scattered 4 KiB
pages rather than the large contiguous ones a fresh write or a
readahead gets, which Zen's TLBs can coalesce). A copy made just before
comparing removes that from the comparison.
"""
import json
import multiprocessing
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BENCH = os.path.join(ROOT, "build", "bench", "bench_scene")


def spin(n):
    x = 0
    for i in range(n):
        x += i
    return x


def burn(procs):
    t = time.perf_counter()
    with multiprocessing.Pool(procs) as pool:
        pool.map(spin, [8_000_000] * procs)
    return time.perf_counter() - t


def two_cores():
    one, two = burn(1), burn(2)
    return two < 1.25 * one


def median_ms(scene, frames, env, lib):
    env = dict(os.environ, **env, LD_LIBRARY_PATH=lib)
    out = subprocess.run([BENCH, scene, "1920", "1080", frames, "/tmp/ab_pairs.pam"], env=env, capture_output=True, text=True, check=True).stdout
    ms = json.loads(out.strip().splitlines()[-1])["ms"]
    return statistics.median(ms[1:] or ms)


def main():
    if len(sys.argv) < 7:
        sys.exit(__doc__)
    scene, pairs, frames, envs, libs = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5:]
    env = {} if envs == "-" else dict(kv.split("=", 1) for kv in envs.split(","))
    scratch = tempfile.mkdtemp(prefix="ab_pairs.")
    try:
        fresh = {lib: shutil.copytree(lib, os.path.join(scratch, str(i)), symlinks=True) for i, lib in enumerate(libs)}
        res, skipped = run_pairs(scene, pairs, frames, env, libs, fresh)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    report(scene, envs, libs, res, skipped)


def run_pairs(scene, pairs, frames, env, libs, fresh):
    """({lib: [median frame ms of each pair]}, pairs skipped), each
    library run from its fresh copy `fresh[lib]`."""
    res = {lib: [] for lib in libs}
    skipped = 0
    while len(res[libs[0]]) < pairs and skipped < 300:
        if not two_cores():
            skipped += 1
            time.sleep(2)
            continue
        order = libs if len(res[libs[0]]) % 2 == 0 else libs[::-1]
        for lib in order:
            res[lib].append(median_ms(scene, frames, env, fresh[lib]))
    return res, skipped


def report(scene, envs, libs, res, skipped):
    if not res[libs[0]]:
        sys.exit("the host never gave two cores")
    for lib in libs:
        v = res[lib]
        print(f"{scene} {envs} {lib}: median {statistics.median(v):.2f} ms (min {min(v):.2f}, max {max(v):.2f}) {[round(x, 1) for x in v]}")
    won = sum(1 for a, b in zip(res[libs[0]], res[libs[1]]) if b < a)
    print(f"pairs the second won: {won}/{len(res[libs[0]])}; pairs skipped (one core): {skipped}")


if __name__ == "__main__":
    main()
