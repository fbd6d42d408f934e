"""Evaluation: the validity rules of SCENE_FORMAT.md, metrics and prompt coverage.

>>> report = evaluate_house(house, expect)          # doctest: +SKIP
>>> report.ok, report.metrics["oob_rate"], report.coverage.score   # doctest: +SKIP
"""

from __future__ import annotations

from anyhome.evaluate.coverage import count_rows, evaluate_coverage
from anyhome.evaluate.evaluator import evaluate_house
from anyhome.evaluate.expectations import (
    expectation_for_prompt,
    load_expectations,
    load_prompt_records,
    validate_expect,
)
from anyhome.evaluate.report import CheckResult, Coverage, EvalReport, Violation
from anyhome.evaluate.validity import RULES, check_validity

__all__ = [
    "RULES",
    "CheckResult",
    "Coverage",
    "EvalReport",
    "Violation",
    "check_validity",
    "count_rows",
    "evaluate_coverage",
    "evaluate_house",
    "expectation_for_prompt",
    "load_expectations",
    "load_prompt_records",
    "validate_expect",
]
