"""solve_floorplan: HouseSpec -> Floorplan by seeded room growth with bounded retries.

A program with an enclosed courtyard (rooms.yaml ``enclosed``) is first laid out as a
ring of rooms around it, or a U of wings (:mod:`anyhome.floorplan.court`). Otherwise
each attempt draws a compact footprint (rectangle, L or U) sized from the target areas,
places one seed per room with a force layout of the bubble diagram, slices the
footprint into room rectangles following the seeds, and then checks the hard
constraints: usable room
shapes and areas, a shared wall for every connection, an exterior wall for the
entrance and every habitable room. Valid attempts are scored on area error and shape;
the best of the first few is kept. A program that fails every attempt raises
:class:`~anyhome.errors.FloorplanError` naming the most common failure.
"""

from __future__ import annotations

import dataclasses
import logging
from collections import Counter
from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace

import numpy as np
from scipy import ndimage

from anyhome.errors import FloorplanError
from anyhome.floorplan.anneal import anneal
from anyhome.floorplan.budget import spend_attempt
from anyhome.floorplan.court import court_owner
from anyhome.floorplan.doors import PlacedDoor, door_kind, place_door
from anyhome.floorplan.grid import FREE, OUTSIDE, Grid, make_footprint, min_side_cells
from anyhome.floorplan.options import FloorplanOptions
from anyhome.floorplan.program import CORRIDOR_TYPES, Program
from anyhome.floorplan.seeds import seed_positions
from anyhome.floorplan.slicing import SliceRooms, slice_footprint, tree_rects
from anyhome.floorplan.small import small_owners
from anyhome.floorplan.spine import spine_owner
from anyhome.floorplan.tune import TuneRooms, tune_tree
from anyhome.floorplan.walls import (
    Run,
    bbox_aspect,
    narrow_share,
    room_outline,
    runs_between,
    simply_connected,
    wall_runs,
)
from anyhome.floorplan.windows import PlacedWindow, free_slots, place_windows, window_room_ok
from anyhome.house import Door, Floorplan, Room, Window
from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.spec import HouseSpec

log = logging.getLogger(__name__)

@dataclass(frozen=True)
class Layout:
    """One valid attempt."""

    owner: np.ndarray
    cell_m: float
    doors: list[PlacedDoor]
    windows: list[PlacedWindow]
    score: float
    origin: tuple[float, float] = (0.0, 0.0)
    """Where the owner grid's corner lies (a given footprint's corner)."""


def solve_floorplan(
    spec: HouseSpec,
    rng: np.random.Generator,
    options: FloorplanOptions | None = None,
    *,
    kb: KnowledgeBase | None = None,
    footprint: object | None = None,
    fixed: Mapping[str, tuple[float, float, float, float]] | None = None,
    min_length_m: Mapping[str, float] | None = None,
    min_side_m: Mapping[str, float] | None = None,
    stair_m: Mapping[str, float] | None = None,
) -> Floorplan:
    """Lay out ``spec``'s rooms, doors and windows.

    Parameters
    ----------
    spec : the planned house
    rng : the only source of randomness; the same seed gives the same floorplan
    options : the solver's tunable numbers; None: ``FloorplanOptions()``
    kb : the knowledge base whose room types give each room's narrowest width
        (``rooms.yaml`` ``min_width_m``); None: the one in force
    footprint : a shapely polygon (or a list of (x, y) points) the rooms must fill
        exactly (an upper storey on the ground floor's footprint); None: the solver
        draws one. See :mod:`anyhome.floorplan.fixed` for what is supported.
    fixed : room id -> axis-aligned rectangle (x0, y0, x1, y1) in meters that room must
        occupy exactly (a stairwell at the same place on every level)
    min_length_m : room id -> the shortest long side that room may have (a stairwell: its
        stair and the floor at the stair's foot)
    min_side_m : room id -> the narrowest side that room may have, where more than its
        type's norm (a stair hall: its stair and a landing beside it)
    stair_m : room id -> the length of the dog-leg stair box that room holds (a
        stairwell): its doors are placed, where they can be, where the stair and the
        strip at its foot stay clear of them (:func:`~anyhome.floorplan.stairs.stair_fits`)

    Raises
    ------
    FloorplanError
        if no attempt within ``options.max_attempts`` satisfies the hard constraints,
        or ``footprint``/``fixed`` cannot be honoured.
    """
    prog, layouts = _layouts(spec, rng, options, kb, footprint, fixed, min_length_m, min_side_m, stair_m)
    return _to_floorplan(spec, prog, layouts[0])


def floorplan_candidates(
    spec: HouseSpec,
    rng: np.random.Generator,
    options: FloorplanOptions | None = None,
    *,
    kb: KnowledgeBase | None = None,
    min_length_m: Mapping[str, float] | None = None,
    min_side_m: Mapping[str, float] | None = None,
    stair_m: Mapping[str, float] | None = None,
    accept: Callable[[Floorplan], Floorplan | None] | None = None,
) -> list[Floorplan]:
    """Every valid layout one :func:`solve_floorplan` search found (up to
    ``options.wanted_candidates``), best score first: the first is the floorplan
    :func:`solve_floorplan` gives with the same generator. A caller with checks of its
    own (a storey whose stair must fit and stack) tries the others before searching
    again, or passes them as ``accept`` (a layout -> the layout as the caller keeps it,
    or None: refused): a refused layout is a failed attempt (:data:`REFUSED`) and the
    search goes on. Same parameters and errors as :func:`solve_floorplan`."""
    kept: dict[int, Floorplan] = {}  # id(layout) -> what ``accept`` made of it

    def check(prog: Program, lay: Layout) -> str:
        plan = _to_floorplan(spec, prog, lay)
        if accept is not None:
            made = accept(plan)
            if made is None:
                return REFUSED
            plan = made
        kept[id(lay)] = plan
        return ""

    _, layouts = _layouts(spec, rng, options, kb, None, None, min_length_m, min_side_m, stair_m, check)
    return [kept[id(lay)] for lay in layouts]


REFUSED = "refused by the caller's own check"
"""The failure of a layout :func:`floorplan_candidates`' ``accept`` refused."""


def _layouts(spec: HouseSpec, rng: np.random.Generator, options: FloorplanOptions | None, kb: KnowledgeBase | None,
             footprint: object | None, fixed: Mapping[str, tuple[float, float, float, float]] | None,
             min_length_m: Mapping[str, float] | None, min_side_m: Mapping[str, float] | None,
             stair_m: Mapping[str, float] | None,
             check: Callable[[Program, Layout], str] | None = None) -> tuple[Program, list[Layout]]:
    """The program of ``spec`` and its valid layouts, best score first (see :func:`solve_floorplan`);
    ``check``: a further test of each valid layout ('' or why it fails)."""
    opts = options or FloorplanOptions()
    if kb is None:
        from anyhome.plan.knowledge import knowledge_base

        kb = knowledge_base()
    prog = Program.from_spec(spec, opts, kb)
    if min_length_m:
        prog = dataclasses.replace(prog, min_length_m=tuple(float(min_length_m.get(i, 0.0)) for i in prog.ids))
    if min_side_m:
        prog = dataclasses.replace(prog, min_width_m=tuple(  # a stairwell: the side its stair needs (a ladder's is narrow)
            float(min_side_m[i]) if stair_m and i in stair_m and i in min_side_m else max(w, float(min_side_m.get(i, 0.0)))
            for i, w in zip(prog.ids, prog.min_width_m or (0.0,) * prog.n)))
    if stair_m:
        prog = dataclasses.replace(prog, stair_m=tuple(float(stair_m.get(i, 0.0)) for i in prog.ids))
    _precheck(prog, opts)
    if footprint is not None or fixed:
        from anyhome.floorplan.fixed import solve_in_footprint

        return prog, [solve_in_footprint(prog, rng, footprint, dict(fixed or {}))]
    def checked(lay: Layout | str) -> Layout | str:
        lay = _long_enough(prog, lay)
        if check is None or isinstance(lay, str):
            return lay
        return check(prog, lay) or lay

    ring = _court_ring(prog, rng, opts, checked)
    if ring is not None:
        return prog, [ring]
    slicing_attempts = opts.slicing_attempts if prog.n <= opts.slicing_max_rooms else 0
    short = [0]  # slicing attempts so far, every one of which left a room too short
    exact = small_owners(prog, opts, rng)  # a storey of two or three rooms: its exact arrangements first

    def attempt(i: int) -> Layout | str:
        if i < len(exact):
            return checked(_constructed_attempt(prog, exact[i], rng, opts))
        i -= len(exact)
        if i < slicing_attempts and not (opts.slicing_short_give_up and short[0] >= opts.slicing_short_give_up):
            result = checked(_attempt(prog, rng, opts))
            short[0] = short[0] + 1 if short[0] == i and isinstance(result, str) and result.endswith(TOO_SHORT) else 0
            return result
        return checked(_constructed_attempt(prog, spine_owner(prog, rng), rng, opts, opts.spine_score_handicap))

    return prog, best_attempts(attempt, prog.n, opts)


TOO_SHORT = "too short"
"""The failure of a layout whose room falls short of its least length (``Program.min_length_m``)."""


def _long_enough(prog: Program, lay: Layout | str) -> Layout | str:
    """``lay``, or why not: a room whose type sets a shortest long side
    (``Program.min_length_m``: a stairwell) must reach it."""
    if isinstance(lay, str) or not any(prog.min_length_m):
        return lay
    for k, least in enumerate(prog.min_length_m):
        if least > 0:
            xs, ys = np.nonzero(lay.owner == k)
            if len(xs) and max(xs.max() - xs.min() + 1, ys.max() - ys.min() + 1) * lay.cell_m < least - 1e-6:
                return f"room {prog.ids[k]!r} {TOO_SHORT}"
    return lay


def _court_ring(prog: Program, rng: np.random.Generator, opts: FloorplanOptions,
                checked: Callable[[Layout | str], Layout | str] | None = None) -> Layout | None:
    """The best ring of rooms around the program's enclosed courtyard (closed, or a U at
    ``court_open_side_probability``; a closed ring that fails is tried as a U), or None;
    ``checked``: a layout or why not -> the same after the caller's checks (None:
    :func:`_long_enough`)."""
    if checked is None:
        checked = lambda lay: _long_enough(prog, lay)  # noqa: E731
    if not any(prog.enclosed) or not opts.court_attempts:
        return None
    tries = replace(opts, max_attempts=opts.court_attempts)
    shapes = [True] if rng.random() < opts.court_open_side_probability else [False, True]
    for open_side in shapes:
        try:
            return best_attempt(
                lambda i: checked(_constructed_attempt(prog, court_owner(prog, rng, open_side), rng, opts)),
                prog.n, tries, " around its courtyard")
        except FloorplanError:
            log.debug("floorplan: no courtyard %s in %d attempts", "U" if open_side else "ring", opts.court_attempts)
    return None


def best_attempt(attempt: Callable[[int], Layout | str], n_rooms: int, opts: FloorplanOptions,
                 where: str = "") -> Layout:
    """The best-scoring of the first ``opts.wanted_candidates`` valid layouts that
    ``attempt(i)`` (a layout, or why it failed) gives in ``opts.max_attempts`` tries; a
    FloorplanError naming the commonest failure when none is valid."""
    return best_attempts(attempt, n_rooms, opts, where)[0]


def best_attempts(attempt: Callable[[int], Layout | str], n_rooms: int, opts: FloorplanOptions,
                  where: str = "") -> list[Layout]:
    """The first ``opts.wanted_candidates`` valid layouts that ``attempt(i)`` gives in
    ``opts.max_attempts`` tries, best score first (ties in the order found); a
    FloorplanError naming the commonest failure when none is valid. Each attempt spends
    one of the whole search's budget, where one is set (:mod:`anyhome.floorplan.budget`)."""
    failures: Counter[str] = Counter()
    found: list[Layout] = []
    for i in range(opts.max_attempts):
        spend_attempt()
        result = attempt(i)
        if isinstance(result, str):
            failures[result] += 1
            continue
        found.append(result)
        if len(found) >= opts.wanted_candidates:
            break
    if not found:
        reason, count = failures.most_common(1)[0]
        raise FloorplanError(
            f"could not lay out the {n_rooms}-room program{where} in {opts.max_attempts} attempts "
            f"(most often: {reason}, {count}x)"
        )
    log.debug("floorplan: %d attempts, failures %s", i + 1, dict(failures))
    return sorted(found, key=lambda lay: lay.score)


def floorplan_errors(spec: HouseSpec) -> list[str]:
    """Why ``spec``'s rooms and connections cannot be laid out as a floorplan (one line,
    from the solver at seed 0), or [] when they can. The LLM planner checks a program
    reply with it (``LLMPlanner(config, floorplan_check=floorplan_errors)``)."""
    try:
        solve_floorplan(spec, np.random.default_rng(0))
    except FloorplanError as e:
        return [str(e)]
    return []

def _precheck(prog: Program, opts: FloorplanOptions) -> None:
    """Reject programs whose rooms cannot have enough wall for their doors."""
    for k, deg in enumerate(prog.doors.tolist()):
        if not deg:
            continue
        area = prog.areas_m2[k] * (1 + opts.area_tolerance_frac)
        perimeter = 2 * (np.sqrt(opts.max_room_aspect_ratio * area) + np.sqrt(area / opts.max_room_aspect_ratio))
        if prog.types[k] not in CORRIDOR_TYPES and deg * opts.precheck_wall_per_door_m + opts.precheck_wall_spare_m > perimeter:
            raise FloorplanError(
                f"room {prog.ids[k]!r} ({prog.areas_m2[k]:.1f} m2) is too small for its {deg} doors"
            )


def _attempt(prog: Program, rng: np.random.Generator, opts: FloorplanOptions, grid: Grid | None = None) -> Layout | str:
    """One try: a Layout, or a short reason it failed; ``grid``: the footprint to fill
    (None: one drawn at random)."""
    if grid is None:
        grid = make_footprint(float(prog.areas_m2.sum()), prog.n, rng, opts, allow_u=not prog.stacked,
                              min_long_m=max(prog.min_length_m, default=0.0))
    owner = _slice_rooms(prog, grid, rng, opts)
    reason, score = _check_rooms(prog, owner, grid.cell_m, opts)
    if reason:
        return reason
    if _has_courtyard(owner):
        return "the footprint enclosed an empty courtyard"
    runs = wall_runs(owner)
    doors = _place_doors(prog, runs, grid.cell_m, rng, owner)
    if isinstance(doors, str):
        return doors
    windows = _place_windows(prog, runs, doors, grid.cell_m)
    if isinstance(windows, str):
        return windows
    return Layout(owner, grid.cell_m, doors, windows, score)


def _constructed_attempt(prog: Program, owner: np.ndarray | str, rng: np.random.Generator, opts: FloorplanOptions,
                         handicap: float = 0.0) -> Layout | str:
    """A constructive layout (a spine, :mod:`anyhome.floorplan.spine`, or a courtyard
    ring, :mod:`anyhome.floorplan.court`) checked and given doors and windows; its score
    is its area error plus ``handicap``."""
    if isinstance(owner, str):
        return owner
    cell_m = opts.spine_cell_m
    reason = _check_shapes(prog, owner, cell_m, opts)
    if reason:
        return reason
    runs = wall_runs(owner)
    doors = _place_doors(prog, runs, cell_m, rng, owner)
    if isinstance(doors, str):
        return doors
    windows = _place_windows(prog, runs, doors, cell_m)
    if isinstance(windows, str):
        return windows
    area = np.array([(owner == k).sum() for k in range(prog.n)]) * cell_m**2
    score = float(np.abs(area / prog.areas_m2 - 1).sum()) + handicap
    return Layout(owner, cell_m, doors, windows, score)


def _slice_rooms(prog: Program, grid: Grid, rng: np.random.Generator, opts: FloorplanOptions) -> np.ndarray:
    """Owner array of the footprint sliced into one rectangle per room (void = outside)."""
    exterior = prog.needs_exterior()
    pos = seed_positions(grid, prog.areas_m2, prog.edges, exterior, prog.hubs(), rng, opts) - 1.0
    cell = grid.cell_m
    nx, ny = grid.shape
    void = np.argwhere(grid.owner[1:-1, 1:-1] == OUTSIDE)
    cells = prog.areas_m2 / cell**2
    min_side = np.array([min_side_cells(prog.min_side_m(k), cell, opts) * cell for k in range(prog.n)])
    corridor = np.array([t in CORRIDOR_TYPES for t in prog.types])
    max_aspect = np.array([prog.max_aspect(k) for k in range(prog.n)])
    void_id = None
    if len(void):
        void_id = prog.n
        cells = np.append(cells, len(void) * cells.sum() / (nx * ny - len(void)))
        min_side, corridor = np.append(min_side, 2 * cell), np.append(corridor, True)
        max_aspect = np.append(max_aspect, np.inf)
        exterior, pos = np.append(exterior, False), np.vstack([pos, void.mean(axis=0) + 0.5])
    min_long = np.array(prog.min_length_m or (0.0,) * prog.n, dtype=float)
    if void_id is not None:
        min_long = np.append(min_long, 0.0)
    rooms = SliceRooms(cells, min_side, corridor, exterior, void_id, pos, frozenset(prog.edges), cell, opts, max_aspect,
                       grid.void_sides, min_long if min_long.any() else None)
    tree = slice_footprint((0, 0, nx, ny), rooms, rng)
    targets = np.maximum(cells, (min_side / cell) ** 2)
    if void_id is not None and grid.void_sides == 2:
        targets[void_id] = 1.0
    tune_rooms = TuneRooms(targets, min_side, corridor, exterior, void_id, tuple(prog.edges), cell, opts, max_aspect,
                           min_long_m=min_long if min_long.any() else None, void_sides=grid.void_sides)
    tree = anneal(tree, (0, 0, nx, ny), tune_rooms, rng, opts)
    tune_tree(tree, (0, 0, nx, ny), tune_rooms)
    owner = np.full((nx + 2, ny + 2), OUTSIDE, dtype=np.int32)
    owner[1:-1, 1:-1] = FREE
    for k, (x0, y0, x1, y1) in tree_rects(tree, (0, 0, nx, ny)).items():
        owner[x0 + 1 : x1 + 1, y0 + 1 : y1 + 1] = OUTSIDE if k == void_id else k
    return owner


def _has_courtyard(owner: np.ndarray) -> bool:
    """True if some outside cells are enclosed by rooms (a hole in the footprint)."""
    labels, n = ndimage.label(owner == OUTSIDE)
    border = set(np.unique(np.concatenate([labels[0], labels[-1], labels[:, 0], labels[:, -1]])))
    return any(k not in border for k in range(1, n + 1))


def _check_rooms(prog: Program, owner: np.ndarray, cell_m: float, opts: FloorplanOptions) -> tuple[str, float]:
    """('', score) if every room has a usable shape and area, else (reason, inf)."""
    score = 0.0
    for k in range(prog.n):
        mask = owner == k
        cells = int(mask.sum())
        if cells == 0 or not simply_connected(mask):
            return f"room {prog.ids[k]!r} did not grow into one simple shape", np.inf
        min_side = prog.min_side_m(k)
        ratio = cells * cell_m**2 / max(prog.areas_m2[k], min_side**2)
        if abs(ratio - 1) > opts.area_tolerance_frac and not (ratio > 1 and cells * cell_m**2 <= (1 + opts.area_tolerance_frac) * min_side**2):
            return f"room {prog.ids[k]!r} area off target", np.inf
        aspect = bbox_aspect(mask)
        if aspect > prog.max_aspect(k) + 1e-9:
            return f"room {prog.ids[k]!r} too elongated", np.inf
        if narrow_share(mask, min_side_cells(min_side, cell_m, opts)) > opts.max_narrow_share_frac:
            return f"room {prog.ids[k]!r} too narrow", np.inf
        score += abs(ratio - 1) + opts.score_aspect_weight * max(0.0, aspect - opts.score_aspect_free_ratio)
    return "", score


def _check_shapes(prog: Program, owner: np.ndarray, cell_m: float, opts: FloorplanOptions) -> str:
    """'' if every room keeps its type's proportions and width, else the reason."""
    for k in range(prog.n):
        mask = owner == k
        xs, ys = np.nonzero(mask)
        w, h = int(xs.max() - xs.min() + 1), int(ys.max() - ys.min() + 1)
        if max(w, h) / min(w, h) > prog.max_aspect(k) + 1e-9:
            return f"room {prog.ids[k]!r} too elongated"
        least = min_side_cells(prog.min_side_m(k), cell_m, opts)
        narrow = min(w, h) < least if w * h == len(xs) else narrow_share(mask, least) > opts.max_narrow_share_frac
        if narrow:
            return f"room {prog.ids[k]!r} too narrow"
    return ""


def _place_doors(prog: Program, runs: list[Run], cell_m: float, rng, owner: np.ndarray | None = None) -> list[PlacedDoor] | str:
    """Doors for every link in order (entrances last), plus doors that make all reachable."""
    placed: dict[int, PlacedDoor] = {}
    order = sorted(range(len(prog.links)), key=lambda i: prog.links[i][1] == OUTSIDE)
    for i in order:
        a, b = prog.links[i]
        kind = door_kind(prog.types[a], prog.types[b] if b != OUTSIDE else None)
        stair = _stair_penalty(prog, a, b, owner, placed, cell_m)
        penalty = _entrance_penalty(prog, a, b, runs, placed, cell_m) or stair
        opts = prog.options if stair is None else _stair_door_options(prog.options)  # a door may stand in the strip at the stair's foot
        door = place_door((a, b), kind, runs, cell_m, list(placed.values()), rng, opts, penalty)
        if door is None:
            return f"connection {prog.label(a)}-{prog.label(b)} has no shared wall long enough"
        placed[i] = door
    doors = [placed[i] for i in range(len(prog.links))]
    return _connect_unreachable(prog, runs, cell_m, doors, rng)


def _stair_door_options(opts: FloorplanOptions) -> FloorplanOptions:
    """``opts`` for a stairwell's doors: as near a corner as
    :data:`~anyhome.floorplan.stairs.DOOR_CORNER_M` (a door in a long wall fits the
    strip of floor at the stair's foot)."""
    from anyhome.floorplan.stairs import DOOR_CORNER_M

    return replace(opts, door_end_margin_m=min(opts.door_end_margin_m, DOOR_CORNER_M))


def _stair_penalty(prog, a, b, owner, placed, cell_m):
    """For a door of a stairwell (``Program.stair_m``): penalise a door that, with the
    stairwell's doors placed before it, leaves no place for its stair
    (:func:`~anyhome.floorplan.stairs.stair_fits`); None: no stairwell, or not a rectangle."""
    if owner is None or not prog.stair_m:
        return None
    well = next((k for k in (a, b) if k != OUTSIDE and prog.stair_m[k] > 0), None)
    if well is None:
        return None
    xs, ys = np.nonzero(owner == well)
    if not len(xs) or len(xs) != (xs.max() - xs.min() + 1) * (ys.max() - ys.min() + 1):
        return None
    from anyhome.floorplan.stairs import stair_fitter

    rect = ((xs.min() - 1) * cell_m, (ys.min() - 1) * cell_m, (xs.max() - xs.min() + 1) * cell_m, (ys.max() - ys.min() + 1) * cell_m)
    own = [d.opening.segment() for d in placed.values() if well in d.rooms]
    fits, cost = stair_fitter(rect, own, prog.stair_m[well]), prog.options.door_stair_penalty  # stair_fits(rect, [*own, opening])

    def penalty(opening) -> float:
        return 0.0 if fits([opening.segment()]) else cost

    return penalty


def _entrance_penalty(prog, a, b, runs, placed, cell_m):
    """For a habitable entrance room: penalise doors that leave no room for a window."""
    if b != OUTSIDE or not prog.habitable(a):
        return None
    others = list(placed.values())
    opts = prog.options

    def penalty(opening) -> float:
        slots = free_slots(a, runs, others + [PlacedDoor((a, b), opening)], cell_m, opts)
        return 0.0 if window_room_ok(slots, opts) else opts.door_entrance_window_penalty

    return penalty


def _connect_unreachable(prog, runs, cell_m, doors, rng) -> list[PlacedDoor] | str:
    """Add doors from rooms the plan left unreachable to a reachable neighbour."""
    doors = list(doors)
    for _ in range(prog.n):
        reached = _reached(prog, doors)
        missing = [k for k in range(prog.n) if k not in reached]
        if not missing:
            return doors
        door = _bridge(prog, runs, cell_m, doors, reached, missing, rng)
        if door is None:
            return f"room {prog.ids[missing[0]]!r} cannot be reached from the entrance"
        log.info("floorplan: added a door %s-%s to reach every room", *map(prog.label, door.rooms))
        doors.append(door)
    return doors


def _reached(prog: Program, doors: list[PlacedDoor]) -> set[int]:
    reached = {OUTSIDE}
    grew = True
    while grew:
        grew = False
        for d in doors:
            a, b = d.rooms
            if (a in reached) != (b in reached):
                reached |= {a, b}
                grew = True
    return reached - {OUTSIDE}


def _bridge(prog, runs, cell_m, doors, reached, missing, rng) -> PlacedDoor | None:
    for k in missing:
        partners = sorted(
            (p for p in reached if runs_between(runs, k, p)),
            key=lambda p: -max(r.length for r in runs_between(runs, k, p)),
        )
        for p in partners:
            door = place_door((p, k), "door", runs, cell_m, doors, rng, prog.options)
            if door is not None:
                return door
    return None


def _place_windows(prog, runs, doors, cell_m) -> list[PlacedWindow] | str:
    windows: list[PlacedWindow] = []
    courts = frozenset(k for k in range(prog.n) if prog.enclosed and prog.enclosed[k])
    for k in range(prog.n):
        slots = free_slots(k, runs, doors, cell_m, prog.options, courts)
        placed = place_windows(k, prog.habitable(k), prog.types[k] == "bathroom", slots, prog.options)
        if prog.habitable(k) and not placed:
            return f"habitable room {prog.ids[k]!r} has no exterior wall for a window"
        windows.extend(placed)
    return windows


DOOR_HEIGHT_M = 2.1
"""Height of a door opening, where the rooms' ceilings allow it (a physical standard)."""
OPENING_HEADROOM_M = 0.1
"""Wall kept between the top of a door or window and the ceiling (a physical standard)."""


def _to_floorplan(spec: HouseSpec, prog: Program, lay: Layout) -> Floorplan:
    ox, oy = lay.origin

    def moved(points):
        if ox == 0 and oy == 0:
            return points
        return type(points)((round(x + ox, 4), round(y + oy, 4)) for x, y in points)

    rooms = [
        Room(
            id=r.id, name=r.name, type=r.type, height=r.height_m, style=r.style, open_air=r.open_air, ceiling=r.ceiling,
            materials=dict(r.materials), polygon=moved(room_outline(lay.owner == k, lay.cell_m)),
        )
        for k, r in enumerate(spec.rooms)
    ]
    heights = {r.id: r.height for r in rooms}
    doors = []
    for i, d in enumerate(lay.doors):
        sides = spec.connections[i] if i < len(spec.connections) else (prog.label(d.rooms[0]), prog.label(d.rooms[1]))
        # a door fits under the lower ceiling of the rooms it joins
        ceiling_m = min(heights.get(s, DOOR_HEIGHT_M + OPENING_HEADROOM_M) for s in sides)
        doors.append(Door(id=f"door-{i}", rooms=sides, segment=moved(d.opening.segment()), kind=d.kind,
                          height=min(DOOR_HEIGHT_M, ceiling_m - OPENING_HEADROOM_M)))
    windows = []
    for i, w in enumerate(lay.windows):
        room_id = prog.ids[w.room]
        # a window's top stays under its room's ceiling
        height_m = min(w.height_m, heights[room_id] - OPENING_HEADROOM_M - w.sill_m)
        windows.append(Window(id=f"win-{i}", room=room_id, segment=moved(w.opening.segment()), height=height_m, sill=w.sill_m))
    return Floorplan(rooms=rooms, doors=doors, windows=windows, connections=list(spec.connections))
