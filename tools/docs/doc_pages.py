"""What the documentation scripts of tools/docs/ share: the pages and how a check ends.

The pages are those benchmarks/render_tables.py renders numbers into (README.md,
benchmarks/README.md and docs/**/*.md without its symbolic links), so every check reads the
same set.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                                "benchmarks"))
from render_tables import documents  # noqa: E402,F401  (re-exported)


def repository_root():
    """The repository this script belongs to (the default of every --root)."""
    return os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def report(problems, summary):
    """Prints the problems (stderr) or the summary; the process's exit code."""
    for msg in problems:
        print(msg, file=sys.stderr)
    if problems:
        return 1
    print(summary)
    return 0
