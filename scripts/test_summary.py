#!/usr/bin/python3
"""The closing count of scripts/test.sh over all its phases: reads the JUnit files ctest wrote
(--output-junit) and the fuzzers' status files, prints one line per phase, every failure and every
skip with its reason (a GTest skip's message, a pytest skip's reason from `-rs`), then one line
`N passed, N failed, N skipped`; exits 1 when anything failed or a phase left no result.

Usage: scripts/test_summary.py PHASE=PATH ...   (PATH: a JUnit XML file, or fuzz:DIR with the
       fuzzers' <target>.status files, 0 for a clean search)
"""
import pathlib
import re
import sys
import xml.etree.ElementTree as ET

SKIP_LINE = re.compile(r"^SKIPPED \[\d+\] (.*)$", re.M)           # pytest -rs
GTEST_SKIP = re.compile(r"^(?:.*: )?Skipped\n(.*)$", re.M)        # GTEST_SKIP() << "why"


def junit(path):
    """(passed, failed, skipped, [failures], [skip reasons]) of one ctest JUnit file."""
    root = ET.parse(path).getroot()
    passed = failed = skipped = 0
    failures, reasons = [], []
    for case in root.iter("testcase"):
        name = case.get("name")
        out = "".join(e.text or "" for e in case.iter("system-out"))
        status = case.get("status")
        if case.find("failure") is not None or status == "fail":
            failed += 1
            failures.append(name)
        elif case.find("skipped") is not None or status in ("notrun", "disabled"):
            skipped += 1
            why = GTEST_SKIP.search(out)
            reasons.append(f"{name}: {why.group(1).strip() if why else 'skipped'}")
        else:
            passed += 1
        # Skips inside a test that passed (one ctest test runs a whole pytest file).
        for reason in SKIP_LINE.findall(out):
            skipped += 1
            reasons.append(f"{name}: {reason.strip()}")
    return passed, failed, skipped, failures, reasons


def fuzz(directory):
    passed = failed = 0
    failures = []
    for status in sorted(pathlib.Path(directory).glob("*.status")):
        if status.read_text().strip() == "0":
            passed += 1
        else:
            failed += 1
            failures.append(status.stem)
    return passed, failed, 0, failures, []


def main(argv):
    totals = [0, 0, 0]
    missing = []
    for arg in argv:
        phase, _, path = arg.partition("=")
        if path.startswith("fuzz:"):
            result = fuzz(path[5:])
            empty = result[0] + result[1] == 0
        elif pathlib.Path(path).is_file():
            result = junit(path)
            empty = False
        else:
            result, empty = (0, 0, 0, [], []), True
        if empty:
            missing.append(phase)
            print(f"isopatch: {phase}: no results (the phase did not run to its end)")
            continue
        passed, failed, skipped, failures, reasons = result
        print(f"isopatch: {phase}: {passed} passed, {failed} failed, {skipped} skipped")
        for name in failures:
            print(f"isopatch:   failed: {name}")
        for reason in reasons:
            print(f"isopatch:   skipped: {reason}")
        totals = [totals[0] + passed, totals[1] + failed, totals[2] + skipped]
    print(f"isopatch: {totals[0]} passed, {totals[1]} failed, {totals[2]} skipped")
    return 1 if totals[1] or missing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
