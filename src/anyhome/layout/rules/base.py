"""What every placement rule is made of: candidate poses, a parameters model, a context.

A rule (:class:`PlacementRule`) is one module of this package: a pydantic parameters
model (:class:`RuleParams`, its defaults stated there once) and a candidate generator
``candidates(ctx) -> (Cands, kind)`` returning every pose the rule allows (on a ~0.1 m
grid) with a preference (higher is better). Validity is not checked here; the layout
filters with :meth:`anyhome.space.RoomSpace.valid` and picks among what is left.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
import shapely
from pydantic import BaseModel, ConfigDict

from anyhome.geometry import footprint_polygon, wrap_yaw
from anyhome.geometry import front_dir as front_dir  # the rules import them from here
from anyhome.geometry import right_dir as right_dir
from anyhome.space import RoomSpace, Wall, rect_corners

if TYPE_CHECKING:
    from anyhome.house import HouseObject
    from anyhome.layout.options import LayoutOptions

GRID_STEP_M = 0.1
"""Spacing of candidate positions along walls and over the room."""
FAR_MET_PREF = 2.0
"""Preference added to a pose at least ``far_m`` from its target (more than noise,
spacing and the group's room bonus together can add)..."""
FAR_PER_M = 0.5
"""...and per metre of distance up to ``far_m``: when no pose is far enough, the
furthest wins (the relation relaxed, the object kept)."""
HALF_PI = np.pi / 2

Kind = Literal["floor", "wall", "top"]
"""Where a rule puts an object: standing on the floor, hung on a wall, on another's top."""
Placement = Literal["pose", "around", "top"]
"""How a group member's copies are placed: each by its own candidate poses, spread over
the sides of the target (chairs around a table), or on a supporting top."""
Extent = tuple[float, float, float, float]
"""(x0, x1, y0, y1) of a group copy in its anchor's frame (front is +y)."""


class RuleParams(BaseModel):
    """Parameters of a rule: unknown keys are refused, defaults are stated once, here; a
    field's docstring is its description (in the LLM planner's schemas and prompts)."""

    model_config = ConfigDict(extra="forbid", frozen=True, use_attribute_docstrings=True)


class NoParams(RuleParams):
    """The rule takes no parameters."""


@dataclass
class Cands:
    """Candidate poses: centre of the bottom face (x, y), yaw, z and preference."""

    xy: np.ndarray
    yaw: np.ndarray
    z: np.ndarray
    pref: np.ndarray

    @staticmethod
    def empty() -> Cands:
        return Cands(np.zeros((0, 2)), np.zeros(0), np.zeros(0), np.zeros(0))

    def __len__(self) -> int:
        return len(self.xy)

    def __add__(self, other: Cands) -> Cands:
        return Cands(
            np.concatenate([self.xy, other.xy]),
            np.concatenate([self.yaw, other.yaw]),
            np.concatenate([self.z, other.z]),
            np.concatenate([self.pref, other.pref]),
        )

    @staticmethod
    def join(parts: list[Cands]) -> Cands:
        """The candidates of ``parts`` in turn, as adding them to :meth:`empty` one by one does."""
        every = [Cands.empty(), *parts]
        return Cands(np.concatenate([c.xy for c in every]), np.concatenate([c.yaw for c in every]),
                     np.concatenate([c.z for c in every]), np.concatenate([c.pref for c in every]))

    def shifted_pref(self, delta: float) -> Cands:
        return Cands(self.xy, self.yaw, self.z, self.pref + delta)


@dataclass
class RuleContext:
    """Everything a rule's candidate generator may read for one object copy.

    ``ref`` is the object a relative rule places against (None: there is none),
    ``prev_same`` the previous copy of the same item, ``prev_wall`` the last object the
    group stood against a wall; ``copy``/``count`` number the copy among its item's.
    """

    space: RoomSpace
    size: Sequence[float]
    params: RuleParams
    options: LayoutOptions
    ref: HouseObject | None = None
    prev_same: HouseObject | None = None
    prev_wall: HouseObject | None = None
    copy: int = 0
    count: int = 1
    rng: np.random.Generator | None = None
    run: Sequence[HouseObject] = ()
    """Pieces of the run the object continues (its group's objects against a wall, the
    previous copies of a run of anchors), oldest first; ``prev_wall`` is among them."""


Candidates = Callable[[RuleContext], tuple[Cands, Kind]]


def _no_extent(box: Extent, anchor_size: Sequence[float], size: Sequence[float], params: Any,
               count: int, near_m: float | None) -> Extent:
    return box


def _same_params(params: dict[str, Any], copy: int, count: int) -> dict[str, Any]:
    return params


@dataclass(frozen=True)
class PlacementRule:
    """One placement rule of the AnyHome paper.

    name : the rule's name in plans (``ItemSpec.rule``)
    params : its parameters model
    candidates : pose generator for an anchor, member or ornament copy
    copy_candidates : the generator for a member's or ornament's copy, when it differs
        (alternate sides, copies side by side); None: ``candidates``
    relative : placed relative to a target object (``ItemSpec.target``)
    needs_target : without a target it falls back to ``untargeted``, else the room centre
    untargeted : the generator used when a ``needs_target`` rule has no target (a TV
        stand with no sofa: on a wall)
    against_wall : the object's back is on a wall (standing or hung)
    kind : standing on the floor, hung on a wall, or on a top
    placement : how a member's copies are placed (see :data:`Placement`)
    copy_params : the parameters of copy ``i`` of ``count`` (beside alternates sides)
    extent : grows a group copy's extent (anchor frame) by a member placed by this rule;
        ``near_m`` not None leaves out members placed further than that (a TV)
    faces_anchor : whether a member by this rule (with these params) faces the anchor
    continues : a copy goes next to the previous one (a run): ranked without spacing
        and with a member's noise, so the run continues rather than jumps
    """

    name: str
    params: type[RuleParams]
    candidates: Candidates
    doc: str
    relative: bool = False
    needs_target: bool = False
    against_wall: bool = False
    kind: Kind = "floor"
    placement: Placement = "pose"
    copy_candidates: Candidates | None = None
    copy_params: Callable[[dict[str, Any], int, int], dict[str, Any]] = _same_params
    extent: Callable[[Extent, Sequence[float], Sequence[float], Any, int, float | None], Extent] = _no_extent
    faces_anchor: Callable[[Any], bool] = lambda params: False
    continues: bool = False
    untargeted: Candidates | None = None

    @property
    def runs_along_wall(self) -> bool:
        """Stands on the floor against a wall: the next object of a run goes beside it."""
        return self.against_wall and self.kind == "floor"

    def parse(self, raw: dict[str, Any], lenient: bool = False) -> RuleParams:
        """``raw`` (``ItemSpec.params``) as this rule's typed parameters, defaults filled.

        With ``lenient``, keys this rule does not take are left out (an item placed by
        another rule than its own, as an arrangement does)."""
        return self.params.model_validate(self.taken(raw) if lenient else raw)

    def taken(self, raw: dict[str, Any]) -> dict[str, Any]:
        """The entries of ``raw`` this rule takes (those written for another rule left out)."""
        return {k: v for k, v in raw.items() if k in self.params.model_fields}


# ------------------------------------------------------------------ geometry helpers
def yaw_facing(direction: np.ndarray) -> float:
    """Yaw whose front (+y local) points along ``direction``."""
    return float(np.arctan2(-direction[0], direction[1]))


wrap = wrap_yaw


def wall_positions(wall: Wall, width: float, step: float = GRID_STEP_M) -> np.ndarray:
    """Positions along ``wall`` where an object ``width`` wide fits, ``step`` apart."""
    if wall.length < width - 1e-9:
        return np.zeros(0)
    lo, hi = width / 2, wall.length - width / 2
    t = np.arange(lo, hi + 1e-9, step)
    if hi - t[-1] > 1e-6:
        t = np.append(t, hi)
    return t


def on_wall(wall: Wall, t: np.ndarray, depth: float) -> np.ndarray:
    """Centres of objects ``depth`` deep with their backs on ``wall`` at positions ``t``."""
    return wall.a[None] + wall.u[None] * t[:, None] + wall.n[None] * (depth / 2)


def footprint_gaps(xy: np.ndarray, size: Sequence[float], yaw: np.ndarray, ref: HouseObject) -> np.ndarray:
    """Distances (m) between the footprints of boxes ``size`` at poses ``xy`` (n, 2),
    ``yaw`` (n,) and ``ref``'s footprint; (n,) float, 0 where they touch."""
    if not len(xy):
        return np.zeros(0)
    out = np.empty(len(xy))
    # boxes turned by a multiple of 90 degrees, like ref: the gap of two axis-aligned rectangles
    quarter = np.round(np.asarray(yaw) / HALF_PI)
    aligned = np.abs(np.asarray(yaw) - quarter * HALF_PI) < 1e-6
    rq = round(ref.yaw / HALF_PI)
    if abs(ref.yaw - rq * HALF_PI) >= 1e-6:
        aligned[:] = False
    if np.count_nonzero(aligned):
        odd = (quarter[aligned].astype(int) % 2) == 1
        hx = np.where(odd, size[1], size[0]) / 2
        hy = np.where(odd, size[0], size[1]) / 2
        rx, ry = (ref.size[1], ref.size[0]) if rq % 2 else (ref.size[0], ref.size[1])
        dx = np.maximum(0.0, np.abs(xy[aligned, 0] - ref.position[0]) - hx - rx / 2)
        dy = np.maximum(0.0, np.abs(xy[aligned, 1] - ref.position[1]) - hy - ry / 2)
        out[aligned] = np.hypot(dx, dy)
    rest = ~aligned
    if np.count_nonzero(rest):
        polys = shapely.polygons(rect_corners(xy[rest], size[:2], np.asarray(yaw)[rest]))
        out[rest] = shapely.distance(polys, footprint_polygon(ref.position, ref.size, ref.yaw))
    return out


def prefer_far(c: Cands, size: Sequence[float], ref: HouseObject | None, far_m: float) -> Cands:
    """``c`` with poses at least ``far_m`` from ``ref`` preferred (:data:`FAR_MET_PREF`),
    and the further the better up to it (:data:`FAR_PER_M`); unchanged without a
    target or a distance."""
    if far_m <= 0 or ref is None or not len(c):
        return c
    gaps = footprint_gaps(c.xy, size, c.yaw, ref)
    bonus = FAR_MET_PREF * (gaps >= far_m) + FAR_PER_M * np.minimum(gaps, far_m)
    return Cands(c.xy, c.yaw, c.z, c.pref + bonus)
