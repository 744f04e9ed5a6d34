"""Progress of ssc sweep when stderr is not a terminal (batch jobs, logs): a line each time
another 5 % of the trials is done; none with --no-progress."""

import os
import shutil
import subprocess
import sys
import tempfile
import unittest

BIN = os.environ.get(
    "SSC_BIN_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "build", "bin")
)
SSC = os.path.join(BIN, "ssc")


class CliProgressTest(unittest.TestCase):
    def sweep(self, *extra):
        out = tempfile.mkdtemp(prefix="ssc_progress_")
        self.addCleanup(shutil.rmtree, out, True)
        return subprocess.run(
            [
                SSC,
                "sweep",
                "--pref",
                "100,1000",
                "--beta",
                "2",
                "--step",
                "7.5",
                "--repeats",
                "1",
                "--threads",
                "2",
                "--no-plot",
                "--out",
                out,
                *extra,
            ],
            capture_output=True,
            text=True,
            timeout=300,
        )

    def test_piped_stderr_gets_progress_lines(self):
        r = self.sweep()
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = [l for l in r.stderr.splitlines() if l.startswith("ssc sweep: ")]
        self.assertEqual(
            [l.split(" trials")[0] for l in lines], ["ssc sweep: 1/2", "ssc sweep: 2/2"], r.stderr
        )
        self.assertIn("(100 %)", lines[-1])
        self.assertNotIn("\r", r.stderr)  # no bar drawn into a log

    def test_no_progress_prints_none(self):
        r = self.sweep("--no-progress")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertNotIn("trials (", r.stderr)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
