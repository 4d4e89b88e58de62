"""The example notebook (python/examples/kinergy.ipynb) executed as Jupyter would, by nbclient with
Debian's python3 kernel: every cell runs without an error, the scene shows as SVG and the solution
as LaTeX."""
import os

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

HERE = os.path.dirname(os.path.abspath(__file__))
NOTEBOOK = os.path.join(HERE, "..", "examples", "kinergy.ipynb")


def test_the_example_notebook_runs():
    nb = nbformat.read(NOTEBOOK, as_version=4)
    client = nbclient.NotebookClient(nb, timeout=120, kernel_name="python3",
                                     resources={"metadata": {"path": os.path.dirname(NOTEBOOK)}})
    client.execute()  # raises CellExecutionError at the first failing cell
    outputs = [o for cell in nb.cells if cell.cell_type == "code" for o in cell.get("outputs", [])]
    kinds = set()
    for o in outputs:
        kinds.update(o.get("data", {}).keys())
        assert o.get("output_type") != "error"
    assert "image/svg+xml" in kinds  # the scene drawn
    assert "text/latex" in kinds     # the solution's results
    text = "".join(o.get("text", "") for o in outputs if o.get("output_type") == "stream")
    assert "l = 2.0 m: omega2 = 2.712471 rad/s" in text
    assert "first at 0.494619 s" in text
