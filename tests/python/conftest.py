"""Shared fixtures: the CLI binary (for messages and consistency checks)."""
import csv
import io
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli():
    """Runs the frictionref binary: cli(*args) -> (exit code, stdout, stderr)."""
    binary = os.environ.get("FRICTIONREF_BINARY")
    if not binary or not os.path.exists(binary):
        pytest.skip("no frictionref binary (FRICTIONREF_BINARY)")

    def run(*args, stdin=None):
        done = subprocess.run([binary, *map(str, args)], capture_output=True, text=True,
                              input=stdin, timeout=300)
        return done.returncode, done.stdout, done.stderr

    return run


@pytest.fixture(scope="session")
def cli_error(cli):
    """The one-line message of a refused command line (exit code 2)."""

    def error(*args):
        code, out, err = cli(*args)
        assert code == 2, (args, code, out, err)
        prefix = "frictionref: error: "
        assert err.startswith(prefix) and err.count("\n") == 1, err
        return err[len(prefix):].rstrip("\n")

    return error


def joined(parts):
    """Structured arrays one after the other, in their own dtype (numpy's
    concatenate would repack it)."""
    import numpy as np

    rows = np.empty(sum(len(p) for p in parts), dtype=parts[0].dtype)
    begin = 0
    for part in parts:
        rows[begin:begin + len(part)] = part
        begin += len(part)
    return rows


def read_csv(text):
    """The rows of a CSV the CLI wrote (# lines skipped) as dicts of strings."""
    lines = [line for line in text.splitlines() if not line.startswith("#")]
    return list(csv.DictReader(io.StringIO("\n".join(lines))))
