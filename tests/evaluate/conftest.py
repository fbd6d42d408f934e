"""Fixtures of the evaluation tests (the houses themselves are built in eval_houses.py)."""

from __future__ import annotations

import pytest
from eval_houses import make_valid_house

from anyhome.house import House


@pytest.fixture
def house() -> House:
    return make_valid_house()
