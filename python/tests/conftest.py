"""The module under test is the one CMake built: PYTHONPATH names <build>/python (ctest sets it)."""

import os
import pathlib

import pytest


@pytest.fixture
def source_dir():
    return pathlib.Path(os.environ.get("IMASIM_SOURCE_DIR",
                                       pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture
def imasim_binary():
    path = os.environ.get("IMASIM_BINARY")
    if not path:
        pytest.skip("IMASIM_BINARY names the imasim program (ctest sets it)")
    return path
