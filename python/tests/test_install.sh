#!/usr/bin/env bash
# The Python package as a user installs it (issue 29): into a fresh virtual environment with
# `pip install --no-build-isolation --no-index .` (offline: kinergy's build backend needs nothing
# from a package index), then the whole pytest suite against that install; and plain `pip install .`
# (pip's build isolation, offline) into a bare venv, which imports it and solves a bundled scene;
# and pip install -e . (PEP 660), which imports it from the build directory.
#   bash python/tests/test_install.sh PYTHON BUILD_DIR
# The wheel is built from BUILD_DIR (configured for PYTHON: nothing is compiled again).
set -euo pipefail
py="$1"
build="$(cd "$2" && pwd)"
src="$(cd "$(dirname "$0")/../.." && pwd)"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
export KINERGY_BUILD_DIR="$build" PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_CACHE_DIR=1 PYTHONDONTWRITEBYTECODE=1
unset PYTHONPATH

# 1. the suite's venv: Debian's numpy, sympy, pytest, pandas seen through --system-site-packages
"$py" -m venv --system-site-packages "$t/venv"
"$t/venv/bin/python" -m pip install --quiet --no-build-isolation --no-index "$src"
# it is the installed package that is imported, not a source or build tree
where=$(cd "$t" && "$t/venv/bin/python" -c "import kinergy; print(kinergy.__file__)")
case "$where" in
  "$t/venv/"*) echo "installed: $where" ;;
  *) echo "FAIL: kinergy was imported from $where, not from the venv" >&2; exit 1 ;;
esac
(cd "$t" && "$t/venv/bin/python" -m pip show --files kinergy | grep -E "^(Name|Version|Location):|py.typed|__init__.pyi|kinergy_arb.so|sliding_rod.yaml")
(cd "$t" && KINERGY_SOURCE_DIR="$src" KINERGY_CLI="$build/kinergy" "$t/venv/bin/python" -m pytest -q -p no:cacheprovider -rs "$src/python/tests")

# 2. a bare venv (nothing but pip) and pip's build isolation, offline
"$py" -m venv "$t/bare"
"$t/bare/bin/python" -m pip install --quiet --no-index "$src"
(cd "$t" && "$t/bare/bin/python" -c "
import kinergy
r = kinergy.example('energy/sliding_rod').solve()['omega2']
assert r.closed_form == 'sqrt(3*g*sin(theta2)/l)', r.closed_form
# by hand: sqrt(3 * 9.81 * sin(30 deg) / 1.2)
assert abs(float(r) - (3 * 9.81 * 0.5 / 1.2) ** 0.5) < 1e-12
print('a bare venv, pip install . offline:', r)
")

# 3. an editable install (PEP 660): the build directory's package on the path
"$py" -m venv "$t/edit"
"$t/edit/bin/python" -m pip install --quiet --no-index -e "$src"
where=$(cd "$t" && "$t/edit/bin/python" -c "import kinergy; print(kinergy.__file__); kinergy.example('energy/sliding_rod').solve()")
case "$where" in
  "$build/python/kinergy/"*) echo "editable: $where" ;;
  *) echo "FAIL: the editable install imported kinergy from $where, not from $build/python" >&2; exit 1 ;;
esac
