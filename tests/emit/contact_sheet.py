#!/usr/bin/env python3
"""Contact sheets of the worked solutions' figures: for each folder of derivations/, every figure
of every derivation (kinergy draw --figure N, as the LaTeX numbers them) side by side, three to a
row, each captioned with its derivation and number, written as one PNG (rsvg-convert) to
docs/gallery/contact_FOLDER.png. Run by tests/emit/make_gallery.sh; look at the PNGs before
committing them.

    python3 tests/emit/contact_sheet.py BUILD_DIR/kinergy
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

COLUMNS, CELL, GAP, CAPTION = 3, 420, 16, 22


def figures(kinergy, scene, tmp):
    """The SVG text of each figure of the scene's worked solution, in order."""
    out = []
    n = 1
    while True:
        path = os.path.join(tmp, "figure.svg")
        run = subprocess.run([kinergy, "draw", scene, "--figure", str(n), "-o", path], capture_output=True, text=True)
        if run.returncode != 0:
            return out
        out.append(open(path, encoding="utf-8").read())
        n += 1


def size_of(svg):
    m = re.search(r'<svg [^>]*width="([0-9.]+)" height="([0-9.]+)"', svg)
    return float(m.group(1)), float(m.group(2))


def sheet(kinergy, folder, target):
    cells = []
    with tempfile.TemporaryDirectory() as tmp:
        for scene in sorted(glob.glob(os.path.join("derivations", folder, "*.yaml"))):
            name = os.path.splitext(os.path.basename(scene))[0]
            for k, svg in enumerate(figures(kinergy, scene, tmp), 1):
                cells.append((f"{name}, figure {k}", svg))
        if not cells:
            return 0
        # rows of three, each as tall as its tallest figure at the cell's width
        parts, y = [], GAP
        for r in range(0, len(cells), COLUMNS):
            row = cells[r: r + COLUMNS]
            heights = []
            for _, svg in row:
                w, h = size_of(svg)
                heights.append(CELL * h / w)
            tall = max(heights)
            for c, ((title, svg), h) in enumerate(zip(row, heights)):
                x = GAP + c * (CELL + GAP)
                w0, h0 = size_of(svg)
                inner = re.sub(r"^<svg [^>]*>", "", svg.strip()).rsplit("</svg>", 1)[0]
                parts.append(f'<svg x="{x}" y="{y}" width="{CELL}" height="{h:.1f}" viewBox="0 0 {w0} {h0}">{inner}</svg>')
                parts.append(f'<rect x="{x}" y="{y}" width="{CELL}" height="{tall:.1f}" fill="none" stroke="#cccccc"/>')
                parts.append(f'<text x="{x + 4}" y="{y + tall + 15:.1f}" font-family="DejaVu Sans, sans-serif" font-size="12" '
                             f'fill="#444444">{title}</text>')
            y += tall + CAPTION + GAP
        width = GAP + COLUMNS * (CELL + GAP)
        doc = (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{y:.0f}" viewBox="0 0 {width} {y:.0f}">'
               f'<rect width="{width}" height="{y:.0f}" fill="white"/>' + "\n".join(parts) + "</svg>\n")
        path = os.path.join(tmp, "sheet.svg")
        open(path, "w", encoding="utf-8").write(doc)
        subprocess.run(["rsvg-convert", "--format", "png", "--output", target, path], check=True)
    return len(cells)


def main():
    kinergy = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build/kinergy")
    os.makedirs("docs/gallery", exist_ok=True)
    for folder in ("energy", "momentum", "impact", "kinetics"):
        n = sheet(kinergy, folder, f"docs/gallery/contact_{folder}.png")
        print(f"contact_sheet: docs/gallery/contact_{folder}.png ({n} figures)")


if __name__ == "__main__":
    main()
