"""Objects of a Python engine beside the fluid, through sph.ObjectExchange."""
import numpy as np
import pytest

import sph

SPACING = 0.01
HALF = np.array([0.07, 0.04, 0.05])  # the buoy's half extents, m
BUOY_DENSITY = 500.0                   # kg/m³: it floats half under


def tank():
    """A tank of water 0.14 m deep, room above it for the buoy."""
    return sph.scene_from_dict({
        "name": "python_buoy",
        "domain": {"min": [-0.05, -0.05, -0.05], "max": [0.35, 0.45, 0.21]},
        "gravity": [0, -9.81, 0],
        "fluid": {"spacing": SPACING, "viscosity": {"value": 0.05},
                  "blocks": [{"min": [0, 0, 0], "max": [0.3, 0.14, 0.16], "hydrostatic": True}]},
        "walls": [{"type": "tank", "min": [0, 0, 0], "max": [0.3, 0.3, 0.16]}],
        "calibration": {"max_expected_speed": 1.5},
        "output": {"format": "none"},
    })


class Buoy:
    """A rigid box on a vertical rail: the particles of its outer layer, half a spacing inside
    its faces, with their outward normals; moved by gravity and the fluid's forces."""

    def __init__(self, centre):
        n = np.rint(2 * HALF / SPACING).astype(int)
        at = np.stack(np.meshgrid(*[np.arange(k) for k in n], indexing="ij"), -1).reshape(-1, 3)
        normal = np.where(at == 0, -1.0, 0.0) + np.where(at == n - 1, 1.0, 0.0)
        outer = np.any(normal != 0, axis=1)
        self.offset = -HALF + (at[outer] + 0.5) * SPACING
        self.normal = normal[outer] / np.linalg.norm(normal[outer], axis=1, keepdims=True)
        self.centre = np.array(centre, dtype=float)
        self.velocity_y = 0.0
        self.mass = BUOY_DENSITY * np.prod(2 * HALF)
        self.exchange = sph.ObjectExchange(len(self.offset))

    def publish(self, time):
        count = len(self.offset)
        velocity = np.zeros((count, 3))
        velocity[:, 1] = self.velocity_y
        self.exchange.publish(self.offset + self.centre, velocity, self.normal,
                              np.full(count, 0.5 * SPACING), np.zeros(count, np.int32), time=time)

    def step(self, gravity_y):
        force, span = self.exchange.take_forces()
        self.velocity_y += (force[:, 1].sum() / self.mass + gravity_y) * span
        self.centre[1] += self.velocity_y * span

    def bottom(self):
        return self.centre[1] - HALF[1]


def water_level(sim):
    """Away from the buoy (x > 0.2): the top particle of each lattice column, averaged, plus half
    a spacing."""
    x = sim.particles()["position"]
    x = x[x[:, 0] > 0.2]
    column = np.floor(x[:, 0] / SPACING) * 1000 + np.floor(x[:, 2] / SPACING)
    keys, which = np.unique(column, return_inverse=True)
    top = np.full(len(keys), -np.inf)
    np.maximum.at(top, which, x[:, 1])
    return top.mean() + 0.5 * SPACING


def test_a_python_driven_buoy_floats_at_its_archimedes_draft():
    buoy = Buoy([0.1, 0.14 + 0.02 + HALF[1], 0.08])  # its bottom 2 cm above the water
    buoy.publish(0.0)
    sim = sph.Simulation(tank(), threads=2)
    sim.attach_object_engine(buoy.exchange)
    drafts, next_sample = [], 1.2
    while sim.time < 1.5:
        sim.step(1.5)
        buoy.step(-9.81)
        buoy.publish(sim.time)
        if sim.time >= next_sample - 1e-9:  # settled: average the bobbing
            drafts.append(water_level(sim) - buoy.bottom())
            next_sample += 0.05
    archimedes = 2 * HALF[1] * BUOY_DENSITY / 1000.0
    assert len(drafts) >= 6
    assert np.mean(drafts) == pytest.approx(archimedes, rel=0.10)
    # The fluid's force on it, as the simulation reports it, carries its weight.
    [stats] = sim.objects()
    assert stats["fluid_force"][1] == pytest.approx(buoy.mass * 9.81, rel=0.25)


def test_what_breaks_the_exchange_is_refused():
    exchange = sph.ObjectExchange(4)
    x = np.zeros((4, 3))
    with pytest.raises(ValueError, match="velocity"):
        exchange.publish(x, np.zeros((3, 3)), x, np.ones(4), np.zeros(4, np.int32))
    with pytest.raises(ValueError, match="radius"):
        exchange.publish(x, x, x, np.ones(5), np.zeros(4, np.int32))
    with pytest.raises(IndexError):
        exchange.publish(x, x, x, np.ones(4), np.array([0, 0, -1, 0], np.int32))
    with pytest.raises(IndexError):
        exchange.publish(x, x, x, np.ones(4), np.zeros(4, np.int32), handle=np.arange(1, 5))
    exchange.publish(x, x, x, np.ones(4), np.zeros(4, np.int32))
    force, span = exchange.take_forces()
    assert force.shape == (4, 3) and span == 0.0
