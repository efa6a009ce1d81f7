#!/usr/bin/env bash
# The Cortex-M0 benchmark: builds boards/bench-m0 (thumbv6m-none-eabi), runs
# it under qemu-system-arm -machine mps2-an385 -icount shift=0, and prints
# a Markdown table of instruction counts: per renderer the fixed cost of a
# 240x240 frame (no triangles: clear, resolve, gamma, pack, flush), the
# marginal instructions per pixel of triangle area for each size class,
#     (insns(N = 2000) - insns(N = 1)) / (summed area of triangles 2..2000),
# and the 132-triangle screen; then the screen at band heights 16..1, and
# (AA flat RGB, direct and listed) the screen with slanted cells in 16-
# and 3-row bands.
# Then (issue 16) a filled circle, a stroked arc gauge and a line chart (stroked
# in every band, or through a shape cache empty when the frame starts) alone
# on the frame, softedge (AaStyle) against embedded-graphics (PrimitiveStyle):
# the frame's instructions and the shape's marginal cost (frame with the
# shape - the same renderer's frame without it); and (issue 15) a dial
# scene rendered whole and in a 20x20 dirty rectangle (directly, and
# through a shape cache), with the bytes an
# ST7789 would be sent over SPI:
#     pixels * 2 + windows * (3 command + 8 parameter bytes)
# (CASET, RASET, RAMWR per window; softedge sends a window per band).
# Last (issue 14: the firmware's band height), the RP2040 firmware's
# panel (boards/rp2040-st7789/src/ui.rs), a whole frame and the mean of
# 60 partial redraws, by band height.
#
# Installs nothing. Needs (once per machine):
#   rustup target add thumbv6m-none-eabi
#   apt-get install -y qemu-system-arm        # QEMU >= 7.2 (Debian 12)
#
# Usage: bash boards/bench-m0.sh [RAW_OUTPUT_FILE]
# Exits non-zero when the firmware fails (a frame error, a panic, no
# `done` line) or QEMU times out.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
raw="${1:-}"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT

for tool in cargo qemu-system-arm timeout awk; do
    command -v "$tool" >/dev/null || { echo "bench-m0.sh: $tool not found (see the header of $0)" >&2; exit 1; }
done
rustup target list --installed 2>/dev/null | grep -qx thumbv6m-none-eabi \
    || { echo "bench-m0.sh: rustup target add thumbv6m-none-eabi" >&2; exit 1; }

(cd "$here/bench-m0" && cargo build --quiet --release)
start=$(date +%s%N)
# The firmware ends QEMU itself (semihosting exit: 0, or 1 on a failed
# frame or a panic); the timeout catches a hang.
if ! (cd "$here/bench-m0" && timeout 300 cargo run --quiet --release) >"$out"; then
    echo "bench-m0.sh: the firmware failed or timed out" >&2
    cat "$out" >&2
    exit 1
fi
end=$(date +%s%N)
if grep -q '^error' "$out" || ! grep -qx 'done' "$out"; then
    echo "bench-m0.sh: the firmware reported an error" >&2
    cat "$out" >&2
    exit 1
fi
[ -z "$raw" ] || cp "$out" "$raw"

awk '
# Thousands separated by a thin space-free comma: 1234567 -> 1,234,567.
function group(n,    s, r) {
    s = sprintf("%d", n); r = ""
    while (length(s) > 3) { r = "," substr(s, length(s) - 2) r; s = substr(s, 1, length(s) - 3) }
    return s r
}
function mega(n) { return sprintf("%.2f M", n / 1e6) }
function perpx(v) { return v >= 100 ? sprintf("%.0f", v) : sprintf("%.1f", v) }
$1 == "insns_per_tick" { tick = $2 }
$1 == "shape" {
    if (!($2 in sseen)) { sseen[$2] = 1; sorder[++ns] = $2 }
    shape[$2, $3] = $4
}
$1 == "redraw" {
    if (!($2 in rseen)) { rseen[$2] = 1; rorder[++nd] = $2 }
    redraw[$2, $3] = $4; windows[$2, $3] = $5; pixels[$2, $3] = $6; bytes[$2, $3] = $7
}
$1 == "cache" {
    if (!($2 in cseen)) { cseen[$2] = 1; corder[++nk] = $2 }
    cbytes[$2] = $3; cache[$2, $4] = $6; if ($4 == 3) b3 = $5
}
$1 == "cache_listed" { lcache[$2, $4] = $6 }
$1 == "workload" { tris[$2] = $3; area2[$2] = $4; marginal2[$2] = $5 }
$1 == "image" {
    if (!($2 in iseen)) { iseen[$2] = 1; iorder[++ni] = $2 }
    image[$2] = $3; iarea[$2] = $4
}
$1 == "image_lent" { ilent[$2] = $3 }
$1 == "dial_ram" {
    nram++; rslots[nram] = $2; rslotb[nram] = $3; rband[nram] = $4; rdma[nram] = $5; rstack[nram] = $6; rinsns[nram] = $7
}
$1 == "dial_rows" {
    nrows++; drows[nrows] = $2; dband[nrows] = $3; ddma[nrows] = $4; dstack[nrows] = $5; dinsns[nrows] = $6
}
$1 == "panel_shape_cache" { pcache_entries = $2; pcache_segments = $3 }
$1 == "panel" {
    if (!($2 in pseen)) { pseen[$2] = 1; porder[++np] = $2 }
    pbytes[$2] = $3; panel[$2, $4] = $5
}
$1 == "insns" {
    r = $2; w = $3; n = $4; rows = $5
    if (!(r in seen)) { seen[r] = 1; order[++nr] = r }
    if (w == "empty") fixed[r] = $6
    else if (w == "screen") { screen[r, rows] = $6; if (rows == 16 || rows == 240) screen16[r] = $6 }
    else if (w == "slanted") slanted[r, rows] = $6
    else if (w == "wscreen") { wscreen[r, rows] = $6; wseen[r] = 1 }
    else if (n == 1) one[r, w] = $6
    else all[r, w] = $6
}
END {
    label["aa_rgb"] = "softedge AA flat RGB, Rgb565"
    label["aa_gouraud"] = "softedge AA Gouraud RGB, Rgb565"
    label["aa_gray"] = "softedge AA gray, Gray8"
    label["aliased_rgb"] = "softedge aliased flat RGB, Rgb565"
    label["aa_rgb_nocache"] = "softedge AA flat RGB, Rgb565, no walk cache"
    label["aa_rgb_listed"] = "softedge AA flat RGB, Rgb565, `TriangleList` recorded in the frame"
    label["eg_fill"] = "e-g `Triangle` fill, framebuffer with slice `fill_solid`"
    label["eg_stock_fb"] = "e-g `Triangle` fill, e-g `Framebuffer` (`draw_iter`)"
    split("small medium large", cls, " ")
    printf "Cortex-M0 (thumbv6m-none-eabi) under qemu-system-arm -machine mps2-an385 -icount shift=0, "
    printf "240x240 frames, softedge in 16-row bands (insns_per_tick %s)\n\n", tick
    printf "| renderer | fixed cost of a frame (N = 0) "
    for (k = 1; k <= 3; k++) printf "| per px, %s (%.1f px) ", cls[k], area2[cls[k]] / 2 / tris[cls[k]]
    printf "| screen, 132 triangles, 16-row bands |\n"
    printf "| --- | ---: | ---: | ---: | ---: | ---: |\n"
    for (i = 1; i <= nr; i++) {
        r = order[i]
        printf "| %s | %s ", (r in label ? label[r] : r), mega(fixed[r])
        for (k = 1; k <= 3; k++) {
            w = cls[k]
            if ((r, w) in all) printf "| %s ", perpx((all[r, w] - one[r, w]) / (marginal2[w] / 2))
            else printf "| — "
        }
        printf "| %s |\n", mega(screen16[r])
    }
    printf "\nThe screen (132 triangles of about 436 px covering the frame once) by band height (rows per band), softedge:\n\n"
    split("16 8 6 4 3 2 1", bh, " ")
    printf "| renderer "
    for (k = 1; k <= 7; k++) printf "| %s ", bh[k]
    printf "| 3 rows / 16 rows |\n| --- |"
    for (k = 1; k <= 8; k++) printf " ---: |"
    printf "\n"
    for (i = 1; i <= nr; i++) {
        r = order[i]
        if (!((r, 8) in screen)) continue
        printf "| %s ", (r in label ? label[r] : r)
        for (k = 1; k <= 7; k++) printf "| %s ", mega(screen[r, bh[k]])
        printf "| %.3fx |\n", screen[r, 3] / screen[r, 16]
    }
    printf "\nThe same screen with its cells slanted (the bottom corners of each cell 7 px right of its top ones: no vertical edge; softedge walks vertical edges without set-up or state, so this shows what that path gives the screen):\n\n"
    printf "| renderer | 16 | 3 | 3 rows / 16 rows |\n| --- | ---: | ---: | ---: |\n"
    for (i = 1; i <= nr; i++) {
        r = order[i]
        if (!((r, 16) in slanted)) continue
        printf "| %s | %s | %s | %.3fx |\n", (r in label ? label[r] : r), mega(slanted[r, 16]), mega(slanted[r, 3]), slanted[r, 3] / slanted[r, 16]
    }
    split("wsmall wmedium wlarge", wcls, " ")
    printf "\nWell-shaped random triangles (issue 32: no angle below 40°, random size, rotation and 1/16-px position; embedded-graphics draws them rounded to whole pixels), "
    printf "per px as above, and 132 of the medium ones (overlapping at random) in 16- and 3-row bands:\n\n"
    printf "| renderer "
    for (k = 1; k <= 3; k++) printf "| per px, %s (%.1f px) ", wcls[k], area2[wcls[k]] / 2 / tris[wcls[k]]
    printf "| 132 medium, 16-row bands | 3-row bands | 3 rows / 16 rows |\n"
    printf "| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n"
    for (i = 1; i <= nr; i++) {
        r = order[i]
        if (!(r in wseen)) continue
        printf "| %s ", (r in label ? label[r] : r)
        for (k = 1; k <= 3; k++) {
            w = wcls[k]
            if ((r, w) in all) printf "| %s ", perpx((all[r, w] - one[r, w]) / (marginal2[w] / 2))
            else printf "| — "
        }
        if ((r, 3) in wscreen) printf "| %s | %s | %.3fx |\n", mega(wscreen[r, 16]), mega(wscreen[r, 3]), wscreen[r, 3] / wscreen[r, 16]
        else printf "| %s | — | — |\n", mega((r, 16) in wscreen ? wscreen[r, 16] : wscreen[r, 240])
    }
    printf "\nWhat the walk cache buys: the screen, softedge AA flat RGB, drawn directly and from a `TriangleList`, by walk-cache slots (caller-provided, `WalkSlot::<3>::SIZE` bytes each), "
    printf "and the RAM of the 3-row frame (band buffers, %s bytes, + cache; the list is 60 bytes a triangle more):\n\n", group(b3)
    printf "| walk-cache slots | cache bytes | 16-row bands | 3-row bands | 3 rows / 16 rows | listed, 16-row | listed, 3-row | 3 rows / 16 rows | 3-row RAM, band + cache |\n"
    printf "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n"
    for (i = 1; i <= nk; i++) {
        k = corder[i]
        printf "| %s | %s | %s | %s | %.3fx | %s | %s | %.3fx | %s |\n", k, group(cbytes[k]), mega(cache[k, 16]), mega(cache[k, 3]), \
            cache[k, 3] / cache[k, 16], mega(lcache[k, 16]), mega(lcache[k, 3]), lcache[k, 3] / lcache[k, 16], group(cbytes[k] + b3)
    }
    printf "\nRaw counts (instructions per frame):\n\n```\n"
    for (i = 1; i <= nr; i++) {
        r = order[i]
        printf "%-12s N=0 %s", r, group(fixed[r])
        for (k = 1; k <= 3; k++) if ((r, cls[k]) in all) printf "  %s 1: %s 2000: %s", cls[k], group(one[r, cls[k]]), group(all[r, cls[k]])
        printf "\n"
    }
    printf "```\n"
    slabel["aa_rgb"] = "softedge AA (`AaStyle`), 16-row bands"
    slabel["aa_rgb_lent"] = "softedge AA, the same with the band buffer lent (`Renderer::render_lent`)"
    slabel["eg_fill"] = "e-g aliased (`PrimitiveStyle`), framebuffer with slice `fill_solid`"
    slabel["eg_stock_fb"] = "e-g aliased (`PrimitiveStyle`), e-g `Framebuffer` (`draw_iter`)"
    # The shapes of workloads/src/render/ui.rs: a disc of radius 50; an
    # arc stroke of radius 90, width 12, sweep 270 degrees, butt caps, and
    # the same with round caps (two half discs of radius 6 more; e-g has
    # no caps and draws its butt-ended arc again).
    pi = atan2(0, -1)
    area["circle"] = pi * 50 * 50
    area["gauge"] = 270 / 360 * pi * (96 * 96 - 84 * 84)
    area["gauge_round"] = area["gauge"] + pi * 6 * 6
    printf "\nShapes alone on a 240x240 Rgb565 frame (issue 16), instructions; marginal = frame with the shape - frame without it (N = 0):\n\n"
    printf "| renderer | frame, no shape (N = 0) "
    printf "| circle r 50, marginal | per px (%.0f px) | circle, frame ", area["circle"]
    printf "| gauge arc r 90 w 12 270°, marginal | per px (%.0f px) | gauge, frame ", area["gauge"]
    printf "| gauge, round caps, marginal | per px (%.0f px) | gauge, round caps, frame |\n", area["gauge_round"]
    printf "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n"
    for (i = 1; i <= ns; i++) {
        r = sorder[i]
        printf "| %s | %s ", (r in slabel ? slabel[r] : r), group(shape[r, "none"])
        split("circle gauge gauge_round", sh, " ")
        for (k = 1; k <= 3; k++) {
            m = shape[r, sh[k]] - shape[r, "none"]
            printf "| %s | %s | %s ", group(m), perpx(m / area[sh[k]]), group(shape[r, sh[k]])
        }
        printf "|\n"
    }
    # The line chart of ui.rs: 60 points 4 px apart, stroke 3 px, miter
    # joins, butt caps; softedge strokes it in every band it meets, or
    # through a shape cache (`Renderer::with_shape_cache`, empty when the
    # frame starts: described in the first band, filled from the cache in
    # the others; e-g draws its polyline again for the second column).
    printf "\nA line chart (60 points, stroke 3 px, miter joins), instructions; marginal as above:\n\n"
    printf "| renderer | chart, marginal | chart, frame | shape cache, marginal | shape cache, frame |\n"
    printf "| --- | ---: | ---: | ---: | ---: |\n"
    for (i = 1; i <= ns; i++) {
        r = sorder[i]
        if (!((r, "chart") in shape)) continue
        printf "| %s | %s | %s | %s | %s |\n", (r in slabel ? slabel[r] : r), \
            group(shape[r, "chart"] - shape[r, "none"]), group(shape[r, "chart"]), \
            group(shape[r, "chart_cached"] - shape[r, "none"]), group(shape[r, "chart_cached"])
    }
    ilabel["copy64"] = "64x64 Rgb565 sprite, unscaled at a whole pixel (copy)"
    ilabel["rotated30"] = "64x64 Rgb565 sprite rotated 30° (bilinear)"
    ilabel["icon48"] = "24-px 1-bpp icon scaled to 48 px, tinted (bilinear mask)"
    if (ni > 0) {
        printf "\nImages alone on a 240x240 Rgb565 frame (issue 35), softedge `AaImage`, 16-row bands; marginal = frame with the image - frame without it, per px = marginal / image pixels on screen:\n\n"
        printf "| image | marginal | image px | per px | frame | band buffer lent (`render_lent`): marginal | per px |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n"
        for (i = 1; i <= ni; i++) {
            k = iorder[i]
            if (k == "none") continue
            m = image[k] - image["none"]
            ml = ilent[k] - ilent["none"]
            printf "| %s | %s | %s | %s | %s | %s | %s |\n", (k in ilabel ? ilabel[k] : k), group(m), group(iarea[k]), perpx(m / iarea[k]), group(image[k]), group(ml), perpx(ml / iarea[k])
        }
        printf "\n(frame without an image: %s)\n", group(image["none"])
    }
    rlabel["aa_rgb"] = "softedge AA, `render` / `render_window`, 16-row bands"
    rlabel["aa_rgb_lent"] = "softedge AA, the band buffer lent (`render_lent` / `render_window_lent`)"
    rlabel["aa_rgb_cache_first"] = "softedge AA, the same through a shape cache (`Renderer::with_shape_cache`, 25.6 KB of segments), its first frame"
    rlabel["aa_rgb_cached"] = "softedge AA, the same through the shape cache, a later frame"
    rlabel["eg_fill"] = "e-g aliased, framebuffer; window: the shapes meeting it, `clipped`"
    printf "\nPartial redraw (issue 15): the dial scene (8 shapes) whole, and only its 20x20 dirty rectangle at (110, 110); "
    printf "SPI bytes = pixels x 2 + windows x 11 (CASET + RASET + RAMWR, 3 command + 8 parameter bytes):\n\n"
    printf "| renderer | redrawn | instructions | windows | pixels sent | SPI bytes |\n"
    printf "| --- | --- | ---: | ---: | ---: | ---: |\n"
    split("full window", wh, " ")
    wlabel["full"] = "full frame 240x240"
    wlabel["window"] = "dirty 20x20"
    for (i = 1; i <= nd; i++) {
        r = rorder[i]
        for (k = 1; k <= 2; k++) {
            w = wh[k]
            printf "| %s | %s | %s | %s | %s | %s |\n", (r in rlabel ? rlabel[r] : r), wlabel[w], \
                group(redraw[r, w]), group(windows[r, w]), group(pixels[r, w]), group(bytes[r, w])
        }
    }
    if (nram > 0) {
        printf "\nRAM of the dial scene'"'"'s whole frame on the plain path (`Renderer::render`, 16-row bands), by walk-cache slots: "
        printf "band buffers (accumulator, cover scratch and tags), the walk cache, the one-band Rgb565 DMA buffer the firmware streams, "
        printf "and the stack the frame needs below its caller, bytes (issue 32'"'"'s goal: 32 KiB in all, 32,768):\n\n"
        printf "| walk-cache slots | band buffers | walk cache | DMA band | stack of the frame | total | instructions |\n"
        printf "| ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n"
        for (i = 1; i <= nram; i++) {
            printf "| %s | %s | %s | %s | %s | %s | %s |\n", rslots[i], group(rband[i]), group(rslotb[i]), group(rdma[i]), \
                group(rstack[i]), group(rband[i] + rslotb[i] + rdma[i] + rstack[i]), group(rinsns[i])
        }
    }
    if (nrows > 0) {
        printf "\nRAM of the dial scene'"'"'s whole frame on the plain path without a walk cache, by band height: "
        printf "band buffers, the one-band Rgb565 DMA buffer and the frame'"'"'s stack, bytes, and the frame'"'"'s instructions (32 KiB = 32,768):\n\n"
        printf "| band rows | band buffers | DMA band | stack of the frame | total | instructions |\n"
        printf "| ---: | ---: | ---: | ---: | ---: | ---: |\n"
        for (i = 1; i <= nrows; i++) {
            printf "| %s | %s | %s | %s | %s | %s |\n", drows[i], group(dband[i]), group(ddma[i]), group(dstack[i]), \
                group(dband[i] + ddma[i] + dstack[i]), group(dinsns[i])
        }
    }
    printf "\nThe RP2040 firmware'"'"'s panel (boards/rp2040-st7789/src/ui.rs: dial, ticks, needle, arc gauge with round caps, readout, button), "
    printf "softedge AA into a one-band stream; whole frame, and the mean of its partial redraws (frames 1..60, each from the one before, `render_window` per dirty rectangle), by band height:\n\n"
    printf "With a shape cache (`Renderer::with_shape_cache`; the panel'"'"'s outlines hold %s segments in %s entries), a later frame: the same measured after one whole frame filled the cache.\n\n", group(pcache_segments), pcache_entries
    printf "| band rows | band buffers, bytes | whole frame | partial redraw, mean | whole frame, shape cache | partial redraw, shape cache, mean |\n"
    printf "| ---: | ---: | ---: | ---: | ---: | ---: |\n"
    for (i = 1; i <= np; i++) {
        r = porder[i]
        printf "| %s | %s | %s | %s | %s | %s |\n", r, group(pbytes[r]), group(panel[r, "whole"]), group(panel[r, "partial"]), \
            group(panel[r, "whole_cached"]), group(panel[r, "partial_cached"])
    }
}' "$out"
ms=$(( (end - start) / 1000000 ))
printf '\nqemu_seconds %d.%03d\n' $((ms / 1000)) $((ms % 1000))
