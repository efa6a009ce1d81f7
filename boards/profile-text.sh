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
for tool in cargo qemu-system-arm cc python3; do
    command -v "$tool" >/dev/null || { echo "profile-text.sh: $tool not found" >&2; exit 1; }
done

fw="$here/bench-text"
(cd "$fw" && cargo build --quiet --release)
elf="$fw/target/thumbv6m-none-eabi/release/softedge-bench-text"

build="$fw/target/insn-profile"
mkdir -p "$build"
plugin="$build/libinsn-profile.so"
if [ ! -e "$plugin" ] || [ "$here/tools/insn-profile.c" -nt "$plugin" ]; then
    cc -shared -fPIC -O2 -Wall -Wextra -std=c11 -o "$plugin" "$here/tools/insn-profile.c"
fi

nm_tool=$(ls "$(rustc --print sysroot)"/lib/rustlib/*/bin/llvm-nm 2>/dev/null | head -n 1 || true)
[ -n "$nm_tool" ] || nm_tool=$(command -v llvm-nm || command -v nm || true)
[ -n "$nm_tool" ] || { echo "profile-text.sh: no llvm-nm or nm (rustup component add llvm-tools)" >&2; exit 1; }
mark() {
    local a
    a=$("$nm_tool" "$elf" | awk -v s="$1" '$3 == s { print $1; exit }')
    [ -z "$a" ] || printf '%x' $(( 0x$a & ~1 ))
}
on=$(mark bench_profile_on)
off=$(mark bench_profile_off)
[ -n "$on" ] && [ -n "$off" ] || { echo "profile-text.sh: marks not found in $elf" >&2; exit 1; }

out="$build/profile-label.txt"
echo "== qemu: label_prerasterized"
timeout 300 qemu-system-arm -machine mps2-an385 -nographic \
    -semihosting-config enable=on,target=native -icount shift=0 \
    -plugin "$plugin,out=$out,on=$on,off=$off" \
    -kernel "$elf" \
    | grep -E '^(insns label|error)' || { echo "profile-text.sh: the firmware run failed" >&2; exit 1; }
echo
python3 "$here/tools/profile-report.py" "$elf" "$out" "$@"
