#!/usr/bin/env python3
"""Instruction profile of a Cortex-M0 (thumbv6m) firmware run under QEMU.

Reads the per-PC counts written by the insn-profile plugin
(boards/tools/insn-profile.c: lines `<pc hex> <size> <encoding hex>
<executions> <taken>`), maps every PC to its function with the ELF's symbol
table (llvm-nm, or nm), and prints the top functions with their share of
the instructions. With llvm-symbolizer (or llvm-addr2line) it also charges
each instruction to the source function it was inlined from, which is
where the time goes in an LTO build.

It also decodes each instruction (ARMv6-M Thumb) into a class and
estimates Cortex-M0+ cycles from the documented timings of the Cortex-M0+
Technical Reference Manual (table 3.1, zero wait states, single-cycle
multiplier as on the RP2040): data processing 1, MULS 1, loads and stores
2, LDM/STM/PUSH 1+N, POP 1+N (3+N with PC), B<cond> 2 taken / 1 not taken,
B 2, BL 3, BX/BLX 2, ADD/MOV to PC 2, MRS/MSR/DMB/DSB/ISB 3 (rare here).
Exception entry and wait states are not modelled.

Usage: profile-report.py ELF PROFILE [--top N]
"""

import argparse
import bisect
import collections
import os
import re
import shutil
import subprocess
import sys


def llvm_tool(name):
    """The rustup llvm-tools binary if installed, else one on PATH."""
    try:
        sysroot = subprocess.run(
            ["rustc", "--print", "sysroot"], capture_output=True, text=True, check=True
        ).stdout.strip()
        for d in os.listdir(os.path.join(sysroot, "lib", "rustlib")):
            p = os.path.join(sysroot, "lib", "rustlib", d, "bin", name)
            if os.access(p, os.X_OK):
                return p
    except (OSError, subprocess.CalledProcessError):
        pass
    return shutil.which(name)


HASH = re.compile(r"::h[0-9a-f]{16}$")
LLVM_SUFFIX = re.compile(r" ?\(?\.llvm\.\d+\)?$")
# Rust's legacy mangling escapes, which older demanglers leave in place.
ESCAPES = {
    "$LT$": "<", "$GT$": ">", "$C$": ",", "$RF$": "&", "$BP$": "*",
    "$LP$": "(", "$RP$": ")", "$SP$": "@", "$u20$": " ", "$u27$": "'",
    "$u5b$": "[", "$u5d$": "]", "$u7b$": "{", "$u7d$": "}", "$u7e$": "~",
}
ESCAPE = re.compile("|".join(re.escape(k) for k in ESCAPES))


def clean(name):
    """A readable Rust name: legacy escapes undone, hash suffix dropped."""
    name = LLVM_SUFFIX.sub("", HASH.sub("", name))
    if "$" in name:
        name = re.sub(r"(^|::)_(?=\$)", r"\1", name)
        name = ESCAPE.sub(lambda m: ESCAPES[m.group(0)], name).replace("..", "::")
    return name


def symbols(elf):
    """Sorted (start, end, name) of the ELF's function symbols."""
    nm = llvm_tool("llvm-nm") or shutil.which("nm")
    if nm is None:
        sys.exit("profile-report: no llvm-nm or nm (rustup component add llvm-tools)")
    out = subprocess.run(
        [nm, "-n", "-S", "--defined-only", "-C", elf],
        capture_output=True, text=True, check=True,
    ).stdout
    syms = []
    for line in out.splitlines():
        parts = line.split(None, 3)
        if len(parts) == 4 and parts[2] in "tTwW":
            addr, size, name = int(parts[0], 16) & ~1, int(parts[1], 16), parts[3]
            syms.append((addr, addr + size, clean(name)))
        elif len(parts) == 3 and parts[1] in "tT":
            # Labels without size (assembly): up to the next symbol.
            syms.append((int(parts[0], 16) & ~1, None, clean(parts[2])))
    syms.sort()
    fixed = []
    for k, (a, e, n) in enumerate(syms):
        if e is None or e <= a:
            e = syms[k + 1][0] if k + 1 < len(syms) else a + 2
        fixed.append((a, e, n))
    return fixed


def inline_names(elf, pcs):
    """{pc: innermost source function} from the debug info, or None."""
    tool = llvm_tool("llvm-symbolizer") or shutil.which("llvm-symbolizer")
    if tool is None:
        return None
    query = "".join(f"0x{pc:x}\n" for pc in pcs)
    try:
        out = subprocess.run(
            [tool, f"--obj={elf}", "--inlining", "--functions=linkage", "--demangle"],
            input=query, capture_output=True, text=True, check=True,
        ).stdout
    except (OSError, subprocess.CalledProcessError):
        return None
    names = {}
    blocks = out.split("\n\n")
    for pc, block in zip(pcs, blocks):
        lines = block.strip().splitlines()
        # Pairs of (function, file:line:col), innermost first.
        names[pc] = clean(lines[0]) if lines and lines[0] != "??" else "??"
    return names


def popcount(v):
    return bin(v).count("1")


def classify(enc, size):
    """(class, base cycles, extra cycles when the branch is taken)."""
    if size == 4 and (enc & 0xFFFF) >> 11 >= 0x1D:
        hi, lo = enc & 0xFFFF, enc >> 16
        if (hi & 0xF800) == 0xF000 and (lo & 0xD000) == 0xD000:
            return "call", 3, 0  # BL
        return "system", 3, 0  # MRS, MSR, DMB, DSB, ISB
    op = enc & 0xFFFF
    if op >> 11 == 0b01001:
        return "load", 2, 0  # LDR literal
    if op >> 12 == 0b0101:
        return ("store" if ((op >> 9) & 7) < 3 else "load"), 2, 0
    if op >> 13 == 0b011 or op >> 12 in (0b1000, 0b1001):
        return ("load" if op & 0x0800 else "store"), 2, 0
    if op >> 10 == 0b010000:
        if (op >> 6) & 0xF == 0b1101:
            return "multiply", 1, 0  # MULS
        return "alu", 1, 0
    if op >> 10 == 0b010001:
        kind = (op >> 8) & 3
        if kind == 3:
            return ("call" if op & 0x80 else "return/jump"), 2, 0  # BLX / BX
        rd = (op & 7) | ((op >> 4) & 8)
        if kind in (0, 2) and rd == 15:
            return "return/jump", 2, 0  # ADD PC / MOV PC
        return "alu", 1, 0
    if op >> 12 == 0b1011:
        if (op & 0x0600) == 0x0400:
            low = popcount(op & 0xFF)
            if op & 0x0800:
                if op & 0x0100:
                    return "return/jump", 3 + low, 0  # POP {.., PC}
                return "load multiple", 1 + low, 0  # POP
            n = low + ((op >> 8) & 1)  # LR counts
            return "store multiple", 1 + n, 0  # PUSH
        return "alu", 1, 0  # SP adjust, extend, reverse, CPS, hints
    if op >> 12 == 0b1100:
        n = popcount(op & 0xFF)
        return ("load multiple" if op & 0x0800 else "store multiple"), 1 + n, 0
    if op >> 12 == 0b1101:
        if (op >> 8) & 0xF >= 0xE:
            return "system", 1, 0  # UDF, SVC
        return "cond branch", 1, 1  # 2 cycles when taken
    if op >> 11 == 0b11100:
        return "branch", 2, 0
    return "alu", 1, 0  # ADR, ADD SP, shifts, add/sub, mov/cmp imm


def bl_target(pc, enc):
    """The target of a BL at `pc` (encoding: first halfword in the low half)."""
    hi, lo = enc & 0xFFFF, enc >> 16
    s = (hi >> 10) & 1
    i1 = 1 - (((lo >> 13) & 1) ^ s)
    i2 = 1 - (((lo >> 11) & 1) ^ s)
    imm = (s << 24) | (i1 << 23) | (i2 << 22) | ((hi & 0x3FF) << 12) | ((lo & 0x7FF) << 1)
    if s:
        imm -= 1 << 25
    return pc + 4 + imm


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("elf")
    ap.add_argument("profile")
    ap.add_argument("--top", type=int, default=15)
    args = ap.parse_args()

    per_pc = {}
    for line in open(args.profile):
        pc, size, enc, execs, taken = line.split()
        pc, execs, taken = int(pc, 16), int(execs), int(taken)
        e = per_pc.setdefault(pc, [int(size), int(enc, 16), 0, 0])
        e[2] += execs
        e[3] += taken
    if not per_pc:
        sys.exit("profile-report: empty profile")

    syms = symbols(args.elf)
    starts = [s[0] for s in syms]

    def function_of(pc):
        k = bisect.bisect_right(starts, pc) - 1
        if k >= 0 and syms[k][0] <= pc < syms[k][1]:
            return syms[k][2]
        return f"?? 0x{pc:x}"

    pcs = sorted(per_pc)
    inlined = inline_names(args.elf, pcs)

    total = cycles_total = 0
    by_fn = collections.defaultdict(lambda: [0, 0])
    by_src = collections.defaultdict(lambda: [0, 0])
    by_class = collections.defaultdict(lambda: [0, 0])
    calls = collections.defaultdict(int)
    taken_total = cond_total = 0
    for pc in pcs:
        size, enc, execs, taken = per_pc[pc]
        cls, base, extra = classify(enc, size)
        taken = min(taken, execs)
        cyc = execs * base + (taken * extra if cls == "cond branch" else 0)
        if cls == "cond branch":
            cond_total += execs
            taken_total += taken
        total += execs
        cycles_total += cyc
        for table, key in ((by_fn, function_of(pc)), (by_class, cls)):
            table[key][0] += execs
            table[key][1] += cyc
        if cls == "call" and size == 4:
            caller = inlined.get(pc, "??") if inlined is not None else function_of(pc)
            calls[(function_of(bl_target(pc, enc)), caller)] += execs
        if inlined is not None:
            by_src[inlined.get(pc, "??")][0] += execs
            by_src[inlined.get(pc, "??")][1] += cyc

    print(
        f"{total:,} instructions in the profiled window; estimated Cortex-M0+ cycles "
        f"{cycles_total:,} (CPI {cycles_total / total:.2f})"
    )
    mix = ", ".join(
        f"{name} {v[0] / total:.1%}"
        for name, v in sorted(by_class.items(), key=lambda kv: -kv[1][0])
    )
    print(f"mix: {mix}; conditional branches taken {taken_total / max(cond_total, 1):.0%}")

    def table(title, rows):
        print()
        print(title)
        print(f"  {'insns':>6} {'cycles':>6}  {'instructions':>14}  function")
        for name, (n, c) in sorted(rows.items(), key=lambda kv: -kv[1][0])[: args.top]:
            print(f"  {n / total:6.1%} {c / cycles_total:6.1%}  {n:14,}  {name}")

    table("top functions (symbols: code inlined by LTO counts in its caller)", by_fn)
    if inlined is not None:
        table("top source functions (debug info: inlined code counts where it was written)", by_src)
    else:
        print("\n(no llvm-symbolizer: install rustup's llvm-tools for the inlined view)")
    print()
    print("most frequent calls (BL): callee <- calling source function")
    for (callee, caller), n in sorted(calls.items(), key=lambda kv: -kv[1])[: args.top]:
        print(f"  {n:14,}  {callee} <- {caller}")


if __name__ == "__main__":
    main()
