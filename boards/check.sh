#!/usr/bin/env bash
# Bit identity of the reference scenes on the host, on Cortex-M0 and on
# Cortex-M3: renders every scene of softedge-refscenes four ways and fails
# unless the four `crc <scene> <crc32>` listings (host example, softedge-sim
# crc of the scene files, Cortex-M0, Cortex-M3) are identical line for line.
#
# Installs nothing. Needs (once per machine):
#   rustup target add thumbv6m-none-eabi thumbv7m-none-eabi
#   apt-get install -y qemu-system-arm        # QEMU >= 7.2 (Debian 12)
#
# Usage: bash boards/check.sh      (from anywhere)
# Prints the host listing, then the boards' extra lines (instruction counts,
# stack depth) and each QEMU run's wall time.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

for tool in cargo qemu-system-arm timeout; do
    command -v "$tool" >/dev/null || { echo "check.sh: $tool not found (see the header of $0)" >&2; exit 1; }
done
installed="$(rustup target list --installed 2>/dev/null || true)"
for target in thumbv6m-none-eabi thumbv7m-none-eabi; do
    grep -qx "$target" <<<"$installed" || { echo "check.sh: rustup target add $target" >&2; exit 1; }
done

echo "== host"
(cd "$root" && cargo run --quiet --release -p softedge-refscenes --example host_crc) >"$out/host.full"
grep '^crc ' "$out/host.full" >"$out/host" || true
cat "$out/host"
scenes=$(wc -l <"$out/host")
[ "$scenes" -gt 0 ] || { echo "check.sh: the host printed no crc line" >&2; exit 1; }

status=0
# The same scenes as scene files (refscenes/scenes/, generated from the Rust
# data by host-sim/tests/refscenes_toml.rs), through the simulator's CLI.
echo "== softedge-sim crc refscenes/scenes/*.toml"
(cd "$root" && cargo build --quiet --release -p softedge-sim)
: >"$out/sim"
while read -r _ name _; do
    "$root/target/release/softedge-sim" crc "$root/refscenes/scenes/$name.toml" >>"$out/sim"
done <"$out/host"
if diff -u "$out/host" "$out/sim"; then
    echo "softedge-sim: $scenes crc lines identical to the host"
else
    echo "check.sh: softedge-sim crc differs from the host (diff above)" >&2
    status=1
fi

for board in qemu-m0 qemu-m3; do
    echo "== $board"
    (cd "$here/$board" && cargo build --quiet --release)
    start=$(date +%s%N)
    # The firmware ends QEMU itself through semihosting (exit status 0, or 1
    # on a failed scene or a panic); the timeout catches a hang.
    if ! (cd "$here/$board" && timeout 120 cargo run --quiet --release) >"$out/$board.full" 2>"$out/$board.err"; then
        echo "check.sh: $board failed or timed out" >&2
        cat "$out/$board.full" "$out/$board.err" >&2
        status=1
        continue
    fi
    end=$(date +%s%N)
    grep '^crc ' "$out/$board.full" >"$out/$board" || true
    grep -v '^crc ' "$out/$board.full" || true
    ms=$(( (end - start) / 1000000 ))
    printf 'qemu_seconds %d.%03d\n' $((ms / 1000)) $((ms % 1000))
    if diff -u "$out/host" "$out/$board"; then
        echo "$board: $scenes crc lines identical to the host"
    else
        echo "check.sh: $board differs from the host (diff above)" >&2
        status=1
    fi
done
exit $status
