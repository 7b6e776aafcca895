"""Shared fixtures of the Python package's tests: the repository root, the fixture parameter
file and the `carvallo` command-line binary the results are compared with."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def root() -> pathlib.Path:
    return ROOT


@pytest.fixture(scope="session")
def fixture_file() -> pathlib.Path:
    return ROOT / "data" / "benchmark-1pct.txt"


@pytest.fixture(scope="session")
def cli():
    """Runs the `carvallo` binary (CARVALLO_BIN, or target/release/carvallo) and parses its
    JSON output. A missing binary is an error, not a skip: the comparison is the point."""
    exe = pathlib.Path(os.environ.get("CARVALLO_BIN", ROOT / "target" / "release" / "carvallo"))
    if not exe.is_file():
        pytest.fail(f"the carvallo binary {exe} is missing: run `cargo build --release -p carvallo-cli` or set CARVALLO_BIN")

    def run(*args: str):
        out = subprocess.run([str(exe), *args], check=True, capture_output=True, text=True)
        return json.loads(out.stdout)

    return run
