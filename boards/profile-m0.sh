#!/usr/bin/env bash
# Where the instructions of one benchmark frame go, by function: runs the
# Cortex-M0 benchmark firmware (boards/bench-m0) under QEMU with the
# insn-profile TCG plugin (boards/tools/insn-profile.c, built here with cc)
# and prints the top functions, the instruction mix and a Cortex-M0+ cycle
# estimate (boards/tools/profile-report.py).
#
# Usage: bash boards/profile-m0.sh <renderer> <workload> [band rows] [--top N]
#   renderer: aa_rgb aa_gouraud aa_gray aliased_rgb aa_rgb_rows eg_fill eg_stock_fb
#   workload: small medium large screen slanted empty
#   e.g. bash boards/profile-m0.sh aa_rgb medium
#        bash boards/profile-m0.sh aa_rgb screen 16
# The firmware runs only that frame (all of the workload's triangles; see
# boards/bench-m0/src/cmdline.rs), and the plugin counts only between the
# firmware's marks bench_profile_on / bench_profile_off around it, so the
# profile is the measured frame's (start-up and reporting left out).
#
# Needs: qemu-system-arm (QEMU 7.2 accepts -plugin), a C compiler (cc),
# python3, and llvm-nm or nm (rustup component add llvm-tools gives
# llvm-nm and llvm-symbolizer; with llvm-symbolizer the report also charges
# inlined code to the function it was written in).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if [ $# -lt 2 ]; then
    sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//' >&2
    exit 2
fi
renderer=$1
workload=$2
shift 2
rows=""
if [ $# -gt 0 ] && [[ $1 =~ ^[0-9]+$ ]]; then
    rows=$1
    shift
fi

# shellcheck source=tools/profile-lib.sh
. "$here/tools/profile-lib.sh"
echo "== qemu: $renderer $workload ${rows:+(bands of $rows rows)}"
profile_firmware profile-m0.sh "$here/bench-m0" softedge-bench-m0 \
    "profile-$renderer-$workload${rows:+-$rows}" '^(insns|image|error)' \
    "$renderer $workload $rows" "$@"
