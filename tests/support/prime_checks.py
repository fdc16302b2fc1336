"""What the end-to-end check scripts share: running the real `prime` without
a display, and collecting the checks that fail.

    checks = Checks(PRIME_EXE)
    r = checks.run(["trace", scene, "-q"])
    checks.check(r.returncode == 0, "trace exits 0")
    sys.exit(checks.report("camera hand-off"))
"""
import os
import subprocess


class Checks:
    def __init__(self, prime):
        self.prime = prime
        self.failures = []

    def run(self, args):
        env = dict(os.environ, DISPLAY="", WAYLAND_DISPLAY="")
        return subprocess.run([self.prime] + args, capture_output=True, text=True, env=env)

    def check(self, ok, what):
        if not ok:
            self.failures.append(what)
        return ok

    def report(self, what):
        """Prints the failures and a last line; returns the exit status."""
        for f in self.failures:
            print("FAIL:", f)
        print(f"{what}: {len(self.failures)} failure(s)")
        return 1 if self.failures else 0
