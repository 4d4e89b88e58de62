#!/usr/bin/env python3
"""Writes src/draw/glyphs_table.cpp: the measured sizes of the glyphs figure labels are set in.

- SVG labels: DejaVu Sans (the font the SVG names), each character's advance and ink box from the
  font file itself (its cmap, hmtx, loca and glyf tables), in ems.
- TikZ labels: the Computer Modern fonts LaTeX sets math in at 9 and 10 pt (and their 6 and 7 pt
  subscripts), each character's width, height, depth and italic correction from its TFM file
  (read through tftopl), in ems of the design size; the quad, the interword space and the kerns
  between characters.

Run from the repository's root when a font changes:  python3 src/draw/glyphs_table.py
It needs the Debian packages fonts-dejavu-core and texlive-base (tftopl, kpsewhich); the table it
writes is kept in the repository, so a build needs neither.
"""
import re
import struct
import subprocess
import sys

DEJAVU = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
TEX_FONTS = ["cmmi9", "cmmi6", "cmr9", "cmr6", "cmbx9", "cmbx6", "cmsy9", "cmsy6",
             "cmmi10", "cmmi7", "cmr10", "cmr7", "cmbx10", "cmbx7", "cmsy10", "cmsy7", "cmex10"]
# the characters SVG labels use: ASCII, Latin-1, Greek, combining marks, a few symbols
CODEPOINTS = (list(range(0x20, 0x7F)) + list(range(0xA0, 0x100)) + list(range(0x300, 0x370))
              + list(range(0x391, 0x3CA)) + [0x3D1, 0x3D5, 0x3F5] + list(range(0x2010, 0x2040))
              + list(range(0x2070, 0x2090)) + [0x2202, 0x2206, 0x2211, 0x2212, 0x221A, 0x221E, 0x222B, 0x2248, 0x2260, 0x2264, 0x2265])


def ttf_metrics(path):
    data = open(path, "rb").read()
    num = struct.unpack(">H", data[4:6])[0]
    tables = {}
    for i in range(num):
        tag, _, off, length = struct.unpack(">4sIII", data[12 + 16 * i: 28 + 16 * i])
        tables[tag.decode()] = (off, length)
    head = tables["head"][0]
    units = struct.unpack(">H", data[head + 18: head + 20])[0]
    loca_long = struct.unpack(">h", data[head + 50: head + 52])[0] == 1
    hhea = tables["hhea"][0]
    n_hmetrics = struct.unpack(">H", data[hhea + 34: hhea + 36])[0]
    hmtx = tables["hmtx"][0]
    maxp = tables["maxp"][0]
    n_glyphs = struct.unpack(">H", data[maxp + 4: maxp + 6])[0]

    def advance(g):
        g = min(g, n_hmetrics - 1)
        return struct.unpack(">H", data[hmtx + 4 * g: hmtx + 4 * g + 2])[0]

    loca = tables["loca"][0]
    glyf = tables["glyf"][0]

    def box(g):
        if loca_long:
            a, b = struct.unpack(">II", data[loca + 4 * g: loca + 4 * g + 8])
        else:
            a, b = (2 * v for v in struct.unpack(">HH", data[loca + 2 * g: loca + 2 * g + 4]))
        if a == b:
            return 0, 0
        _, _, ymin, _, ymax = struct.unpack(">hhhhh", data[glyf + a: glyf + a + 10])
        return ymin, ymax

    # cmap: the Windows Unicode BMP subtable, format 4
    cmap = tables["cmap"][0]
    n_sub = struct.unpack(">H", data[cmap + 2: cmap + 4])[0]
    sub = None
    for i in range(n_sub):
        plat, enc, off = struct.unpack(">HHI", data[cmap + 4 + 8 * i: cmap + 12 + 8 * i])
        if plat == 3 and enc == 1:
            sub = cmap + off
    assert sub is not None and struct.unpack(">H", data[sub: sub + 2])[0] == 4
    segs = struct.unpack(">H", data[sub + 6: sub + 8])[0] // 2
    ends = struct.unpack(">%dH" % segs, data[sub + 14: sub + 14 + 2 * segs])
    p = sub + 16 + 2 * segs
    starts = struct.unpack(">%dH" % segs, data[p: p + 2 * segs])
    deltas = struct.unpack(">%dh" % segs, data[p + 2 * segs: p + 4 * segs])
    range_at = p + 4 * segs
    offsets = struct.unpack(">%dH" % segs, data[range_at: range_at + 2 * segs])

    def glyph(cp):
        for i in range(segs):
            if starts[i] <= cp <= ends[i]:
                if offsets[i] == 0:
                    return (cp + deltas[i]) & 0xFFFF
                at = range_at + 2 * i + offsets[i] + 2 * (cp - starts[i])
                g = struct.unpack(">H", data[at: at + 2])[0]
                return (g + deltas[i]) & 0xFFFF if g else 0
        return 0

    out = []
    for cp in CODEPOINTS:
        g = glyph(cp)
        if g == 0 or g >= n_glyphs:
            continue
        ymin, ymax = box(g)
        out.append((cp, advance(g) / units, ymin / units, ymax / units))
    return out


def tfm_metrics(name):
    path = subprocess.run(["kpsewhich", name + ".tfm"], capture_output=True, text=True, check=True).stdout.strip()
    pl = subprocess.run(["tftopl", path], capture_output=True, text=True, check=True).stdout
    size = float(re.search(r"\(DESIGNSIZE R ([0-9.]+)\)", pl).group(1))
    chars = {}
    for m in re.finditer(r"\(CHARACTER ([CO]) (\S+)\n((?:   .*\n)*)", pl):
        code = ord(m.group(2)) if m.group(1) == "C" else int(m.group(2), 8)
        body = m.group(3)

        def get(key):
            k = re.search(r"\(" + key + r" R (-?[0-9.]+)\)", body)
            return float(k.group(1)) if k else 0.0

        chars[code] = (get("CHARWD"), get("CHARHT"), get("CHARDP"), get("CHARIC"))
    def fontdimen(key):
        k = re.search(r"\(" + key + r" R (-?[0-9.]+)\)", pl)
        return float(k.group(1)) if k else 0.0

    quad = fontdimen("QUAD")
    # the symbol font's placing of scripts (0 in the other fonts)
    script_dimens = tuple(fontdimen(k) for k in ("XHEIGHT", "SUP2", "SUB1", "SUB2", "SUPDROP", "SUBDROP", "AXISHEIGHT"))
    space = float(re.search(r"\(SPACE R (-?[0-9.]+)\)", pl).group(1))
    # the kerns of the lig/kern program: each label's entries up to its STOP
    kerns = {}
    table = re.search(r"\(LIGTABLE\n(.*?)\n   \)", pl, re.S)
    labels = []
    for row in (table.group(1).split("\n") if table else []):
        row = row.strip()
        m = re.match(r"\(LABEL ([CO]) (\S+)\)", row)
        if m:
            labels.append(ord(m.group(2)) if m.group(1) == "C" else int(m.group(2), 8))
            continue
        m = re.match(r"\(KRN ([CO]) (\S+) R (-?[0-9.]+)\)", row)
        if m:
            right = ord(m.group(2)) if m.group(1) == "C" else int(m.group(2), 8)
            for left in labels:
                kerns.setdefault((left, right), float(m.group(3)))
            continue
        if row.startswith("(STOP)"):
            labels = []
    return size, quad, space, script_dimens, chars, kerns


def main():
    out = ["// Written by src/draw/glyphs_table.py from the fonts' own files; do not edit.",
           "// Glyph sizes in ems: DejaVu Sans (SVG labels) and Computer Modern (TikZ labels).",
           '#include "glyphs.hpp"', "", "namespace kinergy::draw::detail {", "",
           "// DejaVu Sans: code point, advance, ink bottom, ink top (ems; y up from the baseline)",
           "const SvgGlyph kDejaVuSans[] = {"]
    rows = ttf_metrics(DEJAVU)
    for i in range(0, len(rows), 6):
        out.append("    " + " ".join("{0x%04X, %.4f, %.4f, %.4f}," % r for r in rows[i: i + 6]))
    out += ["};", "const std::size_t kDejaVuSansCount = %d;" % len(rows), ""]
    out.append("// Computer Modern, by font: each character (0..127) as width, height, depth, italic correction")
    out.append("const TexFont kTexFonts[] = {")
    all_kerns = []
    for index, name in enumerate(TEX_FONTS):
        size, quad, space, dimens, chars, kerns = tfm_metrics(name)
        all_kerns += [(index, l, r, k) for (l, r), k in sorted(kerns.items()) if l < 127 and r < 127]  # (127: the skew char, for accents)
        out.append('    {"%s", %.1f, %.6f, %.6f, %s, {' % (name, size, quad, space, ", ".join("%.6f" % d for d in dimens)))
        cells = ["{%.4f, %.4f, %.4f, %.4f}" % chars.get(c, (0, 0, 0, 0)) for c in range(128)]
        for i in range(0, 128, 8):
            out.append("        " + ", ".join(cells[i: i + 8]) + ",")
        out.append("    }},")
    out += ["};", "const std::size_t kTexFontCount = %d;" % len(TEX_FONTS), ""]
    out.append("// Their kerns: font (its index above), left character, right character, kern (ems)")
    out.append("const TexKern kTexKerns[] = {")
    for i in range(0, len(all_kerns), 8):
        out.append("    " + " ".join("{%d, %d, %d, %.6f}," % k for k in all_kerns[i: i + 8]))
    out += ["};", "const std::size_t kTexKernCount = %d;" % len(all_kerns), "", "}  // namespace kinergy::draw::detail", ""]
    target = sys.argv[1] if len(sys.argv) > 1 else "src/draw/glyphs_table.cpp"
    with open(target, "w") as f:
        f.write("\n".join(out))


if __name__ == "__main__":
    main()
