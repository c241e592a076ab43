# Shared by the tests: the gyrores CLI as the reference (GYRORES_CLI, set by ctest when the CLI is
# built; the tests that need it are skipped otherwise).
import json
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli_json():
    """cli_json("pair", "6", "5", "--digits", "30") -> the parsed JSON of `gyrores ... --json`."""
    cli = os.environ.get("GYRORES_CLI", "")
    if not cli or not os.access(cli, os.X_OK):
        pytest.skip("the gyrores CLI is not built (GYRORES_CLI unset)")

    def run(*args):
        out = subprocess.run([cli, *args, "--json"], check=True, capture_output=True, text=True).stdout
        return json.loads(out)

    return run
