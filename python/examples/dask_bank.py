"""A problem bank solved on a Dask cluster (Debian python3-distributed): every scene of a bank in
several variants (a parameter set per student, say), each solved on a worker, the results gathered.

    python3 python/examples/dask_bank.py [SCHEDULER_ADDRESS]

Without an address it starts a LocalCluster of two worker processes on this machine; with one
(tcp://host:8786) it uses that cluster, whose workers must be able to `import kinergy` and read
the scene files. Tested by python/tests/test_dask.py."""
import os
import sys

import kinergy


def solve_one(path, sets):
    """One scene with its parameters set: {result name: value as text}, or {"error": message}."""
    try:
        scene = kinergy.load(path)
        for name, value in sets.items():
            scene.set(name, value)
        return {r.name: r.value() for r in scene.solve().results}
    except kinergy.SceneError as e:
        return {"error": e.message}


def bank(root):
    """(path, sets) for each variant: three lengths of the sliding rod, three masses of the bar on
    its spring, and a few derivations as written."""
    energy = os.path.join(root, "derivations", "energy")
    items = [(os.path.join(energy, "sliding_rod.yaml"), {"l": f"{l} m"}) for l in (0.8, 1.2, 1.6)]
    items += [(os.path.join(energy, "bar_spring.yaml"), {"m": f"{m} kg"}) for m in (8, 10, 12)]
    items += [(os.path.join(energy, name), {}) for name in ("atwood_pulley.yaml", "braking_friction.yaml")]
    return items


def solve_chunk(path, variants, start):
    """Variants of one scene (a dict of parameter values each), in one kinergy.batch call: they
    share the scene's solution where it holds. {result name: value as text} or {"error": message}
    for each."""
    results = kinergy.batch({"scene": path, "set": sets, "id": start + i} for i, sets in enumerate(variants))
    return [{r["name"]: r["value"] for r in out["solution"]["results"]} if out["ok"] else {"error": out["error"]["message"]}
            for out in results]


def solve_variants(client, path, variants, chunk=10000):
    """A bank of variants of one scene on the cluster, `chunk` variants a task, in order."""
    futures = [client.submit(solve_chunk, path, variants[i:i + chunk], i, pure=False) for i in range(0, len(variants), chunk)]
    return [r for part in client.gather(futures) for r in part]


def solve_bank(client, items):
    futures = [client.submit(solve_one, path, sets, pure=False) for path, sets in items]
    return client.gather(futures)


def main():
    from distributed import Client, LocalCluster

    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    items = bank(root)
    if len(sys.argv) > 1:
        client = Client(sys.argv[1])
    else:
        client = Client(LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None))
    for (path, sets), result in zip(items, solve_bank(client, items)):
        print(os.path.basename(path), sets, result)
    client.close()


if __name__ == "__main__":
    main()
