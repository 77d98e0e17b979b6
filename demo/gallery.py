#!/usr/bin/env python3
"""Write out/index.html: the gallery of the book ports and the demo scenes.

    demo/gallery.py OUT_DIR RUN_LOG

For every c_tests/book/t_book_*.c it reads the "BOOK:", "SHOWS:" and
"FEATURES:" lines of the header comment, finds its images
OUT_DIR/book/<program>-*.png (program = file name without "t_book_"),
and takes PASS/FAIL/SKIP from RUN_LOG (the output of c_tests/run.sh).
Then the Free Pascal (Delphi mode) samples, described by
delphi_samples/gallery.tsv, with their images in OUT_DIR/demo/delphi/, and
the demo scenes OUT_DIR/demo/*.png.  Standard library only.
"""
import glob
import html
import os
import re
import sys

SECTIONS = [
    ("s0_", "Persian book: 3D programming with OpenGL in Delphi, ch. 21 (S0)"),
    ("s2_", "Russian web page: Krasnov, OpenGL in Delphi, stencil decals (S2)"),
    ("s3_", "Russian OpenGL textbook (S3)"),
]


def header_fields(path):
    text = open(path, encoding="utf-8").read()
    comment = text.split("*/", 1)[0]
    fields = {}
    for key in ("BOOK", "SHOWS", "FEATURES"):
        m = re.search(r"^\s*\*\s*" + key + r":\s*(.*)$", comment, re.M)
        fields[key] = m.group(1).strip() if m else ""
    return fields


def statuses(log_path):
    result = {}
    if log_path and os.path.exists(log_path):
        for line in open(log_path, encoding="utf-8", errors="replace"):
            m = re.match(r"^(PASS|FAIL|SKIP) (t_book_\w+)", line)
            if m:
                result[m.group(2)] = m.group(1)
    return result


def delphi_rows(rows, out_dir):
    """The Delphi-mode samples: one figure per image of gallery.tsv."""
    tsv = "delphi_samples/gallery.tsv"
    if not os.path.exists(tsv):
        return
    e = html.escape
    rows.append("<h2>Free Pascal, Delphi mode (delphi_samples/, see docs/delphi.md)</h2>")
    for line in open(tsv, encoding="utf-8"):
        if line.startswith("#") or not line.strip():
            continue
        name, book, prog, shows = (line.rstrip("\n").split("\t") + ["", "", ""])[:4]
        img = os.path.join(out_dir, "demo", "delphi", name + ".png")
        rows.append("<div class='prog'><h3>%s</h3><p><b>Book:</b> %s<br><b>Program:</b> delphi_samples/%s<br>"
                    "<b>Shows:</b> %s</p>" % (e(name), e(book), e(prog), e(shows)))
        if os.path.exists(img):
            rel = os.path.relpath(img, out_dir)
            rows.append("<figure><img src='%s'></figure>" % e(rel))
        else:
            rows.append("<p class='FAIL'>no image (run make demo)</p>")
        rows.append("</div>")


def main():
    out_dir, log = sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else None
    status = statuses(log)
    rows = []
    e = html.escape
    rows.append("<!doctype html><meta charset='utf-8'><title>softgl: the books' programs</title>")
    rows.append("<style>body{font-family:sans-serif;background:#222;color:#ddd;max-width:1300px;margin:auto}"
                "a{color:#8cf}.prog{border-top:1px solid #555;padding:8px 0}img{margin:4px;border:1px solid #444;"
                "image-rendering:pixelated}.PASS{color:#6d6}.FAIL{color:#f66}.SKIP{color:#fc6}"
                "figure{display:inline-block;margin:0}figcaption{font-size:11px;color:#aaa}</style>")
    rows.append("<h1>softgl: the three textbooks' programs</h1>")
    rows.append("<p>C ports of every program and fragment of <code>seeds-inventory.md</code> §3, rendered "
                "through softgl (the book's wgl window code over <code>softglCreateDC</code>). Each program "
                "checks its pixels (and stencil, depth, GL errors) and compares its images with the goldens in "
                "<code>c_tests/golden/book/</code>; see <a href='../docs/book-gallery.md'>docs/book-gallery.md</a>.</p>")
    progs = sorted(glob.glob("c_tests/book/t_book_*.c"))
    counts = {"PASS": 0, "FAIL": 0, "SKIP": 0, "?": 0}
    for prefix, title in SECTIONS:
        rows.append("<h2>%s</h2>" % e(title))
        for src in progs:
            name = os.path.basename(src)[:-2]
            short = name[len("t_book_"):]
            if not short.startswith(prefix):
                continue
            f = header_fields(src)
            st = status.get(name, "?")
            counts[st] = counts.get(st, 0) + 1
            rows.append("<div class='prog'><h3>%s <span class='%s'>%s</span></h3>" % (e(short), st, st))
            rows.append("<p><b>Book:</b> %s<br><b>Program:</b> <a href='../%s'>%s</a><br>"
                        "<b>Shows:</b> %s<br><b>GL features:</b> %s</p>"
                        % (e(f["BOOK"]), e(src), e(src), e(f["SHOWS"]), e(f["FEATURES"])))
            for img in sorted(glob.glob(os.path.join(out_dir, "book", short + "-*.png"))):
                rel = os.path.relpath(img, out_dir)
                view = os.path.basename(img)[len(short) + 1:-4]
                rows.append("<figure><a href='%s'><img src='%s' alt='%s'></a><figcaption>%s</figcaption></figure>"
                            % (e(rel), e(rel), e(view), e(view)))
            rows.append("</div>")
    delphi_rows(rows, out_dir)
    demo = sorted(glob.glob(os.path.join(out_dir, "demo", "*.png")))
    if demo:
        rows.append("<h2>Demo scenes (demo/scenes.c)</h2><div class='prog'>")
        for img in demo:
            rel = os.path.relpath(img, out_dir)
            rows.append("<figure><img src='%s'><figcaption>%s</figcaption></figure>"
                        % (e(rel), e(os.path.basename(img)[:-4])))
        rows.append("</div>")
    rows.append("<p>%d programs: %d pass, %d fail, %d skipped, %d not run.</p>"
                % (len(progs), counts["PASS"], counts["FAIL"], counts["SKIP"], counts["?"]))
    with open(os.path.join(out_dir, "index.html"), "w", encoding="utf-8") as fh:
        fh.write("\n".join(rows) + "\n")
    print("%s/index.html: %d programs (%d pass, %d fail)" % (out_dir, len(progs), counts["PASS"], counts["FAIL"]))


if __name__ == "__main__":
    main()
