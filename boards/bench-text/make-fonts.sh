#!/usr/bin/env bash
# Regenerates the fonts of boards/bench-text/src/fonts with softedge-sim's
# `font` command (the bundled font, and DejaVu Sans from Debian's
# fonts-dejavu-core for the ASCII + Latin-1 figure).
#
# Usage: bash boards/bench-text/make-fonts.sh [path/to/DejaVuSans.ttf]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
dejavu="${1:-/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf}"
sim=(cargo run --quiet --release --manifest-path "$root/Cargo.toml" -p softedge-sim --)
"${sim[@]}" font --size 16 --chars latin1 --name SANS_16 -o "$here/src/fonts/sans16.rs"
"${sim[@]}" font "$dejavu" --size 16 --chars latin1 --name SANS_16_LATIN1 -o "$here/src/fonts/latin1.rs"
