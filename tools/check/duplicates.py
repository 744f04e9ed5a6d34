"""Reads `lizard -Eduplicate` output on stdin; fails on any repeated block not allowlisted.

Usage: lizard -Eduplicate FILES | python3 tools/check/duplicates.py ALLOWLIST
ALLOWLIST lines: `file_a file_b ...  # reason`. A block is allowed when every file it spans is on
one line (a single file on a line allows a block repeated inside that file).
"""

import re
import sys


def read_allowlist(path):
    allowed = set()
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if line:
                allowed.add(frozenset(line))
    return allowed


def read_blocks(lines):
    blocks, current = [], None
    for line in lines:
        if line.startswith("Duplicate block:"):
            current = []
            blocks.append(current)
        elif current is not None and re.match(r"^\S+:\d+ ~ \d+$", line.strip()):
            current.append(line.strip())
    return blocks


def main():
    allowed = read_allowlist(sys.argv[1])
    new = []
    for block in read_blocks(sys.stdin):
        files = frozenset(place.split(":")[0] for place in block)
        if not any(files <= group for group in allowed):
            new.append(block)
    for block in new:
        print("repeated block:\n  " + "\n  ".join(block))
    if new:
        print(
            f"{len(new)} repeated block(s): share the code, or allowlist the pair with its "
            f"reason in {sys.argv[1]}"
        )
        return 1
    print("no repeated blocks outside the allowlist")
    return 0


if __name__ == "__main__":
    sys.exit(main())
