"""sph from Python: SPH fluids and the objects in them.

    import sph
    scene = sph.load_scene("scenes/dam_break.json", set={"fluid.spacing": 0.01})
    sim = sph.Simulation(scene, threads=2)
    sim.run(0.5, callback=lambda s: print(s.time, s.stats()["max_speed"]), every=0.1)
    p = sim.particles()          # numpy arrays, copies: p["position"] is (n, 3)
    v = sim.view()               # the fluid's arrays in place, until the next step

Keys are the scene file's (the README's scene reference), changed with the same dotted paths
as `sph run --set`. A bad scene raises sph.SceneError (a ValueError) whose message names the
file, the key and what was expected.
"""

import json

from ._sph import (FluidArrays, ObjectExchange, OutputError, Scene, SceneError, Simulation,
                   SimulationFailure, StaleViewError)
from ._sph import _load_scene, _parse_scene, box_drop_scene, read_frame

__all__ = ["load_scene", "scene_from_dict", "Scene", "Simulation", "FluidArrays", "ObjectExchange",
           "SceneError", "read_frame", "box_drop_scene",
           "SimulationFailure", "OutputError", "StaleViewError"]


def _overrides(changes):
    """{"fluid.spacing": 0.01, "output.format": "ply"} as `--set` texts."""
    texts = []
    for key, value in (changes or {}).items():
        text = value if isinstance(value, str) else json.dumps(value)
        texts.append(f"{key}={text}")
    return texts


def load_scene(path, set=None):
    """Reads a scene file and applies `set` ({dotted key: value}), in order."""
    return _load_scene(str(path), _overrides(set))


def scene_from_dict(document, name="<dict>", set=None):
    """A scene from a dict shaped like a scene file; `name` names it in messages (and a relative
    mesh file is found beside it)."""
    return _parse_scene(json.dumps(document), name, _overrides(set))


def _to_dict(scene):
    """Every key of the scene, defaults included."""
    return json.loads(scene.to_json())


def _with_changes(scene, set):
    """A copy of the scene with `set` ({dotted key: value}) applied and checked again."""
    return _parse_scene(scene.to_json(), scene.source, _overrides(set))


Scene.to_dict = _to_dict
Scene.with_changes = _with_changes


def _run(sim, duration, callback=None, every=None):
    """Advances by `duration` simulated seconds, calling callback(sim) every `every` seconds of
    simulated time (and at the end); without `every`, after each step."""
    end = sim.time + duration
    while sim.time < end:
        if every is None:
            sim.step()
            if sim.time > end:
                break
        else:
            sim.advance_to(min(end, sim.time + every))
        if callback is not None:
            callback(sim)


Simulation.run = _run
