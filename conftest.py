"""Tests and doctests name the samples as the README does (samples/press.toml): they run
from the repository's root, whatever folder pytest was started in."""

import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent


@pytest.fixture(scope="session", autouse=True)
def _from_the_repository_root():
    before = os.getcwd()
    os.chdir(ROOT)
    yield
    os.chdir(before)
