"""Shared fixtures: the CLI binary built from the same tree, for bit-for-bit comparisons."""

import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def cli() -> str:
    """The `tidepath` binary: $TIDEPATH_CLI, else target/debug/tidepath (scripts/test_python.sh
    builds it); a test that needs it fails, naming the fix, when it is missing."""
    path = os.environ.get("TIDEPATH_CLI") or str(REPO / "target" / "debug" / "tidepath")
    if not os.path.exists(path):
        pytest.fail(f"no CLI binary at {path}: run `cargo build -p tidepath-cli` or set TIDEPATH_CLI")
    return path


def run_cli(cli: str, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([cli, *args], capture_output=True, text=True, timeout=600)
