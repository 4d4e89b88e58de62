"""kinergy: the plane motion of rigid bodies by energy and momentum, in closed form.

    import kinergy
    scene = kinergy.example("energy/sliding_rod")      # or kinergy.load("my_scene.yaml")
    scene.set(l="2 m")
    solution = scene.solve()                            # each analysis confirmed a second way
    solution["omega2"].closed, float(solution["omega2"]), solution["omega2"].sympy()
    solution.derive("text"), solution.simulate(until=2.0), solution.to_dataframe()

A bad scene or request raises kinergy.SceneError (a ValueError) with file, line, column, message
and fix. Calls release the GIL while they compute; kinergy's core takes one call at a time, so
parallel solving is by processes (multiprocessing, Dask: Scene and Solution pickle).
"""
import json as _json
import os as _os

from ._kinergy import (  # noqa: F401
    Result,
    Scene,
    SceneError,
    Solution,
    Verdict,
    __version__,
    _batch,
    load,
    loads,
)

__all__ = ["Result", "Scene", "SceneError", "Solution", "Verdict", "load", "loads", "derivations", "example", "batch", "__version__"]

# the classes are kinergy's (their module is the package's, for help(), repr and pickle)
for _cls in (Result, Scene, Solution, Verdict):
    _cls.__module__ = "kinergy"
load.__module__ = loads.__module__ = "kinergy"


def _error(message: str, fix: str) -> SceneError:
    # as the compiled core raises them: a place that is not in a file is None
    e = SceneError(f"{message} \u2014 {fix}")
    e.file = e.line = e.column = None
    e.message, e.fix = message, fix
    return e


def derivations() -> str:
    """The directory of the worked problems installed with kinergy (its derivations/: scene files
    by principle, e.g. energy/sliding_rod.yaml)."""
    here = _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), "derivations")
    if not _os.path.isdir(here):
        raise _error(f"the worked problems are not installed beside kinergy ({here})",
                     "install kinergy with pip (pip install .), or build it with CMake")
    return here


def example(name: str) -> Scene:
    """A worked problem installed with kinergy, by its path under derivations/ without '.yaml':
    example("energy/sliding_rod")."""
    path = _os.path.join(derivations(), *name.split("/")) + ("" if name.endswith(".yaml") else ".yaml")
    if not _os.path.isfile(path):
        found = sorted(_os.path.relpath(_os.path.join(d, f), derivations())[:-5]
                       for d, _, fs in _os.walk(derivations()) for f in fs if f.endswith(".yaml"))
        raise _error(f"there is no worked problem '{name}'", "name one of: " + ", ".join(found))
    return load(path)


def batch(requests):
    """Many requests in one call, each as `kinergy batch` reads a line: a dict such as
    {"scene": "derivations/energy/sliding_rod.yaml", "set": {"l": "2 m"}, "id": 7} (or its JSON
    text). Returns each result as `kinergy batch` writes it, as a dict, in order: "ok", and the
    "solution" or the "error". Requests that differ only in the values "set" gives share the first
    one's solution wherever every choice it made falls the same way (its closed forms evaluated
    there; a sample solved in full must agree): a bank of variants runs at the speed of the closed
    form. A failing request is a result with "ok": False; it never raises."""
    lines = [r if isinstance(r, str) else _json.dumps(r) for r in requests]
    for i, line in enumerate(lines):
        if "\n" in line or not line.strip():
            raise _error(f"request {i} is blank or spans lines", "give one JSON object a request")
    return [_json.loads(out) for out in _batch(lines)]
