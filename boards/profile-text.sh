#!/usr/bin/env bash
# Where the instructions of issue #33's label frame go, by function: runs
# the Cortex-M0 text benchmark firmware (boards/bench-text) under QEMU with
# the insn-profile TCG plugin (boards/tools/insn-profile.c) and prints the
# top functions, the instruction mix and a Cortex-M0+ cycle estimate
# (boards/tools/profile-report.py), as boards/profile-m0.sh does for the
# shape benchmark. The plugin counts between the firmware's marks
# bench_profile_on / bench_profile_off, which surround the frame of the
# 55-glyph label drawn with the bundled 16-px font rasterized ahead
# (`label_prerasterized` in bench-text.sh's output; the frame in all, the
# empty frame's 0.12 M included).
#
# Usage: bash boards/profile-text.sh [--top N]
# Needs what profile-m0.sh needs: qemu-system-arm, cc, python3, llvm-nm.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# shellcheck source=tools/profile-lib.sh
. "$here/tools/profile-lib.sh"
echo "== qemu: label_prerasterized"
profile_firmware profile-text.sh "$here/bench-text" softedge-bench-text \
    profile-label '^(insns label|error)' "" "$@"
