#!/usr/bin/env python3
"""Training data for learned simulators: randomized dam breaks, written in LagrangeBench's layout.

    PYTHONPATH=build/python /usr/bin/python3 examples/make_dataset.py OUT [--train 8 --valid 2
        --test 2 --duration 1.0 --every 0.01 --spacing 0.01 --seed 0]

Each trajectory is a water column of random width and height collapsing in a narrow tank,
with, at random, a box standing on the floor in its way. OUT receives:

  train.h5, valid.h5, test.h5  one group a trajectory ("00000", "00001", ...), each with
                               position       (samples, particles, 3) float32, m
                               particle_type  (particles,) int32: 0 fluid, 1 wall
  metadata.json                the bounds, the time between samples (dt), the samples a
                               trajectory (sequence_length_*), the trajectories a split
                               (num_trajs_*), the most particles in one (num_particles_max),
                               the connectivity radius (the SPH support radius), and the
                               statistics of the velocity and acceleration, per axis, over
                               every fluid particle of the training split: vel as displacement
                               a sample, acc as its change a sample, as graph network
                               simulators normalize their inputs and targets

The same seed gives the same files: the scenes come from numpy's generator seeded with it, and
sph's CPU backend gives the same bytes for the same scene.
"""

import argparse
import json
import pathlib
import sys

import h5py
import numpy as np

import sph

TANK = (0.5, 0.3, 0.06)  # m: long, high, and a few particles deep


def random_scene(rng, spacing):
    """A dam break with a random column and, half the time, a box in its way."""
    def spacings(low, high):  # a length from low to high m, in whole spacings (at least two)
        return spacing * int(rng.integers(max(2, round(low / spacing)),
                                          max(2, round(high / spacing)) + 1))

    width, height = spacings(0.1, 0.2), spacings(0.1, 0.2)
    walls = [{"type": "tank", "min": [0, 0, 0], "max": list(TANK), "layers": 2, "closed": True}]
    if rng.random() < 0.5:
        size = spacings(0.04, 0.08)
        x = round(float(rng.uniform(width + 0.1, TANK[0] - size - 0.05)), 4)
        walls.append({"name": "obstacle", "type": "box", "min": [x, 0, 0],
                      "max": [x + size, spacings(0.04, 0.1), TANK[2]]})
    return {
        "name": "dataset_dam_break",
        "domain": {"min": [-0.05, -0.05, -0.05],
                   "max": [TANK[0] + 0.05, TANK[1] + 0.05, TANK[2] + 0.05], "outside": "remove"},
        "gravity": [0, -9.81, 0],
        "fluid": {"spacing": spacing, "kernel": "cubic_spline",
                  "viscosity": {"model": "artificial", "value": 0.02},
                  "blocks": [{"min": [0, 0, 0], "max": [width, height, TANK[2]]}]},
        "walls": walls,
        "output": {"format": "none"},
    }


def trajectory(document, duration, every):
    """Positions (samples, particles, 3) and types (particles,), ordered by particle id."""
    sim = sph.Simulation(sph.scene_from_dict(document), threads=0)
    frames = []
    samples = int(round(duration / every)) + 1
    for k in range(samples):
        sim.advance_to(k * every)
        p = sim.particles(include_boundary=True)
        frames.append(p["position"])
    kinds = p["kind"].astype(np.int32)
    if sim.removed_count:
        raise RuntimeError(f"{sim.removed_count} particles left the closed tank")
    return np.stack(frames).astype(np.float32), kinds, sim.calibration


def statistics(trajectories):
    """Mean and standard deviation per axis of the fluid's displacement a sample and of its
    change a sample, over every trajectory given."""
    velocities, accelerations = [], []
    for position, kinds in trajectories:
        fluid = position[:, kinds == 0, :].astype(np.float64)
        v = np.diff(fluid, axis=0)
        velocities.append(v.reshape(-1, 3))
        accelerations.append(np.diff(v, axis=0).reshape(-1, 3))
    v = np.concatenate(velocities)
    a = np.concatenate(accelerations)
    return {"vel_mean": v.mean(0).tolist(), "vel_std": v.std(0).tolist(),
            "acc_mean": a.mean(0).tolist(), "acc_std": a.std(0).tolist()}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out", type=pathlib.Path)
    parser.add_argument("--train", type=int, default=8)
    parser.add_argument("--valid", type=int, default=2)
    parser.add_argument("--test", type=int, default=2)
    parser.add_argument("--duration", type=float, default=1.0, help="simulated s a trajectory")
    parser.add_argument("--every", type=float, default=0.01, help="s between samples")
    parser.add_argument("--spacing", type=float, default=0.01, help="particle spacing, m")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    for name in ("train", "valid", "test"):
        if getattr(args, name) < 0:
            parser.error(f"--{name}: expected a count of trajectories >= 0")
    if args.train < 1:
        parser.error("--train: expected at least one trajectory (the statistics come from it)")
    if not 0 < args.every <= args.duration:
        parser.error("--every: expected a time between samples in (0, --duration]")

    rng = np.random.default_rng(args.seed)
    args.out.mkdir(parents=True, exist_ok=True)
    metadata = {"case": "DAM", "solver": "sph (WCSPH)", "dim": 3, "dx": args.spacing,
                "dt": args.every, "t_end": args.duration, "seed": args.seed,
                "periodic_boundary_conditions": [False, False, False],
                "bounds": [[-0.05, TANK[0] + 0.05], [-0.05, TANK[1] + 0.05],
                           [-0.05, TANK[2] + 0.05]],
                "particle_types": {"0": "fluid", "1": "wall"}}
    most, training = 0, []
    for split in ("train", "valid", "test"):
        count = getattr(args, split)
        with h5py.File(args.out / f"{split}.h5", "w") as f:
            for k in range(count):
                position, kinds, calibration = trajectory(random_scene(rng, args.spacing),
                                                          args.duration, args.every)
                group = f.create_group(f"{k:05d}")
                group.create_dataset("position", data=position)
                group.create_dataset("particle_type", data=kinds)
                most = max(most, position.shape[1])
                metadata["default_connectivity_radius"] = calibration["support_radius"]
                if split == "train":
                    training.append((position, kinds))
                print(f"{split} {k + 1}/{count}: {position.shape[1]} particles, "
                      f"{position.shape[0]} samples", file=sys.stderr)
        metadata[f"sequence_length_{split}"] = int(round(args.duration / args.every)) + 1
        metadata[f"num_trajs_{split}"] = count
    metadata["num_particles_max"] = most
    metadata.update(statistics(training))
    (args.out / "metadata.json").write_text(json.dumps(metadata, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
