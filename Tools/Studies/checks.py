"""The checks of the Python test scripts (testStudyRunner.py, Tools/Calibration/testCalibrationFit.py):
each check prints "ok" or "FAIL" with what it checked; finish ends the script with the count of
failures, or the line its ctest case waits for."""
import sys

failures = []


def check(condition, message):
    print(("ok    " if condition else "FAIL  ") + message)
    if not condition:
        failures.append(message)


def finish(name):
    if failures:
        sys.exit(f"{name}: {len(failures)} checks failed")
    print(f"{name}: all checks passed")
