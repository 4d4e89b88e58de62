"""The symbolic version of a derivation, as an author would write it: every parameter given a
number made a symbol with its unit and no value (`m: 2 kg` -> `m: kg`, `mu: 0.25` -> `mu: number`),
every result asked without `unit:`, the `expect` claims left out (their values need numbers).
Text edits only: the scene keeps its lines, comments and order."""
import re
import sys

NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def symbolize(text):
    out, block, values = [], None, {}
    for line in text.splitlines(keepends=True):
        top = re.match(r"^([A-Za-z_]\w*):", line)
        if top:
            block = top.group(1)
        if block == "expect":
            continue
        if top and block == "parameters" and "{" in line:  # flow style: parameters: {m: 40 kg, ...}
            inner = line[line.index("{") + 1:line.rindex("}")]
            items = []
            for item in inner.split(","):
                name, value = (x.strip() for x in item.split(":", 1))
                m = re.match(r"^(" + NUMBER + r")(?:\s+(\S.*))?$", value)
                items.append(f"{name}: {(m.group(2) or 'number') if m else value}")
            line = "parameters: {" + ", ".join(items) + "}\n"
        if block == "parameters" and not top:  # theta2: {value: 210 deg, in: [180 deg, 270 deg]}
            m = re.match(r"^(\s+)([A-Za-z_]\w*):\s*\{value:\s*(" + NUMBER + r")(?:\s+([^,}]+?))?\s*,(.*)$", line.rstrip("\n"))
            if m:
                indent, name, value, unit, rest = m.groups()
                values[name] = (value, unit)
                out.append(f"{indent}{name}: {{value: {unit if unit else 'number'},{rest}\n")
                continue
        if block == "parameters" and not top:
            m = re.match(r"^(\s+)([A-Za-z_]\w*):\s*(" + NUMBER + r")(?:\s+(\S.*?))?\s*(#.*)?$", line.rstrip("\n"))
            if m:
                indent, name, value, unit, comment = m.groups()
                values[name] = (value, unit)
                line = f"{indent}{name}: {unit if unit else 'number'}" + (f"  {comment}" if comment else "") + "\n"
        if block == "find" and not top:
            line = re.sub(r",\s*unit:\s*[^,}]+", "", line)
        out.append(line)
    return "".join(out), values


if __name__ == "__main__":
    text, _ = symbolize(open(sys.argv[1]).read())
    sys.stdout.write(text)
