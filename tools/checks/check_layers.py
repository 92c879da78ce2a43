#!/usr/bin/env python3
"""Checks that libemb's modules include only the modules they depend on.

The module graph (a module may include itself and what it depends on, transitively) is the
one the CMake targets link; an include against it (an upward include, or one that skips a
declared dependency) is reported with file and line, and the exit code is 1.

Usage: tools/checks/check_layers.py [REPO_ROOT]
"""
import pathlib
import re
import sys

# module -> the modules it may include directly (its CMake link dependencies).
DEPENDS = {
    "common": [],
    "mesh": ["common"],
    "linalg": ["common"],
    "fe": ["common", "mesh", "linalg"],
    "io": ["common", "mesh", "fe"],
    "cms": ["common", "mesh", "linalg", "fe", "io"],
    "beam": ["common", "mesh", "linalg", "fe"],
    "compare": ["beam", "cms"],
    "integrators": ["common"],
    "tribology": ["common"],
    "mbs/core": ["common"],
    "mbs/constraints": ["mbs/core"],
    "mbs/forces": ["mbs/constraints"],
    "mbs/dae": ["mbs/forces", "integrators"],
    "mbs/flexible": ["mbs/dae"],
    "mbs/analysis": ["mbs/dae", "mbs/flexible"],
    "mbs/linear": ["mbs/analysis"],
    "mbs/parts": ["mbs/forces", "beam", "cms"],
    "engine": ["mbs/forces", "tribology"],
    "driveline": ["mbs/forces"],
    "results": ["mbs/analysis", "mbs/parts", "io"],
    "scene": ["mbs/analysis", "mbs/parts", "engine", "driveline", "results"],
    "sweep": ["scene", "results", "io"],
    "distributed": ["common", "linalg"],
}


def closure(module, seen=None):
    seen = set() if seen is None else seen
    for dep in DEPENDS[module]:
        if dep not in seen:
            seen.add(dep)
            closure(dep, seen)
    return seen


def module_of(rel):
    """'mbs/core/system.h' -> 'mbs/core'; 'fe/assembly.h' -> 'fe'."""
    parts = rel.split("/")
    for n in (2, 1):
        name = "/".join(parts[:n])
        if name in DEPENDS:
            return name
    return None


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    lib = root / "libemb"
    include = re.compile(r'^\s*#\s*include\s+"libemb/([^"]+)"')
    errors = []
    for path in sorted(lib.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        rel = path.relative_to(lib).as_posix()
        mod = module_of(rel)
        if mod is None:
            errors.append(f"libemb/{rel}: in no known module (add its folder to DEPENDS)")
            continue
        allowed = closure(mod) | {mod}
        for lineno, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            m = include.match(line)
            if not m:
                continue
            target = module_of(m.group(1))
            if target is None:
                errors.append(f"libemb/{rel}:{lineno}: includes libemb/{m.group(1)}, "
                              "which is in no known module")
            elif target not in allowed:
                errors.append(f"libemb/{rel}:{lineno}: module '{mod}' includes "
                              f"libemb/{m.group(1)} of module '{target}', which it does not "
                              f"depend on (allowed: {', '.join(sorted(allowed))})")
    for e in errors:
        print(e)
    print(f"check_layers: {len(errors)} violation(s)")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
