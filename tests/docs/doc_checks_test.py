#!/usr/bin/python3
"""The documentation's checks catch what they are for (so that a passing check means
something): on a copy of the pages, check_pages.py fails on a path that does not exist, an
issue number in a heading, an equation left out of the theory manual, a page missing from
the navigation and a README without the set-up command; check_commands.py on an
unknown option and subcommand; doc_blocks.py on a runnable block that fails, and runs only
the marked blocks.

Usage: doc_checks_test.py SOURCE_DIR EMB
"""
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

root = pathlib.Path(sys.argv[1])
emb = sys.argv[2]
tools = root / "tools" / "docs"


def run(*args):
    return subprocess.run(["/usr/bin/python3", *map(str, args)], capture_output=True, text=True)


def expect(r, code, words, what):
    if r.returncode != code or any(w not in r.stdout + r.stderr for w in words):
        print(r.stdout, r.stderr)
        sys.exit(f"doc_checks_test: {what}: expected exit {code} naming {words}, got {r.returncode}")


with tempfile.TemporaryDirectory() as tmp:
    t = pathlib.Path(tmp)
    (t / "benchmarks").mkdir()
    shutil.copy(root / "README.md", t / "README.md")
    shutil.copy(root / "mkdocs.yml", t / "mkdocs.yml")
    shutil.copy(root / "benchmarks" / "README.md", t / "benchmarks" / "README.md")
    shutil.copytree(root / "docs", t / "docs", symlinks=True)
    for d in ("libemb", "tools", "tests", "meshes", "examples", "cmake"):
        os.symlink(root / d, t / d)
    os.symlink(root / "benchmarks" / "results", t / "benchmarks" / "results")
    for f in os.listdir(root / "benchmarks"):
        if not (t / "benchmarks" / f).exists():
            os.symlink(root / "benchmarks" / f, t / "benchmarks" / f)

    expect(run(tools / "check_pages.py", "--root", t), 0, ["paths exist"], "the pages as they are")
    theory = t / "docs" / "theory.md"
    text = theory.read_text()
    theory.write_text(text + "\n## Moved (issue 99)\n\nSee `libemb/mbs/no_such_file.h`.\n")
    expect(run(tools / "check_pages.py", "--root", t), 1,
           ["libemb/mbs/no_such_file.h", "issue number"], "a stale path and an issue heading")
    theory.write_text(text.replace("(1.26)", "(one-twenty-six)"))
    expect(run(tools / "check_pages.py", "--root", t), 1, ["(1.26)"], "an equation left out")
    theory.write_text(text)
    readme = (t / "README.md").read_text()
    (t / "README.md").write_text(readme.replace("bash tools/setup.sh test", "bash tools/setup.sh"))
    expect(run(tools / "check_pages.py", "--root", t), 1, ["bash tools/setup.sh test"],
           "a README without the test command")
    (t / "README.md").write_text(readme)

    orphan = t / "docs" / "tasks" / "orphan.md"
    orphan.write_text("# A page no one links\n")
    expect(run(tools / "check_pages.py", "--root", t), 1, ["orphan.md: not in the navigation"],
           "a page missing from the navigation")
    orphan.unlink()

    expect(run(tools / "check_commands.py", "--root", t, "--emb", emb), 0, ["options exist"],
           "the commands as they are")
    page = t / "docs" / "tasks" / "planted.md"
    page.write_text("# Planted\n\n```sh\nbuild/tools/emb/emb modes part.geo --no-such-option 3\n"
                    "emb frobnicate x\n```\n")
    expect(run(tools / "check_commands.py", "--root", t, "--emb", emb), 1,
           ["--no-such-option", "frobnicate"], "an unknown option and subcommand")

    page.write_text("# Planted\n\n```sh\nexit 7\n```\n\n<!-- doc-run -->\n```sh\necho first\n```\n\n"
                    "<!-- doc-run -->\n```sh\nfalse\n```\n")
    listed = run(tools / "doc_blocks.py", "list", page)
    if "exit 7" in listed.stdout or "echo first" not in listed.stdout:
        sys.exit("doc_checks_test: doc_blocks.py list: expected the marked blocks only:\n" + listed.stdout)
    build = pathlib.Path(emb).parent.parent.parent
    expect(run(tools / "doc_blocks.py", "run", page, "--root", root, "--build", build), 1,
           ["first", "failed with exit code 1"], "a failing runnable block")
print("documentation checks: they catch stale paths, headings, commands and failing blocks")
