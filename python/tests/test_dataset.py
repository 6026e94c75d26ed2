"""examples/make_dataset.py: LagrangeBench's layout, reloaded with h5py, reproducible."""
import importlib.util
import json
import pathlib

import h5py
import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def make_dataset():
    spec = importlib.util.spec_from_file_location("make_dataset",
                                                  ROOT / "examples" / "make_dataset.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def run(out, seed):
    assert make_dataset().main([str(out), "--train", "2", "--valid", "1", "--test", "0",
                                "--duration", "0.1", "--every", "0.02", "--spacing", "0.02",
                                "--seed", str(seed)]) == 0
    with h5py.File(out / "train.h5") as f:
        return {key: (f[key]["position"][:], f[key]["particle_type"][:]) for key in f}


def test_the_dataset_reloads_with_its_shapes_and_statistics(tmp_path):
    train = run(tmp_path / "a", seed=3)
    meta = json.loads((tmp_path / "a" / "metadata.json").read_text())
    assert list(train) == ["00000", "00001"]
    assert meta["num_trajs_train"] == 2 and meta["num_trajs_valid"] == 1
    assert meta["num_trajs_test"] == 0
    assert meta["sequence_length_train"] == 6 and meta["dt"] == 0.02
    bounds = np.array(meta["bounds"])
    for position, types in train.values():
        assert position.dtype == np.float32 and types.dtype == np.int32
        assert position.shape == (6, len(types), 3)
        assert set(np.unique(types)) == {0, 1}
        assert np.all(position >= bounds[:, 0]) and np.all(position <= bounds[:, 1])
        walls = position[:, types == 1, :]
        assert np.array_equal(walls[0], walls[-1])  # walls stand still
        assert position.shape[1] <= meta["num_particles_max"]
    # The statistics are those of the training split's fluid, a sample at a time.
    v = np.concatenate([np.diff(p[:, t == 0].astype(np.float64), axis=0).reshape(-1, 3)
                        for p, t in train.values()])
    a = np.concatenate([np.diff(np.diff(p[:, t == 0].astype(np.float64), axis=0),
                                axis=0).reshape(-1, 3) for p, t in train.values()])
    assert meta["vel_mean"] == pytest.approx(v.mean(0).tolist(), abs=1e-9)
    assert meta["vel_std"] == pytest.approx(v.std(0).tolist(), abs=1e-9)
    assert meta["acc_std"] == pytest.approx(a.std(0).tolist(), abs=1e-9)
    # The water falls: its mean displacement a sample points down.
    assert meta["vel_mean"][1] < 0
    with h5py.File(tmp_path / "a" / "valid.h5") as f:
        assert list(f) == ["00000"]


def test_the_same_seed_gives_the_same_data_and_another_seed_other_data(tmp_path):
    first = run(tmp_path / "a", seed=5)
    again = run(tmp_path / "b", seed=5)
    other = run(tmp_path / "c", seed=6)
    for key in first:
        assert np.array_equal(first[key][0], again[key][0])
    assert any(first[k][0].shape != other[k][0].shape or
               not np.array_equal(first[k][0], other[k][0]) for k in first)
