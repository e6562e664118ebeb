#!/usr/bin/python3
"""Load launch files with the real roslaunch ``XmlLoader`` and print what it made of them.

Runs under Debian's ``/usr/bin/python3`` with ``python3-roslaunch`` installed; the test
suite and the corpus scripts call it as a subprocess and compare with launch-linter.

Input (a JSON document on stdin)::

    {"package_path": ["DIR", ...],            # the only folders $(find) searches
     "files": [{"path": "a.launch",
                "args": {"name": "value"},    # as `roslaunch a.launch name:=value`
                "env": {"NAME": "value"}}]}   # the whole environment $(env) sees

With ``"repeat": N`` in the request, the files are instead loaded N times over and the
only output is ``{"files": F, "runs": [seconds, ...], "cpu_runs": [seconds, ...]}``: the
wall-clock and CPU time of each pass over all files, measured in this process (for
benchmarks).

Output: one JSON object per file and line, in input order::

    {"path": P, "ok": false, "error_type": "XmlParseException", "error": "..."}
    {"path": P, "ok": true, "seconds": T, "nodes": [{"package", "type", "name",
     "namespace", "resolved_name", "args", "file", "line", "column"}, ...]}

Each file is loaded into a fresh ``ROSLaunchConfig``, as ``roslaunch`` would load it,
with four differences that make the result reproducible and safe to compute:
``<param command=…>`` is not run (the parameter gets a placeholder), ``$(find)`` sees
only ``package_path`` (Debian's ``/usr/share`` and ``/usr`` workspace are hidden),
``$(anon id)`` yields ``id_anon<N>`` with N counted per file, and ``$(eval)`` gets
only the builtins roslaunch intends to allow (the real loader leaks all of them).
Line and column are those of the ``<node`` start tag, 1-based, as expat reports them.
"""

from __future__ import annotations

import builtins
import contextlib
import json
import os
import sys
import time
from typing import Any
from xml.dom import expatbuilder

import catkin.find_in_workspaces
import rosgraph.names
import roslaunch.config
import roslaunch.loader
import roslaunch.substitution_args
import roslaunch.xmlloader
import rospkg

_EVAL_BUILTINS = ("list", "dict", "map", "str", "float", "int")


class _Positions:
    """Where each DOM element started, noted by a hook on minidom's expat builder."""

    def __init__(self) -> None:
        self.by_element: dict[int, tuple[Any, int, int]] = {}

    def install(self) -> None:
        original = expatbuilder.ExpatBuilderNS.start_element_handler
        positions = self

        def start_element(builder: Any, name: str, attributes: Any) -> None:
            parser = builder._parser
            line, column = parser.CurrentLineNumber, parser.CurrentColumnNumber + 1
            original(builder, name, attributes)
            element = builder.curNode
            positions.by_element[id(element)] = (element, line, column)

        expatbuilder.ExpatBuilderNS.start_element_handler = start_element

    def of(self, element: Any) -> tuple[int | None, int | None]:
        entry = self.by_element.get(id(element))
        if entry is None or entry[0] is not element:
            return None, None
        return entry[1], entry[2]


class _NodeTags:
    """Maps each roslaunch ``Node`` back to the ``<node>`` element it came from."""

    def __init__(self, positions: _Positions) -> None:
        self.positions = positions
        self.by_node: dict[int, tuple[Any, int | None, int | None]] = {}

    def install(self) -> None:
        original = roslaunch.xmlloader.XmlLoader._node_tag
        tags = self

        def node_tag(loader: Any, tag: Any, *args: Any, **kwargs: Any) -> Any:
            node = original(loader, tag, *args, **kwargs)
            if node is not None:
                line, column = tags.positions.of(tag)
                tags.by_node[id(node)] = (node, line, column)
            return node

        roslaunch.xmlloader.XmlLoader._node_tag = node_tag

    def of(self, node: Any) -> tuple[int | None, int | None]:
        entry = self.by_node.get(id(node))
        if entry is None or entry[0] is not node:
            return None, None
        return entry[1], entry[2]


class _StableAnon:
    def __init__(self) -> None:
        self.count = 0

    def __call__(self, anon_id: str) -> str:
        self.count += 1
        return f"{anon_id}_anon{self.count}"


def _restricted_eval(source: str, _globals: Any, mapping: Any) -> Any:
    allowed = {name: getattr(builtins, name) for name in _EVAL_BUILTINS}
    return builtins.eval(source, {"__builtins__": allowed}, mapping)


def _placeholder_param_value(
    loader: Any, verbose: Any, name: Any, ptype: Any, value: Any, textfile: Any, binfile: Any,
    command: Any, _original: Any = roslaunch.loader.Loader.param_value,
) -> Any:
    if command is not None:
        return f"<command not run: {command}>"
    return _original(loader, verbose, name, ptype, value, textfile, binfile, command)


def _isolate(package_path: list[str]) -> _StableAnon:
    catkin.find_in_workspaces.get_workspaces = lambda: []
    roslaunch.substitution_args._rospack = rospkg.RosPack(ros_paths=list(package_path))
    roslaunch.loader.Loader.param_value = _placeholder_param_value
    # _eval() looks `eval` up in its module's globals before the builtins.
    roslaunch.substitution_args.eval = _restricted_eval  # type: ignore[attr-defined]
    anon = _StableAnon()
    rosgraph.names.anonymous_name = anon
    return anon


def _load(path: str, args: dict[str, str], env: dict[str, str], anon: _StableAnon,
          tags: _NodeTags) -> dict[str, Any]:
    anon.count = 0
    tags.by_node.clear()
    tags.positions.by_element.clear()
    os.environ.clear()
    os.environ.update(env)
    argv = [f"{name}:={value}" for name, value in args.items()]
    started = time.perf_counter()
    config = roslaunch.config.ROSLaunchConfig()
    loader = roslaunch.xmlloader.XmlLoader()
    loader.ignore_unset_args = False
    try:
        with contextlib.redirect_stdout(sys.stderr):
            loader.load(path, config, argv=argv, verbose=False)
    except Exception as exc:  # roslaunch raises many unrelated types; report them all
        return {"path": path, "ok": False, "error_type": type(exc).__name__, "error": str(exc)}
    seconds = time.perf_counter() - started
    nodes = []
    for node in config.nodes:
        line, column = tags.of(node)
        nodes.append({
            "package": node.package,
            "type": node.type,
            "name": node.name,
            "namespace": node.namespace,
            "resolved_name": (
                rosgraph.names.ns_join(node.namespace, node.name) if node.name else None
            ),
            "args": node.args,
            "file": node.filename,
            "line": line,
            "column": column,
        })
    return {"path": path, "ok": True, "seconds": round(seconds, 6), "nodes": nodes}


def _time_passes(files: list[dict[str, Any]], repeat: int, anon: _StableAnon,
                 tags: _NodeTags) -> dict[str, Any]:
    runs, cpu_runs = [], []
    for _ in range(repeat):
        started, cpu_started = time.perf_counter(), time.process_time()
        for item in files:
            _load(item["path"], item.get("args", {}), item.get("env", {}), anon, tags)
        runs.append(time.perf_counter() - started)
        cpu_runs.append(time.process_time() - cpu_started)
    return {"files": len(files), "runs": runs, "cpu_runs": cpu_runs}


def main() -> int:
    request = json.load(sys.stdin)
    saved_env = dict(os.environ)
    anon = _isolate([os.path.abspath(p) for p in request.get("package_path", [])])
    positions = _Positions()
    positions.install()
    tags = _NodeTags(positions)
    tags.install()
    out = sys.stdout
    repeat = int(request.get("repeat", 0))
    if repeat:
        out.write(json.dumps(_time_passes(request["files"], repeat, anon, tags)) + "\n")
        os.environ.clear()
        os.environ.update(saved_env)
        return 0
    for item in request["files"]:
        result = _load(item["path"], item.get("args", {}), item.get("env", {}), anon, tags)
        out.write(json.dumps(result) + "\n")
        out.flush()
    os.environ.clear()
    os.environ.update(saved_env)
    return 0


if __name__ == "__main__":
    sys.exit(main())
