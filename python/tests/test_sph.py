"""The Python module against the physics and the rules the C++ library is held to."""
import math
import pathlib

import numpy as np
import pytest

import sph

ROOT = pathlib.Path(__file__).resolve().parents[2]


def resting_tank(spacing=0.01, depth=0.1):
    """A tank 10 × 10 cm, water `depth` deep, laid out at rest (hydrostatic)."""
    return {
        "name": "python_tank",
        "domain": {"min": [-0.03, -0.03, -0.03], "max": [0.13, 0.2, 0.13]},
        "gravity": [0, -9.81, 0],
        "fluid": {"spacing": spacing, "kernel": "cubic_spline", "viscosity": {"value": 0.1},
                  "blocks": [{"min": [0, 0, 0], "max": [0.1, depth, 0.1], "hydrostatic": True}]},
        "walls": [{"type": "tank", "min": [0, 0, 0], "max": [0.1, 0.15, 0.1]}],
        "output": {"format": "none"},
    }


def test_a_scene_file_loads_and_dotted_keys_change_it():
    scene = sph.load_scene(ROOT / "scenes" / "dam_break.json")
    assert scene.to_dict()["fluid"]["spacing"] == pytest.approx(0.2 / 30)
    coarse = scene.with_changes({"fluid.spacing": 0.02})
    assert coarse.to_dict()["fluid"]["spacing"] == 0.02
    # The column a = 0.2 m square, 0.1 m deep, at 2 cm: 10 × 10 × 5 particles.
    assert sph.Simulation(coarse, threads=1).fluid_count == 500


def test_a_bad_key_raises_with_its_path_and_the_file():
    with pytest.raises(sph.SceneError) as caught:
        sph.scene_from_dict(resting_tank(), name="tank.json", set={"fluid.spacing": -1})
    assert "tank.json" in str(caught.value)
    assert "fluid.spacing" in str(caught.value)
    document = resting_tank()
    document["fluid"]["viscosity"] = {"model": "honey"}
    with pytest.raises(ValueError, match="fluid.viscosity.model"):
        sph.scene_from_dict(document)


def test_a_resting_tank_holds_its_hydrostatic_pressure_and_every_particle():
    scene = sph.scene_from_dict(resting_tank())
    sim = sph.Simulation(scene, threads=2)
    start = sim.particles()
    n = len(start["id"])
    assert start["position"].shape == (n, 3)
    assert np.all(start["kind"] == 0)
    seen = []
    sim.run(1.0, callback=lambda s: seen.append(s.time), every=0.25)
    assert seen == pytest.approx([0.25, 0.5, 0.75, 1.0])
    # Settled; averaged over 0.2 s, as what is left of the start's oscillation averages out:
    # the layer at mid-depth carries the weight of the particles above it.
    mass = sim.calibration["mass"]
    ratios = []
    for k in range(5):
        sim.advance_to(1.0 + 0.05 * k)
        p = sim.particles()
        y = p["position"][:, 1]
        layer = np.abs(y - 0.045) < 0.005
        weight = np.count_nonzero(y > 0.045) * mass * 9.81 / (0.1 * 0.1)
        ratios.append(np.mean(p["pressure"][layer]) / weight)
    assert np.mean(ratios) == pytest.approx(1.0, abs=0.05)
    assert sorted(p["id"]) == sorted(start["id"])
    assert np.percentile(np.linalg.norm(p["velocity"], axis=1), 99) < 0.03
    assert sim.stats()["fluid_count"] == n


def test_particles_are_copies_ordered_by_id():
    sim = sph.Simulation(sph.scene_from_dict(resting_tank(0.02)), threads=1)
    first = sim.particles()
    assert np.all(np.diff(first["id"].astype(np.int64)) > 0)
    first["position"][:] = 0.0
    sim.step()
    assert not np.allclose(sim.particles()["position"], 0.0)
    walls = sim.particles(include_boundary=True)
    assert np.count_nonzero(walls["kind"] == 1) == sim.calibration["boundary_particles"]


def test_a_view_reads_the_simulation_in_place_and_refuses_after_a_step():
    sim = sph.Simulation(sph.scene_from_dict(resting_tank(0.02)), threads=1)
    sim.step()
    view = sim.view()
    assert not view.copied
    position = view.position
    assert position.shape == (view.count, 3)
    assert np.shares_memory(position, view.position)  # both the simulation's own memory
    assert not position.flags.writeable
    # The engine's order, not the ids': the same particles as a frame once sorted by id.
    frame = sim.particles()
    order = np.argsort(view.id)
    np.testing.assert_array_equal(view.id[order], frame["id"])
    np.testing.assert_array_equal(view.position[order], frame["position"])
    np.testing.assert_array_equal(view.velocity[order], frame["velocity"])
    np.testing.assert_array_equal(view.density[order], frame["density"])
    np.testing.assert_array_equal(view.pressure[order], frame["pressure"])
    np.testing.assert_array_equal(view.kind, frame["kind"])  # every row the fluid's
    before = position.copy()
    sim.step()
    assert not np.array_equal(position, before)  # an array kept sees the simulation move on
    with pytest.raises(sph.StaleViewError, match="take a new one"):
        view.position
    with pytest.raises(sph.StaleViewError):
        view.count
    assert sim.view().count == len(frame["id"])


def test_live_parameters_change_the_run():
    sim = sph.Simulation(sph.scene_from_dict(resting_tank(0.02)), threads=1)
    assert sim.live_parameters["gravity"] == pytest.approx([0, -9.81, 0])
    sim.live_parameters = {"gravity": [0.0, 0.0, 0.0]}
    assert sim.live_parameters["gravity"] == pytest.approx([0, 0, 0])
    with pytest.raises(KeyError, match="not a live parameter"):
        sim.live_parameters = {"colour": 1.0}


def test_the_calibration_reports_the_derived_values():
    sim = sph.Simulation(sph.scene_from_dict(resting_tank(0.02)), threads=1)
    c = sim.calibration
    assert c["spacing"] == 0.02
    assert c["mass"] == pytest.approx(1000 * 0.02 ** 3, rel=0.02)
    assert c["sound_speed"] > 10 * math.sqrt(2 * 9.81 * 0.1) * 0.99


@pytest.mark.parametrize("form", ["vtp", "ply", "csv"])
def test_a_frame_written_from_python_reads_back_as_sph_run_writes_it(tmp_path, form):
    sim = sph.Simulation(sph.scene_from_dict(resting_tank(0.02)), threads=1)
    sim.advance_to(0.01)
    path = tmp_path / f"frame.{form}"
    sim.write_frame(path, format=form)
    back = sph.read_frame(path)
    now = sim.particles(include_boundary=True)
    np.testing.assert_array_equal(back["id"], now["id"])
    np.testing.assert_allclose(back["position"], now["position"], rtol=1e-6)
    np.testing.assert_allclose(back["pressure"], now["pressure"], rtol=1e-5, atol=1e-3)
    np.testing.assert_array_equal(back["kind"], now["kind"])
    with pytest.raises(ValueError, match="format"):
        sim.write_frame(path, format="xyz")
