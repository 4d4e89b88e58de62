#!/usr/bin/env bash
# The README's picture of the example notebook (docs/notebook.png): python/examples/kinergy.ipynb
# executed (nbclient, a kernel of the Python kinergy is importable in), exported to HTML (nbconvert)
# and rendered by headless Chromium. The mathematics is MathML, typeset by the browser itself.
#   bash python/examples/make_notebook_png.sh [PYTHON]   (PYTHON defaults to /usr/bin/python3 with
#                                                         build/python on its path)
set -euo pipefail
cd "$(dirname "$0")/../.."
py="${1:-/usr/bin/python3}"
[ -n "${1:-}" ] || export PYTHONPATH="$PWD/build/python"
command -v chromium >/dev/null || { echo "make_notebook_png: chromium is not installed (bash .ci/setup --deps)" >&2; exit 1; }
t=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] && cp "$t/kinergy.html" "$KEEP"; rm -rf "$t"' EXIT
mkdir -p "$t/kernels/kinergy"
printf '{"argv": ["%s", "-m", "ipykernel_launcher", "-f", "{connection_file}"], "display_name": "Python 3", "language": "python"}' "$py" >"$t/kernels/kinergy/kernel.json"
JUPYTER_PATH="$t" "$py" - "$t" <<'PY'
import sys, nbformat, nbclient, nbconvert
t = sys.argv[1]
nb = nbformat.read("python/examples/kinergy.ipynb", as_version=4)
nbclient.NotebookClient(nb, timeout=120, kernel_name="kinergy", resources={"metadata": {"path": t}}).execute()
page, _ = nbconvert.HTMLExporter().from_notebook_node(nb)
open(t + "/kinergy.html", "w").write(page)
PY
chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1000,1450 --virtual-time-budget=3000 \
  --screenshot="$PWD/docs/notebook.png" "file://$t/kinergy.html" 2>/dev/null
echo "docs/notebook.png"
