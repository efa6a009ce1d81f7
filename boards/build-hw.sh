#!/usr/bin/env bash
# Builds the real-hardware firmware (boards/rp2040-st7789 for the Raspberry
# Pi Pico, boards/esp32c3-ssd1306 for the ESP32-C3) and prints their sizes.
# Flashes nothing and runs nothing: see boards/README.md for that.
#
# Adds the two Rust targets (and llvm-tools, for llvm-size/llvm-nm) through
# rustup when they are missing; builds with the committed Cargo.lock files
# (--locked).
#
# Usage: bash boards/build-hw.sh      (from anywhere)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

boards=(
    "rp2040-st7789 thumbv6m-none-eabi softedge-rp2040-st7789"
    "esp32c3-ssd1306 riscv32imc-unknown-none-elf softedge-esp32c3-ssd1306"
)

installed="$(rustup target list --installed)"
for target in thumbv6m-none-eabi riscv32imc-unknown-none-elf; do
    if ! grep -qx "$target" <<<"$installed"; then
        rustup target add "$target"
    fi
done

sysroot="$(rustc --print sysroot)"
host="$(rustc -vV | sed -n 's/^host: //p')"
bin="$sysroot/lib/rustlib/$host/bin"
if [ ! -x "$bin/llvm-size" ]; then
    rustup component add llvm-tools >/dev/null 2>&1 || true
fi

for entry in "${boards[@]}"; do
    read -r dir target name <<<"$entry"
    echo "== build $dir ($target)"
    start=$(date +%s)
    (cd "$here/$dir" && cargo build --release --locked)
    echo "build_seconds $dir $(($(date +%s) - start))"
done

if [ ! -x "$bin/llvm-size" ]; then
    echo "build-hw.sh: llvm-size not available (rustup component add llvm-tools); sizes skipped"
    exit 0
fi

for entry in "${boards[@]}"; do
    read -r dir target name <<<"$entry"
    elf="$here/$dir/target/$target/release/$name"
    echo "== size $dir"
    "$bin/llvm-size" "$elf"
    # Section by section, without debug info and empty sections.
    "$bin/llvm-size" -A "$elf" | awk 'NR > 2 && $1 !~ /^\.debug/ && $2 > 0 && $1 != "Total"'
    if [ "$dir" = esp32c3-ssd1306 ]; then
        echo "(esp32c3: Berkeley 'text' counts .stack, the free DRAM left to the stack, and"
        echo " .rotext_dummy, address-space padding; the flash image is .trap + .rwtext +"
        echo " .data + .flash.appdesc + .rodata + .text)"
    fi
    # Code and tables of softedge (core) that survived as symbols of their
    # own; what LTO inlined into the firmware's functions is not counted.
    "$bin/llvm-nm" --demangle --print-size --size-sort --radix=d "$elf" |
        awk '$4 ~ /^<?softedge::/ { n += $2 } END { printf "softedge_symbols_bytes %d\n", n }'
done
