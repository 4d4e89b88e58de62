"""kinergy's PEP 517 build backend: the Python package kinergy as a wheel, its compiled core built
with CMake for the interpreter that runs the build. Standard library only, so that a build needs
no package index (Debian 12 packages no scikit-build-core; machines without the index build too).

The wheel holds python/kinergy/ (__init__.py, its stubs, py.typed), the compiled core
_kinergy<EXT_SUFFIX> and kinergy_arb.so beside it (the ball arithmetic, loaded from beside the core),
and the worked problems derivations/**.yaml as package data (kinergy.example("energy/sliding_rod")).

Where it builds: $KINERGY_BUILD_DIR, else config setting build-dir (pip install . -C build-dir=D,
pip >= 22.1), else build/python-wheel-<tag> under the source (one per interpreter: CMake's and
pybind11's cached findings are the interpreter's). A build directory that exists is used as it is
when it was configured for this interpreter (a developer's build/: nothing is compiled again, and the
suite's install test builds from it); one configured for another interpreter is refused, not
configured again under its owner.
"""
import base64
import hashlib
import io
import os
import re
import subprocess
import sys
import sysconfig
import tarfile
import zipfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
NAME = "kinergy"
SUMMARY = "Plane motion of rigid bodies by energy and momentum, in closed form (GiNaC), confirmed a second way"
REQUIRES_PYTHON = ">=3.9"
# what the optional parts of the API import (sympy(), simulate(), to_dataframe())
EXTRAS = {"sympy": ["sympy"], "numpy": ["numpy"], "pandas": ["pandas"]}


def _version():
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        m = re.search(r"project\(\s*kinergy\s+VERSION\s+([0-9.]+)", f.read())
    if not m:
        raise RuntimeError("CMakeLists.txt names no project(kinergy VERSION x.y.z)")
    return m.group(1)


def _tag():
    # cp311-cp311-linux_x86_64: this interpreter, its ABI, this platform (the core is built here,
    # against this machine's shared libraries: a local wheel, not a portable one)
    py = "cp%d%d" % sys.version_info[:2]
    abi = py + getattr(sys, "abiflags", "")
    plat = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return "%s-%s-%s" % (py, abi, plat)


def _metadata():
    lines = ["Metadata-Version: 2.1", "Name: " + NAME, "Version: " + _version(), "Summary: " + SUMMARY,
             "License-File: LICENSE" if os.path.exists(os.path.join(ROOT, "LICENSE")) else None,
             "Requires-Python: " + REQUIRES_PYTHON]
    for extra, reqs in EXTRAS.items():
        lines.append("Provides-Extra: " + extra)
        lines += ['Requires-Dist: %s; extra == "%s"' % (r, extra) for r in reqs]
    lines.append("Description-Content-Type: text/markdown")
    text = "\n".join(x for x in lines if x) + "\n\n"
    readme = os.path.join(ROOT, "README.md")
    if os.path.exists(readme):
        with open(readme, encoding="utf-8") as f:
            text += f.read()
    return text


def _cache(build):
    path = os.path.join(build, "CMakeCache.txt")
    out = {}
    if os.path.exists(path):
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                m = re.match(r"([A-Za-z_0-9]+):[A-Z]+=(.*)$", line.rstrip("\n"))
                if m:
                    out[m.group(1)] = m.group(2)
    return out


def _configure_command(build, cache, executable):
    """The CMake configuration the build directory needs for the interpreter `executable`, or None
    where it has it. A directory configured for another interpreter — another venv, one since
    deleted (recreating a venv is routine), or another Python — is configured again for this one:
    FindPython's cached choice dropped (-U), the interpreter given; CMake then rebuilds only what
    that changes (the module, where the headers differ)."""
    if not cache:
        return ["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_TESTING=OFF", "-DPython_EXECUTABLE=" + executable]
    # the interpreter FindPython took (CMakeLists.txt sets Python_EXECUTABLE without caching it)
    configured = cache.get("_Python_EXECUTABLE") or cache.get("Python_EXECUTABLE")
    # a venv's python is a link to its base interpreter: the same headers, the same module
    if configured and os.path.exists(configured) and os.path.realpath(configured) == os.path.realpath(executable):
        return None
    return ["cmake", "-S", ROOT, "-B", build, "-U_Python_*", "-DPython_EXECUTABLE=" + executable]


def _build_dir(config_settings):
    d = os.environ.get("KINERGY_BUILD_DIR") or (config_settings or {}).get("build-dir")
    if d:
        return os.path.abspath(d), True  # (given)
    return os.path.join(ROOT, "build", "python-wheel-" + _tag()), False


def _run(cmd):
    print("kinergy build:", " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True, stdout=sys.stderr)


def _compile(config_settings):
    """The package's files in the build directory, built for this interpreter: its path."""
    build = _build_dir(config_settings)[0]
    configure = _configure_command(build, _cache(build), sys.executable)
    if configure:
        _run(configure)
    jobs = str(os.cpu_count() or 1)
    _run(["cmake", "--build", build, "--target", "kinergy_python", "-j", jobs])
    package = os.path.join(build, "python", NAME)
    core = os.path.join(package, "_kinergy" + sysconfig.get_config_var("EXT_SUFFIX"))
    if not os.path.exists(core):
        raise RuntimeError("CMake built no %s (is pybind11-dev installed? Debian: bash .ci/setup --deps)" % core)
    return package, core


def _files(package, core):
    """(path in the wheel, file on disk): the package, its core and the worked problems."""
    src = os.path.join(ROOT, "python", NAME)
    out = [(NAME + "/" + f, os.path.join(src, f)) for f in ("__init__.py", "__init__.pyi", "py.typed")]
    out.append((NAME + "/" + os.path.basename(core), core))
    out.append((NAME + "/kinergy_arb.so", os.path.join(package, "kinergy_arb.so")))
    derivations = os.path.join(ROOT, "derivations")
    for d, dirs, fs in os.walk(derivations):
        dirs.sort()
        for f in sorted(fs):
            if f.endswith(".yaml"):
                rel = os.path.relpath(os.path.join(d, f), derivations).replace(os.sep, "/")
                out.append((NAME + "/derivations/" + rel, os.path.join(d, f)))
    return out


def _record_line(arcname, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return "%s,sha256=%s,%d" % (arcname, digest, len(data))


def _dist_info_files():
    info = "%s-%s.dist-info" % (NAME, _version())
    wheel = "Wheel-Version: 1.0\nGenerator: kinergy_build\nRoot-Is-Purelib: false\nTag: %s\n" % _tag()
    files = [(info + "/METADATA", _metadata().encode()), (info + "/WHEEL", wheel.encode()), (info + "/top_level.txt", (NAME + "\n").encode())]
    if os.path.exists(os.path.join(ROOT, "LICENSE")):
        with open(os.path.join(ROOT, "LICENSE"), "rb") as f:
            files.append((info + "/LICENSE", f.read()))
    return info, files


# ---------------------------------------------------------------- PEP 517 hooks

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    info, files = _dist_info_files()
    for arcname, data in files:
        path = os.path.join(metadata_directory, arcname)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(data)
    return info


def _write_wheel(wheel_directory, files):
    """A wheel of (path in the wheel, bytes), its dist-info and RECORD added: its file name."""
    info, meta = _dist_info_files()
    name = "%s-%s-%s.whl" % (NAME, _version(), _tag())
    record = []
    with zipfile.ZipFile(os.path.join(wheel_directory, name), "w", compression=zipfile.ZIP_DEFLATED) as z:
        for arcname, data in list(files) + meta:
            zi = zipfile.ZipInfo(arcname, date_time=(1980, 1, 1, 0, 0, 0))  # the same bytes every build
            zi.external_attr = (0o100000 | (0o755 if arcname.endswith(".so") else 0o644)) << 16
            zi.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(zi, data)
            record.append(_record_line(arcname, data))
        record.append(info + "/RECORD,,")
        z.writestr(zipfile.ZipInfo(info + "/RECORD", date_time=(1980, 1, 1, 0, 0, 0)), ("\n".join(record) + "\n").encode())
    return name


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    package, core = _compile(config_settings)

    def contents():
        for arcname, disk in _files(package, core):
            with open(disk, "rb") as f:
                yield arcname, f.read()
    return _write_wheel(wheel_directory, contents())


# PEP 660: `pip install -e .` puts the build directory's package on the path (a .pth file): its
# Python files are links to python/kinergy/ (an edit shows at once), its core is what CMake built
# last (after a C++ change: cmake --build on that directory, or pip install -e . again)
def get_requires_for_build_editable(config_settings=None):
    return []


def prepare_metadata_for_build_editable(metadata_directory, config_settings=None):
    return prepare_metadata_for_build_wheel(metadata_directory, config_settings)


def build_editable(wheel_directory, config_settings=None, metadata_directory=None):
    package, _ = _compile(config_settings)
    return _write_wheel(wheel_directory, [("kinergy_editable.pth", (os.path.dirname(package) + "\n").encode())])


def build_sdist(sdist_directory, config_settings=None):
    # the files git tracks (a checkout's sources, without build directories)
    try:
        listed = subprocess.run(["git", "-C", ROOT, "ls-files", "-z"], check=True, capture_output=True).stdout.decode().split("\0")
    except (OSError, subprocess.CalledProcessError) as e:
        raise RuntimeError("an sdist is made from a git checkout (git ls-files): %s" % e)
    base = "%s-%s" % (NAME, _version())
    name = base + ".tar.gz"
    with tarfile.open(os.path.join(sdist_directory, name), "w:gz", format=tarfile.PAX_FORMAT) as t:
        for rel in sorted(x for x in listed if x):
            path = os.path.join(ROOT, rel)
            if os.path.isfile(path):
                t.add(path, arcname=base + "/" + rel, recursive=False)
        pkg_info = _metadata().encode()
        ti = tarfile.TarInfo(base + "/PKG-INFO")
        ti.size = len(pkg_info)
        t.addfile(ti, io.BytesIO(pkg_info))
    return name
