"""Throughput of a problem bank on a Dask LocalCluster of 1 and of 2 worker processes (issue 16):
every derivation solved `repeats` times, wall time of the whole bank. Prints one line:
    workers_1_seconds workers_2_seconds tasks
    python3 tests/bench/batch_scaling.py ROOT REPEATS"""
import glob
import os
import sys
import time

from distributed import Client, LocalCluster

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python", "examples"))
import dask_bank  # noqa: E402


def main():
    root, repeats = sys.argv[1], int(sys.argv[2])
    items = [(p, {}) for p in sorted(glob.glob(os.path.join(root, "derivations", "*", "*.yaml")))] * repeats
    times = []
    for workers in (1, 2):
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
        dask_bank.solve_bank(client, items[:4])  # warm the workers (imports, caches)
        start = time.perf_counter()
        dask_bank.solve_bank(client, items)
        times.append(time.perf_counter() - start)
        client.close()
        cluster.close()
    print(f"{times[0]:.3f} {times[1]:.3f} {len(items)}")


# the worker processes import this file again: only the main process runs the bench
if __name__ == "__main__":
    main()
