#!/usr/bin/env bash
# Lists the panic call sites that survive optimisation in a board's release
# firmware (what makes `cargo build --release --features no-panic` fail to
# link): one line per source location, the innermost frame outside the Rust
# standard library, with the kind of panic and how many call sites.
#
# Needs: rustup component add llvm-tools (llvm-nm, llvm-objdump) and
# llvm-symbolizer (Debian: apt-get install -y llvm).
# Usage: bash boards/panic-sites.sh qemu-m0|qemu-m3
set -euo pipefail

board="${1:-qemu-m0}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cd "$here/$board"
bin="$(rustc --print sysroot)/lib/rustlib/x86_64-unknown-linux-gnu/bin"
target="$(sed -n 's/^target = "\(.*\)"/\1/p' .cargo/config.toml)"
elf="target/$target/release/softedge-$board"
cargo build --quiet --release

# Addresses of the panic entry points (their names in the demangled table).
"$bin/llvm-nm" -C "$elf" |
    awk '$3 ~ /^core::(panicking|slice::index|option|result)::/ {print $1, $3}' >"$elf.panics"
# Every branch-with-link into one of them, outside the panic machinery itself.
"$bin/llvm-objdump" -d --no-show-raw-insn "$elf" |
    awk -v list="$elf.panics" '
        BEGIN { while ((getline l < list) > 0) { split(l, f, " "); a = f[1]; sub(/^0+/, "", a); want["0x" a] = f[2] } }
        /^[0-9a-f]+ <.*>:$/ { fn = $2; next }
        $2 == "bl" && ($3 in want) && fn !~ /4core9panicking|4core5slice5index/ {
            sub(":", "", $1); print "0x" $1, want[$3]
        }' |
    while read -r addr kind; do
        frame="$(llvm-symbolizer --obj="$elf" -C -i "$addr" | paste - - |
            awk -F'\t' '{last = $2 "  " $1} $2 !~ /^\/rustc\// {print last; found = 1; exit} END {if (!found) print last}')"
        printf '%s  %s\n' "${frame:-?}" "${kind##*::}"
    done |
    sed -e "s|$(cd "$here/.." && pwd)/||" -e 's/::h[0-9a-f]\{16\}//g' \
        -e 's/\$LT\$/</g; s/\$GT\$/>/g; s/\$u7b\$/{/g; s/\$u7d\$/}/g; s/\$C\$/,/g' |
    sort | uniq -c | sort -k2
