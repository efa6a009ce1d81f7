#!/usr/bin/env bash
# Regenerates boards/bench-text/src/fonts/latin1.rs with softedge-sim's
# `font` command: DejaVu Sans (Debian's fonts-dejavu-core) at 16 px,
# printable ASCII and Latin-1, one phase.
#
# Usage: bash boards/bench-text/make-fonts.sh [path/to/DejaVuSans.ttf]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
dejavu="${1:-/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf}"
cargo run --quiet --release --manifest-path "$root/Cargo.toml" -p softedge-sim -- \
    font "$dejavu" --size 16 --chars latin1 --name SANS_16_LATIN1 -o "$here/src/fonts/latin1.rs"
