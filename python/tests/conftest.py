"""Shared fixtures: the real maps of ``../shared/data`` (beside the
checkout, not part of the repository; see README, "Tests"), skipped with
a visible reason when that folder is absent."""

import pathlib

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
DATA = REPO.parent / "shared" / "data"


@pytest.fixture
def shared():
    """The path of a file of ../shared/data, or a skip naming it."""

    def path(rel):
        p = DATA / rel
        if not p.is_file():
            pytest.skip(f"{p} is absent (../shared/data beside the checkout; see README, Tests)")
        return p

    return path
