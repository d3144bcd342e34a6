"""The fixtures the Python tests share."""
import pytest

import tandem


@pytest.fixture(scope="module")
def cluttered():
    """The problem most of the tests plan on."""
    return tandem.Problem("cluttered-1")
