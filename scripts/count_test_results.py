#!/usr/bin/python3
"""Counts the test cases in the JUnit/gtest XML files under a catkin test_results directory.

Usage: count_test_results.py TEST_RESULTS_DIR

Prints one line per result file, then every failed test case with the start of its message, and
as the LAST line "N passed, N failed" (", N skipped" appended when some were skipped or disabled).
Exits 1 if any test failed or errored, if a result file is unreadable, or if there are no results.

What counts:
- gtest files: each <testcase> once; <failure>/<error> -> failed; <skipped> or status "notrun"
  (GTEST_SKIP, DISABLED_) -> skipped.
- MISSING-*.xml: catkin writes one when a test wrote no result file, e.g. a test binary that
  crashed. It holds one failed placeholder case, counted as a failure.
- rostest-*.xml: rostest's wrapper case per test node only checks that the node wrote results;
  the node's own cases are in rosunit-*.xml and are counted there. A passing wrapper is therefore
  not counted again, a failing one (node crashed, timed out, wrote nothing) is a failure.
- A suite whose failures/errors attributes exceed its failed cases (a failure outside any test
  case) adds the difference as failures.
Uses only the standard library, so it runs with Debian's /usr/bin/python3.
"""

import os
import sys
import xml.etree.ElementTree as ET

ROSTEST_WRAPPER_CLASS = "rostest.runner.RosTest"
MESSAGE_CHARS = 300


class Counts:
    def __init__(self):
        self.passed = 0
        self.failed = 0
        self.skipped = 0

    def add(self, other):
        self.passed += other.passed
        self.failed += other.failed
        self.skipped += other.skipped

    def text(self):
        line = "%d passed, %d failed" % (self.passed, self.failed)
        if self.skipped:
            line += ", %d skipped" % self.skipped
        return line


def first_lines(text):
    text = (text or "").strip()
    if len(text) > MESSAGE_CHARS:
        text = text[:MESSAGE_CHARS] + "..."
    return text.replace("\n", "\n      ")


def case_outcome(case):
    """'failed', 'skipped' or 'passed', and the failure message."""
    for tag in ("failure", "error"):
        problem = case.find(tag)
        if problem is not None:
            return "failed", problem.get("message") or problem.text or tag
    if (
        case.find("skipped") is not None
        or case.get("status") == "notrun"
        or case.get("result") in ("skipped", "suppressed")
    ):
        return "skipped", ""
    return "passed", ""


def int_attribute(element, name):
    try:
        return int(element.get(name, "0"))
    except ValueError:
        return 0


def suites_of(root):
    if root.tag == "testsuite":
        return [root]
    if root.tag == "testsuites":
        return root.findall("testsuite")
    raise ValueError("root element is <%s>, not <testsuites> or <testsuite>" % root.tag)


def count_file(path, name, failures):
    """Counts of one result file; appends (label, message) of each failure to `failures`."""
    counts = Counts()
    try:
        root = ET.parse(path).getroot()
        suites = suites_of(root)
    except (ET.ParseError, ValueError, OSError) as error:
        counts.failed += 1
        failures.append(("%s: unreadable result file" % name, str(error)))
        return counts
    for suite in suites:
        suite_name = suite.get("name", "?")
        failed_here = 0
        for case in suite.findall("testcase"):
            outcome, message = case_outcome(case)
            wrapper = case.get("classname") == ROSTEST_WRAPPER_CLASS
            if wrapper and outcome == "passed":
                continue  # the node's own cases are in its rosunit-*.xml
            label = "%s: %s.%s" % (name, case.get("classname") or suite_name, case.get("name", "?"))
            if outcome == "failed":
                counts.failed += 1
                failed_here += 1
                failures.append((label, message))
            elif outcome == "skipped":
                counts.skipped += 1
            else:
                counts.passed += 1
        declared = int_attribute(suite, "failures") + int_attribute(suite, "errors")
        if declared > failed_here:
            counts.failed += declared - failed_here
            failures.append(
                (
                    "%s: suite %s" % (name, suite_name),
                    "%d failure(s) outside any test case" % (declared - failed_here),
                )
            )
    return counts


def result_files(directory):
    found = []
    for dirpath, dirnames, filenames in os.walk(directory):
        dirnames.sort()
        for filename in sorted(filenames):
            if filename.endswith(".xml"):
                found.append(os.path.join(dirpath, filename))
    return found


def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 2
    directory = argv[1]
    files = result_files(directory) if os.path.isdir(directory) else []

    total = Counts()
    failures = []
    for path in files:
        name = os.path.relpath(path, directory)
        counts = count_file(path, name, failures)
        print("%-60s %s" % (name, counts.text()))
        total.add(counts)

    if failures:
        print("\nFailed:")
        for label, message in failures:
            print("  FAIL %s" % label)
            if message:
                print("      %s" % first_lines(message))
        print()

    if not files:
        print("count_test_results.py: no test result files under %s" % directory, file=sys.stderr)
        total.failed += 1
    elif total.passed + total.failed == 0:
        print("count_test_results.py: the result files hold no test that ran", file=sys.stderr)
        total.failed += 1
    print(total.text())
    return 1 if total.failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
