"""roslaunch's rules for graph resource names and namespaces (``rosgraph.names``)."""

from __future__ import annotations

import re

_NAME_LEGAL = re.compile(r"[~/A-Za-z][\w/]*\Z")
_COLLAPSE_SLASHES = re.compile("//+")


def make_global_ns(ns: str) -> str:
    if ns.startswith("~"):
        raise ValueError(f"cannot turn [{ns}] into a global name")
    if not ns.startswith("/"):
        ns = "/" + ns
    return ns if ns.endswith("/") else ns + "/"


def ns_join(ns: str, name: str) -> str:
    if name.startswith(("/", "~")):
        return name
    if ns == "~":
        return "~" + name
    if not ns:
        return name
    return ns + name if ns.endswith("/") else ns + "/" + name


def _is_legal_name(name: str) -> bool:
    """rosgraph's ``is_legal_name`` (the empty name is legal)."""
    return name == "" or (_NAME_LEGAL.match(name) is not None and "//" not in name)


def _canonical_name(name: str) -> str:
    if not name or name == "/" or ("//" not in name and name[-1] != "/"):
        return name
    canonical = "/".join(x for x in name.split("/") if x)
    return "/" + canonical if name.startswith("/") else canonical
