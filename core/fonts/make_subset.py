#!/usr/bin/env python3
"""Regenerates softedge's bundled font, `SoftedgeSans-Subset.ttf`.

A dev-time tool, not a build dependency: the subset it writes is committed.
It needs fontTools (`pip install fonttools`) and DejaVu Sans 2.37 (Debian's
`fonts-dejavu-core`: /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf).

    python3 core/fonts/make_subset.py [path/to/DejaVuSans.ttf]

What it keeps: printable ASCII (U+0020..U+007E) and a few symbols of
instrument displays (see EXTRA), the .notdef outline, the glyph outlines
(`glyf`), metrics, the GPOS `kern` feature and the legacy `kern` table.
What it drops: hinting instructions (softedge draws unhinted outlines),
every other layout feature and the glyph names.

The Bitstream Vera licence lets a modified font be distributed only under
a name without "Bitstream" or "Vera", so the family is renamed
"Softedge Sans Subset"; the copyright and licence notices stay in the
`name` table and in LICENSE-DejaVu.txt beside the font.
"""
import sys
from fontTools import subset
from fontTools.ttLib import TTFont

SRC = sys.argv[1] if len(sys.argv) > 1 else "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
OUT = __file__.rsplit("/", 1)[0] + "/SoftedgeSans-Subset.ttf" if "/" in __file__ else "SoftedgeSans-Subset.ttf"

ASCII = list(range(0x20, 0x7F))
# degree, plus-minus, micro, multiplication, division, middle dot, superscript
# two and three, one half, en and em dash, typographic quotes, bullet,
# ellipsis, euro, pound, ohm (Greek capital omega), arrows, less/greater or
# equal, not equal, almost equal, infinity, check mark.
EXTRA = [0xB0, 0xB1, 0xB5, 0xD7, 0xF7, 0xB7, 0xB2, 0xB3, 0xBD, 0x2013, 0x2014,
         0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2026, 0x20AC, 0xA3, 0x3A9,
         0x2190, 0x2191, 0x2192, 0x2193, 0x2264, 0x2265, 0x2260, 0x2248,
         0x221E, 0x2713]

LICENCE_SUMMARY = (
    "Fonts are (c) Bitstream (see name 0). DejaVu changes are in public domain. "
    "Subset and renamed by softedge. Licensed under the Bitstream Vera licence: "
    "see LICENSE-DejaVu.txt distributed with this font, or name 14."
)

opts = subset.Options()
opts.layout_features = ["kern"]
opts.legacy_kern = True
opts.hinting = False
opts.notdef_outline = True
opts.glyph_names = False
opts.name_IDs = [0, 1, 2, 3, 4, 5, 6, 13, 14]
opts.name_languages = [0x409]
opts.drop_tables += ["FFTM", "GDEF", "GSUB", "MATH"]

font = TTFont(SRC)
sub = subset.Subsetter(opts)
sub.populate(unicodes=ASCII + EXTRA)
sub.subset(font)

NEW = "Softedge Sans Subset"
for rec in font["name"].names:
    if rec.nameID in (1, 4):
        rec.string = NEW
    elif rec.nameID == 3:
        rec.string = NEW + " (from DejaVu Sans 2.37)"
    elif rec.nameID == 6:
        rec.string = "SoftedgeSans-Subset"
    elif rec.nameID == 13:
        # The full notice (4.7 k characters, 9.5 KB in UTF-16) is in
        # LICENSE-DejaVu.txt; the font keeps the copyright (name 0), this
        # summary and the licence's address (name 14).
        rec.string = LICENCE_SUMMARY
font.save(OUT)
print(OUT)
