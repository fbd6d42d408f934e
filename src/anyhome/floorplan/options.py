"""The floorplan search's tunable numbers, as one frozen set of named options.

``solve_floorplan(spec, rng, options=FloorplanOptions())``: every try count, tolerance,
scoring weight and design preference the search uses is a field here (units in the
names: ``_m`` meters, ``_frac`` a share of 1, ``_cells`` grid cells; weights and costs
are in units of the score they add to). The defaults are AnyHome's own, so the default
options give the same floorplans as always. Each field has a valid range; a value out
of it (or of the wrong type) is refused with one :class:`FloorplanOptionsError` line.

Physical standards and the format's own values are not options and stay constants:
door and entrance widths (``doors.DOOR_WIDTH_M``, ``ENTRANCE_WIDTH_M``), door height and
headroom (``solver.DOOR_HEIGHT_M``, ``OPENING_HEADROOM_M``), window and bathroom-window
sill, height and width (``windows.WINDOW_SILL_M`` ...), the 5 cm snapping grid
(``grid.SNAP_M``, part of the house format) and the door keep-clear depth
(``geometry.DOOR_CLEARANCE_M``, shared with layout and evaluation).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field, fields
from typing import Any

from anyhome.errors import AnyHomeError


class FloorplanOptionsError(AnyHomeError):
    """A FloorplanOptions value is out of its range or of the wrong type."""


def _opt(default: float, lo: float, hi: float) -> Any:
    """A field with its default and its valid range ``[lo, hi]``."""
    return field(default=default, metadata={"range": (lo, hi)})


# pairs (low, high) that must be ordered: low <= high
_ORDERED = (
    ("cell_min_m", "cell_max_m"),
    ("footprint_aspect_min", "footprint_aspect_max"),
    ("l_cut_min_frac", "l_cut_max_frac"),
    ("l_corner_x_min_frac", "l_corner_x_max_frac"),
    ("u_notch_min_frac", "u_notch_max_frac"),
    ("spine_block_depth_min_m", "spine_block_depth_max_m"),
    ("spine_depth_jitter_min", "spine_depth_jitter_max"),
    ("spine_aspect_min", "spine_aspect_max"),
    ("open_min_width_m", "open_max_width_m"),
    ("window_min_width_m", "window_max_width_m"),
    ("anneal_end_temperature", "anneal_start_temperature"),
)


@dataclass(frozen=True)
class FloorplanOptions:
    """Tunable numbers of :func:`anyhome.floorplan.solve_floorplan`."""

    # ---------------------------------------------------------------- the search
    max_attempts: int = _opt(40, 1, 10_000)
    """Attempts before giving up with a FloorplanError."""
    level_attempts: int = _opt(8, 1, 1_000)
    """Solves per storey of a house of several storeys before a FloorplanError."""
    levels_max_attempts: int = _opt(500, 1, 1_000_000)
    """Layout attempts of all the searches of one house of several storeys together (every storey, retry and fallback): past it, a FloorplanError (floorplan.budget)."""
    storey_anneal_patience_frac: float = _opt(0.25, 0.0, 1.0)
    """``anneal_patience_frac`` of a storey's search (a house of several storeys); the smaller of the two applies."""
    storey_seed_settled_cells: float = _opt(0.01, 0.0, 10.0)
    """``seed_settled_cells`` of a storey's search (a house of several storeys); the larger of the two applies."""
    storey_candidates: int = _opt(3, 1, 100)
    """Layouts tried of each storey off the ground; the one hanging least over nothing is kept."""
    storey_wanted_candidates: int = _opt(1, 1, 1_000)
    """Layouts holding the stair one search of a storey gathers (at most wanted_candidates); the best is kept."""
    overhang_ok_m2: float = _opt(1.0, 0.0, 1_000.0)
    """A storey hanging over nothing by at most this much (m2) is kept at once."""
    stairwell_spare_m: float = _opt(0.3, 0.0, 5.0)
    """A stairwell is planned at least its stair's length by its width plus this (m)."""
    stairwell_roomy_m: float = _opt(1.3, 0.0, 5.0)
    """Added to ``stairwell_spare_m`` in the later half of the tries to stack the storeys."""
    slicing_max_rooms: int = _opt(6, 1, 1_000)
    """Programs up to this many rooms try the slicing search first; larger ones go to the spine."""
    # 15, not 10: a spine's rooms reach the depth of their block, so a small flat that
    # fell back to it was built up to 30 % larger than planned ("a 500 sq ft apartment": 59.9 m2)
    slicing_attempts: int = _opt(15, 0, 10_000)
    """Slicing attempts before falling back to the constructive spine layout."""
    storey_slicing_attempts: int = _opt(8, 0, 10_000)
    """``slicing_attempts`` of a storey's search (a house of several storeys; the smaller of the two applies; not the carve search's, floorplan.carve): measured on the dev storey sets, the slicing that succeeded did so within five attempts in 96 % of the searches, and a third of the searches spent all fifteen before the spine. 8, not 5: with 5 (branch h-scpu) merged beside h-size2's size reading, a tiny two-storey cottage of tests/plan/test_tiny_storeys.py was planned and built at 45.1 m2 (over the tiny 45 m2)."""
    slicing_short_give_up: int = _opt(5, 0, 10_000)
    """The first this many slicing attempts all leaving a room short of its least length (a storey's stairwell, ``min_length_m``): the search goes on with the spine at once (measured on the dev storey sets: slicing that succeeded did so within four such; 0: never)."""
    wanted_candidates: int = _opt(3, 1, 1_000)
    """Valid layouts to collect before keeping the best one (lowest score)."""

    # ------------------------------------------------- hard checks of a layout
    area_tolerance_frac: float = _opt(0.25, 0.0, 1.0)
    """Allowed relative deviation of a room's area from its target (0.25: 25 %)."""
    max_room_aspect_ratio: float = _opt(2.5, 1.0, 20.0)
    """Longest/shortest side of a service room (hallways excepted): checked, and penalised in slicing and tuning."""
    max_habitable_aspect_ratio: float = _opt(1.95, 1.0, 20.0)
    """Longest/shortest side of a habitable room: a hard check (issue 13: at most 2; 1.95 keeps a margin, rooms at exactly 2:1 read as just over)."""
    max_narrow_share_frac: float = _opt(0.08, 0.0, 1.0)
    """Share of a room's floor allowed in arms narrower than its minimum side."""
    precheck_wall_per_door_m: float = _opt(1.2, 0.0, 10.0)
    """Perimeter a room needs per door, when a program is checked before any attempt."""
    precheck_wall_spare_m: float = _opt(1.4, 0.0, 100.0)
    """Perimeter a room needs beyond its doors, when a program is checked before any attempt."""
    min_side_habitable_m: float = _opt(2.4, 0.5, 20.0)
    """Narrowest side of a habitable room."""
    min_side_service_m: float = _opt(1.6, 0.5, 20.0)
    """Narrowest side of a small service room (bathroom, closet...)."""
    corridor_width_m: float = _opt(1.2, 0.5, 20.0)
    """Narrowest hallway."""
    hub_min_side_m: float = _opt(2.2, 0.5, 20.0)
    """Narrowest side of a non-hallway room with hub_min_doors doors or more (wall left for a bench)."""
    hub_min_doors: int = _opt(4, 2, 100)
    """Doors (the way out included) from which a room is held to hub_min_side_m."""
    min_side_leeway_cells: float = _opt(0.2, 0.0, 1.0)
    """Cells a room's span may fall short of its minimum side (grid rounding leeway)."""
    shared_wall_min_m: float = _opt(1.3, 0.5, 10.0)
    """Shared wall a connection should get (door width plus margins, a little spare)."""
    exterior_wall_min_m: float = _opt(1.5, 0.5, 10.0)
    """Exterior wall a room needing a window or entrance should get (tuning cost)."""

    # ------------------------------------------------- the score of a valid layout
    score_aspect_free_ratio: float = _opt(1.6, 1.0, 20.0)
    """A room's bounding-box aspect up to which its shape adds nothing to a layout's score."""
    score_aspect_weight: float = _opt(0.1, 0.0, 100.0)
    """Score per unit of aspect above ``score_aspect_free_ratio``."""
    spine_score_handicap: float = _opt(1.0, 0.0, 1_000.0)
    """Added to a spine layout's score, so a slicing layout wins ties."""

    # ---------------------------------------------------------------- the footprint
    footprint_target_cells: int = _opt(600, 10, 1_000_000)
    """Roughly how many cells the footprint is cut into (sets the cell size)."""
    cell_min_m: float = _opt(0.3, 0.05, 5.0)
    """Smallest cell side of the slicing grid."""
    cell_max_m: float = _opt(1.0, 0.05, 5.0)
    """Largest cell side of the slicing grid."""
    footprint_aspect_min: float = _opt(1.0, 1.0, 10.0)
    """Least long/short side ratio the footprint's is drawn from."""
    footprint_aspect_max: float = _opt(1.6, 1.0, 10.0)
    """Greatest long/short side ratio the footprint's is drawn from."""
    l_shape_probability: float = _opt(0.35, 0.0, 1.0)
    """Chance of an L-shaped footprint (a corner cut away) for programs of ``l_shape_min_rooms``+ rooms."""
    l_shape_min_rooms: int = _opt(4, 1, 1_000)
    """Programs with fewer rooms always get a rectangular footprint."""
    l_cut_min_frac: float = _opt(0.12, 0.0, 0.5)
    """Least share of the bounding rectangle the L-shape's missing corner takes."""
    l_cut_max_frac: float = _opt(0.25, 0.0, 0.5)
    """Greatest share of the bounding rectangle the L-shape's missing corner takes."""
    l_corner_x_min_frac: float = _opt(0.35, 0.05, 0.95)
    """Least share of the footprint's x side the missing corner spans."""
    l_corner_x_max_frac: float = _opt(0.6, 0.05, 0.95)
    """Greatest share of the footprint's x side the missing corner spans."""

    u_shape_probability: float = _opt(0.3, 0.0, 1.0)
    """Chance of a U-shaped footprint (a notch in the middle of one side) for programs of ``u_shape_min_rooms``+ rooms not drawn as an L."""
    u_shape_min_rooms: int = _opt(5, 1, 1_000)
    """Programs with fewer rooms never get a U-shaped footprint."""
    u_notch_min_frac: float = _opt(0.3, 0.05, 0.9)
    """Least share of its side the U's notch spans."""
    u_notch_max_frac: float = _opt(0.45, 0.05, 0.9)
    """Greatest share of its side the U's notch spans."""
    u_arm_min_frac: float = _opt(0.2, 0.0, 0.5)
    """Least share of the notched side each arm of the U keeps."""

    # -------------------------------------------------- seeds (force layout)
    seed_force_iterations: int = _opt(60, 0, 10_000)
    """Relaxation steps of the force layout of the room seeds."""
    # off by default: 0.01 changed one-storey plans, and with them the furnishing
    seed_settled_cells: float = _opt(0.0, 0.0, 10.0)
    """The force layout stops once no seed moves farther than this in a step (cells; 0, the default: never early)."""
    seed_scalar_max_rooms: int = _opt(9, 0, 1_000)
    """Rooms up to which the force layout is stepped in Python floats rather than on arrays (``seeds._scalar_layout``): the same positions, only faster for a few rooms (measured per layout: 2.3 -> 1.2 ms for three rooms, 3.4 -> 3.1 ms for nine, 3.9 -> 4.1 ms for eleven)."""
    seed_jitter_cells: float = _opt(0.4, 0.0, 0.5)
    """Largest random offset of a seed from its drawn cell centre."""
    seed_attract_gain: float = _opt(0.3, 0.0, 1.0)
    """Share of the excess distance a connected pair of seeds closes per step."""
    seed_rest_distance_frac: float = _opt(0.9, 0.0, 5.0)
    """Connected seeds attract beyond this share of the sum of their radii."""
    seed_repel_gain: float = _opt(0.5, 0.0, 1.0)
    """Share of the overlap of two rooms' discs removed per step."""
    seed_edge_gain: float = _opt(0.3, 0.0, 1.0)
    """Share of the distance to the footprint edge an exterior room closes per step."""
    seed_edge_reach_frac: float = _opt(0.6, 0.0, 5.0)
    """An exterior room stops being pulled when the edge is within this share of its radius."""
    seed_center_gain: float = _opt(0.08, 0.0, 1.0)
    """Share of the distance to the centre a hub room closes per step."""

    # ---------------------------------------------------------------- slicing
    slice_cut_edge_cost: float = _opt(1.5, 0.0, 1_000.0)
    """Score per bubble-diagram edge crossing a cut."""
    slice_infeasible_cost: float = _opt(10.0, 0.0, 1_000_000.0)
    """Score of a part that breaks a hard rule (too thin, no exterior wall...)."""
    slice_exterior_per_room_m: float = _opt(2.2, 0.1, 100.0)
    """Exterior wall a part needs per room that must touch the outside."""
    slice_exterior_deficit_weight: float = _opt(2.0, 0.0, 1_000.0)
    """Score per room's worth of exterior wall a part lacks."""
    slice_wall_deficit_weight: float = _opt(4.0, 0.0, 1_000.0)
    """Score per meter a door wall falls short of ``shared_wall_min_m``."""
    slice_noise: float = _opt(0.35, 0.0, 1_000.0)
    """Scale of the random score noise that varies layouts across seeds."""
    slice_lookahead: int = _opt(6, 1, 1_000)
    """Best immediate cuts completed greedily before choosing one."""
    slice_room_aspect_soft: float = _opt(1.5, 1.0, 20.0)
    """Aspect above which a single room's shape starts to cost (1 per unit of aspect)."""
    slice_part_aspect_soft: float = _opt(3.0, 1.0, 20.0)
    """Aspect above which a multi-room part starts to cost."""
    slice_part_aspect_weight: float = _opt(0.3, 0.0, 1_000.0)
    """Score per unit of a multi-room part's aspect above ``slice_part_aspect_soft``."""
    slice_opposite_ports_cost: float = _opt(0.5, 0.0, 1_000.0)
    """Score of a room that must touch two opposite sides of its part."""
    slice_crowded_side_ports: int = _opt(2, 0, 1_000)
    """Rooms that may need a door on the same side of a part before it costs."""
    slice_crowded_side_cost: float = _opt(0.2, 0.0, 1_000.0)
    """Score per room beyond ``slice_crowded_side_ports`` on one side of a part."""

    # ---------------------------------------------------------------- annealing
    anneal_steps_per_room: int = _opt(150, 0, 1_000_000)
    """Annealing steps of the slicing tree per room of the program."""
    anneal_start_temperature: float = _opt(4.0, 1e-6, 1_000_000.0)
    """Starting temperature of the annealing (in units of the layout cost)."""
    anneal_end_temperature: float = _opt(0.05, 1e-6, 1_000_000.0)
    """Final temperature of the annealing (geometric schedule from the start)."""
    # measured on storey programs: of the runs that never reach cost 0, half found their
    # best at the first step and nine in ten within the first fifth of the schedule
    # off by default: 0.25 changed one-storey plans (two key items dropped on the public prompts)
    anneal_patience_frac: float = _opt(1.0, 0.0, 1.0)
    """The annealing stops once this share of its schedule passed without a better tree (1, the default: never early)."""

    # ---------------------------------------------------------------- tuning
    tune_rounds: int = _opt(30, 0, 100_000)
    """Most hill-climbing rounds per layout."""
    tune_nudge_max_cells: int = _opt(2, 1, 100)
    """Cut moves tried per round: every nonzero shift up to this many cells either way."""
    tune_area_slack_frac: float = _opt(0.2, 0.0, 1.0)
    """Relative area error tolerated before the tuning cost rises steeply."""
    tune_violation_weight: float = _opt(10.0, 0.0, 1_000_000.0)
    """Tuning cost per meter (or unit of area error) of a hard-rule shortfall."""
    tune_gap_weight: float = _opt(2.0, 0.0, 1_000_000.0)
    """Tuning cost per meter of gap between two connected rooms that do not touch."""
    tune_aspect_weight: float = _opt(5.0, 0.0, 1_000_000.0)
    """Tuning cost per unit of aspect above a room's greatest aspect."""

    # ------------------------------------------------------- spine (constructive)
    spine_cell_m: float = _opt(0.1, 0.05, 1.0)
    """Cell side of the owner grid the spine layout is drawn on."""
    spine_block_depth_min_m: float = _opt(3.2, 0.5, 100.0)
    """Least depth of the room blocks beside the spine."""
    spine_block_depth_max_m: float = _opt(8.0, 0.5, 100.0)
    """Greatest depth of the room blocks beside the spine (large rooms excepted)."""
    spine_depth_jitter_min: float = _opt(0.9, 0.1, 10.0)
    """Least random factor on the block depth derived from the room areas."""
    spine_depth_jitter_max: float = _opt(1.15, 0.1, 10.0)
    """Greatest random factor on the block depth derived from the room areas."""
    spine_hallway_min_m: float = _opt(1.3, 0.5, 20.0)
    """Narrowest spine hallway (a 0.9 m door plus margins fits its end wall)."""
    spine_window_gap_m: float = _opt(1.9, 0.0, 100.0)
    """Outside stretch kept free beside a habitable spine room whose both sides hold blocks."""
    spine_big_room_aspect: float = _opt(1.8, 1.0, 20.0)
    """Long/short ratio a large room in a block column is held to (its side grows deeper)."""
    spine_big_depth_max_m: float = _opt(16.0, 0.5, 1_000.0)
    """Deepest a side of the spine may grow for a large room."""
    spine_corridor_soft_length_m: float = _opt(7.0, 1.0, 1_000.0)
    """Spine hallway length its sides are deepened to stay within (rooms keeping their proportions)."""
    spine_depth_steps: int = _opt(8, 0, 100)
    """Deeper steps tried for one side of a spine segment (its rooms too long a row)."""
    spine_depth_step_frac: float = _opt(0.1, 0.01, 1.0)
    """Each step deepens the side by this share of its base depth."""
    spine_hall_splits: int = _opt(12, 0, 100_000)
    """Splits of a hall's rooms between its two sides tried for the shortest hall (an end room closing it)."""
    spine_hall_split_max_blocks: int = _opt(8, 0, 30)
    """Halls with more blocks of rooms than this keep the drawn split (a long hall of a hotel floor: too many splits, little to gain)."""
    spine_column_fill_max: float = _opt(2.0, 1.0, 1_000.0)
    """A one-room block column the side's depth would make over this many times its room's area is cut short (a 9 m2 kitchen beside a 7 m deep garage)."""
    spine_aspect_min: float = _opt(1.0, 1.0, 20.0)
    """Least long/short side ratio of a spine room that has no blocks to size it."""
    spine_aspect_max: float = _opt(1.5, 1.0, 20.0)
    """Greatest long/short side ratio of a spine room that has no blocks to size it."""

    # ------------------------------------------------ courtyard ring (constructive)
    court_attempts: int = _opt(6, 0, 10_000)
    """Attempts at a ring of rooms around an enclosed courtyard (rooms.yaml ``enclosed``), before the other searches."""
    court_trials: int = _opt(50, 1, 100_000)
    """Random deals of the court's blocks to its sides per attempt; the one with the fewest faults is drawn."""
    court_open_side_probability: float = _opt(0.2, 0.0, 1.0)
    """Chance (once per plan) of wings on three sides of the court only, a U; a closed ring that fails is tried as a U."""
    court_u_deep_probability: float = _opt(0.5, 0.0, 1.0)
    """Share of the U trials whose court runs the legs' whole length (else it keeps its planned area)."""
    court_max_aspect: float = _opt(2.0, 1.0, 20.0)
    """Longest/shortest side of the court the wings around it may give it."""
    court_max_area_ratio: float = _opt(2.5, 1.0, 100.0)
    """Most the court may grow past its planned area to close the ring of wings."""
    court_room_max_area_ratio: float = _opt(2.0, 1.0, 100.0)
    """Most a room of a courtyard ring may grow past its planned area (hallways excepted)."""
    court_deal_noise_frac: float = _opt(0.7, 0.0, 0.9)
    """Largest random share by which a block's area is jittered when the blocks are dealt to the sides (trials differ)."""
    court_corner_room_probability: float = _opt(0.5, 0.0, 1.0)
    """Share of the trials in which a corner square goes whole to a wing's end room (else spread along the east or west wing)."""
    court_depth_pull_max: float = _opt(1.0, 0.0, 1.0)
    """Greatest pull (drawn per trial) of the wings' depth from their rooms' own toward the one that wraps the court at its area."""

    # ---------------------------------------------------------------- doors
    door_end_margin_m: float = _opt(0.15, 0.0, 10.0)
    """Least distance from a door to the ends of its shared wall run."""
    door_gap_m: float = _opt(0.3, 0.0, 10.0)
    """Least distance between two openings on the same wall line."""
    door_center_penalty: float = _opt(0.3, 0.0, 1_000.0)
    """Score added to a door in the middle of a wall (it splits the wall for furniture)."""
    door_noise: float = _opt(0.05, 0.0, 1_000.0)
    """Scale of the random score noise between equally good door positions."""
    door_entrance_window_penalty: float = _opt(100.0, 0.0, 1_000_000.0)
    """Score of an entrance door that leaves its habitable room no wall for a window."""
    door_stair_penalty: float = _opt(50.0, 0.0, 1_000_000.0)
    """Score of a stairwell's door that leaves no place for its stair (a townhouse's ground floor took 10 tries without it)."""
    well_trim_min_m: float = _opt(0.3, 0.0, 10.0)
    """Narrowest band of a stairwell beyond its stair given to the room across (floorplan.wells), m."""
    stair_carve_attempts: int = _opt(1, 0, 100)
    """Searches of a storey with its stairwell carved from a corner of the one room it opens onto (floorplan.carve) before it is laid out with a stairwell of its own; 0: never carved."""
    stair_carve_left_m: float = _opt(1.2, 0.5, 10.0)
    """Narrowest strip of a room left beside a stairwell carved from its corner along it (a passage), m."""
    open_stair_max_corners: int = _opt(8, 4, 8)
    """Most corners of a room with its stairwell merged in: 4 a rectangle, 6 an L, 8 a T or Z (the stairwell an alcove off part of one wall)."""
    stair_carve_max_attempts: int = _opt(12, 1, 10_000)
    """Slicing attempts of one such search (``max_attempts`` at most)."""
    stair_carve_hopeless_test: int = _opt(1, 0, 1)
    """1: a carve search known to fail from the storey's program alone (floorplan.carve_fit: a hallway with too many doors for its passage, two rooms no rectangle cut once holds) is not run; 0: run (as before)."""
    stair_carve_hall_max_links: int = _opt(5, 1, 1_000)
    """Links (doors to rooms, the outside counted) at which a hallway carved into a stair and its passage is not searched (floorplan.carve_fit.crowded_hall; measured on the dev storey sets: 5 or more, 0 of 88 such searches found a layout; 4, 40 of 59)."""
    stair_carve_fit_slack_cells: float = _opt(0.5, 0.0, 10.0)
    """Grid cells a side may be off in floorplan.carve_fit.two_rooms_unfit: the footprint's sides are rounded to whole cells (measured on the dev storey sets: 0.5, 169 of the 384 failed carve searches told, none of the 572 that found a layout; 1.0, 147; 0, two that found one told)."""
    stair_carve_fit_steps: int = _opt(200, 10, 100_000)
    """Places of the one cut tried across the footprint in floorplan.carve_fit.two_rooms_unfit (its proportions: an eighth as many)."""
    small_exact_max_rooms: int = _opt(3, 0, 3)
    """Most rooms of a storey (of a house of several) laid out first by the exact arrangements of floorplan.small (strips, or one room along a side and two beside it) before the slicing search; 0: never."""
    small_exact_candidates: int = _opt(8, 1, 1_000)
    """Best exact arrangements of such a storey tried (floorplan.small), each an attempt."""
    small_circulation_excess_weight: float = _opt(2.0, 0.0, 1_000.0)
    """Extra weight in floorplan.small's score of a circulation room's floor beyond its target: of two arrangements equally far off, the one whose stairwell is the larger is the worse."""
    small_stair_excess_frac: float = _opt(0.35, 0.0, 10.0)
    """Most a room holding a stair may exceed its least rectangle in floorplan.small (its ends beyond the stair go to the room across when the storeys are stacked, floorplan.wells)."""
    small_door_wall_m: float = _opt(1.0, 0.5, 10.0)
    """Least wall two linked rooms share in floorplan.small's arrangements (a door and its frame), m."""
    well_end_trim: int = _opt(1, 0, 1)
    """1: a stairwell's ends beyond its stair's box and foot strip go to the room across (floorplan.wells.wells_end_trimmed); 0: kept."""
    well_doors_to_strip: int = _opt(1, 0, 1)
    """1: a stairwell's doors beside its stair slide onto the strip at its foot, so the passage beside the stair is trimmed (floorplan.wells.wells_doors_to_strip); 0: kept."""
    open_min_width_m: float = _opt(1.2, 0.5, 20.0)
    """Narrowest wall opening (kind "open"); below this an open pair gets a plain door."""
    open_max_width_m: float = _opt(1.8, 0.5, 20.0)
    """Widest wall opening (kind "open")."""

    # ---------------------------------------------------------------- windows
    window_min_width_m: float = _opt(0.8, 0.3, 20.0)
    """Narrowest window (a habitable room needs a free exterior stretch this wide)."""
    window_max_width_m: float = _opt(1.8, 0.3, 20.0)
    """Widest window."""
    window_wall_share_frac: float = _opt(0.45, 0.0, 1.0)
    """A window's width as a share of its wall run (before clamping)."""
    window_corner_margin_m: float = _opt(0.3, 0.0, 10.0)
    """Least distance from a window to a corner (run end) and to a door on the same wall."""
    second_window_run_m: float = _opt(2.5, 0.0, 100.0)
    """Exterior runs at least this long get a window of their own (after the first)."""
    max_windows_per_room: int = _opt(3, 1, 100)
    """Most windows in one room."""

    # ------------------------------------------------- open-plan L rooms (merge.py)
    open_plan_probability: float = _opt(0.5, 0.0, 1.0)
    """Chance that a house whose plan allows an open-plan L room gets one (its words not asking for it)."""
    open_plan_words_probability: float = _opt(1.0, 0.0, 1.0)
    """The same chance when the prompt or style asks for open plan (``open_plan.yaml`` words)."""
    open_plan_max_rooms: int = _opt(1, 0, 100)
    """Most L rooms merged in one house (0: none, every room stays a rectangle)."""
    open_stair_max_aspect_ratio: float = _opt(1.99, 1.0, 20.0)
    """Longest side / widest disc of a room with its storey's stairwell merged in (an open stair, ``levels.stairs_opened``): the room itself keeps ``max_habitable_aspect_ratio``, the stair's end is floor kept clear; under the plan metrics' 2."""

    def __post_init__(self) -> None:
        for name, lo, hi, is_int in _ranges():
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, int if is_int else (int, float)) or not lo <= v <= hi:
                kind = "an integer" if is_int else "a number"
                raise FloorplanOptionsError(f"FloorplanOptions.{name} must be {kind} in [{lo}, {hi}], got {v!r}")
        for low, high in _ORDERED:
            if getattr(self, low) > getattr(self, high):
                raise FloorplanOptionsError(
                    f"FloorplanOptions.{low} ({getattr(self, low)!r}) must not exceed {high} ({getattr(self, high)!r})"
                )


@functools.cache
def _ranges() -> tuple[tuple[str, float, float, bool], ...]:
    """(name, low, high, is an integer) of every field of :class:`FloorplanOptions`,
    read once (the options are checked at every ``dataclasses.replace``)."""
    return tuple((f.name, *f.metadata["range"], isinstance(f.default, int)) for f in fields(FloorplanOptions))
