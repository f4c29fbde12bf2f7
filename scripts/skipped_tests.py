#!/usr/bin/env python3
"""Names every gtest case that called GTEST_SKIP, from the XML reports the test programs
write (--gtest_output=xml, CMakeLists.txt's photon_add_test_program): ctest runs each
program as one test, so it sees a program pass and not the cases inside that skipped.

Usage: skipped_tests.py REPORT_DIR  (prints "program: Suite.Case: message", one a line)
"""
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path


def skipped(report: Path):
    for case in ElementTree.parse(report).getroot().iter("testcase"):
        if case.get("result") == "skipped":
            reason = case.find("skipped")
            message = (reason.get("message") or "").strip().splitlines() if reason is not None else []
            yield f"{report.stem}: {case.get('classname')}.{case.get('name')}" + (f": {message[-1]}" if message else "")


def main() -> int:
    reports = Path(sys.argv[1])
    for report in sorted(reports.glob("*.xml")) if reports.is_dir() else []:
        try:
            for line in skipped(report):
                print(line)
        except ElementTree.ParseError as error:  # a program that crashed mid-write
            print(f"{report.stem}: its report could not be read ({error})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
