"""The tally of failed checks of the Python test scripts (each prints its failures and exits 1 if any)."""
import sys

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAILED:", what)


def finish():
    if failures:
        print(f"{len(failures)} FAILURES")
        sys.exit(1)
    print("all passed")
