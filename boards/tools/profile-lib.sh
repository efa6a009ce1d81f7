# Shared by boards/profile-m0.sh and boards/profile-text.sh (sourced, not
# run): build a benchmark firmware, run it under QEMU with the insn-profile
# TCG plugin counting between its marks bench_profile_on / bench_profile_off,
# and print the report (boards/tools/profile-report.py).
#
# profile_firmware <name> <firmware dir> <elf name> <out file stem> <grep pattern> <qemu -append or ""> [report args...]

profile_firmware() {
    local name=$1 fw=$2 elf_name=$3 stem=$4 pattern=$5 append=$6
    shift 6
    local here
    here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
    for tool in cargo qemu-system-arm cc python3; do
        command -v "$tool" >/dev/null || { echo "$name: $tool not found" >&2; exit 1; }
    done
    (cd "$fw" && cargo build --quiet --release)
    local elf="$fw/target/thumbv6m-none-eabi/release/$elf_name"

    local build="$fw/target/insn-profile"
    mkdir -p "$build"
    local plugin="$build/libinsn-profile.so"
    if [ ! -e "$plugin" ] || [ "$here/tools/insn-profile.c" -nt "$plugin" ]; then
        cc -shared -fPIC -O2 -Wall -Wextra -std=c11 -o "$plugin" "$here/tools/insn-profile.c"
    fi

    # The window marks: entry addresses of the two functions (Thumb bit off).
    local nm_tool
    nm_tool=$(ls "$(rustc --print sysroot)"/lib/rustlib/*/bin/llvm-nm 2>/dev/null | head -n 1 || true)
    [ -n "$nm_tool" ] || nm_tool=$(command -v llvm-nm || command -v nm || true)
    [ -n "$nm_tool" ] || { echo "$name: no llvm-nm or nm (rustup component add llvm-tools)" >&2; exit 1; }
    mark() {
        local a
        a=$("$nm_tool" "$elf" | awk -v s="$1" '$3 == s { print $1; exit }')
        [ -z "$a" ] || printf '%x' $(( 0x$a & ~1 ))
    }
    local on off
    on=$(mark bench_profile_on)
    off=$(mark bench_profile_off)
    [ -n "$on" ] && [ -n "$off" ] || { echo "$name: marks not found in $elf" >&2; exit 1; }

    local out="$build/$stem.txt"
    local extra=()
    [ -z "$append" ] || extra=(-append "$append")
    timeout 300 qemu-system-arm -machine mps2-an385 -nographic \
        -semihosting-config enable=on,target=native -icount shift=0 \
        -plugin "$plugin,out=$out,on=$on,off=$off" \
        -kernel "$elf" "${extra[@]}" \
        | grep -E "$pattern" || { echo "$name: the firmware run failed" >&2; exit 1; }
    echo
    python3 "$here/tools/profile-report.py" "$elf" "$out" "$@"
}
