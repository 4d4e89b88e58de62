"""Throughput of a problem bank on a Dask LocalCluster of 1 and of 2 worker processes (issues 16,
30): every derivation solved `repeats` times, wall time of the whole bank; and a bank of VARIANTS
variants of the sliding rod (its length and angle), 10 000 a task, each task one kinergy.batch call
(the variants share the rod's solution). Prints one line:
    workers_1_seconds workers_2_seconds tasks variants_1_seconds variants_2_seconds variants
    python3 tests/bench/batch_scaling.py ROOT REPEATS [VARIANTS]"""
import glob
import os
import sys
import time

from distributed import Client, LocalCluster

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python", "examples"))
import dask_bank  # noqa: E402


def main():
    root, repeats = sys.argv[1], int(sys.argv[2])
    n = int(sys.argv[3]) if len(sys.argv) > 3 else 100000
    items = [(p, {}) for p in sorted(glob.glob(os.path.join(root, "derivations", "*", "*.yaml")))] * repeats
    rod = os.path.join(root, "derivations", "energy", "sliding_rod.yaml")
    variants = [{"l": f"{0.5 + 1.5 * (i % 1000) / 999:.6f} m", "theta2": f"{20 + 150 * (i // 1000) / (n // 1000):.5f} deg"} for i in range(n)]
    times, banks = [], []
    for workers in (1, 2):
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
        dask_bank.solve_bank(client, items[:4])  # warm the workers (imports, caches)
        start = time.perf_counter()
        dask_bank.solve_bank(client, items)
        times.append(time.perf_counter() - start)
        start = time.perf_counter()
        results = dask_bank.solve_variants(client, rod, variants)
        banks.append(time.perf_counter() - start)
        assert len(results) == n and all("omega2" in r for r in results)
        client.close()
        cluster.close()
    print(f"{times[0]:.3f} {times[1]:.3f} {len(items)} {banks[0]:.3f} {banks[1]:.3f} {n}")


# the worker processes import this file again: only the main process runs the bench
if __name__ == "__main__":
    main()
