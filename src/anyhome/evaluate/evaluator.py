"""``evaluate_house``: validity rules, metrics and (optionally) prompt coverage in one report."""

from __future__ import annotations

import logging
import time
from typing import Any

from anyhome.evaluate.coverage import evaluate_coverage
from anyhome.evaluate.furnish_metrics import furnish_metrics
from anyhome.evaluate.plan_metrics import plan_metrics
from anyhome.evaluate.report import EvalReport
from anyhome.evaluate.validity import check_validity
from anyhome.house import House
from anyhome.plan.kb import KnowledgeBase

log = logging.getLogger(__name__)


def evaluate_house(house: House, expect: dict[str, Any] | None = None,
                   kb: KnowledgeBase | None = None) -> EvalReport:
    """Check ``house`` against SCENE_FORMAT.md's rules and, given one, an ``expect`` entry.

    Parameters
    ----------
    house : the house to check
    expect : an expectations entry as in ``prompts.jsonl`` (see
        :mod:`anyhome.evaluate.coverage`) or a whole record of such a file (its
        ``expect`` is used); ``None`` leaves ``coverage`` unset
    kb : the knowledge base whose room norms the plan figures use; None: the one in force

    Returns
    -------
    EvalReport
        ``violations`` (empty for a valid house), ``metrics`` (counts, ``oob_rate``,
        violations per rule, ``connections_realized``, ``nav_reachable_fraction``,
        ``objects_per_habitable_room``, ``eval_s``...), ``coverage`` and ``plan`` (the
        figures of :mod:`anyhome.evaluate.plan_metrics`) and ``furnish`` (those of
        :mod:`anyhome.evaluate.furnish_metrics`): figures, not violations.

    Raises
    ------
    EvalError
        if ``expect`` is malformed.
    """
    t0 = time.perf_counter()
    coverage = evaluate_coverage(house, expect) if expect is not None else None
    validity = check_validity(house)
    if kb is None:
        from anyhome.plan.knowledge import knowledge_base

        kb = knowledge_base()
    plan = plan_metrics(house, kb)
    furnish = furnish_metrics(house)
    metrics = dict(validity.metrics)
    if coverage is not None:
        metrics["coverage"] = coverage.score
    metrics["eval_s"] = time.perf_counter() - t0
    log.debug("evaluated house in %.3f s: %d violations", metrics["eval_s"],
              len(validity.violations))
    return EvalReport(violations=validity.violations, metrics=metrics, coverage=coverage, plan=plan,
                      furnish=furnish)
