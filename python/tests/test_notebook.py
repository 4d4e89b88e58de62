"""The example notebook (python/examples/kinergy.ipynb) executed as Jupyter would, by nbclient with a
kernel running this interpreter (the one kinergy is installed in): every cell runs without an error,
the scene shows as SVG, the solution as HTML with typeset mathematics (MathML, which a notebook
shows before text/latex) and as LaTeX; exported to HTML (nbconvert), the page carries that
mathematics."""
import json
import os
import re
import sys
import xml.etree.ElementTree as ET

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

HERE = os.path.dirname(os.path.abspath(__file__))
NOTEBOOK = os.path.join(HERE, "..", "examples", "kinergy.ipynb")
MATHML = "{http://www.w3.org/1998/Math/MathML}"


def executed(tmp_path, monkeypatch):
    # a kernel of this interpreter (the system's "python3" kernel may run another Python)
    spec = tmp_path / "kernels" / "kinergy-test"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "kinergy test", "language": "python"}))
    monkeypatch.setenv("JUPYTER_PATH", str(tmp_path))
    nb = nbformat.read(NOTEBOOK, as_version=4)
    client = nbclient.NotebookClient(nb, timeout=120, kernel_name="kinergy-test",
                                     resources={"metadata": {"path": str(tmp_path)}})
    client.execute()  # raises CellExecutionError at the first failing cell
    return nb


def test_the_example_notebook_runs_and_shows_mathematics(tmp_path, monkeypatch):
    nb = executed(tmp_path, monkeypatch)
    outputs = [o for cell in nb.cells if cell.cell_type == "code" for o in cell.get("outputs", [])]
    kinds = set()
    for o in outputs:
        kinds.update(o.get("data", {}).keys())
        assert o.get("output_type") != "error"
    assert "image/svg+xml" in kinds  # the scene drawn
    assert "<svg" in nb.cells[1].outputs[0]["data"]["text/html"]  # and inline in HTML
    assert "text/latex" in kinds     # the solution's results
    text = "".join(o.get("text", "") for o in outputs if o.get("output_type") == "stream")
    assert "l = 2.0 m: omega2 = 2.712471 rad/s" in text
    assert "301 regular rows and 21 impacts, the first at 0.494619 s" in text
    # the solution's HTML (what Jupyter shows): omega2 = sqrt(3 g sin(theta2) / l) = 3.50179 rad/s as MathML
    solution_html = nb.cells[2].outputs[0]["data"]["text/html"]
    math = ET.fromstring(re.search(r"<math.*</math>", solution_html, re.S).group(0))
    assert math.find(f".//{MATHML}msqrt/{MATHML}mrow/{MATHML}mfrac") is not None
    assert "3.50179" in "".join(math.itertext())
    # the results as a table (pandas' HTML)
    assert "<table" in nb.cells[7].outputs[0]["data"]["text/html"]


def test_the_notebook_exported_to_html_carries_the_mathematics(tmp_path, monkeypatch):
    nbconvert = pytest.importorskip("nbconvert")
    nb = executed(tmp_path, monkeypatch)
    page, _ = nbconvert.HTMLExporter().from_notebook_node(nb)
    # typeset by the browser itself: MathML elements in the page, no script needed for them
    assert "<math" in page and "<msqrt>" in page and "<mfrac>" in page
    # the scene's drawing with its elements (nbconvert empties an image/svg+xml output's <svg>)
    assert 'data-name="rod.G"' in page
    (tmp_path / "kinergy.html").write_text(page)
