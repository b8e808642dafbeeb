"""The checks of the python tests (tests/harness/test_*.py, tests/trace/test_*.py): each
check prints one line, 'ok' or 'FAIL' with its name (and on failure what was seen), and
the run ends with 'LABEL: N passed, N failed', the line ./fixpipe check counts.

    T = Tally()
    T.check("a name", cond, detail)
    sys.exit(T.summary("label"))          # or T.run_tests(globals(), "label")
"""


class Tally:
    def __init__(self, indent=""):
        self.indent = indent
        self.passed = self.failed = 0

    def check(self, name, cond, detail=""):
        if cond:
            self.passed += 1
            print(f"{self.indent}ok   {name}")
        else:
            self.failed += 1
            print(f"{self.indent}FAIL {name}" + (f"\n{detail}" if detail else ""))

    def summary(self, label):
        """The closing line; the exit status: 1 on a failure."""
        print(f"{label}: {self.passed} passed, {self.failed} failed")
        return 1 if self.failed else 0

    def run_tests(self, namespace, label):
        """Every function test_* of namespace (a module's globals()) in name order, an
        exception in one a failed check and not the end of the run; then the summary."""
        for name, fn in sorted(namespace.items()):
            if name.startswith("test_"):
                print(f"{name}:")
                try:
                    fn()
                except Exception as e:  # a broken case is a failure, not the end of the suite
                    self.check(name, False, f"{type(e).__name__}: {e}")
        return self.summary(label)
