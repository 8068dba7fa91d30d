#!/usr/bin/env python3
"""check_headers.py SRC [MAX] - prints each C file of kernel/, analytic/ and verify/ (their
tests/ included) whose header (the comment lines before the first line of code or the
first blank line) is over MAX lines (15), as "FILE LINES"; exits 1 if there is one.  A
header says what the file does and the equations it cites; histories go to
docs/findings.md."""
import glob
import os
import sys


def header_lines(path):
    n, inside = 0, False
    for line in open(path, encoding="utf-8").read().split("\n"):
        s = line.strip()
        if inside:
            n += 1
            inside = "*/" not in s
        elif s.startswith("//"):
            n += 1
        elif s.startswith("/*"):
            n += 1
            inside = "*/" not in s[2:]
        else:
            break
    return n


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "."
    most = int(sys.argv[2]) if len(sys.argv) > 2 else 15
    long = []
    for d in ("kernel", "analytic", "verify"):
        for f in sorted(glob.glob(os.path.join(src, d, "*.[ch]")) + glob.glob(os.path.join(src, d, "tests", "*.[ch]"))):
            n = header_lines(f)
            if n > most:
                long.append("%s %d" % (os.path.relpath(f, src), n))
    print("\n".join(long))
    return 1 if long else 0


if __name__ == "__main__":
    sys.exit(main())
