"""Shared fixtures: the relgeo tool of the same build (RELGEO_TOOL, set by
CTest) to compare the bindings with, and the tool's test data."""

import json
import os
import pathlib
import subprocess

import pytest

TESTDATA = pathlib.Path(__file__).resolve().parents[2] / "tools" / "relgeo" / "testdata"


class Tool:
    """Runs the relgeo tool and parses its JSON answers."""

    def __init__(self, path):
        self.path = path

    def run(self, *args, expect_codes=(0,)):
        done = subprocess.run([self.path, *map(str, args)], capture_output=True, text=True, timeout=120)
        assert done.returncode in expect_codes, done.stderr
        return done

    def json(self, *args, expect_codes=(0,)):
        """The JSON record, its infinite measures ("inf") as floats, as the bindings give them."""
        return measures(json.loads(self.run(*args, "--format", "json", expect_codes=expect_codes).stdout))

    def error(self, *args):
        """The one-line message of a usage error (exit 2), without 'relgeo: error: '."""
        done = self.run(*args, expect_codes=(2,))
        return done.stderr.strip().removeprefix("relgeo: error: ")


@pytest.fixture(scope="session")
def tool():
    path = os.environ.get("RELGEO_TOOL")
    if not path:
        pytest.skip("RELGEO_TOOL (the relgeo tool of this build) is not set")
    return Tool(path)


def measures(value):
    """A JSON value with the strings "inf" and "-inf" (io::json_measure's
    infinities) as floats, everywhere in it."""
    if isinstance(value, dict):
        return {k: measures(v) for k, v in value.items()}
    if isinstance(value, list):
        return [measures(v) for v in value]
    return float(value) if value in ("inf", "-inf") else value
