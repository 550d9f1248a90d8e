"""Shared helpers of the command-line tools' tests (tests/cli): named checks counted to a
closing 'N passed, M failed', files in the test's scratch folder, one run of the tool,
and the one-triangle STL the migrate decks name.

    T = clilib.Tool(sys.argv[1], "rs_migrate_")
    T.check("name", cond, detail)      # detail printed on failure
    T.migrate(deck)                    # (exit status, stdout, stderr)
    T.finish()                         # prints the count, removes the folder, exits
"""
import os
import shutil
import subprocess
import sys
import tempfile

# One triangle in the z = 0 plane: a mesh a deck can name (rigidsurf-migrate reads every
# mesh it migrates and stops at one it cannot find, as LIGGGHTS does).
TRI = ("solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n"
       "   vertex 0 1 0\n  endloop\n endfacet\nendsolid t\n")


def close(a, b, tol=1e-12):
    """Element-wise equality to tol, relative above 1 and absolute below."""
    return all(abs(x - y) <= tol * max(1.0, abs(x), abs(y)) for x, y in zip(a, b))


class Tool:
    """One command-line tool under test and the scratch folder its inputs go to."""

    def __init__(self, exe, prefix):
        self.exe = os.path.abspath(exe)
        self.tmp = tempfile.mkdtemp(prefix=prefix)
        self.passed = 0
        self.failed = 0

    def check(self, name, cond, detail=""):
        """Counts and prints one check; detail is printed on failure. Returns cond."""
        if cond:
            self.passed += 1
            print("ok   " + name)
        else:
            self.failed += 1
            print("FAIL " + name + (": " + detail if detail else ""))
        return cond

    def write(self, name, text):
        """Writes text to name in the scratch folder, as it is (no newline
        translation); returns the path."""
        path = os.path.join(self.tmp, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", newline="") as f:
            f.write(text)
        return path

    def run(self, args, stdin=None, cwd=None, timeout=60):
        """Runs the tool with args; returns (exit status, stdout, stderr)."""
        p = subprocess.run([self.exe] + list(args), input=stdin, capture_output=True,
                           text=True, timeout=timeout, cwd=cwd)
        return p.returncode, p.stdout, p.stderr

    def migrate(self, deck, args=(), name="in.deck", cwd="scratch"):
        """Writes deck to name and runs the tool on it, in the scratch folder unless cwd
        says otherwise (None: this process's folder)."""
        path = self.write(name, deck)
        return self.run([path] + list(args), cwd=self.tmp if cwd == "scratch" else cwd)

    def finish(self):
        """Prints the count, removes the scratch folder and exits: 1 on a failure or when
        nothing was checked."""
        print("%d passed, %d failed" % (self.passed, self.failed))
        shutil.rmtree(self.tmp, ignore_errors=True)
        sys.exit(1 if self.failed or not self.passed else 0)
