#!/usr/bin/env bash
# The Cortex-M0 text benchmark (issue #17): builds boards/bench-text
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
# Usage: bash boards/bench-text.sh
set -euo pipefail

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
