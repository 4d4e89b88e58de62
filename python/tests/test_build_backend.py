"""The build backend follows the interpreter that runs pip (issue 44, item 9): a build directory
configured for a venv since deleted, or for another interpreter, is configured again for this one
instead of refusing; one configured for this interpreter (or a venv of it) is used as it is."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "build_backend"))
import kinergy_build  # noqa: E402


def test_a_fresh_directory_is_configured_for_this_interpreter():
    cmd = kinergy_build._configure_command("/b", {}, sys.executable)
    assert cmd[:4] == ["cmake", "-S", kinergy_build.ROOT, "-B"] and "-DPython_EXECUTABLE=" + sys.executable in cmd


def test_the_same_interpreter_or_a_venv_of_it_is_used_as_it_is():
    assert kinergy_build._configure_command("/b", {"_Python_EXECUTABLE": sys.executable}, sys.executable) is None
    with tempfile.TemporaryDirectory() as d:
        link = os.path.join(d, "python3")
        os.symlink(os.path.realpath(sys.executable), link)  # as a venv's bin/python3 is
        assert kinergy_build._configure_command("/b", {"_Python_EXECUTABLE": link}, sys.executable) is None


def test_a_deleted_venv_or_another_interpreter_is_configured_again():
    with tempfile.TemporaryDirectory() as d:
        gone = os.path.join(d, "venv1", "bin", "python3")  # the first venv, since deleted
        cmd = kinergy_build._configure_command("/b", {"_Python_EXECUTABLE": gone}, sys.executable)
        assert cmd == ["cmake", "-S", kinergy_build.ROOT, "-B", "/b", "-U_Python_*", "-DPython_EXECUTABLE=" + sys.executable]
        other = os.path.join(d, "python9")
        with open(other, "w") as f:
            f.write("#!/bin/sh\n")
        cmd = kinergy_build._configure_command("/b", {"Python_EXECUTABLE": other}, sys.executable)
        assert "-DPython_EXECUTABLE=" + sys.executable in cmd
