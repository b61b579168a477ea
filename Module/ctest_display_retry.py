"""Run ctest; rerun a failed test only when its output shows a display-connection
failure (Xvfb refuses an X connection now and then: XCB_CONN_ERROR, "bad X server
connection"), at most twice, and report every rerun. Any other failure fails.

Usage: ctest_display_retry.py BUILD_DIR [CTEST ARGS...]
"""
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

DISPLAY_FAILURE = re.compile(
    r"bad X server connection|XCB_CONN|cannot open display|Can't open display|"
    r"could not open display|Could not open X display|XOpenDisplay")
RETRIES = 2


def run(build, args, junit):
    command = ["ctest", "--test-dir", build, "--output-on-failure",
               "--output-junit", junit] + args
    return subprocess.call(command)


def failed(junit):
    """{name: output} of the failed tests in a ctest JUnit report."""
    result = {}
    for case in ET.parse(junit).getroot().iter("testcase"):
        if case.get("status") == "fail" or case.find("failure") is not None:
            output = "".join(e.text or "" for e in case.iter() if e.tag in ("system-out", "failure"))
            output += " ".join(e.get("message", "") for e in case.iter("failure"))
            result[case.get("name")] = output
    return result


def real_failures(failures):
    """The names of failed tests whose output shows no display-connection
    failure (these are never rerun)."""
    return sorted(n for n, out in failures.items() if not DISPLAY_FAILURE.search(out))


def main():
    build, args = sys.argv[1], sys.argv[2:]
    junit = os.path.join(os.path.abspath(build), "Testing", "ppiray-junit.xml")
    if run(build, args, junit) == 0:
        return 0
    failures = failed(junit)
    for attempt in range(1, RETRIES + 1):
        real = real_failures(failures)
        if real:
            print("[ppiray] failed: %s" % ", ".join(real), flush=True)
            return 1
        if not failures:
            print("[ppiray] ctest failed without a failed test", flush=True)
            return 1
        names = sorted(failures)
        print("[ppiray] rerun %d of %d for a display-connection failure: %s"
              % (attempt, RETRIES, ", ".join(names)), flush=True)
        pattern = "^(%s)$" % "|".join(re.escape(n) for n in names)
        filtered = [a for a in args]
        if run(build, filtered + ["-R", pattern], junit) == 0:
            print("[ppiray] passed on rerun %d: %s" % (attempt, ", ".join(names)), flush=True)
            return 0
        failures = failed(junit)
    print("[ppiray] still failing after %d reruns: %s" % (RETRIES, ", ".join(sorted(failures))),
          flush=True)
    return 1


if __name__ == "__main__":
    sys.exit(main())
