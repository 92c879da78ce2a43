#!/usr/bin/python3
"""Every `emb` command line the documentation shows uses a subcommand and options that the
built emb has.

Reads the fenced blocks of README.md, benchmarks/README.md and docs/**/*.md (shell blocks and
blocks without a language), finds each command that runs emb (`emb`, `build/tools/emb/emb`,
also after `mpirun ...`, `env ...`, `flock ...` or inside a quoted `--wrap '...'`), and
checks its subcommand against `emb --help` and each option against `emb SUB --help`.

Usage (stdlib only; /usr/bin/python3):
    check_commands.py --emb build/tools/emb/emb [--root .]
Exit 1 listing file:line, the command and the unknown name (the ctest docs_commands_test).
"""
import argparse
import os
import re
import shlex
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from doc_blocks import fenced_blocks  # noqa: E402
from doc_pages import documents, report, repository_root  # noqa: E402
from generated_pages import subcommands  # noqa: E402

SHELL_INFO = {"", "sh", "bash", "console", "shell"}
CONTROL = {"&&", "||", ";", "|", "&", "(", ")"}


def help_options(emb, args):
    r = subprocess.run(["emb", *args, "--help"], executable=emb, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"check_commands.py: {emb} {' '.join(args)} --help failed: {r.stderr}")
    names = set()
    for line in r.stdout.splitlines():
        m = re.match(r"^\s+(-[^\s]+)", line)
        if m:
            names.update(n for n in m.group(1).split(",") if n.startswith("-"))
    return r.stdout, names


def logical_lines(body):
    """(offset, text) of each command line of a block, continuation lines joined."""
    out, cur, start = [], "", 0
    for i, line in enumerate(body.split("\n")):
        if not cur:
            start = i
        if line.rstrip().endswith("\\"):
            cur += line.rstrip()[:-1] + " "
            continue
        out.append((start, cur + line))
        cur = ""
    if cur:
        out.append((start, cur))
    return out


def emb_commands(text):
    """The token lists that follow an emb executable in a command line."""
    try:
        lexer = shlex.shlex(text, posix=True, punctuation_chars="|&;()")
        lexer.whitespace_split = True
        lexer.commenters = "#"
        tokens = list(lexer)
    except ValueError:
        return []
    found, i = [], 0
    while i < len(tokens):
        t = tokens[i]
        if " " in t and re.match(r"^\s*(\S*/)?emb\s", t):
            found += emb_commands(t)
        # The executable, not the value of an option (`--emb build/tools/emb/emb`).
        if os.path.basename(t) == "emb" and "=" not in t and not (i and tokens[i - 1].startswith("-")):
            j = i + 1
            while j < len(tokens) and tokens[j] not in CONTROL:
                j += 1
            found.append(tokens[i + 1:j])
            i = j
            continue
        i += 1
    return found


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--emb", required=True)
    p.add_argument("--root", default=repository_root())
    a = p.parse_args()
    top_help, top_options = help_options(a.emb, [])
    options = {sub: help_options(a.emb, [sub])[1] for sub in subcommands(top_help)}
    problems, checked = [], 0
    for rel in documents(a.root):
        with open(os.path.join(a.root, rel), encoding="utf-8") as f:
            text = f.read()
        for first, info, body, _ in fenced_blocks(text):
            if info not in SHELL_INFO:
                continue
            for offset, line in logical_lines(body):
                for cmd in emb_commands(line):
                    where = f"{rel}:{first + 1 + offset}"
                    checked += 1
                    if not cmd or cmd[0].startswith("-"):
                        bad = [t for t in cmd if t.startswith("-") and t.split("=")[0] not in top_options]
                        problems += [f"{where}: emb {t}: unknown option" for t in bad]
                        continue
                    sub = cmd[0]
                    if sub not in options:
                        problems.append(f"{where}: unknown subcommand 'emb {sub}'")
                        continue
                    for t in cmd[1:]:
                        if not t.startswith("-") or t == "-" or re.match(r"^-\d", t):
                            continue
                        if t.split("=")[0] not in options[sub]:
                            problems.append(f"{where}: emb {sub}: unknown option '{t}'")
    return report(problems, f"{checked} emb command lines in the documentation: subcommands and "
                            "options exist")


if __name__ == "__main__":
    sys.exit(main())
