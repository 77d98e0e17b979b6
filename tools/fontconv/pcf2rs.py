#!/usr/bin/env python3
"""pcf2rs: converts X11 PCF bitmap fonts into softgl's built-in font data.

Run once (the output is committed):

    apt-get install xfonts-base
    python3 tools/fontconv/pcf2rs.py > src/fonts/misc_fixed.rs

Reads the misc-fixed fonts of Debian's xfonts-base (public domain, see
docs/fonts.md) from /usr/share/fonts/X11/misc and writes, for each, only
the code points softgl's wgl/glX fonts need: ASCII, Latin-1, Cyrillic
U+0400-045F and U+0490/0491, everything Windows code pages 1251 and 1252
put at 0x80-0xFF, and U+FFFD (the default glyph). Each glyph is trimmed
to its ink box; rows are stored top-down, MSB = leftmost pixel, each row
padded to a whole byte, as one hex string per font.
"""
import gzip
import struct
import sys

FONT_DIR = "/usr/share/fonts/X11/misc"
# (file, name, weight): Windows weights (FW_NORMAL 400, FW_BOLD 700).
FONTS = [
    ("8x13", 400), ("8x13B", 700),
    ("9x15", 400), ("9x15B", 700),
    ("9x18", 400), ("9x18B", 700),
    ("10x20", 400),
]

PCF_PROPERTIES, PCF_METRICS, PCF_BITMAPS, PCF_BDF_ENCODINGS = 1, 4, 8, 32
PCF_BYTE_MASK, PCF_BIT_MASK, PCF_COMPRESSED_METRICS = 1 << 2, 1 << 3, 0x100


def code_points():
    cps = set(range(0x20, 0x7F)) | set(range(0xA0, 0x100))
    cps |= set(range(0x400, 0x460)) | {0x490, 0x491, 0xFFFD}
    for cp in ("cp1251", "cp1252"):
        for b in range(0x80, 0x100):
            try:
                cps.add(ord(bytes([b]).decode(cp)))
            except UnicodeDecodeError:
                pass
    return sorted(cps)


class Reader:
    def __init__(self, data, off, fmt):
        self.d, self.p = data, off
        self.e = ">" if fmt & PCF_BYTE_MASK else "<"

    def get(self, f):
        v = struct.unpack_from(self.e + f, self.d, self.p)
        self.p += struct.calcsize(f)
        return v[0]


def read_pcf(path):
    data = gzip.open(path).read()
    assert data[:4] == b"\x01fcp", path
    (n,) = struct.unpack_from("<i", data, 4)
    tables = {}
    for i in range(n):
        t, fmt, size, off = struct.unpack_from("<iiii", data, 8 + 16 * i)
        tables[t] = (fmt, off)

    def table(t):
        fmt, off = tables[t]
        (fmt2,) = struct.unpack_from("<i", data, off)
        return fmt2, Reader(data, off + 4, fmt2)

    # Metrics.
    fmt, r = table(PCF_METRICS)
    metrics = []
    if fmt & PCF_COMPRESSED_METRICS:
        for _ in range(r.get("h")):
            lsb, rsb, w, a, d = (r.get("B") - 0x80 for _ in range(5))
            metrics.append((lsb, rsb, w, a, d))
    else:
        for _ in range(r.get("i")):
            lsb, rsb, w, a, d = (r.get("h") for _ in range(5))
            r.get("H")
            metrics.append((lsb, rsb, w, a, d))
    # Bitmaps.
    fmt, r = table(PCF_BITMAPS)
    count = r.get("i")
    offsets = [r.get("i") for _ in range(count)]
    sizes = [r.get("i") for _ in range(4)]
    bits = data[r.p:r.p + sizes[fmt & 3]]
    pad = 1 << (fmt & 3)
    unit = 1 << ((fmt >> 4) & 3)
    msb_bytes, msb_bits = bool(fmt & PCF_BYTE_MASK), bool(fmt & PCF_BIT_MASK)
    # Encodings.
    fmt, r = table(PCF_BDF_ENCODINGS)
    min2, max2, min1, max1, default = (r.get("h") for _ in range(5))
    cols = max2 - min2 + 1
    index = [r.get("H") for _ in range(cols * (max1 - min1 + 1))]

    def glyph_index(cp):
        b1, b2 = cp >> 8, cp & 0xFF
        if not (min1 <= b1 <= max1 and min2 <= b2 <= max2):
            return None
        g = index[(b1 - min1) * cols + (b2 - min2)]
        return None if g == 0xFFFF else g

    def glyph(g):
        lsb, rsb, adv, asc, desc = metrics[g]
        w, h = rsb - lsb, asc + desc
        stride = ((w + 7) // 8 + pad - 1) // pad * pad
        rows = []
        for y in range(h):
            row = bytearray(bits[offsets[g] + y * stride: offsets[g] + (y + 1) * stride])
            if msb_bytes != msb_bits and unit > 1:
                for i in range(0, len(row), unit):
                    row[i:i + unit] = row[i:i + unit][::-1]
            if not msb_bits:
                row = bytearray(int(f"{b:08b}"[::-1], 2) for b in row)
            v = int.from_bytes(row, "big") if row else 0
            # pixel x (0 = left) is bit (len*8 - 1 - x)
            rows.append([(v >> (len(row) * 8 - 1 - x)) & 1 for x in range(w)])
        # Trim to the ink box (top-down rows; y of row 0 is asc - 1).
        ink = [(x, y) for y in range(h) for x in range(w) if rows[y][x]]
        if not ink:
            return (0, 0, 0, 0, adv, b"")
        x0 = min(x for x, _ in ink); x1 = max(x for x, _ in ink) + 1
        y0 = min(y for _, y in ink); y1 = max(y for _, y in ink) + 1
        out = bytearray()
        for y in range(y0, y1):
            bw = (x1 - x0 + 7) // 8
            v = 0
            for x in range(x0, x1):
                v = (v << 1) | rows[y][x]
            v <<= bw * 8 - (x1 - x0)
            out += v.to_bytes(bw, "big")
        gw, gh = x1 - x0, y1 - y0
        xoff = lsb + x0            # left edge of the ink box from the origin
        yoff = asc - y1            # bottom edge of the ink box from the baseline
        return (gw, gh, xoff, yoff, adv, bytes(out))

    return metrics, glyph_index, glyph


def main():
    cps = code_points()
    out = sys.stdout
    out.write("//! Built-in bitmap fonts: a subset of the misc-fixed fonts of X11\n")
    out.write("//! (Debian package xfonts-base, font-misc-misc: \"Public domain font.\n")
    out.write("//! Share and enjoy.\"). Generated once by tools/fontconv/pcf2rs.py; do not\n")
    out.write("//! edit. See docs/fonts.md.\n\n")
    out.write("use super::{hex, FontData, G};\n\n")
    names = []
    for fname, weight in FONTS:
        metrics, glyph_index, glyph = read_pcf(f"{FONT_DIR}/{fname}.pcf.gz")
        # Cell metrics from the font's 'M'... use the max ascent/descent of all glyphs kept.
        glyphs, blob, missing = [], bytearray(), []
        asc = max(metrics[glyph_index(cp)][3] for cp in cps if glyph_index(cp) is not None)
        desc = max(metrics[glyph_index(cp)][4] for cp in cps if glyph_index(cp) is not None)
        cellw = metrics[glyph_index(ord("M"))][2]
        for cp in cps:
            g = glyph_index(cp)
            if g is None:
                missing.append(cp)
                continue
            w, h, xo, yo, adv, bits = glyph(g)
            glyphs.append((cp, w, h, xo, yo, adv, len(blob)))
            blob += bits
        ident = "F_" + fname.upper()
        names.append(ident)
        hexs = blob.hex()
        out.write(f"/// misc-fixed {fname}: cell {cellw}x{asc + desc}, {len(glyphs)} glyphs")
        if missing:
            out.write(f"; not in the font: {', '.join(f'U+{c:04X}' for c in missing)}")
        out.write(".\n")
        out.write(f"pub static {ident}: FontData = FontData {{\n")
        out.write(f"    name: \"{fname}\",\n    weight: {weight},\n    ascent: {asc},\n    descent: {desc},\n    cell_width: {cellw},\n")
        out.write("    glyphs: &[\n")
        line = "       "
        for (cp, w, h, xo, yo, adv, off) in glyphs:
            item = f" G(0x{cp:04X}, {w}, {h}, {xo}, {yo}, {adv}, {off}),"
            if len(line) + len(item) > 100:
                out.write(line + "\n")
                line = "       "
            line += item
        out.write(line + "\n    ],\n")
        out.write(f"    bits: &{ident}_BITS,\n}};\n")
        out.write(f"static {ident}_BITS: [u8; {len(blob)}] = hex(concat!(\n")
        for i in range(0, len(hexs), 96):
            out.write(f"    \"{hexs[i:i + 96]}\",\n")
        out.write("));\n\n")
    out.write("/// Every built-in font.\n")
    out.write(f"pub static ALL: [&FontData; {len(names)}] = [{', '.join('&' + n for n in names)}];\n")


if __name__ == "__main__":
    main()
