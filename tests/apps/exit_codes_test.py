"""One exit code per class of outcome (common/exit_codes.h, docs/reliability.md), the same on
every command: a table of cases, each a command line with the class it must end in."""

import os
import subprocess
import tempfile
import unittest

BIN = os.environ.get(
    "SSC_BIN_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "build", "bin")
)
SSC = os.path.abspath(os.path.join(BIN, "ssc"))
OK, USAGE, MISSING, BAD_DATA, TRIAL_FAILED = 0, 2, 3, 4, 5
COMMANDS = [
    "probe",
    "trial",
    "sweep",
    "validate",
    "equivalence",
    "objects",
    "view",
    "compare",
    "stability",
    "calibrate",
    "charts",
    "tune",
    "sil",
    "bench",
]


def cases(tmp):
    bad_xml = os.path.join(tmp, "bad.xml")
    with open(bad_xml, "w") as f:
        f.write("<mujoco><worldbody><geom type='nonsense'/></worldbody></mujoco>\n")
    garbage = os.path.join(tmp, "garbage.csv")
    with open(garbage, "w") as f:
        f.write("this,is\nnot,a log\n")
    binary = os.path.join(tmp, "bin.py")
    with open(binary, "wb") as f:
        f.write(b"\x7fELF\x00\x01")
    absent = os.path.join(tmp, "absent")
    out = os.path.join(tmp, "out")
    rows = [(["no_such_command"], USAGE), ([], USAGE)]
    rows += [([c, "--no-such-option"], USAGE) for c in COMMANDS]
    rows += [
        (["trial", "--scene", "no_such_scene", "--out", out], MISSING),
        (["sweep", "--scene", "no_such_scene", "--out", out], MISSING),
        (["validate", "--scene", "no_such_scene", "--out", out], MISSING),
        (["validate", "--map", absent + ".csv", "--out", out], MISSING),
        (["view", "no_such_scene"], MISSING),
        (["view", "--scene", "no_such_scene"], MISSING),
        (["compare", absent + ".csv", "--out", out], MISSING),
        (["stability", "--scene", "no_such_scene", "--out", out], MISSING),
        (["tune", "--scene", "no_such_scene", "--out", out], MISSING),
        (["sil", absent + ".py"], MISSING),
        (["trial", "--scene", bad_xml, "--out", out], BAD_DATA),
        (["sweep", "--scene", bad_xml, "--out", out], BAD_DATA),
        (["compare", garbage, "--out", out], BAD_DATA),
        (["validate", "--map", garbage, "--out", out], BAD_DATA),
        (["sil", "--out", out, binary], BAD_DATA),
        (
            ["trial", "--start-offset", "200", "--timeout", "5", "--no-plot", "--out", out],
            TRIAL_FAILED,
        ),
        (["--version"], OK),
        (["trial", "--help"], OK),
    ]
    return rows


SRC = os.environ.get("SSC_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


class ExitCodesTest(unittest.TestCase):
    def test_the_documented_table_is_the_codes_home(self):
        import re

        with open(os.path.join(SRC, "common", "exit_codes.h")) as f:
            home = re.findall(r'\{k\w+, "(\w+)",', f.read())
        with open(os.path.join(SRC, "common", "exit_codes.h")) as f:
            values = dict(re.findall(r"(k\w+) = (\d+),", f.read()))
        with open(os.path.join(SRC, "docs", "reliability.md")) as f:
            doc = re.findall(r"^\| (\d+) \| (\w+) \|", f.read(), re.M)
        self.assertEqual([name for _, name in doc], home)
        self.assertEqual(
            sorted(int(code) for code, _ in doc), sorted(int(v) for v in values.values())
        )

    def test_each_class_ends_in_its_code_on_every_command(self):
        tmp = tempfile.mkdtemp(prefix="ssc_exit_codes_")
        try:
            for args, code in cases(tmp):
                with self.subTest(args=" ".join(args)):
                    r = subprocess.run(
                        [SSC] + args, capture_output=True, text=True, cwd=tmp, timeout=300
                    )
                    self.assertEqual(r.returncode, code, (r.stdout + r.stderr)[-800:])
                    if code not in (OK, TRIAL_FAILED):
                        self.assertTrue((r.stdout + r.stderr).strip(), "no message")
        finally:
            import shutil

            shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    unittest.main()
