#!/usr/bin/env bash
# `pip install .` into a fresh virtual environment, offline, from the CMake build the test
# command made (SPH_BUILD_DIR): the installed package imports outside the source tree and runs.
# Usage: pip_install.sh PYTHON SOURCE_DIR BUILD_DIR
set -euo pipefail
python="$1" source="$2" build="$3"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
"$python" -m venv --system-site-packages "$scratch/venv"
SPH_BUILD_DIR="$build" "$scratch/venv/bin/pip" install --no-build-isolation --no-index --no-deps \
  --quiet "$source"
cd "$scratch"
"$scratch/venv/bin/python" - "$scratch/venv" <<'PY'
import pathlib, sys
import sph
assert pathlib.Path(sph.__file__).resolve().is_relative_to(pathlib.Path(sys.argv[1]).resolve()), sph.__file__
scene = sph.scene_from_dict({
    "domain": {"min": [-0.05, -0.05, -0.05], "max": [0.15, 0.2, 0.15]},
    "fluid": {"spacing": 0.02, "blocks": [{"min": [0, 0, 0], "max": [0.1, 0.1, 0.1]}]},
    "walls": [{"type": "tank", "min": [0, 0, 0], "max": [0.1, 0.15, 0.1]}],
    "output": {"format": "none"}})
sim = sph.Simulation(scene, threads=1)
sim.advance_to(0.05)
assert sim.fluid_count == 125 and abs(sim.time - 0.05) < 1e-9
print("installed", sph.__file__)
PY
