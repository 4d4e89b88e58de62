"""What confirmation costs (issue 25): every derivation solved as a whole `kinergy solve` process
with the default (each analysis confirmed a second way: a simulation of the same scene, else the
equations' residuals at 50 digits) and with --no-confirm, the two alternated, each scene's median
of repeats. The target: the median over the derivations of the solve time with confirmation at
most 2x the median without. Writes the markdown report (default docs/confirm.md) with the command,
date and machine.
"""
import argparse
import datetime
import glob
import os
import platform
import statistics
import subprocess
import time


def timed(cmd):
    t = time.perf_counter()
    r = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - t, r.returncode


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--kinergy", required=True)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--out", default="docs/confirm.md")
    ap.add_argument("--command", default="bash tests/bench/run_confirm.sh")
    a = ap.parse_args()
    scenes = sorted(glob.glob("derivations/*/*.yaml"))
    rows = []
    for f in scenes:
        on, off = [], []
        for _ in range(a.repeats):  # alternated: a slow moment of the machine falls on both
            t, rc = timed([a.kinergy, "solve", f])
            on.append(t)
            t2, rc2 = timed([a.kinergy, "solve", "--no-confirm", f])
            off.append(t2)
        rows.append((f, statistics.median(on), statistics.median(off), rc, rc2))
    med_on = statistics.median(r[1] for r in rows)
    med_off = statistics.median(r[2] for r in rows)
    ratio = med_on / med_off
    ratios = sorted(r[1] / r[2] for r in rows)
    worst = max(rows, key=lambda r: r[1] / r[2])
    failed = [r[0] for r in rows if r[3] != 0 or r[4] != 0]
    with open(a.out, "w") as out:
        out.write("# What confirmation costs\n\n")
        out.write("Every derivation solved as a whole `kinergy solve` process, with the default (each analysis confirmed "
                  "a second way: a simulation of the same scene on the tape, else the equations' residuals at 50 digits) "
                  "and with `--no-confirm`, the two alternated, the median of "
                  f"{a.repeats} runs of each. Measured side by side in one run.\n\n")
        out.write(f"- command: `{a.command}`\n- date: {datetime.date.today().isoformat()}\n"
                  f"- machine: {platform.machine()}, {os.cpu_count()} cores, {platform.platform()}\n\n")
        out.write("| what | with confirmation | without | ratio | target | met |\n| --- | --- | --- | --- | --- | --- |\n")
        out.write(f"| median over the {len(rows)} derivations of the solve time | {med_on * 1e3:.1f} ms | {med_off * 1e3:.1f} ms | "
                  f"{ratio:.2f}x | <= 2x | {'yes' if ratio <= 2 else 'no'} |\n")
        out.write(f"| median of the per-scene ratios | | | {statistics.median(ratios):.2f}x | | |\n")
        out.write(f"| the dearest scene ({worst[0]}) | {worst[1] * 1e3:.1f} ms | {worst[2] * 1e3:.1f} ms | {worst[1] / worst[2]:.2f}x | | |\n\n")
        if failed:
            out.write("Scenes that did not solve: " + ", ".join(failed) + "\n\n")
        out.write("Each scene:\n\n| scene | with | without | ratio |\n| --- | --- | --- | --- |\n")
        for r in rows:
            out.write(f"| {r[0]} | {r[1] * 1e3:.1f} ms | {r[2] * 1e3:.1f} ms | {r[1] / r[2]:.2f}x |\n")
    print(f"median with confirmation {med_on * 1e3:.1f} ms, without {med_off * 1e3:.1f} ms: {ratio:.2f}x (target <= 2x)")


if __name__ == "__main__":
    main()
