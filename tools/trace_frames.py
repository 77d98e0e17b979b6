#!/usr/bin/env python3
"""Per-thread time breakdown of 2-thread frames from a SOFTGL_TRACE file
(round 13, docs/perf-notes.md). Usage:

    SOFTGL_TRACE=/tmp/t.txt SOFTGL_THREADS=2 LD_LIBRARY_PATH=build/lib \\
        build/bench/bench_scene spheres_l 1920 1080 12 /tmp/x.pam
    python3 tools/trace_frames.py /tmp/t.txt [FIRST_FRAME]

The trace holds lines `thread kind t0 t1 arg cpu` (ns; cpu: the core the
event ended on). Kinds: b band, l band
listing (bin_once), S tile::submit, F tile::flush, L a flight launched
(arg: its triangles), j a worker's run of a job, p a worker's spin, z a
worker's sleep, o pool::finish's own run, w pool::finish's wait, W the
pool's start (workers created), s a worker thread's first instant.
Each dump begins with a line `# base UNIX_SECONDS` (time 0), skipped. Frames
are the spans between the calling thread's flushes (glFinish). Prints
milliseconds a frame, averaged over frames FIRST_FRAME.. (default 3).
"""
import collections
import sys


def main():
    ev = []
    for line in open(sys.argv[1]):
        if line.startswith('#'):
            continue
        t, k, a, b, arg = line.split()[:5]
        ev.append((int(t), k, int(a), int(b), int(arg)))
    first = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    caller = next(e[0] for e in ev if e[1] == 'F')
    ends = sorted(e[3] for e in ev if e[1] == 'F' and e[0] == caller)
    tot, n = collections.Counter(), 0
    for i in range(max(first, 1), len(ends)):
        a, b = ends[i - 1], ends[i]
        c = collections.Counter()
        for t, k, t0, t1, arg in ev:
            if t1 <= a or t0 >= b:
                continue
            who = 'C' if t == caller else 'W'
            c[who + k] += min(t1, b) - max(t0, a)
            if k == 'L' and a <= t0 < b:
                c['flights'] += 1
                c['tris'] += arg
            if k == 'b':
                c[who + '#b'] += 1
        c['frame'] = b - a
        tot.update(c)
        n += 1
    if n == 0:
        sys.exit("no complete frames")
    ms = lambda k: tot[k] / n / 1e6
    print("frames %d, frame %.2f ms, %.1f flights a frame, %.0f triangles a flight"
          % (n, ms('frame'), tot['flights'] / n, tot['tris'] / max(1, tot['flights'])))
    print("calling thread: serial (frame - finish) %.2f, bands %.2f, listing %.2f, finish's own run %.2f, finish's wait %.2f, submit %.2f, flush %.2f"
          % (ms('frame') - ms('Co') - ms('Cw'), ms('Cb'), ms('Cl'), ms('Co'), ms('Cw'), ms('CS'), ms('CF')))
    print("workers: bands %.2f, listing %.2f, jobs %.2f, spin %.2f, sleep %.2f"
          % (ms('Wb'), ms('Wl'), ms('Wj'), ms('Wp'), ms('Wz')))
    print("bands a frame: calling thread %.1f, workers %.1f" % (tot['C#b'] / n, tot['W#b'] / n))


main()
