"""Module/ctest_display_retry.py reruns only display-connection failures: a
ctest JUnit report with one test aborted on "bad X server connection" (the
output of a real Xvfb refusal here), one failed on an image difference and one
passed; the script's parser must find both failures and classify only the
first as a display failure.

Usage: TestDisplayRetry.py MODULE_DIR
"""
import os
import sys
import tempfile

sys.path.insert(0, sys.argv[1])
import ctest_display_retry as retry  # noqa: E402

REPORT = """<?xml version="1.0" encoding="UTF-8"?>
<testsuite name="x" tests="3" failures="2">
  <testcase name="A.Display" status="fail"><failure message="Subprocess aborted"/>
    <system-out>vtkXOpenGLRenderWindow (0x5650fe102950): bad X server connection. DISPLAY=:101. Aborting.</system-out>
  </testcase>
  <testcase name="B.Image" status="fail"><failure message="Failed"/>
    <system-out>FAILED: TestX.png differs from its baseline: mean 16.6 p99 108 max 133</system-out>
  </testcase>
  <testcase name="C.Good" status="run"><system-out>ok</system-out></testcase>
</testsuite>
"""

with tempfile.NamedTemporaryFile("w", suffix=".xml", delete=False) as f:
    f.write(REPORT)
failures = retry.failed(f.name)
os.unlink(f.name)
real = retry.real_failures(failures)
print("failed:", sorted(failures), "not display:", real)
if sorted(failures) != ["A.Display", "B.Image"] or real != ["B.Image"]:
    print("FAILED: display-connection failures are not told from real ones")
    sys.exit(1)
