"""Named options of the layout stage: every scoring weight, try count and noise level."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class LayoutOptions:
    """The layout's tunable numbers; ``layout_house(..., options=LayoutOptions(noise=0))``."""

    anchor_tries: int = 6
    """Anchor poses tried per group copy when its members do not all fit."""
    anchor_tries_required: int = 10
    """Anchor poses tried for groups the text asked for explicitly."""
    anchor_min_sep_m: float = 0.5
    """Anchor poses tried for one copy are at least this far apart (or turned)."""
    noise: float = 0.3
    """Weight of the seeded random term in an anchor's score."""
    member_noise: float = 0.05
    """Weight of the seeded random term in a member's score."""
    spacing_weight: float = 0.3
    """Weight of the free distance (capped at ``spacing_cap_m``) around an anchor."""
    spacing_cap_m: float = 0.8
    zone_spacing_weight: float = 1.5
    """Weight of the free distance (capped at ``zone_spacing_cap_m``) around the anchor of a
    zone (:mod:`anyhome.layout.fill`): a reading corner away from the sofa, not beside it."""
    zone_spacing_cap_m: float = 2.0
    """Free distance around a zone's anchor counted at most (m)."""
    window_penalty: float = 0.6
    """Score taken from tall floor objects standing in front of a window."""
    tall_m: float = 1.0
    """Floor objects taller than this avoid windows."""
    group_room_bonus: float = 0.8
    """Score added to anchor poses that leave room for the whole group around them."""
    zone_bonus: float = 1.0
    """Score added to floor poses inside the arm of an open-plan room that belongs to the
    planned room whose group is being placed (:mod:`anyhome.layout.zones`)."""
    beside_lane_bonus: float = 0.8
    """Score added to anchor poses with a free lane along each side a member stands beside
    (:func:`anyhome.layout.scoring.beside_lanes_free`)."""
    beside_lane_m: float = 0.6
    """Least width of that lane: an agent of 0.25 m radius walks up a lane this wide."""
    beside_lane_front_m: float = 0.3
    """The lane reaches this far beyond the anchor's front (where it opens to the room)."""
    group_room_height_m: float = 0.9
    """Height up to which the room around an anchor is checked for its group."""
    near_m: float = 1.0
    """Members placed further than this in front (a TV) do not count for the room bonus."""
    member_nav_retries: int = 4
    """Next-best poses tried when a member would block a walkway."""
    anchor_reach_retries: int = 4
    """Further anchor poses tried when every one tried leaves some floor object out of reach."""
    reach_retries: int = 8
    """Further poses tried for a member or ornament when none of the first keeps every
    floor object reachable."""
    verify_factor: int = 40
    """Candidates checked exactly per pose wanted."""
    corner_wall_pref: float = -1.0
    """Preference shift of plain wall poses offered to a corner item when no corner fits."""
    next_wall_fallback_pref: float = -0.5
    """Preference of a wall pose away from the previous object of a run..."""
    next_wall_fallback_per_m: float = 0.1
    """...less this much per metre away from it."""
    other_side_pref: float = -0.5
    """Preference shift of the other side for a member beside its target."""
    center_pref_scale: float = 3.0
    """Preference scale of an anchor's poses in a ``center`` arrangement."""
    row_aisle_u_m: float = 0.5
    """Aisle between the columns of a ``rows`` arrangement."""
    row_aisle_v_m: float = 0.5
    """Aisle between the rows of a ``rows`` arrangement."""
    row_front_clearance_m: float = 1.0
    """Free band kept in front of the wall the rows face."""
    row_front_aisle_m: float = 0.8
    """Walkway kept between the first row and what stands in front of it (a teacher's desk
    and chair), so the aisles behind can be reached from either side."""
    row_side_clearance_m: float = 0.3
    """Band kept along the other walls of a ``rows`` arrangement."""
    row_shifts_m: tuple[float, ...] = (0.0, 0.1, -0.1, 0.2, -0.2)
    """Shifts along the front wall tried for an anchor of a rows cell (first preferred)."""
    front_wall_bonus: float = 2.0
    """Score added to front-of-room items' poses (tag ``front_of_room``) on the wall the rows face."""
    surface_top_range_m: tuple[float, float] = (0.4, 1.2)
    """Top heights an ornament without a named target may stand on."""
    min_surface_m2: float = 0.04
    """Smallest top an ornament without a named target may stand on."""
    wall_item_gap_m: float = 0.1
    """Gap kept above the object a wall item hangs over (without its own elevation)."""
    ceiling_gap_m: float = 0.05
    """Gap kept under the ceiling by wall items."""


DEFAULT_OPTIONS = LayoutOptions()
