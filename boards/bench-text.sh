#!/usr/bin/env bash
# The Cortex-M0 text benchmark (issues #17 and #33): builds boards/bench-text
# (thumbv6m-none-eabi), runs it under qemu-system-arm -machine mps2-an385
# -icount shift=0 and prints instructions per glyph of softedge::text at
# 12 and 24 px (320x240 Rgb565 frame, 16-row bands, the bundled font), then
# the flash of the same firmware built without the `text` feature (same
# frame loop and shape, no parser, no font) and with it (llvm-size).
#
# Installs nothing. Needs: rustup target add thumbv6m-none-eabi;
# apt-get install -y qemu-system-arm; llvm-size (llvm, or rustup component
# add llvm-tools).
#
# Issue #33: the 55-glyph label "The quick brown\nfox: 0123 °C\nSphinx of
# black\nquartz 3.71 V" in a 16-px font, white on black, 240x240 Rgb565,
# 16-row bands, drawn with embedded-graphics' Text and softedge's
# AaTextStyle: instructions over the empty frame (the marginal cost) with
# the bundled font rasterized ahead of time (text::bundled::SANS_16), and
# with the bundled outline font through a GlyphCache (its first frame, and
# the next, every glyph found); the flash of the 16-px fonts rasterized
# ahead of time (the bundled font; DejaVu Sans with all of ASCII and
# Latin-1).
#
# Usage: bash boards/bench-text.sh [RAW_FILE]
#   RAW_FILE: also write machine-readable lines there:
#     label <prerasterized|outline_cached> <glyphs> <marginal instructions>
#     font_flash <bytes>     (the 16-px ASCII + Latin-1 font)
set -euo pipefail
raw="${1:-}"

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
fw="$here/bench-text"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT
size_tool=$(ls "$(rustc --print sysroot)"/lib/rustlib/*/bin/llvm-size 2>/dev/null | head -n 1 || true)
[ -n "$size_tool" ] || size_tool=$(command -v llvm-size || true)

(cd "$fw" && cargo build --quiet --release --no-default-features --target-dir target/without-text)
(cd "$fw" && cargo build --quiet --release)
if ! (cd "$fw" && timeout 300 cargo run --quiet --release) >"$out"; then
    echo "bench-text.sh: the firmware failed or timed out" >&2
    cat "$out" >&2
    exit 1
fi
grep -qx done "$out" || { echo "bench-text.sh: no done line" >&2; cat "$out" >&2; exit 1; }

awk '
$1 == "insns" { n[$2] = $3; v[$2] = $4 }
function per(name, base) { return (v[name] - v[base]) / n[name] }
END {
    printf "Cortex-M0 (thumbv6m) under qemu-system-arm -machine mps2-an385 -icount shift=0; 320x240 Rgb565, the bundled font, four lines\n\n"
    printf "| size | glyphs | per glyph, 16-row bands | per glyph, one 240-row band | per glyph, 16-row bands, tolerance 1/64 px | layout only (measure), per glyph |\n"
    printf "| --- | ---: | ---: | ---: | ---: | ---: |\n"
    split("12 24", sz, " ")
    for (k = 1; k <= 2; k++) {
        s = sz[k]
        printf "| %s px | %d | %.0f | %.0f | %.0f | %.0f |\n", s, n["text" s], per("text" s, "empty"), per("text" s "_1band", "empty_1band"), per("text" s "_tol16", "empty"), v["measure" s] / n["measure" s]
    }
    printf "\nOpening the font (Font::new): %d instructions. Frame without text: %d (16-row bands), %d (one band).\n", v["parse"], v["empty"], v["empty_1band"]
}' "$out"
grep -E "^(stack_bytes|font_bytes)" "$out"

echo
awk '
$1 == "insns" && $2 ~ /^label_/ { n[$2] = $3; v[$2] = $4 }
$1 == "font_flash" { g[$2] = $3; f[$2] = $4 }
$1 == "cache" { used = $2; kept = $3; ram = $4 }
function row(name, label, empty,   m) {
    m = v[name] - v[empty == "" ? "label_empty" : empty]
    printf "| %s | %d | %.3f M | %.3f M | %.1f k |\n", label, n[name], v[name] / 1e6, m / 1e6, m / n[name] / 1e3
}
END {
    printf "Issue #33 label, 240x240 Rgb565, 16-row bands, white on black (LVGL 9.5, Montserrat 16: 0.554 M, 10.1 k a glyph)\n\n"
    printf "| frame | glyphs | instructions | over the empty frame | per glyph |\n| --- | ---: | ---: | ---: | ---: |\n"
    row("label_prerasterized", "rasterized ahead (text::bundled::SANS_16)")
    row("label_prerasterized_lent", "the same, the band buffer lent (`Renderer::render_lent`, a DMA flush)", "label_empty_lent")
    row("label_outline_cached", "outline font, glyph cache warm")
    row("label_outline_first", "outline font, glyph cache cold (first frame)")
    row("label_outline", "outline font, no cache (text::Text)")
    printf "\nThe empty frame: %.3f M (its first frame, which clears the band buffer: %.3f M).\n", v["label_empty"] / 1e6, v["label_empty_first"] / 1e6
    printf "Glyph cache: %d code bytes in use for %d glyphs; %d bytes of RAM in all (codes, slots, rasterizer cells, the GlyphCache).\n", used, kept, ram
    printf "Flash of the 16-px fonts rasterized ahead: the bundled font (%d glyphs) %d bytes; DejaVu Sans ASCII + Latin-1 (%d glyphs) %d bytes.\n", g["sans16"], f["sans16"], g["latin1"], f["latin1"]
}' "$out"
if [ -n "$raw" ]; then
    awk '
    $1 == "insns" && $2 ~ /^label_/ { n[$2] = $3; v[$2] = $4 }
    $1 == "font_flash" && $2 == "latin1" { flash = $4 }
    END {
        printf "label prerasterized %d %d\n", n["label_prerasterized"], v["label_prerasterized"] - v["label_empty"]
        printf "label prerasterized_lent %d %d\n", n["label_prerasterized_lent"], v["label_prerasterized_lent"] - v["label_empty_lent"]
        printf "label outline_cached %d %d\n", n["label_outline_cached"], v["label_outline_cached"] - v["label_empty"]
        printf "font_flash %d\n", flash
    }' "$out" >"$raw"
fi

if [ -n "$size_tool" ]; then
    echo
    echo "Flash (llvm-size, bytes):"
    echo
    echo '```'
    "$size_tool" "$fw/target/without-text/thumbv6m-none-eabi/release/softedge-bench-text" | sed 's|'"$fw"'/||'
    "$size_tool" "$fw/target/thumbv6m-none-eabi/release/softedge-bench-text" | tail -n 1 | sed 's|'"$fw"'/||'
    echo '```'
    "$size_tool" -A "$fw/target/without-text/thumbv6m-none-eabi/release/softedge-bench-text" >"$out.a"
    "$size_tool" -A "$fw/target/thumbv6m-none-eabi/release/softedge-bench-text" >"$out.b"
    awk 'FNR == 1 { f++ } ($1 == ".text" || $1 == ".rodata") { s[f] += $2 }
         END { printf "\n.text + .rodata: %d without text, %d with text: +%d bytes (the font file is 16648 of them)\n", s[1], s[2], s[2] - s[1] }' "$out.a" "$out.b"
    rm -f "$out.a" "$out.b"
else
    echo "bench-text.sh: llvm-size not found; sizes skipped"
fi
