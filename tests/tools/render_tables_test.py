#!/usr/bin/python3
"""benchmarks/render_tables.py --check: the documentation's benchmark tables and quoted values
are the ones rendered from benchmarks/results/*.json; and the check does catch a stale number
(a copy of the documents with one table cell and one quoted value changed fails, naming them)
and a marker for a results file that does not exist."""
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

root = pathlib.Path(sys.argv[1])
renderer = root / "benchmarks" / "render_tables.py"


def check(repo):
    return subprocess.run([sys.executable, str(renderer), "--check", "--root", str(repo)],
                          capture_output=True, text=True)


real = check(root)
if real.returncode != 0:
    print(real.stdout, real.stderr)
    sys.exit("the documents' benchmark numbers are not the rendered ones")

with tempfile.TemporaryDirectory() as tmp:
    t = pathlib.Path(tmp)
    (t / "benchmarks").mkdir()
    shutil.copytree(root / "benchmarks" / "results", t / "benchmarks" / "results")
    shutil.copy(root / "README.md", t / "README.md")
    text = (root / "benchmarks" / "README.md").read_text()
    # Change the first digit inside the first table block and inside the first value marker.
    table = re.search(r"<!-- table:([\w-]+) -->\n(.*?)<!-- /table:\1 -->", text, re.S)
    value = re.search(r"<!-- value:([^>]+?) -->(.*?)<!-- /value -->", text, re.S)
    if not table or not value:
        sys.exit("benchmarks/README.md has no table or no value marker to test with")

    def bump(s, start, end):
        i = start + re.search(r"\d", s[start:end]).start()
        return s[:i] + str((int(s[i]) + 1) % 10) + s[i + 1:]

    stale = bump(text, table.start(2), table.end(2))
    stale = bump(stale, value.start(2) + (len(stale) - len(text)), value.end(2))
    (t / "benchmarks" / "README.md").write_text(stale)
    r = check(t)
    value_path = value.group(1).split("|")[0]  # the check names a value by its path
    if r.returncode != 1 or table.group(1) not in r.stderr or value_path not in r.stderr:
        print(r.stdout, r.stderr)
        sys.exit("the check missed a changed table cell or value")
    (t / "benchmarks" / "README.md").write_text(text + "\n<!-- table:crank_modes -->\n<!-- /table:crank_modes -->\n")
    (t / "benchmarks" / "results" / "crank_modes.json").unlink()
    r = check(t)
    if r.returncode != 1 or "crank_modes.json does not exist" not in r.stderr:
        print(r.stdout, r.stderr)
        sys.exit("the check missed a missing results file")
print("benchmark tables: up to date, and the check catches stale numbers")
