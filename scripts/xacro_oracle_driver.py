"""Run the real xacro (PyPI ``xacro``, a development-only oracle) on one description and
print its joints as JSON: ``[{"name", "type", "parent", "child", "xyz", "rpy"}, ...]``.

Usage: ``python scripts/xacro_oracle_driver.py FILE PACKAGES_JSON [name:=value ...] [--urdf]``
where PACKAGES_JSON maps package names to folders (``$(find)`` reads nothing else). It runs
in its own process because xacro keeps global state. The linter never imports xacro.
With ``--urdf`` it prints the expanded document itself (for ``check_urdf``), or nothing
(and xacro's refusal on standard error) when xacro refuses it.
"""

from __future__ import annotations

import json
import sys


def main() -> int:
    import xacro  # the oracle; a development dependency only
    from xacro import substitution_args

    path, packages_json, *words = sys.argv[1:]
    as_urdf = "--urdf" in words
    words = [word for word in words if word != "--urdf"]
    packages = json.loads(packages_json)

    def find(package: str) -> str:
        if package not in packages:
            raise substitution_args.SubstitutionException(f"package {package} not found")
        return str(packages[package])

    substitution_args._eval_find = find  # type: ignore[attr-defined]
    mappings = dict(word.split(":=", 1) for word in words)
    try:
        document = xacro.process_file(path, mappings=mappings)
    except Exception as exc:  # the oracle's refusal is an answer too
        refusal = f"{type(exc).__name__}: {exc}"
        print(refusal if as_urdf else json.dumps({"error": refusal}),
              file=sys.stderr if as_urdf else sys.stdout)
        return 0
    if as_urdf:
        print(document.toprettyxml(indent="  "))
        return 0
    joints = []
    robot = document.documentElement
    for joint in robot.childNodes:
        if getattr(joint, "tagName", None) != "joint":
            continue
        entry = {"name": joint.getAttribute("name"), "type": joint.getAttribute("type"),
                 "parent": None, "child": None, "xyz": "0 0 0", "rpy": "0 0 0"}
        seen = set()
        for child in joint.childNodes:
            tag = getattr(child, "tagName", None)
            if tag in ("parent", "child") and tag not in seen:
                seen.add(tag)
                entry[tag] = child.getAttribute("link")
            elif tag == "origin" and "origin" not in seen:
                seen.add("origin")
                for key in ("xyz", "rpy"):
                    if child.hasAttribute(key):
                        entry[key] = child.getAttribute(key)
        joints.append(entry)
    print(json.dumps({"joints": joints}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
