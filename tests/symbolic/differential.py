#!/usr/bin/env python3
"""Differential test (issue 43): every derivation's parameters perturbed (a fixed seed), the
perturbed scene solved by `kinergy solve --json`, and each result compared with the derivation's
`expect` form evaluated here, independently of kinergy, with sympy/mpmath at the perturbed values
(units converted to SI by the table below, not by kinergy). A perturbed scene kinergy refuses,
or at which a form has no real value, is outside the form's conditions: skipped and counted. A
disagreement fails the test.

usage: differential.py KINERGY [DERIVATIONS_DIR] [--rounds N]"""
import json
import math
import os
import random
import re
import subprocess
import sys
import tempfile

import mpmath
import sympy
import yaml

mpmath.mp.dps = 30

# SI factor of each unit a derivation writes (a pound is a force here, as in kinergy's docs)
BASE = {
    "": 1, "kg": 1, "g": mpmath.mpf("0.001"), "slug": mpmath.mpf("14.5939029372063648"),
    "m": 1, "mm": mpmath.mpf("0.001"), "cm": mpmath.mpf("0.01"), "km": 1000,
    "ft": mpmath.mpf("0.3048"), "in": mpmath.mpf("0.0254"),
    "s": 1, "min": 60, "h": 3600,
    "rad": 1, "deg": mpmath.pi / 180, "rev": 2 * mpmath.pi, "rpm": 2 * mpmath.pi / 60,
    "N": 1, "kN": 1000, "lb": mpmath.mpf("4.4482216152605"), "lbf": mpmath.mpf("4.4482216152605"),
    "J": 1, "kJ": 1000, "W": 1, "kW": 1000, "hp": mpmath.mpf("745.69987158227022"),
}


def unit_factor(text):
    """SI factor of a unit text such as N*m/rad, m/s^2, kg*m^2, lb*ft."""
    text = (text or "").strip().replace("·", "*")
    if not text or text == "number":
        return mpmath.mpf(1)
    num, *den = text.split("/")
    f = mpmath.mpf(1)
    for part, sign in [(num, 1)] + [(d, -1) for d in den]:
        for u in part.split("*"):
            name, _, power = u.partition("^")
            if name not in BASE:
                raise KeyError(f"unit '{name}' not in the table")
            f *= mpmath.mpf(BASE[name]) ** (sign * int(power or 1))
    return f


NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def perturbed(text, rng):
    """The scene with every parameter's number scaled by 1 + 0.1 u (u in [-1, 1]), six digits;
    returns the text and each parameter's SI value."""
    values, out, block = {}, [], None

    def scaled(name, number, unit):
        v = float(number) * (1 + 0.1 * (2 * rng.random() - 1))
        t = f"{v:.6g}"
        values[name] = mpmath.mpf(t) * unit_factor(unit)
        return t

    for line in text.splitlines(keepends=True):
        top = re.match(r"^([A-Za-z_]\w*):", line)
        if top:
            block = top.group(1)
        if top and block == "parameters" and "{" in line:
            items = []
            for item in line[line.index("{") + 1:line.rindex("}")].split(","):
                name, value = (x.strip() for x in item.split(":", 1))
                m = re.match(r"^(" + NUMBER + r")(?:\s+(\S.*))?$", value)
                items.append(f"{name}: {scaled(name, m.group(1), m.group(2)) + (' ' + m.group(2) if m.group(2) else '')}" if m else f"{name}: {value}")
            line = "parameters: {" + ", ".join(items) + "}\n"
        elif block == "parameters" and not top and re.match(r"^\s+[A-Za-z_]\w*:\s*\{value:", line):
            # theta2: {value: 210 deg, in: [180 deg, 270 deg]} (the scaled value kept inside its range)
            m = re.match(r"^(\s+)([A-Za-z_]\w*):\s*\{value:\s*(" + NUMBER + r")(?:\s+([^,}]+?))?\s*(,.*)$", line.rstrip("\n"))
            if m:
                indent, name, number, unit, rest = m.groups()
                line = f"{indent}{name}: {{value: {scaled(name, number, unit)}" + (f" {unit}" if unit else "") + rest + "\n"
        elif block == "parameters" and not top:
            m = re.match(r"^(\s+)([A-Za-z_]\w*):\s*(" + NUMBER + r")(?:\s+(\S.*?))?\s*$", line.rstrip("\n"))
            if m:
                indent, name, number, unit = m.groups()
                line = f"{indent}{name}: {scaled(name, number, unit)}" + (f" {unit}" if unit else "") + "\n"
        out.append(line)
    return "".join(out), values


def form_value(form, values):
    """The expected form at the values (SI), with sympy at 30 digits; None where it is not real."""
    names = {n: sympy.Symbol(n) for n in values}
    expr = sympy.sympify(str(form).replace("^", "**"), locals=names)
    v = sympy.N(expr.subs({names[n]: sympy.Float(str(values[n]), 30) for n in values}), 30)
    if not v.is_real:
        return None
    return mpmath.mpf(str(v))


def main():
    kinergy = sys.argv[1]
    root = sys.argv[2] if len(sys.argv) > 2 and not sys.argv[2].startswith("--") else os.path.join(os.path.dirname(__file__), "..", "..", "derivations")
    rounds = int(sys.argv[sys.argv.index("--rounds") + 1]) if "--rounds" in sys.argv else 2
    rng = random.Random(43)  # the fixed seed
    files = sorted(os.path.join(d, f) for d, _, fs in os.walk(root) for f in fs if f.endswith(".yaml"))
    compared = skipped = 0
    bad = []
    with tempfile.TemporaryDirectory() as tmp:
        for path in files:
            text = open(path).read()
            scene = yaml.safe_load(text)
            expect = scene.get("expect") or {}
            forms = {k: v["form"] for k, v in expect.items() if isinstance(v, dict) and "form" in v}
            if not forms:
                continue
            for r in range(rounds):
                new, values = perturbed(text, rng)
                # the claims' values are the original scene's: left out of the perturbed one
                new = new[:new.index("\nexpect:") + 1]
                f = os.path.join(tmp, os.path.basename(path))
                open(f, "w").write(new)
                p = subprocess.run([kinergy, "solve", "--json", f], capture_output=True, text=True, timeout=600)
                if p.returncode != 0:
                    skipped += 1
                    print(f"skipped {os.path.relpath(path, root)} round {r}: refused: {(p.stderr or p.stdout).strip()[:160]}")
                    continue
                results = {x["name"]: x for x in json.loads(p.stdout)["results"]}
                for name, form in forms.items():
                    want = form_value(form, values)
                    got = results.get(name)
                    if want is None or got is None or got.get("value") is None:
                        skipped += 1
                        continue
                    have = mpmath.mpf(got["value"]) * unit_factor(got.get("unit", ""))
                    compared += 1
                    if abs(have - want) > mpmath.mpf("1e-9") * max(abs(want), mpmath.mpf(1e-12)):
                        bad.append(f"{os.path.relpath(path, root)} round {r}: {name}: kinergy {mpmath.nstr(have, 15)}, "
                                   f"the expected form {form} gives {mpmath.nstr(want, 15)}")
    for b in bad:
        print("DISAGREES:", b)
    print(f"{compared} values compared, {len(bad)} disagreements, {skipped} skipped (outside a form's conditions)")
    if compared < 100:
        print("too few values compared")
        return 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
