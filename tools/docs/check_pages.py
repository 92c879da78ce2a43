#!/usr/bin/python3
"""Checks of the documentation's pages that need no build (the ctest docs_paths_test):

- every repository path a page names in a code span (`libemb/...`, `tools/...`, `tests/...`,
  `benchmarks/...`, `meshes/...`, `examples/...`, `cmake/...`, `docs/...`) exists, and every
  relative link of README.md leads to a file; in the theory manual (docs/theory.md) every
  code span that names a source file must be such a path: a file that moved or was renamed
  fails here, naming the page and line;
- the theory manual covers every seed equation (1.18)-(1.30);
- no heading carries an issue number;
- every page of docs/ is in the site's navigation (mkdocs.yml), and every page there exists;
- README.md holds the two set-up commands (`.ci/run` calls the second).

Usage (stdlib only): check_pages.py [--root .]
"""
import argparse
import os
import re
import sys

from doc_pages import documents, report, repository_root

PATH = re.compile(r"^(libemb|tools|tests|benchmarks|meshes|examples|cmake|docs)/[\w./+-]*[\w/]$")
OUTPUT = re.compile(r"\.(h5|csv|xdmf)$")  # what a command writes, e.g. tools/scenes/pendulum.h5
SPAN = re.compile(r"`([^`\n]+)`")
SOURCE_FILE = re.compile(r"[\w/-]+\.(h|cpp|py|sh|geo|yaml|cmake|txt)$")
LINK = re.compile(r"\]\(([^)#\s]+)(#[^)]*)?\)")
EQUATIONS = [f"(1.{n})" for n in range(18, 31)]
SETUP = ["bash tools/setup.sh run", "bash tools/setup.sh test"]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--root", default=repository_root())
    a = p.parse_args()
    problems, named = [], 0
    for rel in documents(a.root):
        with open(os.path.join(a.root, rel), encoding="utf-8") as f:
            text = f.read()
        theory = rel == "docs/theory.md"
        fence = False
        for n, line in enumerate(text.split("\n"), 1):
            if line.startswith("```"):
                fence = not fence
                continue
            if fence:
                continue
            if re.match(r"^#+ .*\bissues? \d", line):
                problems.append(f"{rel}:{n}: a heading with an issue number: {line}")
            for span in SPAN.findall(line):
                span = span.strip()
                if PATH.match(span) and not OUTPUT.search(span):
                    named += 1
                    if not os.path.exists(os.path.join(a.root, span)):
                        problems.append(f"{rel}:{n}: `{span}` does not exist")
                elif theory and SOURCE_FILE.search(span) and " " not in span:
                    problems.append(f"{rel}:{n}: `{span}`: give the path from the repository root")
            if rel == "README.md":
                for target, _ in LINK.findall(line):
                    if not re.match(r"^[a-z]+:", target) and not os.path.exists(os.path.join(a.root, target)):
                        problems.append(f"{rel}:{n}: link to '{target}', which does not exist")
        if theory:
            missing = [e for e in EQUATIONS if e not in text]
            if missing:
                problems.append(f"{rel}: the seed equations {', '.join(missing)} are not mapped")
    docs_pages = {os.path.relpath(p, "docs") for p in documents(a.root) if p.startswith("docs/")}
    with open(os.path.join(a.root, "mkdocs.yml"), encoding="utf-8") as f:
        nav = set(re.findall(r"^\s*- [^:#]+: (\S+\.md)\s*$", f.read(), re.M))
    problems += [f"docs/{p}: not in the navigation of mkdocs.yml" for p in sorted(docs_pages - nav)
                 if p != "benchmarks.md"]
    problems += [f"mkdocs.yml: '{p}' is not a page of docs/" for p in sorted(nav)
                 if not os.path.exists(os.path.join(a.root, "docs", p))]
    with open(os.path.join(a.root, "README.md"), encoding="utf-8") as f:
        readme = f.read()
    problems += [f"README.md: the set-up command `{c}` is missing" for c in SETUP if c not in readme]
    if not os.path.exists(os.path.join(a.root, "docs/theory.md")):
        problems.append("docs/theory.md is missing")
    return report(problems, f"documentation: {named} repository paths exist, theory manual "
                            "complete, headings clean")


if __name__ == "__main__":
    sys.exit(main())
