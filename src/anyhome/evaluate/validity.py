"""The validity rules of SCENE_FORMAT.md, run together, and the metrics they yield.

Rules 1-4 live in :mod:`anyhome.evaluate.objects`, rule 5 and the project rule
"windows" in :mod:`anyhome.evaluate.floorplan`, rule 6 in
:mod:`anyhome.evaluate.navigation`. The project rule "ids" flags duplicate ids (every
reference in house.json is by id) and, with "values" and "heights", the checks of
:mod:`anyhome.evaluate.values`, which also screens out the elements with non-finite or
non-positive numbers before the geometric rules run. The project rule "limits" says
where a check stopped at its bound (``objects.MAX_COLLISIONS``,
``objects.MAX_CANDIDATE_PAIRS``) or where more than ``MAX_PER_CODE`` violations of one
kind were found (the first ``MAX_PER_CODE`` are listed, the metrics count them all).
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

from anyhome.evaluate import floorplan, navigation, objects, values
from anyhome.evaluate.report import Violation
from anyhome.house import House, is_habitable, stand_ins

RULES: tuple[int | str, ...] = (1, 2, 3, 4, 5, 6, "windows", "ids", "values", "heights",
                                "limits")
"""Every rule a violation can name, in report order."""
MAX_PER_CODE = 1000
"""Violations of one code listed in the report; the rest are counted in one line."""


@dataclass(frozen=True)
class ValidityResult:
    violations: list[Violation]
    metrics: dict[str, float | int]


ENTRANCE_CODES = frozenset({"no_entrance", "disconnected_room", "unreachable_room", "unreachable_door"})
"""Codes about reaching rooms from the entrance: on a storey other than the ground floor
they are replaced by reachability through doors and stairs over the whole house."""


def check_validity(house: House) -> ValidityResult:
    """Run every validity rule on ``house``; violations sorted by rule, in house order.
    A house of several storeys is checked storey by storey (rooms overlap only on the
    same storey), plus every room reachable from the entrance through doors and stairs."""
    numbers = house.level_numbers()
    if len(numbers) <= 1:
        return _check_one(house)
    from anyhome.floorplan.levels import level_view, reachable_rooms

    results = {k: _check_one(level_view(house, k)) for k in numbers}
    violations = [v for k in numbers for v in results[k].violations
                  if not (k != 0 and v.code in ENTRANCE_CODES) and v.code != "taller_than_room"
                  or (v.code == "taller_than_room" and not any(i.endswith("-stairs") for i in v.ids))]
    reached = reachable_rooms(house)
    violations += [Violation(5, "disconnected_room",
                             f"room {r.id} cannot be reached from the entrance through doors and stairs", (r.id,))
                   for r in house.rooms if r.id not in reached and r.level != 0]
    order = {rule: k for k, rule in enumerate(RULES)}
    violations.sort(key=lambda v: order.get(v.rule, len(order)))
    metrics = dict(results[0].metrics)  # objects reached: on the ground floor (entered from outside)
    for key in ("n_rooms", "n_objects", "n_doors", "n_windows", "n_oob_objects", "n_colliding_pairs"):
        metrics[key] = sum(int(results[k].metrics[key]) for k in numbers)
    metrics["n_violations"] = len(violations)
    per_rule = Counter(v.rule for v in violations)
    metrics.update({f"violations_rule_{rule}": per_rule.get(rule, 0) for rule in RULES})
    planned = list(house.connections)
    realised = {frozenset(d.rooms) for d in house.doors}
    metrics["connections_realized"] = sum(frozenset(c) in realised for c in planned) / len(planned) if planned else 1.0
    metrics["nav_rooms_reachable_fraction"] = len(reached) / len(house.rooms)
    metrics["n_levels"] = len(numbers)
    metrics["stairs_reachable"] = len(reached) == len(house.rooms)
    return ValidityResult(violations, metrics)


def _check_one(house: House) -> ValidityResult:
    screened = values.screen(house)
    full, house = house, screened.house
    index = objects.ObjectIndex.build(house)
    rule1 = objects.check_in_bounds(index)
    rule2 = objects.check_collisions(index)
    nav = navigation.run_navigability(house, index.footprints)
    violations = (
        _check_ids(full)
        + screened.violations
        + rule1
        + rule2
        + objects.check_grounded(index, house)
        + objects.check_doors_clear(index, house)
        + floorplan.check_floorplan(house)
        + floorplan.check_windows(house)
        + navigation.check_navigable(nav)
        + index.notes
    )
    order = {rule: k for k, rule in enumerate(RULES)}
    violations.sort(key=lambda v: order.get(v.rule, len(order)))
    n_violations = len(violations)
    per_rule = Counter(v.rule for v in violations)
    violations = _cap_per_code(violations)

    object_ids = set(index.by_id)
    oob = {v.ids[0] for v in rule1 if v.ids} | {i for v in rule2 for i in v.ids}
    oob &= object_ids
    n_obj = len(full.objects)
    habitable = [r.id for r in full.rooms if is_habitable(r.type)]
    habitable_ids = set(habitable)
    in_habitable = sum(o.room in habitable_ids for o in full.objects)
    metrics: dict[str, float | int] = {
        "n_rooms": len(full.rooms),
        "n_objects": n_obj,
        "n_doors": len(full.doors),
        "n_windows": len(full.windows),
        "n_violations": n_violations,
        **{f"violations_rule_{rule}": per_rule.get(rule, 0) for rule in RULES},
        "n_oob_objects": len(oob),
        "oob_rate": len(oob) / n_obj if n_obj else 0.0,
        "n_colliding_pairs": len(rule2),
        "connections_realized": floorplan.connections_realized(house),
        "nav_reachable_fraction": _fraction(nav.reachable_cells, nav.free_cells),
        "nav_rooms_reachable_fraction": _fraction(
            len(house.rooms) - len(nav.unreachable_rooms), len(house.rooms)),
        "nav_cell_m": nav.cell_m,
        "complete": not index.notes and nav.checked,
        "objects_per_habitable_room": in_habitable / len(habitable) if habitable else 0.0,
        "n_stand_in_objects": len(stand_ins(full.objects)),
        "n_floor_objects": len(nav.targets_reached),
        "n_floor_objects_reached": sum(nav.targets_reached),
    }
    return ValidityResult(violations, metrics)


def _cap_per_code(violations: list[Violation]) -> list[Violation]:
    """The first ``MAX_PER_CODE`` violations of each code, and a ``limits`` line per code
    saying how many more there are."""
    seen: Counter[str] = Counter(v.code for v in violations)
    if max(seen.values(), default=0) <= MAX_PER_CODE:
        return violations
    kept: Counter[str] = Counter()
    out = []
    for v in violations:
        kept[v.code] += 1
        if kept[v.code] <= MAX_PER_CODE:
            out.append(v)
    for code, n in sorted(seen.items()):
        if n > MAX_PER_CODE:
            out.append(Violation("limits", "more_violations",
                                 f"{n - MAX_PER_CODE} more {code} violations not listed "
                                 f"({n} in all)", ()))
    return out


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
