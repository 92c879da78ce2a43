#!/usr/bin/env python3
"""clang-format (the root .clang-format: Google base, 100 columns) on a growing set of files.

The tree is not reformatted in one go (that would collide with everyone's branches); instead
tools/checks/formatted_files.txt lists the C++ files that are formatted, and the check keeps
them so. A file joins the list when someone touches it anyway: `add` formats it and lists it.
The list only grows; when it holds every file, the check can take the whole tree instead.

Why a committed list and not "the files changed since a base commit": the check then gives
the same answer on every machine and in every checkout (a tarball, a shallow CI clone, a
branch long after its base), needs no git, and a reviewer sees the set grow in the diff.

Usage: tools/checks/check_format.py [--clang-format EXE] check ROOT
         every listed file exists, is formatted, the list is sorted and unique; exit 1 if not
       tools/checks/check_format.py [--clang-format EXE] fix ROOT
         formats every listed file in place
       tools/checks/check_format.py [--clang-format EXE] add ROOT FILE...
         formats FILE... (paths relative to ROOT, .h/.cpp) in place and adds them to the list
"""
import argparse
import pathlib
import subprocess
import sys

LIST = pathlib.Path("tools") / "checks" / "formatted_files.txt"
SUFFIXES = (".h", ".cpp")


def read_list(root):
    """The listed paths, in file order (comments and blank lines skipped)."""
    lines = (root / LIST).read_text(encoding="utf-8").splitlines()
    return [s.strip() for s in lines if s.strip() and not s.lstrip().startswith("#")]


def write_list(root, paths):
    text = (root / LIST).read_text(encoding="utf-8").splitlines()
    header = [s for s in text if s.lstrip().startswith("#")]
    (root / LIST).write_text("\n".join(header + sorted(set(paths))) + "\n", encoding="utf-8")


def clang_format(exe, args):
    try:
        return subprocess.run([exe] + args, capture_output=True, text=True)
    except FileNotFoundError:
        sys.exit(f"check_format: clang-format not found ('{exe}'): install Debian's clang-format "
                 "(tools/setup.sh does)")


def check(exe, root):
    paths = read_list(root)
    errors = []
    if paths != sorted(set(paths)):
        errors.append(f"{LIST}: expected sorted, unique paths (check_format.py add keeps it so)")
    present = []
    for p in paths:
        if not p.endswith(SUFFIXES):
            errors.append(f"{LIST}: '{p}': expected a .h or .cpp file")
        elif not (root / p).is_file():
            errors.append(f"{LIST}: '{p}': no such file (moved? update the list)")
        else:
            present.append(p)
    for p in present:
        r = clang_format(exe, ["--dry-run", "-Werror", "--style=file", str(root / p)])
        if r.returncode != 0:
            first = next((s for s in r.stderr.splitlines() if "error:" in s), r.stderr.strip())
            errors.append(f"{p}: not formatted ({first.strip()}); run "
                          f"tools/checks/check_format.py fix {root}")
    for e in errors:
        print(e)
    version = clang_format(exe, ["--version"]).stdout.strip()
    print(f"check_format: {len(present)} listed file(s), {len(errors)} problem(s) ({version})")
    return 1 if errors else 0


def fix(exe, root, paths):
    for p in paths:
        r = clang_format(exe, ["-i", "--style=file", str(root / p)])
        if r.returncode != 0:
            sys.exit(f"check_format: clang-format failed on {p}: {r.stderr.strip()}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--clang-format", default="clang-format", help="the clang-format program")
    ap.add_argument("command", choices=["check", "fix", "add"])
    ap.add_argument("root", type=pathlib.Path)
    ap.add_argument("files", nargs="*")
    a = ap.parse_args()
    root = a.root.resolve()
    if a.command == "check":
        return check(a.clang_format, root)
    if a.command == "fix":
        fix(a.clang_format, root, read_list(root))
        return 0
    new = []
    for f in a.files:
        rel = None
        for candidate in (pathlib.Path.cwd() / f, root / f):  # relative to here or to ROOT
            c = candidate.resolve()
            if c.is_file() and c.is_relative_to(root) and c.suffix in SUFFIXES:
                rel = c.relative_to(root).as_posix()
                break
        if rel is None:
            sys.exit(f"check_format add: expected an existing .h or .cpp file under {root}, "
                     f"got '{f}'")
        new.append(rel)
    fix(a.clang_format, root, new)
    write_list(root, read_list(root) + new)
    return 0


if __name__ == "__main__":
    sys.exit(main())
