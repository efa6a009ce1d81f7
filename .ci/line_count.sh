#!/usr/bin/env bash
# Issue #34: each example program of host-sim/examples/ against its
# embedded-graphics twin (NAME.rs vs NAME_eg.rs), in non-blank,
# non-comment lines (after rustfmt; `//` and `//!` lines are comments).
# Prints a Markdown table; fails when a softedge program is not shorter
# than its twin.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../host-sim/examples"

count() {
    awk '{ sub(/^[ \t]+/, "") } $0 != "" && $0 !~ /^\/\// { n++ } END { print n + 0 }' "$1"
}

status=0
echo "| program | softedge | embedded-graphics twin |"
echo "| --- | ---: | ---: |"
for twin in *_eg.rs; do
    name="${twin%_eg.rs}"
    a=$(count "$name.rs")
    b=$(count "$twin")
    echo "| $name | $a | $b |"
    if [ "$a" -ge "$b" ]; then
        echo "FAIL: $name.rs ($a lines) is not shorter than $twin ($b)" >&2
        status=1
    fi
done
exit "$status"
