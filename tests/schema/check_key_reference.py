#!/usr/bin/env python3
"""Fails when the committed key reference differs from `softbody schema --markdown` (it is generated).

Usage: check_key_reference.py SOFTBODY REFERENCE_MD
Regenerate with: build/softbody schema --markdown > docs/guide/scene-keys.md
"""
import difflib
import pathlib
import subprocess
import sys


def main():
    softbody, reference = sys.argv[1], pathlib.Path(sys.argv[2])
    generated = subprocess.run([softbody, "schema", "--markdown"], check=True, capture_output=True, text=True).stdout
    committed = reference.read_text(encoding="utf-8") if reference.exists() else ""
    if generated == committed:
        print(f"{reference} is current")
        return 0
    sys.stdout.writelines(difflib.unified_diff(committed.splitlines(True), generated.splitlines(True),
                                               str(reference), "softbody schema --markdown"))
    print(f"\n{reference} is stale: regenerate it with `softbody schema --markdown > {reference}`")
    return 1


if __name__ == "__main__":
    sys.exit(main())
