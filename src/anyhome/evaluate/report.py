"""Result types of the evaluation: violations, coverage checks and the report.

Everything here is plain data: ``EvalReport.to_dict()`` is JSON-serialisable and
``EvalReport.summary_lines()`` gives the short human-readable lines the CLI prints.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from anyhome.evaluate.furnish_metrics import FurnishMetrics
    from anyhome.evaluate.plan_metrics import PlanMetrics

MAX_SUMMARY_VIOLATIONS = 12
"""How many violations ``summary_lines`` lists before it says "... and N more"."""
MAX_SUMMARY_CHECKS = 12
"""How many failed coverage checks ``summary_lines`` lists."""

Rule = int | str
"""A validity rule: 1-6 (SCENE_FORMAT.md) or a project rule name ("windows", "ids")."""


@dataclass(frozen=True)
class Violation:
    """One broken validity rule.

    Attributes
    ----------
    rule : 1-6 (SCENE_FORMAT.md) or a project rule name (``"windows"``, ``"ids"``)
    code : short machine-readable kind, e.g. ``"collision"``
    message : one line naming the ids involved
    ids : the ids of the rooms, doors, windows or objects involved
    """

    rule: Rule
    code: str
    message: str
    ids: tuple[str, ...] = ()

    def to_dict(self) -> dict[str, Any]:
        return {"rule": self.rule, "code": self.code, "message": self.message, "ids": list(self.ids)}

    def __str__(self) -> str:
        rule = f"rule {self.rule}" if isinstance(self.rule, int) else self.rule
        return f"[{rule}: {self.code}] {self.message}"


@dataclass(frozen=True)
class CheckResult:
    """One coverage check against a prompt's expectations.

    ``found`` is what was counted (matching rooms or objects, style terms found, rows);
    ``expected`` is the condition in words (``"== 1"``, ``">= 2"``).
    """

    kind: str
    text: str
    passed: bool
    found: int
    expected: str

    def to_dict(self) -> dict[str, Any]:
        return {
            "kind": self.kind,
            "text": self.text,
            "passed": self.passed,
            "found": self.found,
            "expected": self.expected,
        }

    def __str__(self) -> str:
        mark = "ok" if self.passed else "FAIL"
        return f"{mark:4} {self.text}: found {self.found}, expected {self.expected}"


@dataclass(frozen=True)
class Coverage:
    """Share of a prompt's expectations the house satisfies."""

    checks: tuple[CheckResult, ...] = ()

    @property
    def n_passed(self) -> int:
        return sum(c.passed for c in self.checks)

    @property
    def score(self) -> float:
        """Satisfied checks / total checks, in [0, 1]; 1.0 when nothing is expected."""
        return self.n_passed / len(self.checks) if self.checks else 1.0

    @property
    def failed(self) -> tuple[CheckResult, ...]:
        return tuple(c for c in self.checks if not c.passed)

    def to_dict(self) -> dict[str, Any]:
        return {
            "score": self.score,
            "passed": self.n_passed,
            "total": len(self.checks),
            "checks": [c.to_dict() for c in self.checks],
        }


@dataclass
class EvalReport:
    """Outcome of :func:`anyhome.evaluate.evaluate_house`."""

    violations: list[Violation] = field(default_factory=list)
    metrics: dict[str, float | int] = field(default_factory=dict)
    coverage: Coverage | None = None
    plan: PlanMetrics | None = None
    """Plan figures (circulation, proportions, size words, open air, levels): not violations."""
    furnish: FurnishMetrics | None = None
    """Furnishing figures (drops, rugs, TV stands, sets, floor coverage): not violations."""
    materials: dict[str, Any] | None = None
    """Material words the house's GLB shows (:mod:`anyhome.evaluate.material_words`), when
    the house folder has its house.glb; a figure, not a violation."""

    @property
    def ok(self) -> bool:
        """True when the house breaks no validity rule (coverage does not count)."""
        return not self.violations

    def violations_of(self, rule: Rule) -> list[Violation]:
        return [v for v in self.violations if v.rule == rule]

    def codes(self) -> set[str]:
        return {v.code for v in self.violations}

    def to_dict(self) -> dict[str, Any]:
        return {
            "ok": self.ok,
            "violations": [v.to_dict() for v in self.violations],
            "metrics": {k: _plain(v) for k, v in self.metrics.items()},
            "coverage": self.coverage.to_dict() if self.coverage is not None else None,
            "plan": self.plan.to_dict() if self.plan is not None else None,
            "furnish": self.furnish.to_dict() if self.furnish is not None else None,
            "materials": self.materials,
        }

    def summary_lines(self) -> list[str]:
        m = self.metrics
        lines = [
            f"{m.get('n_rooms', 0)} rooms, {m.get('n_objects', 0)} objects, "
            f"{m.get('n_doors', 0)} doors, {m.get('n_windows', 0)} windows",
        ]
        if self.ok:
            lines.append("valid: no rule violated")
        else:
            per_code = Counter(v.code for v in self.violations)
            kinds = ", ".join(f"{code} {n}" for code, n in sorted(per_code.items()))
            lines.append(f"INVALID: {len(self.violations)} violations ({kinds})")
        lines.append(
            f"OOB rate {100 * float(m.get('oob_rate', 0.0)):.1f}% "
            f"({m.get('n_oob_objects', 0)}/{m.get('n_objects', 0)} objects break rule 1 or 2)"
        )
        lines.append(
            f"connections realized {100 * float(m.get('connections_realized', 1.0)):.0f}%, "
            f"reachable floor {100 * float(m.get('nav_reachable_fraction', 1.0)):.0f}%, "
            f"{float(m.get('objects_per_habitable_room', 0.0)):.1f} objects per habitable room, "
            f"{m.get('n_stand_in_objects', 0)} shown with a stand-in mesh"
        )
        for v in self.violations[:MAX_SUMMARY_VIOLATIONS]:
            lines.append(f"  {v}")
        if len(self.violations) > MAX_SUMMARY_VIOLATIONS:
            lines.append(f"  ... and {len(self.violations) - MAX_SUMMARY_VIOLATIONS} more")
        if self.coverage is not None:
            cov = self.coverage
            lines.append(
                f"coverage {cov.score:.2f} ({cov.n_passed}/{len(cov.checks)} checks satisfied)"
            )
            for c in cov.failed[:MAX_SUMMARY_CHECKS]:
                lines.append(f"  {c}")
        if self.plan is not None:
            lines += self.plan.summary_lines()
        if self.furnish is not None:
            lines += self.furnish.summary_lines()
        if self.materials is not None and self.materials.get("n_material_words"):
            mw = self.materials
            lines.append(f"material words shown in the GLB: {mw['n_material_words_realised']}/{mw['n_material_words']} "
                         f"({100 * float(mw['material_words_realised']):.0f}%)")
            for miss in mw.get("material_word_misses", [])[:MAX_SUMMARY_CHECKS]:
                lines.append(f"  not shown: {miss}")
        return lines


def _plain(value: Any) -> Any:
    """Numpy scalars to Python numbers, so ``json.dumps`` accepts them."""
    if isinstance(value, bool):
        return value
    if isinstance(value, int):
        return int(value)
    if isinstance(value, float):
        return float(value)
    item = getattr(value, "item", None)
    return item() if callable(item) else value
