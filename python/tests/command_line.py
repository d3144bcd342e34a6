"""The tandem command line, which the Python tests compare the module against."""
import os
import subprocess

TANDEM_BIN = os.environ.get("TANDEM_BIN", "build/apps/tandem/tandem")


def run_cli(*args):
    """tandem with these arguments, its output captured, whatever its exit code."""
    return subprocess.run([TANDEM_BIN, *args], capture_output=True, text=True, check=False)
