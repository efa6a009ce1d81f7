#!/usr/bin/env bash
# The Cortex-M0 benchmark: builds boards/bench-m0 (thumbv6m-none-eabi), runs
# it under qemu-system-arm -machine mps2-an385 -icount shift=0, and prints
# a Markdown table of instruction counts: per renderer the fixed cost of a
# 240x240 frame (no triangles: clear, resolve, gamma, pack, flush), the
# marginal instructions per pixel of triangle area for each size class,
#     (insns(N = 2000) - insns(N = 1)) / (summed area of triangles 2..2000),
# and the 132-triangle screen; then the screen at band heights 16..1.
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
$1 == "workload" { tris[$2] = $3; area2[$2] = $4; marginal2[$2] = $5 }
$1 == "insns" {
    r = $2; w = $3; n = $4; rows = $5
    if (!(r in seen)) { seen[r] = 1; order[++nr] = r }
    if (w == "empty") fixed[r] = $6
    else if (w == "screen") { screen[r, rows] = $6; if (rows == 16 || rows == 240) screen16[r] = $6 }
    else if (n == 1) one[r, w] = $6
    else all[r, w] = $6
}
END {
    label["aa_rgb"] = "softedge AA flat RGB, Rgb565"
    label["aa_gouraud"] = "softedge AA Gouraud RGB, Rgb565"
    label["aa_gray"] = "softedge AA gray, Gray8"
    label["aliased_rgb"] = "softedge aliased flat RGB, Rgb565"
    label["aa_rgb_nocache"] = "softedge AA flat RGB, Rgb565, no walk cache"
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
    printf "|\n| --- |"
    for (k = 1; k <= 7; k++) printf " ---: |"
    printf "\n"
    for (i = 1; i <= nr; i++) {
        r = order[i]
        if (!((r, 8) in screen)) continue
        printf "| %s ", (r in label ? label[r] : r)
        for (k = 1; k <= 7; k++) printf "| %s ", mega(screen[r, bh[k]])
        printf "|\n"
    }
    printf "\nRaw counts (instructions per frame):\n\n```\n"
    for (i = 1; i <= nr; i++) {
        r = order[i]
        printf "%-12s N=0 %s", r, group(fixed[r])
        for (k = 1; k <= 3; k++) if ((r, cls[k]) in all) printf "  %s 1: %s 2000: %s", cls[k], group(one[r, cls[k]]), group(all[r, cls[k]])
        printf "\n"
    }
    printf "```\n"
}' "$out"
ms=$(( (end - start) / 1000000 ))
printf '\nqemu_seconds %d.%03d\n' $((ms / 1000)) $((ms % 1000))
