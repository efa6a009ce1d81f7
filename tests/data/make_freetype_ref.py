#!/usr/bin/env python3
"""Regenerates tests/data/freetype_ref.txt: FreeType's unhinted rendering of
glyphs of the bundled font, the reference of tests/tests/text_freetype.rs.

A dev-time tool (pip install freetype-py: it bundles FreeType 2.13); the
data it writes is committed, so the tests need neither Python nor FreeType.

    python3 tests/data/make_freetype_ref.py

Each glyph is rendered by FreeType (FT_LOAD_NO_HINTING, FT_RENDER_MODE_NORMAL,
8-bit coverage) at 8 times the size, with its origin on the oversampled
grid, and each 8x8 block of the oversampled bitmap summed into one pixel
(0..=64*255): FreeType's own area coverage, its flattening error divided
by 8. Origins are at multiples of 1/8 px so they fall on the oversampled
grid.

Line format (one glyph per line, whitespace separated):
    size codepoint origin_x_fine origin_y_fine x0 y0 w h <w*h 4-hex-digit sums, row-major>
"""
import os
import freetype

HERE = os.path.dirname(os.path.abspath(__file__))
FONT = os.path.join(HERE, "..", "..", "core", "fonts", "SoftedgeSans-Subset.ttf")
OUT = os.path.join(HERE, "freetype_ref.txt")
OS = 8  # oversampling

CASES = {
    8: "AVWgjmo@&%$QRS8e?ByKx0147",
    12: "AVWgjmo@&%$QRS8e",
    24: "gmo@&QRS",
    48: "g@&S",
}

face = freetype.Face(FONT)
lines = []
k = 0
for size, chars in CASES.items():
    face.set_pixel_sizes(0, size * OS)
    for ch in chars:
        # Deterministic origins on the 1/8-px grid: (5 + a/8, size + 4 + b/8) px.
        a, b = (3 * k + 1) % 8, (5 * k + 2) % 8
        k += 1
        ox8, oy8 = 5 * OS + a, (size + 4) * OS + b  # in oversampled pixels
        face.load_char(ch, freetype.FT_LOAD_NO_HINTING | freetype.FT_LOAD_NO_BITMAP)
        g = face.glyph
        g.render(freetype.FT_RENDER_MODE_NORMAL)
        bm = g.bitmap
        left, top = g.bitmap_left, g.bitmap_top
        # Oversampled screen pixel of bitmap (c, r): (ox8 + left + c, oy8 - top + r).
        sums = {}
        buf, pitch = bm.buffer, bm.pitch  # (the property copies the buffer)
        for r in range(bm.rows):
            for c in range(bm.width):
                v = buf[r * pitch + c]
                if v:
                    X, Y = (ox8 + left + c) // OS, (oy8 - top + r) // OS
                    sums[(X, Y)] = sums.get((X, Y), 0) + v
        if sums:
            x0 = min(x for x, _ in sums); x1 = max(x for x, _ in sums) + 1
            y0 = min(y for _, y in sums); y1 = max(y for _, y in sums) + 1
        else:
            x0 = y0 = x1 = y1 = 0
        w, h = x1 - x0, y1 - y0
        data = "".join("%04x" % sums.get((x, y), 0) for y in range(y0, y1) for x in range(x0, x1))
        fx, fy = ox8 * 1024 // OS, oy8 * 1024 // OS
        lines.append(f"{size} {ord(ch)} {fx} {fy} {x0} {y0} {w} {h} {data}")

with open(OUT, "w") as f:
    f.write("# FreeType %d.%d.%d unhinted, 8x oversampled, 8x8 sums; see make_freetype_ref.py\n" % freetype.version())
    f.write("\n".join(lines) + "\n")
print(OUT, len(lines), "glyphs")
