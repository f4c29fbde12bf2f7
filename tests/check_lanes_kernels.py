#!/usr/bin/env python3
"""The lanes' kernels (engine/math/lanes.h: PHOTON_LANES_KERNEL) call nothing out of line.

Each kernel is compiled three times, for AVX-512, AVX2 and the baseline CPU, from one
always-inline body. A helper or lambda the compiler leaves out of line is compiled once,
for the baseline, and an AVX-512 or AVX2 kernel calling it passes vectors in a way it does
not expect: a crash, or worse, wrong numbers. Whether GCC inlines a plain helper depends on
what else is in the translation unit (its inlining limits count per unit, and a unity
build groups files by how many there are), so a build that passes today can break when a
file is added. This reads the engine library's machine code and fails on any call or jump
from an AVX-512 or AVX2 kernel into another function, sanitizer hooks aside.

Usage: check_lanes_kernels.py LIBRARY
"""
import re
import subprocess
import sys

ALLOWED = re.compile(r"^(__asan_|__ubsan_|__tsan_|__sanitizer_|__msan_|__stack_chk_fail|memcpy|memset|memmove)")
HEADER = re.compile(r"^[0-9a-f]+ <(.*)>:$")
BRANCH = re.compile(r"\t(call|jmp)\w*\s+[0-9a-f]+ <([^>+]*)(\+0x[0-9a-f]+)?>")


KERNEL = re.compile(r"(\w+)(Avx512|Avx2)\(")


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    dump = subprocess.run(["objdump", "-d", "-C", "--no-show-raw-insn", sys.argv[1]], check=True,
                          capture_output=True, text=True).stdout
    kernels = {"Avx512": 0, "Avx2": 0}
    problems = []
    current = None
    for line in dump.splitlines():
        header = HEADER.match(line)
        if header:
            kernel = KERNEL.search(header.group(1))
            current = header.group(1) if kernel else None
            if kernel:
                kernels[kernel.group(2)] += 1
            continue
        if current is None:
            continue
        branch = BRANCH.search(line)
        if not branch:
            continue
        target = branch.group(2)
        if target == current or ALLOWED.match(target) or target.endswith("@plt") and ALLOWED.match(target[:-4]):
            continue
        problems.append(f"{KERNEL.search(current).group(0)[:-1]} -> {branch.group(1)} {target}")
    if min(kernels.values()) == 0:
        print(f"no lanes kernels found in {sys.argv[1]}: {kernels}")
        return 1
    for p in sorted(set(problems)):
        print(p)
    print(f"{kernels['Avx512']} AVX-512 and {kernels['Avx2']} AVX2 kernels, {len(set(problems))} out-of-line calls")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
