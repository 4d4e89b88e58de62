"""What a derivation's YAML claims, read for the sympy checks beside it (no kinergy): its flat
expect block and its parameters' values."""
import re

import sympy as sp


def expect_entries(text):
    """name -> (form, value text) from the YAML's flat expect block."""
    out = {}
    block = text.split("\nexpect:\n", 1)[1]
    for line in block.splitlines():
        hit = re.match(r"\s+(\w+): \{form: (.*), value: (.*)\}\s*$", line)
        if hit:
            out[hit.group(1)] = (hit.group(2), hit.group(3))
    return out


def parameter_values(text):
    """symbol (positive) -> value in SI, from the parameters block (numbers as written)."""
    vals = {}
    block = text.split("\nparameters:\n", 1)[1].split("\ncoordinates:", 1)[0]
    for line in block.splitlines():
        hit = re.match(r"\s+(\w+): ([-0-9.e]+)", line)
        if hit:
            vals[sp.Symbol(hit.group(1), positive=True)] = sp.Float(hit.group(2), 30)
    return vals
