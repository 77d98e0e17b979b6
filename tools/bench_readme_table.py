#!/usr/bin/env python3
"""The README's benchmark table (one size) from out/bench/results.json,
and issue 9's targets at that size (bench/targets.py: counts, and the
missed scenes grouped by what limits them).

    python3 tools/bench_readme_table.py [results.json] [SIZE]   (default 1920x1080)
"""
import json, os, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "bench"))
import targets  # noqa: E402

path = sys.argv[1] if len(sys.argv) > 1 else "out/bench/results.json"
size = sys.argv[2] if len(sys.argv) > 2 else "1920x1080"
rows = json.load(open(path))
by = {(r["scene"], r["impl"]): r for r in rows if r["size"] == size}
scenes = list(dict.fromkeys(r["scene"] for r in rows if r["size"] == size))

def ms(scene, impl):
    return by.get((scene, impl), {}).get("median_ms")

def fmt(v):
    return "-" if v is None else f"{v:.1f}"

def ratio(a, b):
    return None if a is None or not b else a / b

print(f"| scene ({size}) | softgl ms | softgl 1 thread ms | llvmpipe 1 thread ms | llvmpipe 2 threads ms | softpipe ms "
      "| softgl-1t / llvmpipe-1t | softgl / llvmpipe | softgl / softpipe | first frame ms softgl / llvmpipe "
      "| RMSE vs softpipe: softgl / llvmpipe |")
print("| --- |" + " ---: |" * 10)
for s in scenes:
    g, g1, l1, l, sp = (ms(s, i) for i in ("softgl", "softgl-1t", "llvmpipe-1t", "llvmpipe", "softpipe"))
    r1, r2, rsp = ratio(g1, l1), ratio(g, l), ratio(g, sp)
    fg = by.get((s, "softgl"), {}).get("first_frame_ms")
    fl = by.get((s, "llvmpipe"), {}).get("first_frame_ms")
    eg = by.get((s, "softgl"), {}).get("vs_softpipe") or {}
    el = by.get((s, "llvmpipe"), {}).get("vs_softpipe") or {}
    rm = lambda e: f"{e['rmse']:.2f}" if e else "-"
    x = lambda v: "-" if v is None else f"{v:.2f}x"
    first = f"{fg:.0f} / {fl:.0f}" if fg is not None and fl is not None else "-"
    print(f"| {s} | {fmt(g)} | {fmt(g1)} | {fmt(l1)} | {fmt(l)} | {fmt(sp)} | {x(r1)} | {x(r2)} | {x(rsp)} "
          f"| {first} | {rm(eg)} / {rm(el)} |")
print()
res, _ = targets.judge(by, scenes)
for name, _what in targets.TARGETS:
    met, missed = res[name]
    print(f"{name}: {len(met)}/{len(met) + len(missed)}  missed: {', '.join(missed)}")
print()
print("\n".join(targets.markdown(by, scenes, size)))
