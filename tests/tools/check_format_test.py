#!/usr/bin/env python3
"""tools/checks/check_format.py: every file of tools/checks/formatted_files.txt is formatted,
and the checker does fail (a synthetic tree with a listed file that is not formatted, a listed
file that does not exist, an unsorted list), and `add` formats a file and lists it, so a pass
means something.

Usage: check_format_test.py ROOT CLANG_FORMAT
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile

root = pathlib.Path(sys.argv[1])
clang_format = sys.argv[2]
checker = root / "tools" / "checks" / "check_format.py"


def run(tree, *args):
    return subprocess.run([sys.executable, str(checker), "--clang-format", clang_format, *args,
                           str(tree)], capture_output=True, text=True)


def run_add(tree, *files):
    return subprocess.run([sys.executable, str(checker), "--clang-format", clang_format, "add",
                           str(tree), *files], capture_output=True, text=True)


real = run(root, "check")
print(real.stdout + real.stderr, end="")
if real.returncode != 0:
    sys.exit("listed files are not formatted (tools/checks/check_format.py fix .)")

HEADER = "# test list\n"
UNFORMATTED = "int  f( int x ){return x;}\n"
with tempfile.TemporaryDirectory() as tmp:
    t = pathlib.Path(tmp)
    (t / "tools/checks").mkdir(parents=True)
    (t / "libemb").mkdir()
    shutil.copy(root / ".clang-format", t / ".clang-format")
    lst = t / "tools/checks/formatted_files.txt"

    def expect_failure(listed, fragment, what):
        lst.write_text(HEADER + listed)
        r = run(t, "check")
        if r.returncode != 1 or fragment not in r.stdout:
            print(r.stdout, r.stderr)
            sys.exit(f"the checker missed {what}")

    (t / "libemb/bad.cpp").write_text(UNFORMATTED)
    (t / "libemb/a.cpp").write_text("int a();\n")
    (t / "libemb/b.cpp").write_text("int b();\n")
    expect_failure("libemb/bad.cpp\n", "libemb/bad.cpp: not formatted", "an unformatted file")
    expect_failure("libemb/gone.cpp\n", "'libemb/gone.cpp': no such file", "a missing file")
    expect_failure("libemb/b.cpp\nlibemb/a.cpp\n", "expected sorted, unique paths",
                   "an unsorted list")

    # `add` formats the file, lists it in order, keeps the header; the check then passes.
    lst.write_text(HEADER + "libemb/b.cpp\n")
    r = run_add(t, "libemb/bad.cpp", "libemb/a.cpp")
    if r.returncode != 0:
        print(r.stdout, r.stderr)
        sys.exit("check_format add failed")
    expected = HEADER + "libemb/a.cpp\nlibemb/b.cpp\nlibemb/bad.cpp\n"
    if lst.read_text() != expected:
        sys.exit(f"add left the list as {lst.read_text()!r}, expected {expected!r}")
    if (t / "libemb/bad.cpp").read_text() == UNFORMATTED:
        sys.exit("add did not format the file")
    r = run(t, "check")
    if r.returncode != 0:
        print(r.stdout, r.stderr)
        sys.exit("the check fails right after add")
print("format: ok")
