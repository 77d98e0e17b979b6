#!/usr/bin/env python3
"""softgl benchmark runner (issue 9): runs every scene against softgl and
Mesa (llvmpipe with 1 rasterizer thread, llvmpipe with all cores, softpipe)
in one run, alternating implementations within each repetition, and writes
out/bench/results.{json,md} and plots.

    bench/run.py [--reps N] [--sizes 300x300,1024x768,1920x1080] [--scenes a,b] [--quick]

The scene program (bench/scenes.c) is linked against Mesa's libOSMesa.so.8;
LD_LIBRARY_PATH=build/lib swaps in softgl's libOSMesa.so.8.
"""
import argparse, json, os, statistics, subprocess, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import targets  # noqa: E402  (bench/targets.py: issue 9's targets and what limits a miss)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "out", "bench")
BIN = os.path.join(ROOT, "build", "bench", "bench_scene")

IMPLS = {
    "softgl": {"LD_LIBRARY_PATH": os.path.join(ROOT, "build", "lib")},
    # softgl with SOFTGL_THREADS=1 (no binning, no threads).
    "softgl-1t": {"LD_LIBRARY_PATH": os.path.join(ROOT, "build", "lib"), "SOFTGL_THREADS": "1"},
    # softgl's reference path (SOFTGL_REFERENCE=1): the images errors are measured against.
    "softgl-ref": {"LD_LIBRARY_PATH": os.path.join(ROOT, "build", "lib"), "SOFTGL_REFERENCE": "1", "SOFTGL_THREADS": "1"},
    "llvmpipe-1t": {"GALLIUM_DRIVER": "llvmpipe", "LP_NUM_THREADS": "1"},
    "llvmpipe": {"GALLIUM_DRIVER": "llvmpipe"},
    "softpipe": {"GALLIUM_DRIVER": "softpipe"},
}
# name: (description, triangles per frame or None)
SCENES = {
    "spheres_s": ("25 smooth spheres, 6.4k triangles, depth test", 6400),
    "spheres_m": ("25 smooth spheres, 57.6k triangles, depth test", 57600),
    "spheres_l": ("25 smooth spheres, 410k triangles, depth test", 409600),
    "lit_spheres": ("spheres_m with two lights (positional, attenuated, specular)", 57600),
    "overdraw": ("16 window-sized smooth quads, depth test (opaque overdraw 16)", 32),
    "particles": ("2,000 blended quads of 1/8 the window (additive)", 4000),
    "lines": ("900 lines of width 1, 3 and 5 (stippled), 5,000 3-pixel points", 0),
    "immediate_1m": ("1,000,002 glVertex calls: 333k tiny triangles", 333334),
    "display_list_1m": ("the same through one display list", 333334),
    "readpixels": ("clear + triangle + full-frame glReadPixels RGBA", 1),
    "clear": ("colour + depth + stencil clear", 0),
    "book_dino": ("the Persian book's reflected dinosaur, stencil on (c_tests/book port's code)", None),
    "book_decal": ("the Russian book's decal airplane, stage 6: stencilled decals and the blended shadow", None),
    "book_winding": ("the Persian book's winding-rule panels, re-tessellated (GLU) into lists every frame", None),
    "fog_spheres": ("spheres_m under EXP2 fog, GL_FOG_HINT NICEST (per fragment)", 57600),
    "fog_spheres_fast": ("the same with GL_FOG_HINT FASTEST", 57600),
    "textured": ("a window-filling tunnel, 512x512 RGBA mipmapped, LINEAR_MIPMAP_LINEAR, perspective hint NICEST", 8),
    "textured_fast": ("the same with GL_PERSPECTIVE_CORRECTION_HINT FASTEST", 8),
    "drawpixels": ("a window-sized RGBA glDrawPixels, depth test on", 0),
    "copypixels": ("a triangle, then two glCopyPixels of half the window (overlapping)", 1),
    "arrays_1m": ("immediate_1m's triangles from client arrays, one glDrawArrays", 333334),
    "accum_blur": ("spheres_s four times into the accumulation buffer (LOAD, ACCUM, RETURN)", 25600),
    "shadow_volume": ("stencil shadow volumes (z-pass, INCR_WRAP/DECR_WRAP) of six squares over lit boxes", None),
    "smooth_lines": ("600 antialiased blended lines of width 1.5 and 3, GL_LINE_SMOOTH_HINT NICEST", 0),
    "smooth_lines_fast": ("the same with GL_LINE_SMOOTH_HINT FASTEST", 0),
}
# Scenes of issue 9 that need features softgl does not have yet (none now).
NOT_YET = {}


def frames_for(impl, w, h, scene):
    px = w * h
    base = 30 if px <= 300 * 300 else 12 if px <= 1024 * 768 else 8
    if scene in ("immediate_1m", "display_list_1m", "arrays_1m", "spheres_l", "accum_blur"):
        # Fewer frames for the heavy scenes, but not so few that the
        # threaded path's slower first frames (its batch memory and workers
        # warming up) are all the median sees.
        base = max(6, base * 3 // 4)
    if impl in ("softpipe", "softgl-ref"):
        base = max(2, base // 4)
    return base


def run_one(impl, scene, w, h, frames, pam):
    env = dict(os.environ)
    for k in ("LD_LIBRARY_PATH", "GALLIUM_DRIVER", "LP_NUM_THREADS", "SOFTGL_THREADS", "SOFTGL_REFERENCE"):
        env.pop(k, None)
    env.update(IMPLS[impl])
    start = time.time()
    p = subprocess.run([BIN, scene, str(w), str(h), str(frames), pam], env=env,
                       capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        return {"error": (p.stderr or p.stdout).strip()[-300:]}
    r = json.loads(p.stdout.strip().splitlines()[-1])
    r["first_frame_s"] = r["first_frame_wall"] - start
    # The first frame's parts: process start to main() (exec, dynamic
    # loading, library constructors) and to a current context.
    if "main_wall" in r:
        r["main_s"] = r["main_wall"] - start
        r["context_s"] = r["context_wall"] - start
    # bench_scene is linked against Mesa's libOSMesa: if softgl's library is
    # missing from build/lib, the run silently measures Mesa instead. The
    # renderer string says which library drew.
    want = "softgl" if impl.startswith("softgl") else impl.split("-")[0]
    if want not in r.get("renderer", "").lower():
        return {"error": f"renderer is {r.get('renderer')!r}, expected {want}"}
    return r


def read_pam(path):
    with open(path, "rb") as f:
        data = f.read()
    head, _, body = data.partition(b"ENDHDR\n")
    fields = dict(l.split(b" ", 1) for l in head.splitlines()[1:] if b" " in l)
    return int(fields[b"WIDTH"]), int(fields[b"HEIGHT"]), body


def image_error(a, b):
    """RMSE (0..255), max channel difference, share of pixels off by > 2/255 (RGB)."""
    wa, ha, da = read_pam(a)
    wb, hb, db = read_pam(b)
    if (wa, ha) != (wb, hb):
        return None
    try:
        import numpy as np
        x = np.frombuffer(da, np.uint8).reshape(-1, 4)[:, :3].astype(np.int32)
        y = np.frombuffer(db, np.uint8).reshape(-1, 4)[:, :3].astype(np.int32)
        d = np.abs(x - y)
        m = d.max(axis=1)
        return {"rmse": float(np.sqrt((d * d).mean())), "max": int(m.max()), "off_share": float((m > 2).mean())}
    except ImportError:
        pass
    n = wa * ha
    sq = 0
    mx = 0
    off = 0
    for i in range(0, n * 4, 4):
        d0 = abs(da[i] - db[i]); d1 = abs(da[i + 1] - db[i + 1]); d2 = abs(da[i + 2] - db[i + 2])
        m = max(d0, d1, d2)
        if m > mx:
            mx = m
        if m > 2:
            off += 1
        sq += d0 * d0 + d1 * d1 + d2 * d2
    return {"rmse": (sq / (3 * n)) ** 0.5, "max": mx, "off_share": off / n}


def pct(xs, q):
    xs = sorted(xs)
    k = (len(xs) - 1) * q
    lo, hi = int(k), min(int(k) + 1, len(xs) - 1)
    return xs[lo] + (xs[hi] - xs[lo]) * (k - lo)


def run_tess(quick):
    """bench/tess_bench.c: softgl's tessellator against Mesa's libGLU -> out/bench/tess.md."""
    exe = os.path.join(ROOT, "build", "bench", "tess_bench")
    os.makedirs(OUT, exist_ok=True)
    if not os.path.exists(exe):
        print("tess_bench not built: no GLU tessellator benchmark")
        return
    glu = next((p for p in ("/usr/lib/x86_64-linux-gnu/libGLU.so.1", "/usr/lib64/libGLU.so.1", "/usr/lib/libGLU.so.1")
                if os.path.exists(p)), "libGLU.so.1")
    args = [exe, "--softgl", os.path.join(ROOT, "build", "lib", "libGLU.so.1"), "--glu", glu,
            "--out", os.path.join(OUT, "tess.md")] + (["--quick"] if quick else [])
    p = subprocess.run(args, cwd=ROOT)
    if p.returncode != 0:
        print(f"tess_bench failed ({p.returncode})")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--sizes", default="300x300,1024x768,1920x1080")
    ap.add_argument("--scenes", default=",".join(SCENES))
    ap.add_argument("--impls", default=",".join(IMPLS))
    ap.add_argument("--first-reps", type=int, default=6,
                    help="extra 1-frame runs of softgl and llvmpipe per scene and size for the time to first frame")
    ap.add_argument("--quick", action="store_true", help="one rep, 300x300 only")
    ap.add_argument("--tess-only", action="store_true", help="only the GLU tessellator against libGLU")
    ap.add_argument("--no-tess", action="store_true", help="skip the GLU tessellator benchmark")
    a = ap.parse_args()
    if not a.no_tess:
        run_tess(a.quick)
    if a.tess_only:
        return 0
    if a.quick:
        a.reps, a.sizes, a.first_reps = 1, "300x300", 0
    sizes = [tuple(map(int, s.split("x"))) for s in a.sizes.split(",")]
    scenes = a.scenes.split(",")
    impls = a.impls.split(",")
    os.makedirs(os.path.join(OUT, "img"), exist_ok=True)
    raw = {}
    for rep in range(a.reps):
        for (w, h) in sizes:
            for scene in scenes:
                for impl in (impls if rep % 2 == 0 else impls[::-1]):  # alternate order
                    pam = os.path.join(OUT, "img", f"{scene}_{w}x{h}_{impl}.pam")
                    r = run_one(impl, scene, w, h, frames_for(impl, w, h, scene), pam)
                    key = f"{scene}|{w}x{h}|{impl}"
                    raw.setdefault(key, []).append(r)
                    status = r.get("error") or f"{statistics.median(r['ms']):.2f} ms"
                    print(f"rep {rep + 1} {w}x{h} {scene:16} {impl:12} {status}", flush=True)
    # Time to first frame is one sample a process, and a process start
    # varies by tens of milliseconds on a shared host: the timed runs give
    # only `reps` samples. Extra 1-frame runs of the two implementations
    # the target compares, alternating, add more to the median.
    first = {}
    pair = [i for i in ("softgl", "llvmpipe") if i in impls]
    for rep in range(a.first_reps if len(pair) == 2 else 0):
        for (w, h) in sizes:
            for scene in scenes:
                for impl in (pair if rep % 2 == 0 else pair[::-1]):
                    r = run_one(impl, scene, w, h, 1, os.devnull)
                    if "error" not in r:
                        first.setdefault(f"{scene}|{w}x{h}|{impl}", []).append(r)
        print(f"first-frame rep {rep + 1} of {a.first_reps}", flush=True)
    results = []
    for key, runs in raw.items():
        scene, size, impl = key.split("|")
        ok = [r for r in runs if "error" not in r]
        row = {"scene": scene, "size": size, "impl": impl}
        if not ok:
            row["error"] = runs[0]["error"]
        else:
            ms = [m for r in ok for m in r["ms"]]
            starts = ok + first.get(key, [])
            row.update(median_ms=statistics.median(ms), p90_ms=pct(ms, 0.9),
                       first_frame_ms=1000 * statistics.median(r["first_frame_s"] for r in starts),
                       first_frame_runs=len(starts),
                       main_ms=1000 * statistics.median(r.get("main_s", 0) for r in starts),
                       context_ms=1000 * statistics.median(r.get("context_s", 0) for r in starts),
                       peak_mb=max(r["maxrss_kb"] for r in ok) / 1024, gl_error=ok[-1]["gl_error"],
                       renderer=ok[-1]["renderer"])
            ref = os.path.join(OUT, "img", f"{scene}_{size}_softpipe.pam")
            mine = os.path.join(OUT, "img", f"{scene}_{size}_{impl}.pam")
            if impl != "softpipe" and os.path.exists(ref):
                row["vs_softpipe"] = image_error(mine, ref)
            sref = os.path.join(OUT, "img", f"{scene}_{size}_softgl-ref.pam")
            if impl != "softgl-ref" and os.path.exists(sref):
                row["vs_ref"] = image_error(mine, sref)
        results.append(row)
    with open(os.path.join(OUT, "results.json"), "w") as f:
        json.dump(results, f, indent=1)
    write_markdown(results, sizes, scenes, impls)
    plot(results, sizes, scenes, impls)


def startup_table(by, sizes, scenes):
    """The first frame split at the largest size: process start to main()
    (exec and dynamic loading: llvmpipe loads LLVM), to a current context
    (OSMesaCreateContextExt + MakeCurrent), and to the first finished frame
    (the scene's first drawing, with the first touch of the buffers)."""
    w, h = sizes[-1]
    size = f"{w}x{h}"
    runs = max((by.get((sc, size, "softgl"), {}).get("first_frame_runs", 0) for sc in scenes), default=0)
    rows = ["## Time to first frame, split (" + size + f", medians of {runs} process starts each, ms from process start)", "",
            "| scene | softgl: main / context / first frame | llvmpipe: main / context / first frame | softgl's first frame less context / its median frame |",
            "| --- | --- | --- | --- |"]
    for scene in scenes:
        s, l = by.get((scene, size, "softgl"), {}), by.get((scene, size, "llvmpipe"), {})
        if "first_frame_ms" not in s or "first_frame_ms" not in l:
            continue
        part = lambda r: f"{r.get('main_ms', 0):.1f} / {r.get('context_ms', 0):.1f} / {r['first_frame_ms']:.1f}"
        own = f"{s['first_frame_ms'] - s.get('context_ms', 0):.1f} / {s['median_ms']:.1f}"
        rows.append(f"| {scene} | {part(s)} | {part(l)} | {own} |")
    return rows + [""]


def write_markdown(results, sizes, scenes, impls):
    by = {(r["scene"], r["size"], r["impl"]): r for r in results}
    lines = ["| scene | size | " + " | ".join(f"{i} median / p90 ms" for i in impls) +
             " | softgl / llvmpipe-1t | softgl-1t / llvmpipe-1t | softgl / llvmpipe | softgl / softpipe | first frame ms (softgl / llvmpipe) | peak MB (softgl / llvmpipe) | softgl vs softpipe: RMSE, max, >2/255 | llvmpipe vs softpipe: RMSE, max, >2/255 | softgl vs softgl-ref | llvmpipe vs softgl-ref |",
             "|" + " --- |" * (2 + len(impls) + 10)]
    for scene in scenes:
        for (w, h) in sizes:
            size = f"{w}x{h}"
            cells = []
            for i in impls:
                r = by.get((scene, size, i), {})
                cells.append(f"{r['median_ms']:.2f} / {r['p90_ms']:.2f}" if "median_ms" in r else r.get("error", "-")[:40])
            s, l1, sp, l, s1 = (by.get((scene, size, k), {}) for k in ("softgl", "llvmpipe-1t", "softpipe", "llvmpipe", "softgl-1t"))
            ratio = lambda x, y: f"{x['median_ms'] / y['median_ms']:.2f}x" if "median_ms" in x and "median_ms" in y and y["median_ms"] > 0 else "-"
            err = lambda r, k="vs_softpipe": "{rmse:.2f}, {max}, {off_share:.1%}".format(**r[k]) if r.get(k) else "-"
            ff = f"{s.get('first_frame_ms', 0):.0f} / {l.get('first_frame_ms', 0):.0f}"
            mem = f"{s.get('peak_mb', 0):.0f} / {l.get('peak_mb', 0):.0f}"
            lines.append(f"| {scene} | {size} | " + " | ".join(cells) +
                         f" | {ratio(s, l1)} | {ratio(s1, l1)} | {ratio(s, l)} | {ratio(s, sp)} | {ff} | {mem} | {err(s)} | {err(l)} | {err(s, 'vs_ref')} | {err(l, 'vs_ref')} |")
    text = ["# softgl benchmark", "",
            "Frame times after one warm-up frame; ratios are softgl's median time over the other's (below 1 = softgl faster).",
            "Image error is against softpipe's image of the same frame, and against softgl's reference path (`softgl-ref`, SOFTGL_REFERENCE=1).",
            "`softgl` uses every core (SOFTGL_THREADS unset), `softgl-1t` one thread.", "",
            "Scenes:", ""] + [f"- `{k}`: {v[0]}" for k, v in SCENES.items() if k in scenes] + \
           ([""] + ["Not runnable yet (softgl lacks the features): " + "; ".join(f"{k} ({v})" for k, v in NOT_YET.items())] if NOT_YET else []) + ["", *lines, ""] + \
           startup_table(by, sizes, scenes)
    for (w, h) in sizes:
        size = f"{w}x{h}"
        by_size = {(s, i): r for (s, sz, i), r in by.items() if sz == size}
        text += targets.markdown(by_size, scenes, size)
    with open(os.path.join(OUT, "results.md"), "w") as f:
        f.write("\n".join(text))
    print("\n".join(lines))


def plot(results, sizes, scenes, impls):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not available: no plots")
        return
    by = {(r["scene"], r["size"], r["impl"]): r for r in results}
    colors = {"softgl": "tab:red", "softgl-1t": "tab:orange", "softgl-ref": "tab:brown", "llvmpipe-1t": "tab:blue", "llvmpipe": "tab:cyan", "softpipe": "tab:gray"}
    # Time against error, per scene, at the largest size.
    size = f"{sizes[-1][0]}x{sizes[-1][1]}"
    # A scene's GL_FASTEST variant (NAME_fast) shares NAME's panel, marked x:
    # the hint's two points side by side (issue 9 item 3).
    panels = [s for s in scenes if not (s.endswith("_fast") and s[:-5] in scenes)]
    n = len(panels)
    # Panels in a grid of at most six columns (one row of 25 was unreadable).
    cols = min(n, 6)
    rows = (n + cols - 1) // cols

    def grid():
        fig, axes = plt.subplots(rows, cols, figsize=(3.2 * cols, 3 * rows), squeeze=False)
        flat = [ax for row in axes for ax in row]
        for ax in flat[n:]:
            ax.set_visible(False)
        return fig, flat

    fig, axes = grid()
    for ax, scene in zip(axes, panels):
        for variant, marker in ((scene, "o"), (scene + "_fast", "x")):
            for i in impls:
                r = by.get((variant, size, i), {})
                if "median_ms" in r and (r.get("vs_softpipe") or i == "softpipe"):
                    e = r["vs_softpipe"]["rmse"] if r.get("vs_softpipe") else 0.0
                    ax.scatter([r["median_ms"]], [e], color=colors[i], marker=marker,
                               label=i + (" FASTEST" if marker == "x" else ""))
        ax.set_title(scene, fontsize=8); ax.set_xlabel("median ms"); ax.set_ylabel("RMSE vs softpipe")
    axes[0].legend(fontsize=6)
    fig.tight_layout(); fig.savefig(os.path.join(OUT, "time_vs_error.png"), dpi=80); plt.close(fig)
    # Time against resolution.
    fig, axes = grid()
    for ax, scene in zip(axes, panels):
        for i in impls:
            pts = [(w * h / 1e6, by[(scene, f"{w}x{h}", i)]["median_ms"]) for (w, h) in sizes if "median_ms" in by.get((scene, f"{w}x{h}", i), {})]
            if pts:
                ax.plot(*zip(*pts), marker="o", color=colors[i], label=i)
        ax.set_title(scene, fontsize=8); ax.set_xlabel("megapixels"); ax.set_ylabel("median ms")
    axes[0].legend(fontsize=6)
    fig.tight_layout(); fig.savefig(os.path.join(OUT, "time_vs_resolution.png"), dpi=80); plt.close(fig)
    # Time against triangle count (the sphere scenes).
    fig, ax = plt.subplots(figsize=(4, 3))
    for i in impls:
        pts = [(SCENES[s][1], by[(s, size, i)]["median_ms"]) for s in ("spheres_s", "spheres_m", "spheres_l") if "median_ms" in by.get((s, size, i), {})]
        if pts:
            ax.plot(*zip(*pts), marker="o", color=colors[i], label=i)
    ax.set_xscale("log"); ax.set_xlabel(f"triangles per frame ({size})"); ax.set_ylabel("median ms"); ax.legend(fontsize=6)
    fig.tight_layout(); fig.savefig(os.path.join(OUT, "time_vs_triangles.png"), dpi=80); plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
