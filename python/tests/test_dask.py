"""A bank of scenes x variants solved on a Dask LocalCluster with two worker processes gives the
serial run's results (python/examples/dask_bank.py)."""
import os
import sys

import pytest

distributed = pytest.importorskip("distributed")

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "examples"))

import dask_bank  # noqa: E402


def test_a_bank_on_two_workers_matches_the_serial_run():
    root = os.path.join(HERE, "..", "..")
    items = dask_bank.bank(root)
    serial = [dask_bank.solve_one(path, sets) for path, sets in items]
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    client = distributed.Client(cluster)
    rod = os.path.join(root, "derivations", "energy", "sliding_rod.yaml")
    variants = [{"l": f"{0.5 + 0.001 * i:.4f} m", "theta2": f"{20 + 0.05 * i:.3f} deg"} for i in range(2500)]
    try:
        assert len(client.scheduler_info()["workers"]) == 2
        assert dask_bank.solve_bank(client, items) == serial
        # a bank of variants, 1000 a task, each task one kinergy.batch call
        bank = dask_bank.solve_variants(client, rod, variants, chunk=1000)
    finally:
        client.close()
        cluster.close()
    # the variants differ as the physics says: omega2 of the sliding rod ~ 1/sqrt(l)
    w = [float(r["omega2"]) for r in serial[:3]]
    assert abs(w[0] / w[2] - (1.6 / 0.8) ** 0.5) < 1e-12
    assert all("error" not in r for r in serial)

    # the variants' omega2 by hand: sqrt(3 g sin(theta2) / l)
    import math
    assert len(bank) == len(variants)
    for v, r in zip(variants, bank):
        l, th = float(v["l"].split()[0]), math.radians(float(v["theta2"].split()[0]))
        assert abs(float(r["omega2"]) - math.sqrt(3 * 9.81 * math.sin(th) / l)) < 1e-12 * float(r["omega2"])
