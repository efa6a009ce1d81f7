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

for tool in cargo qemu-system-arm cc python3; do
    command -v "$tool" >/dev/null || { echo "profile-m0.sh: $tool not found" >&2; exit 1; }
done

fw="$here/bench-m0"
(cd "$fw" && cargo build --quiet --release)
elf="$fw/target/thumbv6m-none-eabi/release/softedge-bench-m0"

build="$fw/target/insn-profile"
mkdir -p "$build"
plugin="$build/libinsn-profile.so"
if [ ! -e "$plugin" ] || [ "$here/tools/insn-profile.c" -nt "$plugin" ]; then
    cc -shared -fPIC -O2 -Wall -Wextra -std=c11 -o "$plugin" "$here/tools/insn-profile.c"
fi

# The window marks: entry addresses of the two functions (Thumb bit off).
nm_tool=$(ls "$(rustc --print sysroot)"/lib/rustlib/*/bin/llvm-nm 2>/dev/null | head -n 1 || true)
[ -n "$nm_tool" ] || nm_tool=$(command -v llvm-nm || command -v nm || true)
[ -n "$nm_tool" ] || { echo "profile-m0.sh: no llvm-nm or nm (rustup component add llvm-tools)" >&2; exit 1; }
mark() {
    local a
    a=$("$nm_tool" "$elf" | awk -v s="$1" '$3 == s { print $1; exit }')
    [ -z "$a" ] || printf '%x' $(( 0x$a & ~1 ))
}
on=$(mark bench_profile_on)
off=$(mark bench_profile_off)
[ -n "$on" ] && [ -n "$off" ] || { echo "profile-m0.sh: marks not found in $elf" >&2; exit 1; }

out="$build/profile-$renderer-$workload${rows:+-$rows}.txt"
echo "== qemu: $renderer $workload ${rows:+(bands of $rows rows)}"
timeout 300 qemu-system-arm -machine mps2-an385 -nographic \
    -semihosting-config enable=on,target=native -icount shift=0 \
    -plugin "$plugin,out=$out,on=$on,off=$off" \
    -kernel "$elf" -append "$renderer $workload $rows" \
    | grep -E '^(insns|image|error)' || { echo "profile-m0.sh: the firmware run failed" >&2; exit 1; }
echo
python3 "$here/tools/profile-report.py" "$elf" "$out" "$@"
