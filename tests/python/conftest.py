"""Shared helpers of the Python module's tests: the softbody program beside the module, and running it.

ctest runs these tests from the source folder with PYTHONPATH pointing at build/python and SOFTBODY_PROGRAM at the
program built with it (tests/CMakeLists.txt); by hand:
    PYTHONPATH=build/python SOFTBODY_PROGRAM=build/softbody python3 -m pytest tests/python
"""
import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[2]


def set_arguments(overrides):
    """The program's --set arguments for the overrides load_scene(set=...) takes (str values as they are)."""
    arguments = []
    for key, value in overrides.items():
        text = value if isinstance(value, str) else json.dumps(value)
        arguments += ["--set", f"{key}={text}"]
    return arguments


class Program:
    def __init__(self, path):
        self.path = path

    def run(self, *arguments, check=True):
        """Runs the program from the source folder; returns the CompletedProcess (text)."""
        result = subprocess.run([self.path, *map(str, arguments)], cwd=SOURCE_DIR, capture_output=True, text=True,
                                timeout=120)
        if check and result.returncode != 0:
            raise AssertionError(f"softbody {' '.join(map(str, arguments))} exited {result.returncode}:\n"
                                 f"{result.stderr}")
        return result


@pytest.fixture(scope="session")
def program():
    path = os.environ.get("SOFTBODY_PROGRAM", str(SOURCE_DIR / "build" / "softbody"))
    if not os.access(path, os.X_OK):
        pytest.fail(f"{path}: no softbody program to compare with (build it, or set SOFTBODY_PROGRAM)")
    return Program(path)


@pytest.fixture(autouse=True)
def in_source_dir(monkeypatch):
    """Scene paths in the tests are relative to the source folder, as in the README."""
    monkeypatch.chdir(SOURCE_DIR)
