"""FloorplanOptions: the floorplan search's tunables as named options passed in.

Shown here: the defaults give the solver's own floorplans; a changed option changes
the floorplan the way its name says (window, opening and spine-grid options, the
slicing scores); a bad value is refused with one AnyHomeError line; and the source
keeps no tunable number behind the options' back (every field is read, documented,
and no module constant other than the listed physical standards is left).
"""

from __future__ import annotations

import ast
import math
from collections import Counter
from dataclasses import fields
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import anyhome.floorplan
from anyhome.errors import AnyHomeError
from anyhome.floorplan import FloorplanOptions, solve_floorplan
from anyhome.floorplan.options import FloorplanOptionsError
from anyhome.house import Floorplan
from anyhome.plan import get_planner
from tests.floorplan.programs import family_home

FLOORPLAN_SRC = Path(anyhome.floorplan.__file__).parent
FIELDS = {f.name: f for f in fields(FloorplanOptions)}

# Module constants that are physical standards or the format's own values, not options.
KEPT_CONSTANTS = {
    "SNAP_M", "OUTSIDE", "FREE",  # the format's 5 cm grid; owner-array labels
    "DOOR_WIDTH_M", "ENTRANCE_WIDTH_M", "DOOR_HEIGHT_M", "OPENING_HEADROOM_M",
    "WINDOW_SILL_M", "WINDOW_HEIGHT_M", "BATH_WINDOW_WIDTH_M", "BATH_WINDOW_SILL_M", "BATH_WINDOW_HEIGHT_M",
    "RISER_MAX_M", "GOING_M", "FLIGHT_WIDTH_M", "WELL_GAP_M", "STRIP_M", "DOOR_CORNER_M", "STAIR_CLEAR_M", "HEADROOM_MIN_M", "STAIR_DEPTH_M",
    "SLAB_M",  # stairs (Approved Document K)
    "PASSAGE_M", "HALL_DOORS", "HALL_DOOR_M", "DOOR_SLIDE_M",  # a stair hall: the landing beside the stair, its doors; how far a door slides clear of the stair
    "STAIR_HALL_MIN_DOORS", "LADDER_HALL_MIN_DOORS",  # doors from which a stairwell is a stair hall (those below open onto the strip at its foot)
    "L_CORNERS", "INSCRIBED_TOL_M",  # merge.py: an L's corner count; the widest-disc search's precision
    "THROUGH_FACTOR", "THROUGH_OVERLAP_OK_M2",  # levels.py: what is a double-height room; a snapping sliver
    "SPIRAL_RISER_MAX_M",  # a spiral stair's riser (BS 5395-2)
    "SPIRAL_MAX_FLOOR_M2",  # which houses get a spiral stair: read by the planner too, which has no FloorplanOptions
    "LADDER_MAX_FLOOR_M2",  # which houses get a ship's ladder: read by the planner too
    "LADDER_WIDTH_M",  # a ship's ladder's width (IBC 2018 1011.15)
    "LADDER_RISER_MAX_M",  # a ship's ladder's riser (IBC 2018 1011.14-15)
    "LADDER_GOING_M",  # a ship's ladder's projected tread (IBC 2018 1011.14-15)
    "LADDER_TOP_M",  # the floor at a ladder's top inside its box: the asset draws it too
    "LADDER_WELL_WIDTH_M",  # a ladder's stairwell: the ladder and a passage beside it
}


def _spec(text: str = "a two-bedroom apartment"):
    return get_planner("offline").plan(text, np.random.default_rng(0))


def _length(segment) -> float:
    (x0, y0), (x1, y1) = segment
    return abs(x1 - x0) + abs(y1 - y0)


def _windows_per_room(fp: Floorplan) -> int:
    return max(Counter(w.room for w in fp.windows).values())


def test_default_options_are_the_solver_default():
    spec = _spec()
    a = solve_floorplan(spec, np.random.default_rng(1))
    b = solve_floorplan(spec, np.random.default_rng(1), options=FloorplanOptions())
    assert a.model_dump() == b.model_dump()


def test_options_change_the_search():
    spec = _spec()
    one = solve_floorplan(spec, np.random.default_rng(1), options=FloorplanOptions(slicing_attempts=0, wanted_candidates=1))
    assert one.rooms  # the spine alone, first valid layout kept


def test_window_options_shape_the_windows():
    spec = _spec()
    default = solve_floorplan(spec, np.random.default_rng(0))
    assert _windows_per_room(default) > 1 and max(_length(w.segment) for w in default.windows) > 1.3
    opts = FloorplanOptions(max_windows_per_room=1, window_max_width_m=1.3, window_min_width_m=0.8)
    fp = solve_floorplan(spec, np.random.default_rng(0), options=opts)
    assert _windows_per_room(fp) == 1
    assert max(_length(w.segment) for w in fp.windows) <= 1.3 + 1e-6


def test_open_max_width_bounds_wall_openings():
    spec = _spec()
    default = [_length(d.segment) for d in solve_floorplan(spec, np.random.default_rng(0)).doors if d.kind == "open"]
    assert default and max(default) > 1.4
    fp = solve_floorplan(spec, np.random.default_rng(0), options=FloorplanOptions(open_max_width_m=1.4))
    opened = [_length(d.segment) for d in fp.doors if d.kind == "open"]
    assert opened and max(opened) <= 1.4 + 1e-6


def _on_grid(fp: Floorplan, step: float) -> bool:
    return all(abs(c / step - round(c / step)) < 1e-6 for r in fp.rooms for p in r.polygon for c in p)


def test_spine_cell_sets_the_spine_grid():
    spec = _spec()
    spine_only = {"slicing_attempts": 0}
    default = solve_floorplan(spec, np.random.default_rng(0), options=FloorplanOptions(**spine_only))
    assert not _on_grid(default, 0.25)
    fp = solve_floorplan(spec, np.random.default_rng(0), options=FloorplanOptions(spine_cell_m=0.25, **spine_only))
    assert _on_grid(fp, 0.25)


def test_slicing_scores_change_small_floorplans():
    spec = family_home()
    assert len(spec.rooms) <= FloorplanOptions().slicing_max_rooms  # the slicing search runs
    changed = FloorplanOptions(slice_noise=0.0, slice_cut_edge_cost=0.0, slice_room_aspect_soft=2.4)
    differs = [
        solve_floorplan(spec, np.random.default_rng(s)).model_dump()
        != solve_floorplan(spec, np.random.default_rng(s), options=changed).model_dump()
        for s in range(3)
    ]
    assert any(differs)


@pytest.mark.parametrize(
    "bad",
    [
        {"max_attempts": 0},
        {"max_attempts": 2.5},
        {"max_attempts": True},
        {"tune_rounds": "30"},
        {"area_tolerance_frac": -0.1},
        {"area_tolerance_frac": math.nan},
        {"window_wall_share_frac": 1.5},
        {"seed_repel_gain": math.inf},
        {"spine_cell_m": 0.0},
    ],
)
def test_bad_option_is_refused_in_one_line(bad):
    name = next(iter(bad))
    with pytest.raises(FloorplanOptionsError, match=name) as e:
        FloorplanOptions(**bad)
    assert isinstance(e.value, AnyHomeError)
    assert "\n" not in str(e.value)


def test_unordered_range_is_refused():
    with pytest.raises(FloorplanOptionsError, match="cell_min_m"):
        FloorplanOptions(cell_min_m=1.0, cell_max_m=0.5)
    with pytest.raises(FloorplanOptionsError, match="window_min_width_m"):
        FloorplanOptions(window_min_width_m=2.0)


@settings(max_examples=60, deadline=None)
@given(name=st.sampled_from(sorted(FIELDS)), side=st.sampled_from(["below", "above"]), by=st.floats(0.001, 1e6))
def test_any_field_out_of_range_is_refused(name, side, by):
    lo, hi = FIELDS[name].metadata["range"]
    value = lo - by if side == "below" else hi + by
    if isinstance(FIELDS[name].default, int):
        value = math.floor(value) if side == "below" else math.ceil(value)
    with pytest.raises(FloorplanOptionsError, match=name):
        FloorplanOptions(**{name: value})


def test_every_default_is_inside_its_range():
    for f in fields(FloorplanOptions):
        lo, hi = f.metadata["range"]
        assert lo <= f.default <= hi, f.name


def test_every_option_is_read_by_the_search():
    source = "\n".join(p.read_text() for p in FLOORPLAN_SRC.glob("*.py") if p.name != "options.py")
    unread = [name for name in FIELDS if f".{name}" not in source]
    assert unread == []


def test_every_option_has_a_docstring_and_units():
    tree = ast.parse((FLOORPLAN_SRC / "options.py").read_text())
    cls = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "FloorplanOptions")
    body = cls.body
    for i, node in enumerate(body):
        if isinstance(node, ast.AnnAssign):
            doc = body[i + 1]
            assert isinstance(doc, ast.Expr) and isinstance(doc.value, ast.Constant), node.target
            assert "\n" not in doc.value.value.strip(), node.target


def _numeric(node: ast.expr) -> bool:
    if isinstance(node, ast.Constant):
        return isinstance(node.value, (int, float)) and not isinstance(node.value, bool)
    if isinstance(node, ast.UnaryOp):
        return _numeric(node.operand)
    if isinstance(node, ast.Tuple):
        return bool(node.elts) and all(_numeric(e) for e in node.elts)
    return False


def test_no_tunable_module_constants_left():
    """A number at module level in the floorplan package is a listed physical standard."""
    found = set()
    for path in FLOORPLAN_SRC.glob("*.py"):
        for node in ast.parse(path.read_text()).body:
            targets = node.targets if isinstance(node, ast.Assign) else [node.target] if isinstance(node, ast.AnnAssign) else []
            value = node.value if isinstance(node, (ast.Assign, ast.AnnAssign)) else None
            if value is not None and _numeric(value):
                found |= {f"{path.name}:{t.id}" for t in targets if isinstance(t, ast.Name)}
    assert sorted(n for n in found if n.split(":")[1] not in KEPT_CONSTANTS) == []
