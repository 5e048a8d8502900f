"""magbench.io.peers: Basilisk's detumbling runs, read from data with their checksum."""

import shutil

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.io import DATA_DIR, DataError, load_basilisk_detumble_runs


def test_the_eighteen_runs_as_the_reference_prints_them():
    runs = load_basilisk_detumble_runs()
    assert runs.attitude_mrp.shape == runs.initial_rate.shape == (18, 3)
    # bdot_triad.md §6.1, first and last rows, to their printed digits
    assert_allclose(runs.attitude_mrp[0], [-0.165167, 0.800703, 0.131154], rtol=0, atol=5e-7)
    assert_allclose(runs.initial_rate[-1], [0.23453849, 0.02264905, -0.11409486], rtol=0, atol=5e-9)
    assert runs.detumble_time[0] == 2338 and runs.detumble_time[-1] == 4461
    assert_allclose(np.degrees(runs.late_rate[3]), 0.1310, rtol=0, atol=5e-5)
    # three starts of rising rate per attitude: ω₀ scales 1 : 2 : 3 within each triple
    w = np.linalg.norm(runs.initial_rate, axis=1).reshape(6, 3)
    assert_allclose(w / w[:, :1], np.tile([1.0, 2.0, 3.0], (6, 1)), rtol=1e-6)


def test_the_quaternions_are_scipys_of_the_mrps():
    from scipy.spatial.transform import Rotation

    runs = load_basilisk_detumble_runs()
    q = runs.attitude_quaternion()
    # scipy normalises its result; the closed form is unit to rounding already (4 ulps)
    assert_allclose(q, Rotation.from_mrp(runs.attitude_mrp).as_quat(scalar_first=True), rtol=0, atol=1e-15)


def test_an_edited_copy_is_refused(tmp_path):
    shutil.copytree(DATA_DIR / "peers", tmp_path / "peers")
    path = tmp_path / "peers" / "basilisk_detumble.csv"
    path.write_text(path.read_text().replace("2338", "2339"))
    with pytest.raises(DataError, match="SHA256|checksum"):
        load_basilisk_detumble_runs(tmp_path)
