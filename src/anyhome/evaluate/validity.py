"""The validity rules of SCENE_FORMAT.md, run together, and the metrics they yield.

Rules 1-4 live in :mod:`anyhome.evaluate.objects`, rule 5 and the project rule
"windows" in :mod:`anyhome.evaluate.floorplan`, rule 6 in
:mod:`anyhome.evaluate.navigation`. The project rule "ids" flags duplicate ids (every
reference in house.json is by id).
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

from anyhome.evaluate import floorplan, navigation, objects
from anyhome.evaluate.report import Violation
from anyhome.house import House, is_habitable

RULES: tuple[int | str, ...] = (1, 2, 3, 4, 5, 6, "windows", "ids")
"""Every rule a violation can name, in report order."""


@dataclass(frozen=True)
class ValidityResult:
    violations: list[Violation]
    metrics: dict[str, float | int]


def check_validity(house: House) -> ValidityResult:
    """Run every validity rule on ``house``; violations sorted by rule, in house order."""
    index = objects.ObjectIndex.build(house)
    rule1 = objects.check_in_bounds(index)
    rule2 = objects.check_collisions(index)
    nav = navigation.run_navigability(house)
    violations = (
        _check_ids(house)
        + rule1
        + rule2
        + objects.check_grounded(index, house)
        + objects.check_doors_clear(index, house)
        + floorplan.check_floorplan(house)
        + floorplan.check_windows(house)
        + navigation.check_navigable(nav)
    )
    order = {rule: k for k, rule in enumerate(RULES)}
    violations.sort(key=lambda v: order.get(v.rule, len(order)))

    object_ids = set(index.by_id)
    oob = {v.ids[0] for v in rule1 if v.ids} | {i for v in rule2 for i in v.ids}
    oob &= object_ids
    per_rule = Counter(v.rule for v in violations)
    n_obj = len(house.objects)
    habitable = [r.id for r in house.rooms if is_habitable(r.type)]
    in_habitable = sum(o.room in set(habitable) for o in house.objects)
    metrics: dict[str, float | int] = {
        "n_rooms": len(house.rooms),
        "n_objects": n_obj,
        "n_doors": len(house.doors),
        "n_windows": len(house.windows),
        "n_violations": len(violations),
        **{f"violations_rule_{rule}": per_rule.get(rule, 0) for rule in RULES},
        "n_oob_objects": len(oob),
        "oob_rate": len(oob) / n_obj if n_obj else 0.0,
        "n_colliding_pairs": len(rule2),
        "connections_realized": floorplan.connections_realized(house),
        "nav_reachable_fraction": _fraction(nav.reachable_cells, nav.free_cells),
        "nav_rooms_reachable_fraction": _fraction(
            len(house.rooms) - len(nav.unreachable_rooms), len(house.rooms)),
        "objects_per_habitable_room": in_habitable / len(habitable) if habitable else 0.0,
    }
    return ValidityResult(violations, metrics)


def _fraction(part: int, whole: int) -> float:
    return part / whole if whole else 0.0


def _check_ids(house: House) -> list[Violation]:
    out = []
    for kind, items in (("room", house.rooms), ("door", house.doors),
                        ("window", house.windows), ("object", house.objects)):
        for ident, n in Counter(x.id for x in items).items():
            if n > 1:
                out.append(Violation("ids", "duplicate_id", f"{n} {kind}s share the id {ident}",
                                     (ident,)))
    return out
